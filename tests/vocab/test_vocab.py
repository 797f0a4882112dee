"""ALFRED's vocabulary as data: counts and spot checks against spec/alfred.md section 3."""

from __future__ import annotations

import pytest

from luminous_sim.errors import VocabularyError
from luminous_sim.vocab import (
    ALL_TYPES,
    OBJECTS,
    ROOM_TYPES,
    SLICED_TYPES,
    abilities,
    can_contain,
    check_type,
    object_class_id,
    parent_type,
    receptacle_objects,
    room_objects,
    vocab_data,
)


def test_counts_match_alfred():
    d = vocab_data()
    assert len(OBJECTS) == 108 and OBJECTS[0] == "AlarmClock" and OBJECTS[107] == "WineBottle"
    assert object_class_id("Glassbottle") == 38
    assert len(d["receptacles"]) == 37 and len(d["receptacle_objects"]) == 36
    assert len(d["pickupable"]) == 59
    assert {len(room_objects(r)) for r in ROOM_TYPES} == {58, 46, 52, 41}
    assert len(ALL_TYPES) == 108 + 4 + 5


@pytest.mark.parametrize(
    "recep,n",
    [("ArmChair", 11), ("Bowl", 28), ("Cabinet", 29), ("CounterTop", 58), ("Fridge", 19), ("Microwave", 14),
     ("SinkBasin", 27), ("StoveBurner", 3), ("Toaster", 1), ("TVStand", 1), ("Safe", 7)],
)
def test_compatibility_table_sizes(recep, n):
    assert len(receptacle_objects(recep)) == n


def test_compatibility_spot_checks():
    assert can_contain("Fridge", "Apple") and not can_contain("Fridge", "Laptop")
    assert can_contain("CoffeeMachine", "Mug") and not can_contain("CoffeeMachine", "Cup")
    assert receptacle_objects("Chair") == frozenset()  # not a receptacle in ALFRED


def test_abilities():
    apple = abilities("Apple")
    assert apple.pickupable and apple.sliceable and apple.heatable and apple.coolable and apple.cleanable
    assert not apple.receptacle and not apple.openable
    fridge = abilities("Fridge")
    assert fridge.openable and fridge.receptacle and not fridge.pickupable
    assert abilities("Plate").movable_receptacle and abilities("Plate").dirtyable
    assert abilities("Microwave").toggleable and abilities("Faucet").toggleable
    assert abilities("AppleSliced").pickupable and not abilities("AppleSliced").sliceable


def test_sliced_parents_and_unknown_types():
    assert SLICED_TYPES["TomatoSliced"] == "Tomato" and parent_type("BreadSliced") == "Bread"
    assert parent_type("Mug") == "Mug"
    with pytest.raises(VocabularyError, match="did you mean Tomato"):
        check_type("Tomatoe", "x.yaml: scene.objects[0].type")
    with pytest.raises(VocabularyError, match="unknown room type"):
        room_objects("Garage")
