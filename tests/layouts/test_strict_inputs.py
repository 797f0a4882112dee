"""Issue 27: the layout importers (luminous, front, atiss) check every field they read as strictly as the CDF
validator (finite numbers, positive sizes within bounds, known states, angles, references between entries,
exactly one-hot labels), refuse a file in one line naming the file and the field path, and list every entry
they drop."""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.cli.main import main
from luminous_sim.layouts import LayoutError, import_atiss, import_front, loads, realize
from luminous_sim.limits import MAX_LAYOUT_ROOM_SIDE_M, MAX_LAYOUT_SIDE_M
from tests.layouts.helpers import ATISS, FRONT, MODEL_INFO

ROOM = {"name": "r", "room_type": "Kitchen", "outline": [[0, 0], [3, 0], [3, 3], [0, 3]]}
CHAIR = {"id": "c", "category": "Chair", "size": [0.5, 0.5, 0.9], "position": [1, 1, 0.45]}


def _layout_error(doc: Any) -> str:
    with pytest.raises(LayoutError) as err:
        loads(json.dumps(doc), where="scene.json")
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith("scene.json: ")
    return msg


# -- luminous-layout/1 ------------------------------------------------------------------------------------------


@pytest.mark.parametrize(("change", "needle"), [
    ({"size": [0.5, -0.3, 0.9]}, "objects[0].size[1]: expected greater than 0 (got -0.3)"),
    ({"size": [0.5, MAX_LAYOUT_SIDE_M + 1, 0.9]}, f"objects[0].size[1]: expected less than or equal to "
                                                  f"{MAX_LAYOUT_SIDE_M:g}"),
    ({"size": [0.5, "0.5", 0.9]}, "objects[0].size[1]: expected a valid number (got '0.5')"),
    ({"size": [0.5, True, 0.9]}, "objects[0].size[1]: expected a valid number (got True)"),
    ({"position": [1, 1e9, 0]}, "objects[0].position[1]: expected less than or equal to 1000"),
    ({"yaw": 1e6}, "objects[0].yaw: expected less than or equal to 12.56"),
    ({"states": {"isOpne": True}}, "objects[0].states.isOpne.[key]: expected 'isOpen'"),
    ({"states": {"isOpen": "yes"}}, "objects[0].states.isOpen: expected a valid boolean (got 'yes')"),
    ({"states": {"isOpen": True}}, "objects[0]: states.isOpen: Chair is not openable"),
    ({"category": "kitchen_chair", "states": {"isDirty": False}}, "'kitchen_chair' is not an ALFRED object type"),
    ({"fixed": "no"}, "objects[0].fixed: expected a valid boolean"),
    ({"color": [0.5, 2, 0]}, "objects[0].color[1]: expected less than or equal to 1"),
    ({"color_seed": -1}, "objects[0].color_seed: expected greater than or equal to 0"),
    ({"parent": "c"}, "objects[0] (c): parent 'c' leads back to 'c'"),
    ({"region": "shelf"}, "objects[0] (c): region 'shelf' without a parent"),
    ({"category": ""}, "objects[0].category: String should have at least 1 character"),
])
def test_luminous_layout_fields_are_checked(change: dict[str, Any], needle: str) -> None:
    msg = _layout_error({"room": ROOM, "objects": [{**CHAIR, **change}]})
    assert needle in msg, msg


def test_luminous_layout_parent_cycles_and_room_bounds() -> None:
    a = {**CHAIR, "id": "a", "parent": "b"}
    b = {**CHAIR, "id": "b", "parent": "a"}
    assert "objects[0] (a): parent 'b' leads back to 'a'" in _layout_error({"room": ROOM, "objects": [a, b]})
    side = MAX_LAYOUT_ROOM_SIDE_M + 10
    big = {**ROOM, "outline": [[0, 0], [side, 0], [side, 3], [0, 3]]}
    assert f"outline: spans {side:g} m along x" in _layout_error({"room": big})
    assert "expected a JSON object" in _layout_error([ROOM])
    bad_door = {**ROOM, "doors": [{"wall": 1.5, "offset": 0.2, "width": 0.9}]}
    assert "room.doors[0].wall: expected a valid integer" in _layout_error({"room": bad_door})


def test_many_problems_stay_on_one_line() -> None:
    objects = [{**CHAIR, "id": f"c{i}", "size": [-1, -1, -1]} for i in range(4)]
    msg = _layout_error({"room": ROOM, "objects": objects})
    assert msg.count("expected greater than 0") == 5 and msg.endswith("(and 7 more)")


