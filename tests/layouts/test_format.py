"""The layout format: schema current and honoured, CSSG scenes round-trip exactly, bad files named."""

from __future__ import annotations

import json

import pytest

from luminous_sim import cssg, layouts
from luminous_sim.assets.catalog import default_catalog
from luminous_sim.layouts import LayoutError, layout_of_scene, loads, realize
from luminous_sim.layouts.schema import SCHEMA_FILENAME, schema_text
from tests.layouts.helpers import REPO

COMMITTED = REPO / "cdf" / "schema" / SCHEMA_FILENAME


def test_committed_schema_equals_the_export():
    assert COMMITTED.read_text(encoding="utf-8") == schema_text(), \
        "run `python -c 'from luminous_sim import layouts; layouts.export_schema()'`"


def _round_trip(room_type: str, seed: int):
    generated = cssg.generate(cssg.empty_cdf(room_type), seed=seed)
    layout = layout_of_scene(generated.scene, default_catalog())
    again = loads(layout.to_json())
    assert again == layout and again.to_json() == layout.to_json()
    return generated, layout, realize(again)


@pytest.mark.parametrize("room_type", ["Kitchen", "Bathroom"])
def test_a_cssg_scene_comes_back_the_same(room_type):
    generated, _, realized = _round_trip(room_type, 1)
    assert realized.ok and realized.given.repairs == []
    assert realized.given.generated.scene == generated.scene
    assert realized.given.generated.scene.to_json() == generated.scene.to_json()
    # what differs: the report of a layout has no CDF relations to check
    report = realized.given.generated.report
    assert report.relations == [] and report.overlaps == [] and report.unreachable == []
    assert report.reachable_points == generated.report.reachable_points


@pytest.mark.slow
@pytest.mark.parametrize("room_type", ["Kitchen", "LivingRoom", "Bedroom", "Bathroom"])
def test_cssg_scenes_come_back_the_same_over_seeds(room_type):
    for seed in range(8):
        generated, _, realized = _round_trip(room_type, seed)
        assert realized.given.generated.scene == generated.scene, (room_type, seed)


def test_the_layout_of_a_scene_satisfies_the_json_schema():
    jsonschema = pytest.importorskip("jsonschema")
    _, layout, _ = _round_trip("LivingRoom", 2)
    validator = jsonschema.Draft202012Validator(json.loads(COMMITTED.read_text()))
    assert list(validator.iter_errors(json.loads(layout.to_json()))) == []
    bad = json.loads(layout.to_json())
    bad["objects"][0]["size"] = [1, 0, 1]
    assert list(validator.iter_errors(bad))


def test_boxes_are_centred_on_the_asset():
    """`position` is the box centre: the origin (the asset's bottom centre) sits half a height below it."""
    generated, layout, _ = _round_trip("Bedroom", 0)
    bed = next(o for o in generated.scene.objects if o.type == "Bed")
    box = next(o for o in layout.objects if o.id == bed.id)
    assert box.position[2] == pytest.approx(bed.position[2] + box.size[2] / 2, abs=0.02)


ROOM = {"name": "r", "room_type": "Kitchen", "outline": [[0, 0], [3, 0], [3, 3], [0, 3]]}


@pytest.mark.parametrize(("doc", "needle"), [
    ({"room": ROOM, "objects": [{"id": "a", "category": "Chair", "size": [1, 1, 1], "position": [1, 1, 0.5]}] * 2},
     "duplicate ids a"),
    ({"room": ROOM, "objects": [{"id": "a", "category": "Mug", "size": [1, 1, 1], "position": [1, 1, 1],
                                 "parent": "table"}]}, "objects[0] (a): parent 'table'"),
    ({"room": {**ROOM, "doors": [{"wall": 7, "offset": 0.5, "width": 0.9}]}}, "room.doors[0]: wall 7"),
    ({"room": ROOM, "objects": [{"id": "a", "category": "Chair", "size": [1, -1, 1], "position": [1, 1, 0]}]},
     "objects[0].size[1]"),
    ({"format": "luminous-layout/9", "room": ROOM}, "format: expected 'luminous-layout/1'"),
    ({"room": {**ROOM, "outline": [[0, 0], [1, 0]]}}, "room.outline"),
])
def test_malformed_layouts_name_the_field(doc, needle):
    with pytest.raises(LayoutError, match=None) as err:
        loads(json.dumps(doc), where="my.json")
    assert str(err.value).startswith("my.json: ") and needle in str(err.value)


def test_a_clockwise_outline_is_a_layout_error_naming_the_room():
    layout = loads(json.dumps({"room": {**ROOM, "outline": [[0, 0], [0, 3], [3, 3], [3, 0]]}}))
    with pytest.raises(LayoutError, match="my.json: room: not a valid room .*counter-clockwise"):
        layouts.shell_of_room(layout.room, "my.json")


def test_not_json_and_missing_files_are_layout_errors(tmp_path):
    with pytest.raises(LayoutError, match="not JSON"):
        loads("{", where="x.json")
    with pytest.raises(LayoutError, match="missing.json: no such file; expected a luminous-layout/1 JSON file"):
        layouts.load(tmp_path / "missing.json")


def test_layout_size_and_kind_of_file_are_bounded(tmp_path):
    """Issue 27: a layout of more objects than limits.MAX_LAYOUT_OBJECTS is refused before validation, in one
    line naming the file and field; a folder or a device is named as such."""
    import json as _json

    import pytest as _pytest

    from luminous_sim.layouts.model import LayoutError, load
    from luminous_sim.limits import MAX_LAYOUT_OBJECTS

    big = tmp_path / "big.json"
    big.write_text(_json.dumps({"room": {}, "objects": [{}] * (MAX_LAYOUT_OBJECTS + 1)}))
    with _pytest.raises(LayoutError, match=f"big.json: objects: {MAX_LAYOUT_OBJECTS + 1} objects; a layout may hold"):
        load(big)
    with _pytest.raises(LayoutError, match="a folder; expected a luminous-layout/1 JSON file"):
        load(tmp_path)
    with _pytest.raises(LayoutError, match="/dev/null: a device; expected"):
        load("/dev/null")
