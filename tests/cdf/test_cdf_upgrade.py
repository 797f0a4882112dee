from __future__ import annotations

import copy
from typing import Any

import pytest

from luminous_sim.cdf import CDF_VERSION, CDFValidationError, from_document, loads
from luminous_sim.cdf.upgrade import (
    SUPPORTED_VERSIONS,
    UPGRADES,
    document_version,
    parse_v1_relation,
    upgrade,
)

V1: dict[str, Any] = {
    "cdf_version": 1,
    "name": "legacy",
    "room_type": "Kitchen",
    "room": "FloorPlan3",
    "objects": [
        "CounterTop",
        {"type": "Mug", "color": "white", "size": 1.5, "isDirty": True},
        {"type": "Mug"},
        {"name": "fridge", "type": "Fridge", "isOpen": False, "material": "steel"},
        {"type": "DeskLamp", "isOn": False},
    ],
    "relations": [
        "Mug on CounterTop",
        "fridge beside the CounterTop",
        "CounterTop against wall",
        "Mug_2 in front of fridge",
    ],
    "goal": "(isCool Mug)",
    "initial": "(not (isOpen fridge))",
}

V2: dict[str, Any] = {
    "cdf_version": 2,
    "name": "legacy",
    "scene": {
        "room_type": "Kitchen",
        "objects": [
            {"name": "CounterTop", "type": "CounterTop"},
            {
                "name": "Mug",
                "type": "Mug",
                "attributes": {"colour": "white", "size": 1.5},
                "state": {"isDirty": True},
            },
            {"name": "Mug_2", "type": "Mug"},
            {
                "name": "fridge",
                "type": "Fridge",
                "attributes": {"material": "steel"},
                "state": {"isOpen": False},
            },
            {"name": "DeskLamp", "type": "DeskLamp", "state": {"isToggled": False}},
        ],
        "relations": [
            {"subject": "Mug", "relation": "on", "target": "CounterTop"},
            {"subject": "fridge", "relation": "beside", "target": "CounterTop"},
            {"subject": "CounterTop", "relation": "against_wall"},
            {"subject": "Mug_2", "relation": "in_front_of", "target": "fridge"},
        ],
        "room": "FloorPlan3",
    },
    "task": {"initial": "(not (isOpen fridge))", "goal": "(isCool Mug)"},
}


def test_v1_upgrades_to_v2() -> None:
    assert upgrade(V1) == V2


def test_upgrade_does_not_mutate_its_input() -> None:
    before = copy.deepcopy(V1)
    upgrade(V1)
    assert V1 == before


def test_upgraded_document_validates_and_equals_the_v2_one() -> None:
    assert from_document(V1, "old.yaml") == from_document(V2, "new.yaml")


def test_current_documents_pass_unchanged() -> None:
    assert upgrade(V2) == V2
    assert upgrade(V2) is not V2


def test_chain_covers_every_old_version() -> None:
    assert SUPPORTED_VERSIONS[-1] == CDF_VERSION
    assert set(UPGRADES) == set(range(1, CDF_VERSION))


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Mug on DiningTable", {"subject": "Mug", "relation": "on", "target": "DiningTable"}),
        (
            "Chair in front of Desk",
            {"subject": "Chair", "relation": "in_front_of", "target": "Desk"},
        ),
        ("Bed against wall", {"subject": "Bed", "relation": "against_wall"}),
        ("Bed against the wall", {"subject": "Bed", "relation": "against_wall"}),
        ("Lamp in corner", {"subject": "Lamp", "relation": "in_corner"}),
        ("Table in center", {"subject": "Table", "relation": "in_centre"}),
        ("Chair faces Desk", {"subject": "Chair", "relation": "face", "target": "Desk"}),
        ("Table away from Sofa", {"subject": "Table", "relation": "away_from", "target": "Sofa"}),
        ("Painting above Sofa", {"subject": "Painting", "relation": "above", "target": "Sofa"}),
        ("Apple in Fridge", {"subject": "Apple", "relation": "in", "target": "Fridge"}),
        ("Apple inside Fridge", {"subject": "Apple", "relation": "in", "target": "Fridge"}),
        ("Book on top of Desk", {"subject": "Book", "relation": "on", "target": "Desk"}),
        ("Shelf LEFT OF Desk", {"subject": "Shelf", "relation": "left_of", "target": "Desk"}),
    ],
)
def test_v1_relation_sentences(text: str, expected: dict[str, str]) -> None:
    assert parse_v1_relation(text) == expected


@pytest.mark.parametrize("text", ["", "Mug", "Mug hovers DiningTable", "Mug on Dining Table", "on"])
def test_unreadable_v1_sentences(text: str) -> None:
    with pytest.raises(CDFValidationError, match=r"old.yaml: relations\[3\]: cannot read relation"):
        parse_v1_relation(text, "relations[3]", "old.yaml")


@pytest.mark.parametrize(
    ("change", "path", "fragment"),
    [
        ({"objects": "Mug"}, "objects", "expected a list"),
        ({"relations": [{"subject": "Mug"}]}, "relations[0]", "expected a sentence"),
        ({"objects": [3]}, "objects[0]", "expected an object type or a mapping"),
        ({"goals": "x"}, "goals", "unknown key"),
    ],
)
def test_v1_structure_errors(change: dict[str, Any], path: str, fragment: str) -> None:
    doc = copy.deepcopy(V1) | change
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "old.yaml")
    assert f"old.yaml: {path}: {fragment}" in str(info.value)
    assert "cdf_version 1" in str(info.value)


def test_v1_errors_after_upgrade_say_so() -> None:
    doc = copy.deepcopy(V1)
    doc["relations"].append("Mug near Fridge")
    with pytest.raises(CDFValidationError) as info:
        from_document(doc, "old.yaml")
    text = str(info.value)
    assert "old.yaml: scene.relations[4].target: unknown name 'Fridge'" in text
    assert "upgraded from cdf_version 1" in text


def test_v1_text_loads() -> None:
    cdf = loads(
        "cdf_version: 1\nroom_type: Bedroom\nobjects: [Bed, Desk]\nrelations: [Bed beside Desk]\n"
    )
    assert cdf.scene.relations[0].target == "Desk"


@pytest.mark.parametrize(
    "doc",
    [
        None,
        [],
        "text",
        3,
        {"scene": {}},
        {"cdf_version": 0},
        {"cdf_version": 2.0},
        {"cdf_version": None},
    ],
)
def test_document_version_errors(doc: Any) -> None:
    with pytest.raises(CDFValidationError):
        document_version(doc)
