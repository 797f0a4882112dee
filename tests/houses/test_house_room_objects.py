"""A house CDF's rooms name their own objects and relations: loading, errors naming the room and the object,
and CSSG realising them in that room of the house."""

from __future__ import annotations

import copy
from typing import Any

import pytest

from luminous_sim import cdf
from luminous_sim.cdf import CDFValidationError

HOUSE: dict[str, Any] = {
    "cdf_version": 2,
    "name": "rooms_with_objects",
    "scene": {
        "house": {
            "rooms": [
                {"name": "kitchen", "type": "Kitchen",
                 "objects": [{"name": "mug", "type": "Mug"}, {"name": "table", "type": "DiningTable"}],
                 "relations": [{"subject": "mug", "relation": "on", "target": "table"}]},
                {"name": "living", "type": "LivingRoom",
                 "objects": [{"name": "sofa", "type": "Sofa"}, {"name": "coffee", "type": "CoffeeTable"}],
                 "relations": [{"subject": "coffee", "relation": "in_front_of", "target": "sofa"}]},
                {"name": "bedroom", "type": "Bedroom",
                 "objects": [{"name": "bed", "type": "Bed"}, {"name": "book", "type": "Book"}],
                 "relations": [{"subject": "book", "relation": "on", "target": "bed"}]},
            ],
            "adjacency": [["kitchen", "living"], ["bedroom", "living"]],
        }
    },
    "task": {"goal": "(inReceptacle book sofa)"},
}


def _issues(doc: dict[str, Any]) -> list[tuple[str, str]]:
    with pytest.raises(CDFValidationError) as info:
        cdf.from_document(doc, "house.yaml")
    return [(i.path, i.message) for i in info.value.issues]


def _room(doc: dict[str, Any], i: int) -> dict[str, Any]:
    room: dict[str, Any] = doc["scene"]["house"]["rooms"][i]
    return room


def test_rooms_hold_objects_relations_and_the_goal_names_them() -> None:
    doc = cdf.from_document(HOUSE)
    assert doc.scene.house is not None and [o.name for o in doc.scene.house.rooms[2].objects] == ["bed", "book"]
    assert doc.object_named("sofa") is not None and doc.object_named("sofa").type == "Sofa"  # type: ignore[union-attr]
    assert [o.name for o in doc.all_objects()] == ["mug", "table", "sofa", "coffee", "bed", "book"]
    assert cdf.loads(cdf.dumps(doc)) == doc


def test_a_relation_naming_an_object_of_another_room_names_both_rooms() -> None:
    doc = copy.deepcopy(HOUSE)
    _room(doc, 2)["relations"].append({"subject": "mug", "relation": "on", "target": "bed"})
    issues = _issues(doc)
    assert issues == [("scene.house.rooms[2].relations[1].subject",
                       "'mug' is an object of room 'kitchen' (scene.house.rooms[0]), not of room 'bedroom'; a "
                       "relation holds within one room (expected an object of scene.house.rooms[2].objects)")]


def test_a_room_sections_own_mistakes_are_found_by_the_room_checks_under_the_rooms_path() -> None:
    doc = copy.deepcopy(HOUSE)
    _room(doc, 1)["relations"].append({"subject": "sofa", "relation": "near", "target": "lamp"})
    _room(doc, 0)["relations"].append({"subject": "mug", "relation": "in", "target": "table"})  # two supports
    issues = _issues(doc)
    assert any(p == "scene.house.rooms[1].relations[1].target" and "unknown name 'lamp'" in m
               and "room 'living'" in m for p, m in issues), issues
    assert any(p == "scene.house.rooms[0].relations[1]" and "already on 'table'" in m for p, m in issues), issues


@pytest.mark.parametrize(("path", "value", "where", "words"), [
    ("1.objects.0.name", "mug", "scene.house.rooms[1].objects[0].name", "already an object of room 'kitchen'"),
    ("front_door", "kitchn", "scene.house.front_door", "did you mean 'kitchen'"),
    ("0.shape", "U", "scene.house.rooms[0].shape", "'rect' or 'L'"),
])
def test_house_level_mistakes_name_the_field(path: str, value: Any, where: str, words: str) -> None:
    doc = copy.deepcopy(HOUSE)
    house = doc["scene"]["house"]
    keys = path.split(".")
    node = house["rooms"][int(keys[0])] if keys[0].isdigit() else house
    for k in keys[1:-1] if keys[0].isdigit() else keys[:-1]:
        node = node[int(k)] if k.isdigit() else node[k]
    node[int(keys[-1]) if keys[-1].isdigit() else keys[-1]] = value
    issues = _issues(doc)
    assert any(p == where and words in m for p, m in issues), issues


def test_a_goal_naming_an_object_no_room_declares_is_refused() -> None:
    doc = copy.deepcopy(HOUSE)
    doc["task"]["goal"] = "(inReceptacle book sofaa)"
    assert any(p == "task.goal" and "did you mean 'sofa'" in m for p, m in _issues(doc))


def test_cssg_realises_each_rooms_objects_and_relations_in_that_room() -> None:
    from luminous_sim.cssg import generate_house

    generated = generate_house(cdf.from_document(HOUSE), seed=0)
    scene, report = generated.scene, generated.report
    assert report.ok
    where = {"mug": "kitchen", "table": "kitchen", "sofa": "living", "coffee": "living", "bed": "bedroom",
             "book": "bedroom"}
    by_name = {o.name: o for o in scene.objects if o.name in where}
    assert set(by_name) == set(where)
    for name, room in where.items():
        x, y = by_name[name].position[:2]
        assert scene.room.room_at(x, y) == room, name
    checks = {(c.subject, c.relation, c.anchor): c.met for r in report.rooms.values() for c in r.relations
              if c.explicit}
    assert checks == {("mug", "on", "table"): True, ("coffee", "in_front_of", "sofa"): True,
                      ("book", "on", "bed"): True}


def test_a_room_is_asked_to_keep_room_for_the_house_goals_put_from_another_room() -> None:
    from luminous_sim.cssg.house import room_request
    from luminous_sim.cssg.requests import goal_holds

    doc = cdf.from_document(HOUSE)
    assert goal_holds(room_request(doc, 1)) == {"sofa": {"Book": 1}}
    assert room_request(doc, 0).task is None
