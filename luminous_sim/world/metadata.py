"""AI2-THOR-style object metadata from a World (ids, types, poses, states, containment, visibility)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from luminous_sim.vocab import FILLABLE, abilities

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def _xyz(v) -> dict[str, float]:
    """Our (x, y, z-up) as THOR's {x, y (up), z}."""
    return {"x": round(float(v[0]), 4), "y": round(float(v[2]), 4), "z": round(float(v[1]), 4)}


def object_metadata(world: World, visible: dict[str, int]) -> list[dict[str, Any]]:
    """One dict per object, with AI2-THOR's field names."""
    inter = world.interactions
    # AI2-THOR lists an object under every receptacle whose volume holds it (an apple in a bowl in a fridge
    # under both), as ALFRED's ThorEnv reads a fridge's receptacleObjectIds when it closes
    state = inter.state
    parents = {c: state.parent_receptacles(c) for c in state.objects}
    children: dict[str, list[str]] = {}
    for c in state.objects:  # in the state's order, as receptacleObjectIds lists them
        for p in parents[c]:
            children.setdefault(p, []).append(c)
    out = []
    for oid in sorted(world.built.objects):
        st = state.objects[oid]
        ab = abilities(st.object_type)
        pos, yaw = world.built.pose_of(oid)
        out.append({
            "objectId": oid,
            "objectType": st.object_type,
            "name": world.built.objects[oid].entry.id,
            "position": _xyz(pos),
            "rotation": {"x": 0.0, "y": round(math.degrees(-yaw) % 360, 2), "z": 0.0},
            "visible": oid in visible,
            "visiblePixels": visible.get(oid, 0),
            "distance": round(world.object_distance(oid), 4),
            "pickupable": ab.pickupable, "receptacle": ab.receptacle, "openable": ab.openable,
            "toggleable": ab.toggleable, "sliceable": ab.sliceable, "dirtyable": ab.dirtyable,
            "cookable": ab.heatable, "canFillWithLiquid": st.object_type in FILLABLE,
            "moveable": ab.movable_receptacle,
            "isOpen": st.isOpen, "isToggled": st.isToggled, "isDirty": st.isDirty, "isSliced": st.isSliced,
            "isCooked": st.isCooked, "isFilledWithLiquid": st.isFilledWithLiquid, "isPickedUp": st.isPickedUp,
            "temperature": st.temperature,
            "parentReceptacles": parents[oid],
            "receptacleObjectIds": list(children.get(oid, ())),
        })
    return out

