"""Tasks across the rooms of a house: which room each object is in, and a filter on task parameters that
keeps only tasks whose object and receptacle (or lamp) lie in different rooms."""

from __future__ import annotations

from collections.abc import Callable

from luminous_sim.scene.model import Scene
from luminous_sim.states import WorldState
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.model import PddlParams

__all__ = ["object_rooms", "rooms_apart"]


def object_rooms(scene: Scene) -> dict[str, str]:
    """Object id -> the name of the house room it stands in (objects outside every room are left out).

    Raises:
        TaskError: the scene is a single room, not a house.
    """
    shell = scene.room
    if shell.house is None:
        raise TaskError(f"scene {shell.name!r} is a single room; expected a house (a scene with rooms)")
    out = {}
    for o in scene.objects:
        room = shell.room_at(o.position[0], o.position[1])
        if room is not None:
            out[o.id] = room
    return out


def rooms_apart(scene: Scene, state: WorldState) -> Callable[[PddlParams], bool]:
    """A filter for `sample_task(keep=...)`: True for parameters whose object type's instances all lie in
    other rooms than every instance of the receptacle type (or, for look_at_obj_in_light, the lamp type),
    so that the agent must carry the object from one room into another.

    Raises:
        TaskError: the scene is a single room.
    """
    rooms = object_rooms(scene)
    by_type: dict[str, set[str]] = {}
    for oid, obj in state.objects.items():
        if oid in rooms:
            by_type.setdefault(obj.object_type, set()).add(rooms[oid])

    def keep(p: PddlParams) -> bool:
        other = p.parent_target or p.toggle_target
        here, there = by_type.get(p.object_target, set()), by_type.get(other, set())
        return bool(here) and bool(there) and not here & there

    return keep
