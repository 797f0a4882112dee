"""Which object an interaction means, and whether the agent can reach it: an id given directly or found
from a mask or a point in the current frame; visible and within the visibility distance (or in an open
container in view, as AI2-THOR allows)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.states.model import WorldState
from luminous_sim.vocab import abilities
from luminous_sim.world.masks import resolve_point, resolve_target, rle_to_mask

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def type_of(state: WorldState, oid: str | None) -> str:
    """The object's type, or "" for an unknown id."""
    return state.objects[oid].object_type if oid is not None and oid in state.objects else ""


def interactable(state: WorldState, oid: str) -> bool:
    """Whether any interaction applies to the object (a mask or point may pick it)."""
    ab = abilities(type_of(state, oid))
    return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable or ab.sliceable


def resolve(world: World, state: WorldState, act: dict[str, Any], key: str = "objectId") -> str | None:
    """An object id from the action: given directly, or from a mask (RLE) or a point."""
    if act.get(key):
        return str(act[key])
    seg = world.instance_ids()
    inst = {b: o for b, o in world.body_to_object().items()}

    def usable(oid: str) -> bool:
        return interactable(state, oid)

    if act.get("mask") is not None:
        mask = rle_to_mask(act["mask"], seg.shape) if not isinstance(act["mask"], np.ndarray) else act["mask"]
        return resolve_target(mask, seg, inst, state.held, usable)
    if act.get("point") is not None:
        return resolve_point(tuple(act["point"]), seg, inst, state.held, usable)
    return None


def open_container_in_view(world: World, state: WorldState, oid: str) -> str | None:
    """The open container `oid` sits in, if that container is visible and within reach: AI2-THOR
    lets the agent take things out of an open fridge or microwave it is looking into, however few
    pixels of them show."""
    parent = state.objects[oid].parent if oid in state.objects else None
    if parent is None or not state.objects[parent].isOpen:
        return None
    if parent in world.visible_objects() and world.object_distance(oid) <= world.config.visibility_distance:
        return parent
    return None


def reach_failure(world: World, state: WorldState, oid: str) -> Failure | None:
    """None if the object is visible and within reach (or in an open container in view), else why not."""
    if oid not in world.built.objects:
        return Failure(FailureCode.UNKNOWN_OBJECT, f"unknown object id {oid!r}")
    visible = world.visible_objects()
    if oid not in visible and open_container_in_view(world, state, oid) is None:
        d = world.object_distance(oid)
        if d > world.config.visibility_distance:
            return Failure(FailureCode.OUT_OF_REACH,
                           f"{oid} is too far away ({d:.2f} m > {world.config.visibility_distance} m)")
        return Failure(FailureCode.NOT_VISIBLE, f"{oid} is not visible from here")
    return None
