"""The CDF's house section: loading, the derived room types, and errors that name the field."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from luminous_sim import cdf
from luminous_sim.cdf import CDFValidationError

HOUSE: dict[str, Any] = {
    "cdf_version": 2,
    "scene": {
        "house": {
            "rooms": [
                {"name": "kitchen", "type": "Kitchen", "min_area": 9},
                {"name": "living", "type": "living_room"},
                {"name": "bath", "type": "Bathroom", "max_area": 8},
            ],
            "adjacency": [["kitchen", "living"]],
        }
    },
}


def _issues(doc: dict[str, Any]) -> list[tuple[str, str]]:
    with pytest.raises(CDFValidationError) as info:
        cdf.from_document(doc, "house.yaml")
    return [(i.path, i.message) for i in info.value.issues]


def _with(path: str, value: Any) -> dict[str, Any]:
    doc = copy.deepcopy(HOUSE)
    node: Any = doc
    keys = path.split(".")
    for k in keys[:-1]:
        node = node[int(k)] if k.isdigit() else node[k]
    last = keys[-1]
    node[int(last) if last.isdigit() else last] = value
    return doc


def test_a_house_loads_and_its_room_types_come_from_its_rooms() -> None:
    doc = cdf.from_document(HOUSE)
    assert doc.scene.room_type == ("Kitchen", "LivingRoom", "Bathroom")
    assert doc.scene.house is not None and doc.scene.house.rooms[1].type == "LivingRoom"
    assert cdf.loads(cdf.dumps(doc)) == doc


def test_a_single_room_cdf_has_no_house_key_when_dumped() -> None:
    doc = cdf.loads("cdf_version: 2\nscene: {room_type: Kitchen}\n")
    assert doc.scene.house is None and "house" not in cdf.to_document(doc)["scene"]


@pytest.mark.parametrize(("doc", "path", "words"), [
    (_with("scene.house.rooms.1.type", "Attic"), "scene.house.rooms[1].type", "Attic"),
    (_with("scene.house.adjacency", [["kitchen", "livng"]]), "scene.house.adjacency[0][1]", "did you mean 'living'"),
    (_with("scene.house.adjacency", [["bath", "bath"]]), "scene.house.adjacency[0]", "itself"),
    (_with("scene.house.adjacency", [["bath", "living"], ["living", "bath"]]), "scene.house.adjacency[1]",
     "already listed"),
    (_with("scene.house.rooms.2.name", "kitchen"), "scene.house.rooms[2].name", "duplicate room name"),
    (_with("scene.house.rooms.0.max_area", 5), "scene.house.rooms[0].min_area", "larger than max_area"),
    (_with("scene.house.rooms.0.min_area", 2), "scene.house.rooms[0].min_area", "greater than or equal to 4"),
    (_with("scene.house.size", {"width": 4, "depth": 4}), "scene.house.size", "at least 17"),
    (_with("scene.house.size", {"width": 1, "depth": 4}), "scene.house.size.width", "greater than or equal to 2"),
    (_with("scene.house.rooms", [{"name": "a", "type": "Kitchen"}]), "scene.house.rooms", "at least 2"),
    (_with("scene.objects", [{"name": "apple", "type": "Apple"}]), "scene.objects", "beside scene.house"),
    (_with("scene.room", "FloorPlan1"), "scene.room", "beside scene.house"),
    (_with("scene.room_type", "Kitchen"), "scene.house.rooms[1].type", "not among scene.room_type"),
])
def test_bad_houses_are_refused_naming_the_field(doc: dict[str, Any], path: str, words: str) -> None:
    issues = _issues(doc)
    assert any(p == path and words in m for p, m in issues), issues


def test_rooms_whose_largest_areas_cannot_fill_the_house_are_refused() -> None:
    doc = _with("scene.house.rooms", [{"name": "a", "type": "Kitchen", "max_area": 9},
                                      {"name": "b", "type": "Bedroom", "max_area": 9}])
    doc["scene"]["house"]["adjacency"] = []
    doc["scene"]["house"]["size"] = {"width": 6, "depth": 6}
    assert any(p == "scene.house.size" and "at most 18" in m for p, m in _issues(doc))


def test_the_shipped_default_house_satisfies_the_json_schema() -> None:
    jsonschema = pytest.importorskip("jsonschema")
    from luminous_sim.cdf.reader import parse_text
    from luminous_sim.cli.generate_cmd import DEFAULT_HOUSE

    validator = jsonschema.Draft202012Validator(cdf.schema_dict())
    assert not [e.message for e in validator.iter_errors(parse_text(DEFAULT_HOUSE.read_text()))]
    assert cdf.load(DEFAULT_HOUSE).scene.house is not None
    assert list(validator.iter_errors({"cdf_version": 2, "scene": {}}))  # a room type or a house is needed


def test_the_summary_lists_the_house_rooms() -> None:
    text = cdf.summarize(cdf.from_document(HOUSE))
    assert text.startswith("house: 3 rooms: kitchen (Kitchen), living (LivingRoom), bath (Bathroom); 1 doorways asked")
