"""Hand-built states and scenes for the task tests: the shared kitchen and a living room."""

from __future__ import annotations

from functools import cache

import numpy as np

from luminous_sim.rooms.generate import generate_shell
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Scene, SceneObject
from tests.kitchen import KITCHEN, Layout, state_of, with_, without

__all__ = ["KITCHEN", "LIVING", "Layout", "scene_of", "shell", "state_of", "with_", "without"]

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
