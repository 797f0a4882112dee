"""Functional groups per room, so that a house's rooms can be compared with rooms generated alone: which of
the natural-room groups (`natural.functional_checks`) a room holds, and whether each is met.

A group is held when the room has a member the rule applies to (a chair for "seats at a table", a side table
beside a bed for "side tables at the bed's head"), and met when the rule holds for every such member. A house
room is measured as a room of its own: its shell from the floor plan and the things standing on its floor
(`house_rooms`), which is what CSSG furnished it from (`cssg.house`).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cssg.house import HouseGenerated
from luminous_sim.cssg.natural import functional_checks
from luminous_sim.scene import Scene

GROUPS = {
    "seat at a table, facing it": "seats at a table",
    "stool at a counter, facing it": "stools at a counter",
    "sofa facing the TV or coffee table": "a sofa facing the TV or coffee table",
    "armchair facing the seating group": "armchairs facing the seating group",
    "side table at the bed's head": "side tables at the bed's head",
}
"""The natural-room rules that make a functional group (rule -> group name); the placement rules beside them
(a drawer unit against a wall, a sofa clear of a dining table) are not groups."""


@dataclass(frozen=True)
class GroupState:
    """One functional group in one room."""

    held: bool
    met: bool
    members: int


def room_groups(scene: Scene, catalog: Catalog | None = None) -> dict[str, GroupState]:
    """Every group of GROUPS in `scene` (a single room): held, met, how many members."""
    checks = [c for c in functional_checks(scene, catalog or default_catalog()) if c.rule in GROUPS]
    out = {}
    for rule, name in GROUPS.items():
        mine = [c.met for c in checks if c.rule == rule]
        out[name] = GroupState(bool(mine), bool(mine) and all(mine), len(mine))
    return out


def house_rooms(house: HouseGenerated) -> dict[str, tuple[str, Scene]]:
    """Each room of a generated house as a scene of its own (room name -> (room type, scene)): the room's
    shell and the things whose floor position is in it, with everything they hold."""
    scene = house.scene
    top = {o.id: scene.room.room_at(o.position[0], o.position[1]) for o in scene.objects if o.parent is None}
    parent = {o.id: o.parent for o in scene.objects if o.parent is not None}

    def room_of(oid: str) -> str | None:
        while oid in parent:
            oid = parent[oid]
        return top.get(oid)

    out: dict[str, tuple[str, Scene]] = {}
    for shell in house.plan.rooms:
        objects = tuple(o for o in scene.objects if room_of(o.id) == shell.name)
        out[shell.name] = (shell.room_type, Scene(room=shell, seed=scene.seed, generator=scene.generator,
                                                  objects=objects, source=scene.source))
    return out


def group_rates(rooms: Iterable[Mapping[str, GroupState]]) -> dict[str, dict[str, int]]:
    """Per group over `rooms`: rooms, rooms holding it, rooms where it is met."""
    out = {name: {"rooms": 0, "held": 0, "met": 0} for name in GROUPS.values()}
    for groups in rooms:
        for name, state in groups.items():
            out[name]["rooms"] += 1
            out[name]["held"] += state.held
            out[name]["met"] += state.met
    return out
