"""Placement layers and priorities (data): CSSG places room structure, then furniture, then objects,
then decorations; within a layer, a higher priority `q` is placed first (paper: q(desk) > q(chair)).

Which types are structure or decoration is vocabulary (`vocab.STRUCTURE_TYPES`, `vocab.DECORATION_TYPES`).
CSSG's own placement classes (`cssg.tables.generation_layer`: fixture, furniture, wall, object) answer a
different question, how a piece is placed, and differ from these layers for some types (a Microwave is in
the furniture layer here but stands on a counter as an object there).
"""

from __future__ import annotations

from enum import IntEnum

from luminous_sim.cdf.affordances import has_ability
from luminous_sim.vocab import DECORATION_TYPES, STRUCTURE_TYPES


class Layer(IntEnum):
    """The four placement layers, in placement order."""

    STRUCTURE = 0
    FURNITURE = 1
    OBJECT = 2
    DECORATION = 3


PRIORITY: dict[str, int] = {
    "CounterTop": 100,
    "Bed": 100,
    "Sofa": 95,
    "Fridge": 95,
    "Bathtub": 95,
    "DiningTable": 90,
    "Toilet": 90,
    "Sink": 88,
    "Desk": 85,
    "Dresser": 80,
    "TVStand": 80,
    "Cabinet": 78,
    "Shelf": 70,
    "StoveBurner": 70,
    "CoffeeTable": 60,
    "SideTable": 60,
    "Television": 58,
    "ArmChair": 55,
    "Safe": 45,
    "Chair": 40,
    "Ottoman": 35,
    "Footstool": 30,
    "FloorLamp": 25,
    "GarbageCan": 20,
    "LaundryHamper": 20,
    "HousePlant": 15,
    "Microwave": 66,
    "CoffeeMachine": 65,
    "Toaster": 64,
    "DeskLamp": 62,
    "Lamp": 62,
}
"""Placement priority q(type): furniture, then appliances; others get DEFAULT_PRIORITY."""

DEFAULT_PRIORITY = 50
RECEPTACLE_OBJECT_PRIORITY = 60
"""Movable receptacles (Bowl, Plate, ...) go before the small objects that may sit in them."""

_LAYER_NAMES: dict[str, Layer] = {
    "structure": Layer.STRUCTURE,
    "furniture": Layer.FURNITURE,
    "object": Layer.OBJECT,
    "decoration": Layer.DECORATION,
}


def layer_of(object_type: str, declared: str | None = None, supported: bool = False) -> Layer:
    """The layer an object is placed in.

    Args:
        object_type: Its vocabulary type.
        declared: The layer named in the CDF entry, which wins when given.
        supported: Whether the object is on/in another one, which makes it at least an OBJECT.
    """
    if declared is not None:
        return _LAYER_NAMES[declared]
    if object_type in DECORATION_TYPES:
        return Layer.DECORATION
    if object_type in STRUCTURE_TYPES:
        return Layer.STRUCTURE
    if supported or has_ability(object_type, "pickupable"):
        return Layer.OBJECT
    return Layer.FURNITURE


def priority(object_type: str) -> int:
    """Placement priority q(type): higher is placed earlier within a layer."""
    if object_type in PRIORITY:
        return PRIORITY[object_type]
    if has_ability(object_type, "movable_receptacle"):
        return RECEPTACLE_OBJECT_PRIORITY
    return DEFAULT_PRIORITY