def test_an_asset_must_be_of_the_category_it_claims() -> None:
    from luminous_sim.assets.catalog import default_catalog

    mug = default_catalog().of_type("Mug")[0]
    layout = loads(json.dumps({"room": ROOM, "objects": [{**CHAIR, "asset": mug.id}]}))
    with pytest.raises(LayoutError, match=rf"x.json: objects\[0\].category: asset '{mug.id}' is a Mug; expected "
                                          "category Mug, got 'Chair'"):
        realize(layout, where="x.json")


# -- 3D-FRONT ---------------------------------------------------------------------------------------------------


def _front(tmp_path: Path, change: Any, **kw: Any) -> str:
    data = json.loads(FRONT.read_text())
    change(data)
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(LayoutError) as err:
        import_front(path, **{"model_info": MODEL_INFO, **kw})
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith(f"{path}: "), msg
    return msg[len(str(path)) + 2:]


def _child(d: dict, j: int) -> dict:
    return d["scene"]["room"][1]["children"][j]


@pytest.mark.parametrize(("change", "expected"), [
    (lambda d: d["furniture"][4].update(bbox=[0.46, -0.3, 0.48]),
     "furniture[4].bbox[1]: expected a positive number of at most 30 m (luminous_sim.limits.MAX_LAYOUT_SIDE_M), "
     "got -0.3"),
    (lambda d: d["furniture"][4].update(bbox=[0.46, 0.9]), "furniture[4].bbox: expected a list of 3 numbers, got "
                                                           "[0.46, 0.9]"),
    (lambda d: d["furniture"][0].update(valid="yes"), "furniture[0].valid: expected true or false, got 'yes'"),
    (lambda d: d["furniture"][1].update(uid="f-fridge"), "furniture[1].uid: expected a uid given once (it is also "
                                                         "furniture[0])"),
    (lambda d: d["mesh"][0].update(uid="f-fridge"), "mesh[0].uid: expected a uid given once"),
    (lambda d: _child(d, 0).update(pos=[1, 1e7, 0]), "scene.room[1].children[0].pos[1]: expected a coordinate "
                                                     "within +-1000 m"),
    (lambda d: _child(d, 0).update(rot=[0, 0, 0, 0]), "scene.room[1].children[0].rot: expected a unit quaternion"),
    (lambda d: _child(d, 0).update(rot=[0, 0, 0, None]), "scene.room[1].children[0].rot[3]: expected a finite "
                                                         "number, got None"),
    (lambda d: _child(d, 0).update(scale=[1, 0, 1]), "scene.room[1].children[0].scale[1]: expected a positive "
                                                     "scale of at most 100, got 0"),
    (lambda d: _child(d, 0).update(scale=[100, 1, 1]), "scene.room[1].children[0].scale: expected a scale that "
                                                       "keeps furniture[0].bbox within 30 m"),
    (lambda d: _child(d, 1).update(instanceid="furniture/0"), "scene.room[1].children[1].instanceid: expected an "
                                                              "instance id given once in the room"),
    (lambda d: _child(d, 1).update(ref=7), "scene.room[1].children[1].ref: expected a non-empty string"),
    (lambda d: d["mesh"][0].update(faces=[0, 2, 1, 0, 3, 9]), "mesh[0].faces[1][2]: expected a vertex index, a whole "
                                                              "number 0..3, got 9"),
    (lambda d: d["mesh"][0].update(faces=[0, 2, 1.5, 0, 3, 2]), "mesh[0].faces[0][2]: expected a vertex index"),
    (lambda d: d["mesh"][0]["xyz"].__setitem__(4, "x"), "mesh[0].xyz[4]: expected a finite number, got 'x'"),
    (lambda d: d["scene"]["room"].append(3), "scene.room[2]: expected a JSON object (a room), got int"),
])
def test_front_fields_are_checked(tmp_path: Path, change: Any, expected: str) -> None:
    msg = _front(tmp_path, change)
    assert msg.startswith(expected), msg


def test_front_nan_and_infinity_are_not_json(tmp_path: Path) -> None:
    path = tmp_path / "scene.json"
    path.write_text(FRONT.read_text().replace('"bbox": [\n    0.72', '"bbox": [\n    NaN', 1))
    with pytest.raises(LayoutError, match="scene.json: not JSON .NaN is not a number JSON allows"):
        import_front(path, model_info=MODEL_INFO)


def test_model_info_fields_are_checked(tmp_path: Path) -> None:
    path = tmp_path / "model_info.json"
    path.write_text(json.dumps([{"model_id": "a", "category": 3}]))
    with pytest.raises(LayoutError, match=r"model_info.json: \[0\].category: expected a non-empty string "
                                          r"\(at most 256 characters\), got 3"):
        import_front(FRONT, model_info=path)
    path.write_text(json.dumps({"model_id": "a"}))
    with pytest.raises(LayoutError, match="model_info.json: .top level.: expected a list, got dict"):
        import_front(FRONT, model_info=path)


