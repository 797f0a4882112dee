"""The 3D-FRONT and ATISS importers on hand-written, format-faithful fixtures; malformed input names the field."""

from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from luminous_sim.layouts import LayoutError, import_atiss, import_front
from tests.layouts.helpers import ATISS, FRONT, MODEL_INFO


def _front():
    return import_front(FRONT, model_info=MODEL_INFO)


def test_front_room_outline_doors_and_windows():
    room = _front().room
    assert room.room_type == "Kitchen" and room.name.startswith("front_front_kitchen_Kitchen-2306")
    assert room.outline == ((0.0, 0.0), (4.0, 0.0), (4.0, 3.5), (0.0, 3.5))
    (door,) = room.doors
    assert (door.wall, door.offset, door.width, door.height) == (0, 0.3, 0.9, 2.05)
    (window,) = room.windows
    assert (window.wall, window.offset, window.width, window.sill_height, window.height) == (1, 1.0, 1.2, 0.9, 1.2)


def test_front_furniture_categories_boxes_and_headings():
    layout = _front()
    by_id = {o.id: o for o in layout.objects}
    assert len(by_id) == 9  # the furniture marked valid: false is skipped
    fridge = by_id["furniture/0"]
    assert fridge.category == "Refrigerator" and fridge.size == pytest.approx((0.72, 0.7, 1.78))
    assert fridge.position == pytest.approx((0.45, 3.12, 0.89))
    assert abs(abs(fridge.yaw) - math.pi) < 1e-5  # its front (+z, turned by 0 about y) faces our -y: into the room
    chair = by_id["furniture/4"]
    assert chair.yaw == pytest.approx(0.0, abs=1e-6) and chair.position[2] == pytest.approx(0.45)
    assert by_id["furniture/6"].yaw == pytest.approx(-math.pi / 2, abs=1e-5)
    ignored = layout.provenance.notes["ignored"]
    assert ignored["furniture marked valid: false"] == 1 and ignored["mesh WallInner"] == 1


def test_front_categories_may_come_from_the_furniture_entries():
    data = json.loads(FRONT.read_text())
    for f, m in zip(data["furniture"], json.loads(MODEL_INFO.read_text())):
        f["category"] = m["category"]
    path = FRONT.parent / "tmp_front_cat.json"
    try:
        path.write_text(json.dumps(data))
        assert [o.category for o in import_front(path).objects] == [o.category for o in _front().objects]
    finally:
        path.unlink()


def _front_error(tmp_path, change, **kw) -> str:
    data = json.loads(FRONT.read_text())
    change(data)
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(data))
    with pytest.raises(LayoutError) as err:
        import_front(path, **kw)
    assert str(err.value).startswith(str(path))
    return str(err.value)


def test_front_malformed_input_names_the_field(tmp_path):
    msg = _front_error(tmp_path, lambda d: None)  # no model_info and no categories of its own
    assert "furniture[0].category: missing" in msg and "model_info" in msg
    msg = _front_error(tmp_path, lambda d: d["scene"]["room"][1]["children"][2].update(pos=[1, "a"]),
                       model_info=MODEL_INFO)
    assert "scene.room[1].children[2].pos: expected a list of 3 numbers, got [1, 'a']" in msg
    msg = _front_error(tmp_path, lambda d: d["furniture"][1].pop("bbox"), model_info=MODEL_INFO)
    assert "furniture[1].bbox: missing" in msg
    msg = _front_error(tmp_path, lambda d: d.pop("mesh"), model_info=MODEL_INFO)
    assert msg.endswith("scene.json: mesh: missing")

    def no_floor(d):
        d["mesh"][0]["type"] = "Ceiling"
    assert "no mesh of type Floor" in _front_error(tmp_path, no_floor, model_info=MODEL_INFO)
    assert "no room 'Nope'" in _front_error(tmp_path, lambda d: None, model_info=MODEL_INFO, room="Nope")


def test_atiss_one_hot_labels_half_sizes_and_angles():
    layout = import_atiss(ATISS)
    assert layout.room.room_type == "Bedroom" and layout.room.doors == ()
    assert layout.room.outline == ((0.0, 0.0), (3.6, 0.0), (3.6, 4.0), (0.0, 4.0))
    cats = [o.category for o in layout.objects]
    assert cats == ["double_bed", "nightstand", "nightstand", "wardrobe", "desk", "chair", "pendant_lamp"]
    bed = layout.objects[0]
    assert bed.size == pytest.approx((1.7, 2.1, 1.0))  # ATISS's half extents doubled; y up -> height
    assert bed.position == pytest.approx((1.8, 2.95, 0.5))
    desk = layout.objects[4]
    assert desk.yaw == pytest.approx(0.0, abs=1e-6)  # angle pi about y: facing -z, our +y


def test_atiss_object_lists_full_sizes_and_npz_read_the_same(tmp_path):
    data = json.loads(ATISS.read_text())
    names = data["object_types"] + ["start", "end"]
    listed = {k: v for k, v in data.items() if k not in ("class_labels", "translations", "sizes", "angles")}
    listed["size_convention"] = "full"
    listed["objects"] = [{"class_label": names[int(np.argmax(c))], "translation": t, "size": [2 * s for s in z],
                          "angle": a[0]} for c, t, z, a in zip(data["class_labels"], data["translations"],
                                                               data["sizes"], data["angles"])]
    (tmp_path / "list.json").write_text(json.dumps(listed))
    npz = {k: np.asarray(v) for k, v in data.items()}
    np.savez(tmp_path / "boxes.npz", **npz)
    want = [(o.category, o.size, o.position, o.yaw) for o in import_atiss(ATISS).objects]
    for path in (tmp_path / "list.json", tmp_path / "boxes.npz"):
        got = [(o.category, o.size, o.position, o.yaw) for o in import_atiss(path).objects]
        assert [g[0] for g in got] == [w[0] for w in want]
        assert np.allclose([g[1] + g[2] + (g[3],) for g in got], [w[1] + w[2] + (w[3],) for w in want])


@pytest.mark.parametrize(("change", "needle"), [
    (lambda d: d.pop("translations"), "translations: missing"),
    (lambda d: d.update(sizes=d["sizes"][:-1]), "sizes: 6 rows for 7 translations"),
    (lambda d: d.pop("object_types"), "object_types: needed"),
    (lambda d: d.update(scene_type="garage"), "scene_type: 'garage'"),
    (lambda d: d.update(floor_plan_faces=[[0, 1, 9]]), "floor_plan_faces"),
    (lambda d: d.update(size_convention="double"), "size_convention"),
])
def test_atiss_malformed_input_names_the_key(tmp_path, change, needle):
    data = copy.deepcopy(json.loads(ATISS.read_text()))
    change(data)
    path = tmp_path / "boxes.json"
    path.write_text(json.dumps(data))
    with pytest.raises(LayoutError) as err:
        import_atiss(path)
    assert str(err.value).startswith(str(path)) and needle in str(err.value)


def test_missing_and_non_regular_files_are_refused(tmp_path):
    import os

    os.mkfifo(tmp_path / "fifo")
    for fn in (import_front, import_atiss):
        with pytest.raises(LayoutError, match="fifo: a FIFO"):
            fn(tmp_path / "fifo")
        with pytest.raises(LayoutError, match=f"{tmp_path}: a folder"):
            fn(tmp_path)
        with pytest.raises(LayoutError, match="no such file"):
            fn(tmp_path / "missing.json")
