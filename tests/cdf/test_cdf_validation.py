"""Table-driven checks of every validation message: file name, key path and expectation."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
import yaml

from luminous_sim.cdf import CDFValidationError, ChallengeDefinition, from_document, loads
from luminous_sim.errors import CDFError
from tests.cdf.helpers import BASE, base, rel

Doc = dict[str, Any]


def _parts(path: str) -> list[Any]:
    return [
        int(p) if p.isdigit() else p for p in path.replace("[", ".").replace("]", "").split(".")
    ]


def _node(doc: Doc, parts: list[Any]) -> Any:
    for p in parts:
        doc = doc[p]
    return doc


def set_(path: str, value: Any) -> Callable[[Doc], None]:
    *parents, last = _parts(path)
    return lambda doc: _node(doc, parents).__setitem__(last, value)


def delete(path: str) -> Callable[[Doc], None]:
    *parents, last = _parts(path)
    return lambda doc: _node(doc, parents).__delitem__(last)


def add(objects: list[Doc] = (), relations: list[Doc] = ()) -> Callable[[Doc], None]:  # type: ignore[assignment]
    def apply(doc: Doc) -> None:
        doc["scene"]["objects"].extend(objects)
        doc["scene"]["relations"].extend(relations)

    return apply


def both(*mutations: Callable[[Doc], None]) -> Callable[[Doc], None]:
    def apply(doc: Doc) -> None:
        for m in mutations:
            m(doc)

    return apply


CASES: list[tuple[str, Callable[[Doc], None], str, list[str]]] = [
    # (id, mutation of BASE, key path, fragments the message must hold)
    (
        "missing version",
        delete("cdf_version"),
        "cdf_version",
        ["required key is missing", "expected one of 1, 2"],
    ),
    ("version as text", set_("cdf_version", "2"), "cdf_version", ["expected an integer"]),
    ("bool version", set_("cdf_version", True), "cdf_version", ["expected an integer"]),
    ("newer version", set_("cdf_version", 9), "cdf_version", ["newer than this library"]),
    ("missing scene", delete("scene"), "scene", ["required key is missing"]),
    ("scene not a mapping", set_("scene", [1]), "scene", ["expected a mapping, got list"]),
    (
        "unknown top key",
        set_("scnee", {}),
        "scnee",
        ["unknown key 'scnee'", "did you mean 'scene'?", "expected one of"],
    ),
    (
        "unknown room type",
        set_("scene.room_type", "Kitchn"),
        "scene.room_type[0]",
        ["expected 'Kitchen', 'LivingRoom', 'Bedroom' or 'Bathroom'", "got 'Kitchn'"],
    ),
    ("empty room types", set_("scene.room_type", []), "scene.room_type", ["at least 1"]),
    (
        "unknown object type",
        set_("scene.objects[2].type", "Aple"),
        "scene.objects[2].type",
        ["unknown object type 'Aple'", "did you mean Apple"],
    ),
    (
        "object type not a string",
        set_("scene.objects[2].type", 7),
        "scene.objects[2].type",
        ["expected a string"],
    ),
    (
        "bad name",
        set_("scene.objects[2].name", "my apple"),
        "scene.objects[2].name",
        ["invalid name 'my apple'", "expected a letter"],
    ),
    (
        "duplicate name",
        set_("scene.objects[3].name", "apple"),
        "scene.objects[3].name",
        ["duplicate name 'apple'", "scene.objects[2]", "expected unique names"],
    ),
    (
        "reserved name",
        set_("scene.objects[3].name", "wall"),
        "scene.objects[3].name",
        ["reserved for the room element"],
    ),
    (
        "zero count",
        set_("scene.objects[2].count", 0),
        "scene.objects[2].count",
        ["greater than or equal to 1"],
    ),
    (
        "unknown object key",
        set_("scene.objects[2].colour", "red"),
        "scene.objects[2].colour",
        ["unknown key 'colour'", "expected one of asset, attributes"],
    ),
    (
        "size dims incomplete",
        set_("scene.objects[2].attributes", {"size": {"width": 1}}),
        "scene.objects[2].attributes.size.depth",
        ["required key is missing"],
    ),
    (
        "size negative",
        set_("scene.objects[2].attributes", {"size": -1}),
        "scene.objects[2].attributes.size",
        ["greater than 0"],
    ),
    (
        "state not boolean",
        set_("scene.objects[0].state", {"isOpen": "yes"}),
        "scene.objects[0].state.isOpen",
        ["valid boolean"],
    ),
    (
        "state impossible",
        set_("scene.objects[2].state", {"isOpen": True}),
        "scene.objects[2].state.isOpen",
        ["'apple' is an Apple, which is not openable", "expected isOpen only on openable types"],
    ),
    (
        "room traversal",
        set_("scene.room", "../../etc/passwd"),
        "scene.room",
        ["must match ^[A-Za-z0-9_\\-]+$", "no path separators"],
    ),
    ("room slash", set_("scene.room", "rooms/FloorPlan1"), "scene.room", ["no path separators"]),
    (
        "room unknown",
        set_("scene.room", "Atlantis"),
        "scene.room",
        ["unknown room 'Atlantis'", "expected a room-library name"],
    ),
    (
        "room of other type",
        set_("scene.room", "FloorPlan301"),
        "scene.room",
        ["is a Bedroom", "expected a Kitchen room"],
    ),
    (
        "room bad shape",
        set_("scene.room", {"shape": "hexagon"}),
        "scene.room.shape",
        ["expected 'rect', 'L' or 'two_zone'"],
    ),
    (
        "room min above max",
        set_("scene.room", {"min_area": 30, "max_area": 10}),
        "scene.room",
        ["expected min_area <= max_area"],
    ),
    (
        "asset traversal",
        set_("scene.objects[2].asset", "../Apple_01"),
        "scene.objects[2].asset",
        ["asset reference", "no path separators"],
    ),
    (
        "unknown relation",
        add(relations=[rel("apple", "besid", "fridge")]),
        "scene.relations[2].relation",
        ["unknown relation 'besid'", "did you mean beside"],
    ),
    (
        "unknown subject",
        add(relations=[rel("aple", "near", "fridge")]),
        "scene.relations[2].subject",
        [
            "unknown name 'aple'",
            "did you mean 'apple'?",
            "expected a name declared in scene.objects",
        ],
    ),
    (
        "unknown target",
        add(relations=[rel("chair", "near", "tabel")]),
        "scene.relations[2].target",
        ["unknown name 'tabel'", "or a room element (wall, window, door)"],
    ),
    (
        "room element as subject",
        add(relations=[rel("wall", "near", "fridge")]),
        "scene.relations[2].subject",
        ["room element 'wall' cannot be a subject"],
    ),
    (
        "unary with target",
        add(relations=[rel("fridge", "in_corner", "counter")]),
        "scene.relations[2].target",
        ["'in_corner' is unary and takes no target"],
    ),
    (
        "binary without target",
        add(relations=[rel("fridge", "beside")]),
        "scene.relations[2].target",
        ["'beside' needs a target"],
    ),
    (
        "self relation",
        add(relations=[rel("fridge", "near", "fridge")]),
        "scene.relations[2].target",
        ["cannot be related to itself"],
    ),
    (
        "in a non-receptacle",
        set_("scene.relations[0]", rel("apple", "in", "chair")),
        "scene.relations[0].target",
        ["'chair' is a Chair, not a receptacle", "expected a receptacle"],
    ),
    (
        "forbidden by ALFRED table",
        both(
            add(objects=[{"name": "toaster", "type": "Toaster"}]),
            set_("scene.relations[0]", rel("apple", "in", "toaster")),
        ),
        "scene.relations[0].target",
        [
            "an Apple cannot be in a Toaster",
            "Toaster accepts BreadSliced",
            "expected a receptacle that accepts Apple",
        ],
    ),
    (
        "furniture on furniture",
        add(relations=[rel("fridge", "on", "counter")]),
        "scene.relations[2].target",
        ["'fridge' is a Fridge, a piece of furniture", "cannot be on 'counter'"],
    ),
    (
        "on a room element",
        set_("scene.relations[0]", rel("apple", "on", "wall")),
        "scene.relations[0].target",
        ["needs a receptacle object as target, not the room element 'wall'"],
    ),
    (
        "on two things",
        add(relations=[rel("apple", "in", "fridge")]),
        "scene.relations[2]",
        [
            "'apple' is already on 'counter' (scene.relations[0])",
            "expected one supporting receptacle",
        ],
    ),
    (
        "corner and centre",
        add(relations=[rel("fridge", "in_corner"), rel("fridge", "in_center")]),
        "scene.relations[3].relation",
        ["cannot be both in_corner (scene.relations[2]) and in_centre"],
    ),
    (
        "wall and centre",
        add(relations=[rel("fridge", "in_centre"), rel("fridge", "against_wall")]),
        "scene.relations[3].relation",
        ["cannot be both in_centre"],
    ),
    (
        "near and far",
        add(relations=[rel("fridge", "near", "chair"), rel("chair", "far", "fridge")]),
        "scene.relations[3].relation",
        ["cannot be both near (scene.relations[2]) and far"],
    ),
    (
        "support cycle",
        add(
            objects=[{"name": "mug", "type": "Mug"}, {"name": "bowl", "type": "Bowl"}],
            relations=[rel("mug", "in", "bowl"), rel("bowl", "in", "mug")],
        ),
        "scene.relations[3]",
        ["cycle that no rewriting can resolve", "bowl -> mug -> bowl", "a Bowl cannot be in a Mug"],
    ),
    (
        "face cycle",
        add(relations=[rel("chair", "face", "fridge"), rel("fridge", "face", "chair")]),
        "scene.relations[3]",
        ["cycle that no rewriting can resolve", "fridge -> chair -> fridge"],
    ),
    (
        "on and face cycle",
        add(relations=[rel("counter", "face", "apple")]),
        "scene.relations[",
        ["cycle that no rewriting can resolve", "counter -> apple -> counter"],
    ),
    (
        "axis contradiction",
        add(relations=[rel("chair", "left_of", "fridge"), rel("fridge", "left_of", "chair")]),
        "scene.relations[3]",
        ["contradictory directions"],
    ),
    (
        "weight not positive",
        set_("scene.relations[0].weight", 0),
        "scene.relations[0].weight",
        ["greater than 0"],
    ),
    (
        "hard not boolean",
        set_("scene.relations[0].hard", "maybe"),
        "scene.relations[0].hard",
        ["valid boolean"],
    ),
    (
        "goal unknown predicate",
        set_("task.goal", "(isHott apple)"),
        "task.goal",
        ["unknown predicate 'isHott'", "did you mean isHot"],
    ),
    (
        "goal unknown name",
        set_("task.goal", "(isHot aple)"),
        "task.goal",
        ["in (isHot aple): unknown name 'aple'", "did you mean 'apple'?"],
    ),
    (
        "goal impossible ability",
        set_("task.goal", "(isSliced chair)"),
        "task.goal",
        ["'chair' is a Chair, which is not sliceable"],
    ),
    (
        "goal incompatible receptacle",
        set_("task.goal", "(inReceptacle chair fridge)"),
        "task.goal",
        ["a Chair cannot be in a Fridge"],
    ),
    (
        "goal typed variable",
        set_("task.goal", "(exists (?c - Chair) (isHot ?c))"),
        "task.goal",
        ["'?c' is a Chair, which is not heatable"],
    ),
    ("goal missing", delete("task.goal"), "task.goal", ["required key is missing"]),
    (
        "initial not ground",
        set_("task.initial", "(exists (?x) (isOpen ?x))"),
        "task.initial",
        ["expected ground literals"],
    ),
    (
        "task in wrong room",
        set_("task.type", "look_at_obj_in_light"),
        "task.type",
        ["only in Bedroom, LivingRoom"],
    ),
    (
        "bad horizon",
        set_("task.agent", {"horizon": 20}),
        "task.agent.horizon",
        ["expected -30, -15, 0, 15, 30, 45 or 60"],
    ),
    (
        "step unknown action",
        set_("execution", [{"action": "Fly"}]),
        "execution[0].action",
        ["expected 'GotoLocation'"],
    ),
    ("step not a mapping", set_("execution", [5]), "execution[0]", ["expected a mapping"]),
    (
        "step missing object",
        set_("execution", [{"action": "PickupObject"}]),
        "execution[0]",
        ["PickupObject needs 'object'"],
    ),
    (
        "step unknown name",
        set_("execution", [{"action": "PickupObject", "object": "aple"}]),
        "execution[0].object",
        ["unknown name 'aple'"],
    ),
    (
        "step not pickupable",
        set_("execution", [{"action": "PickupObject", "object": "fridge"}]),
        "execution[0].object",
        ["'fridge' is a Fridge, which is not pickupable"],
    ),
    (
        "low-level nav with object",
        set_("execution", [{"action": "MoveAhead", "objectId": "apple"}]),
        "execution[0]",
        ["MoveAhead takes no objectId"],
    ),
    (
        "low-level put without receptacle",
        set_("execution", [{"action": "PutObject", "objectId": "apple"}]),
        "execution[0]",
        ["PutObject needs 'receptacleObjectId'"],
    ),
    (
        "low-level unknown id",
        set_("execution", [{"action": "OpenObject", "objectId": "fridg"}]),
        "execution[0].objectId",
        ["unknown name 'fridg'"],
    ),
    (
        "low-level put into non-receptacle",
        set_(
            "execution",
            [{"action": "PutObject", "objectId": "apple", "receptacleObjectId": "chair"}],
        ),
        "execution[0].receptacleObjectId",
        ["not receptacle"],
    ),
]


@pytest.mark.parametrize(
    ("mutate", "path", "fragments"), [c[1:] for c in CASES], ids=[c[0] for c in CASES]
)
def test_validation_message(mutate: Callable[[Doc], None], path: str, fragments: list[str]) -> None:
    doc = base()
    mutate(doc)
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "kitchen.yaml")
    text = str(info.value)
    assert f"kitchen.yaml: {path}" in text, text
    for fragment in fragments:
        assert fragment in text, text
    assert all(line.startswith("kitchen.yaml: ") for line in text.splitlines()), text


def test_base_document_is_valid() -> None:
    from_document(base(), "kitchen.yaml")


def test_invertible_cycles_are_resolved_by_rewriting() -> None:
    doc = base()
    doc["scene"]["relations"] += [
        rel("chair", "beside", "fridge"),
        rel("fridge", "in_front_of", "counter"),
        rel("counter", "near", "chair"),
    ]
    from_document(doc, "kitchen.yaml")


def test_appliances_may_stand_on_counters() -> None:
    doc = base()
    doc["scene"]["objects"].append({"name": "coffee", "type": "CoffeeMachine"})
    doc["scene"]["relations"].append(rel("coffee", "on", "counter"))
    from_document(doc, "kitchen.yaml")


def test_several_problems_are_all_reported() -> None:
    doc = base()
    doc["scene"]["objects"][2]["type"] = "Aple"
    doc["scene"]["room_type"] = "Kitchn"
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "kitchen.yaml")
    assert [i.path for i in info.value.issues] == ["scene.room_type[0]", "scene.objects[2].type"]


def test_cdf_errors_are_cdf_errors() -> None:
    with pytest.raises(CDFError):
        loads("cdf_version: 2\nscene: {}\n", source="kitchen.yaml")


def test_relation_on_unquoted_in_yaml_is_the_string_on() -> None:
    text = yaml.safe_dump(BASE).replace("'on'", "on")
    assert "relation: on" in text
    cdf = loads(text, source="kitchen.yaml")
    assert cdf.scene.relations[0].relation == "on"


def test_aliases_are_canonicalised() -> None:
    doc = base()
    doc["scene"]["relations"].append(rel("fridge", "in_center"))
    doc["scene"]["objects"][2]["attributes"] = {"color": "red"}
    doc["scene"]["room_type"] = "kitchen"
    cdf = from_document(doc)
    assert cdf.scene.relations[-1].relation == "in_centre"
    assert cdf.scene.objects[2].attributes.colour == "red"  # type: ignore[union-attr]
    assert cdf.scene.room_type == ("Kitchen",)


def test_building_in_python_runs_the_same_checks() -> None:
    doc = base()
    doc["scene"]["relations"].append(rel("apple", "in", "fridge"))
    with pytest.raises(CDFValidationError, match="<cdf>: scene.relations"):
        ChallengeDefinition.model_validate(doc)