def test_front_lists_every_child_it_drops(tmp_path: Path) -> None:
    data = json.loads(FRONT.read_text())
    _child(data, 2)["ref"] = "nothing-here"
    data["furniture"][3]["jid"] = "not-in-model-info"
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    dropped = import_front(path, model_info=MODEL_INFO).provenance.notes["dropped"]
    assert dropped == [
        {"entry": "scene.room[1].children[2]", "ref": "nothing-here",
         "reason": "its ref names no furniture or mesh uid"},
        {"entry": "scene.room[1].children[7]", "ref": "f-broken", "reason": "its furniture[7] is marked valid: false"},
        {"entry": "scene.room[1].children[3]", "ref": "f-table",
         "reason": "furniture[3] (jid 'not-in-model-info') has no category in model_info nor its own"},
    ]


# -- ATISS ------------------------------------------------------------------------------------------------------


def _atiss_data() -> dict[str, Any]:
    return copy.deepcopy(json.loads(ATISS.read_text()))


def _listed(data: dict[str, Any]) -> dict[str, Any]:
    names = data["object_types"] + ["start", "end"]
    out = {k: v for k, v in data.items() if k not in ("class_labels", "translations", "sizes", "angles")}
    out["objects"] = [{"class_label": names[c.index(1.0)], "translation": t, "size": z, "angle": a[0]}
                      for c, t, z, a in zip(data["class_labels"], data["translations"], data["sizes"], data["angles"])]
    return out


def _atiss(tmp_path: Path, data: dict[str, Any]) -> str:
    path = tmp_path / "boxes.json"
    path.write_text(json.dumps(data))
    with pytest.raises(LayoutError) as err:
        import_atiss(path)
    msg = str(err.value)
    assert "\n" not in msg and msg.startswith(f"{path}: "), msg
    return msg[len(str(path)) + 2:]


def _set(key: str, i: int, j: int | None, value: Any) -> Any:
    def change(d: dict[str, Any]) -> None:
        if j is None:
            d[key][i] = value
        else:
            d[key][i][j] = value
    return change


@pytest.mark.parametrize(("change", "expected"), [
    (_set("sizes", 2, 1, -0.3), "sizes[2][1]: expected a positive number of at most 30 m"),
    (_set("sizes", 2, 1, 20.0), "sizes[2][1]: expected a half size whose full size is at most 30 m"),
    (_set("translations", 0, 2, "x"), "translations[0][2]: expected a finite number, got 'x'"),
    (_set("angles", 3, 0, 1e6), "angles[3][0]: expected an angle within +-4 pi radians, got 1000000.0"),
    (_set("class_labels", 1, 0, 1.0), "class_labels[1]: expected a one-hot row (exactly one 1), got '2 ones'"),
    (_set("class_labels", 1, 12, 0.5), "class_labels[1][12]: expected 0 or 1 (a one-hot row), got 0.5"),
    (_set("class_labels", 1, 12, 0.0), "class_labels[1]: expected a one-hot row (exactly one 1), got '0 ones'"),
    (_set("class_labels", 1, None, [1.0, 0.0]), "class_labels[1]: expected a one-hot row of 21"),
    (_set("floor_plan_faces", 0, 1, 1.5), "floor_plan_faces[0][1]: expected a vertex index, a whole number 0..3"),
    (lambda d: d.update(scene_type=7), "scene_type: expected a room type name, got 7"),
    (lambda d: d.update(floor_plan_centroid=[0, 0]), "floor_plan_centroid: expected a list of 3 numbers"),
])
def test_atiss_fields_are_checked(tmp_path: Path, change: Any, expected: str) -> None:
    data = _atiss_data()
    change(data)
    msg = _atiss(tmp_path, data)
    assert msg.startswith(expected), msg


@pytest.mark.parametrize(("key", "value", "expected"), [
    ("size", [0.2, -1, 0.2], "objects[4].size[1]: expected a positive number"),
    ("angle", "north", "objects[4].angle: expected a finite number, got 'north'"),
    ("translation", 3, "objects[4].translation: expected a list of 3 numbers, got 3"),
    ("class_label", 5, "objects[4].class_label: expected a class name, got 5"),
])
def test_atiss_object_lists_name_the_entry(tmp_path: Path, key: str, value: Any, expected: str) -> None:
    data = _listed(_atiss_data())
    data["objects"][4][key] = value
    assert _atiss(tmp_path, data).startswith(expected)


