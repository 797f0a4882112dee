"""Hand-built states and scenes for the task tests."""

from __future__ import annotations

from functools import cache
from typing import Any

import numpy as np

from luminous_sim.rooms.generate import generate_shell
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Scene, SceneObject
from luminous_sim.states import ObjectState, WorldState

Layout = dict[str, tuple[str, str | None]]
"""id -> (type, parent id)."""

KITCHEN: Layout = {
    "CounterTop|1": ("CounterTop", None),
    "DiningTable|1": ("DiningTable", None),
    "Fridge|1": ("Fridge", None),
    "Microwave|1": ("Microwave", "CounterTop|1"),
    "Cabinet|1": ("Cabinet", None),
    "Sink|1": ("Sink", None),
    "SinkBasin|1": ("SinkBasin", "Sink|1"),
    "Faucet|1": ("Faucet", "Sink|1"),
    "Toaster|1": ("Toaster", "CounterTop|1"),
    "CoffeeMachine|1": ("CoffeeMachine", "CounterTop|1"),
    "Apple|1": ("Apple", "CounterTop|1"),
    "Plate|1": ("Plate", "DiningTable|1"),
    "Mug|1": ("Mug", "CounterTop|1"),
    "Mug|2": ("Mug", "DiningTable|1"),
    "Knife|1": ("Knife", "CounterTop|1"),
    "Potato|1": ("Potato", "DiningTable|1"),
}
LIVING: Layout = {
    "Sofa|1": ("Sofa", None),
    "CoffeeTable|1": ("CoffeeTable", None),
    "SideTable|1": ("SideTable", None),
    "DeskLamp|1": ("DeskLamp", "SideTable|1"),
    "FloorLamp|1": ("FloorLamp", None),
    "Box|1": ("Box", "CoffeeTable|1"),
    "RemoteControl|1": ("RemoteControl", "CoffeeTable|1"),
    "KeyChain|1": ("KeyChain", "SideTable|1"),
    "KeyChain|2": ("KeyChain", "CoffeeTable|1"),
}


def state_of(
    layout: Layout, changes: dict[str, dict[str, Any]] | None = None, **kwargs: Any
) -> WorldState:
    """A state with every object as laid out, some fields changed; `held=` also sets isPickedUp."""
    changes = {k: dict(v) for k, v in (changes or {}).items()}
    held = kwargs.get("held")
    if held is not None:
        changes[held] = {**changes.get(held, {}), "parent": None, "isPickedUp": True}
    objs = [
        ObjectState(oid, kind, **{"parent": parent, **changes.get(oid, {})})
        for oid, (kind, parent) in layout.items()
    ]
    return WorldState.of(objs, **kwargs)


def with_(layout: Layout, **extra: tuple[str, str | None]) -> Layout:
    """A copy of a layout with objects added (keyword `Type_k`) or moved; `None` value removes."""
    out = dict(layout)
    for key, value in extra.items():
        oid = key.replace("_", "|")
        if value is None:
            out.pop(oid, None)
        else:
            out[oid] = value
    return out


def without(layout: Layout, *types: str) -> Layout:
    """A copy of a layout without any object of the given types (and what they held stays)."""
    return {k: v for k, v in layout.items() if v[0] not in types}


@cache
def shell(room_type: str) -> RoomShell:
    return generate_shell(room_type, np.random.default_rng(0))


def scene_of(layout: Layout, room_type: str = "Kitchen", seed: int = 7) -> Scene:
    """A scene holding the layout's objects (positions are irrelevant to the task layer)."""
    objs = tuple(
        SceneObject(
            id=oid,
            type=kind,
            asset=f"{kind}_0",
            position=(0.0, 0.0, 0.0),
            layer="object",
            parent=parent,
        )
        for oid, (kind, parent) in layout.items()
    )
    return Scene(room=shell(room_type), seed=seed, generator="test", objects=objs)