def test_atiss_lists_the_markers_it_drops(tmp_path: Path) -> None:
    data = _atiss_data()
    width = len(data["class_labels"][0])
    data["class_labels"][6] = [0.0] * (width - 1) + [1.0]  # ATISS's end marker
    path = tmp_path / "boxes.json"
    path.write_text(json.dumps(data))
    layout = import_atiss(path)
    assert layout.provenance.notes["dropped"] == [
        {"entry": "class_labels[6]", "reason": "ATISS's 'end' sequence marker, not an object"}]
    assert len(layout.objects) == 6


BAD_NUMBERS = st.one_of(st.floats(max_value=-1e-9, allow_nan=False, allow_infinity=False),
                        st.floats(min_value=1e4, allow_nan=False, allow_infinity=False),
                        st.text(max_size=4), st.booleans(), st.none(), st.lists(st.integers(), max_size=2))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(key=st.sampled_from(["sizes", "translations", "angles"]), i=st.integers(0, 6), j=st.integers(0, 2),
       value=BAD_NUMBERS)
def test_atiss_any_bad_number_is_named_exactly(tmp_path: Path, key: str, i: int, j: int, value: Any) -> None:
    """A negative size, a coordinate or angle out of range, a string, a bool, null or a list in any cell: the
    error names that cell."""
    if key == "angles":
        j = 0
        if isinstance(value, float) and abs(value) <= 4 * math.pi:
            value = 1e9
    if key == "translations" and isinstance(value, float) and abs(value) <= 1000:
        value = 1e9
    data = _atiss_data()
    data[key][i][j] = value
    assert _atiss(tmp_path, data).startswith(f"{key}[{i}][{j}]: expected ")


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(where=st.sampled_from(["bbox", "pos", "scale", "rot"]), i=st.integers(0, 6), k=st.integers(0, 2),
       value=BAD_NUMBERS)
def test_front_any_bad_number_is_named_exactly(tmp_path: Path, where: str, i: int, k: int, value: Any) -> None:
    def change(d: dict[str, Any]) -> None:
        if where == "bbox":
            d["furniture"][i]["bbox"][k] = value
        else:
            child = _child(d, i)
            child[where] = list(child.get(where, {"pos": [0, 0, 0], "scale": [1, 1, 1], "rot": [0, 0, 0, 1]}[where]))
            child[where][k] = value
    if where in ("pos", "rot") and isinstance(value, float) and abs(value) <= 1000:
        value = 1e9  # a small negative quaternion component is a valid rotation (normalised within tolerance)
    msg = _front(tmp_path, change)
    path = f"furniture[{i}].bbox" if where == "bbox" else f"scene.room[1].children[{i}].{where}"
    # a value that is a number but makes the quaternion or the scaled box wrong is named by its vector
    assert msg.startswith((f"{path}[{k}]: expected ", f"{path}: expected ")), msg


# -- the command ------------------------------------------------------------------------------------------------


def test_import_layout_reports_every_entry_dropped(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = json.loads(FRONT.read_text())
    data["furniture"][5]["jid"] = "unknown-jid"
    info = json.loads(MODEL_INFO.read_text()) + [{"model_id": "unknown-jid", "category": "Spaceship Console"}]
    (tmp_path / "info.json").write_text(json.dumps(info))
    (tmp_path / "scene.json").write_text(json.dumps(data))
    out = tmp_path / "o"
    code = main(["import-layout", str(tmp_path / "scene.json"), "--format", "front", "--model-info",
                 str(tmp_path / "info.json"), "--out", str(out), "--no-physics"])
    stdout = capsys.readouterr().out
    assert code == 0
    report = json.loads((out / "repair_report.json").read_text())
    entries = {d["entry"]: d["reason"] for d in report["dropped"]}
    assert entries["scene.room[1].children[7]"] == "its furniture[7] is marked valid: false"
    unmatched = [d for d in report["dropped"] if d.get("category") == "Spaceship Console"]
    assert len(unmatched) == 1 and unmatched[0]["entry"].startswith("objects[")
    assert f"dropped {len(report['dropped'])} entries of {tmp_path / 'scene.json'}" in stdout
    assert "scene.room[1].children[7] (its furniture[7] is marked valid: false)" in stdout


@pytest.mark.parametrize("fmt", ["luminous", "front", "atiss"])
@pytest.mark.parametrize("target", ["/dev/null", "FOLDER", "MISSING"])
def test_import_layout_names_folders_devices_and_missing_files(fmt: str, target: str, tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    path = {"FOLDER": str(tmp_path), "MISSING": str(tmp_path / "missing.json")}.get(target, target)
    code = main(["import-layout", path, "--format", fmt, "--out", str(tmp_path / "o")])
    err = capsys.readouterr().err
    want = {"/dev/null": "a device", "FOLDER": "a folder", "MISSING": "no such file"}[target]
    assert code == 2 and len(err.strip().splitlines()) == 1 and f"{path}: {want}; expected" in err, err
