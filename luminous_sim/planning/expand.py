"""ALFRED's expansions of high-level actions into low-level interactions (spec 2.3), decided against
the current object state, including the rule that keeps a door open when the next high-level action
interacts with the same place again."""

from __future__ import annotations

from dataclasses import dataclass

from luminous_sim.states.model import WorldState
from luminous_sim.states.tables import GATING_OPENABLE


@dataclass(frozen=True)
class Step:
    """One low-level interaction of an expansion: action, target, receptacle (PutObject)."""

    action: str
    object_id: str
    receptacle_id: str | None = None


def _gating_parent(state: WorldState, oid: str) -> str | None:
    """The closest openable container (Fridge, Cabinet, Microwave, Drawer, Safe, Box) holding `oid`."""
    parent = state.objects[oid].parent if oid in state.objects else None
    while parent is not None:
        if state.objects[parent].object_type in GATING_OPENABLE:
            return parent
        parent = state.objects[parent].parent
    return None


def expand(action: str, args: dict, state: WorldState, keep_open: bool) -> list[Step]:
    """Low-level steps of one high-level action, given the state before it.

    `keep_open`: the next high-level action is neither GotoLocation nor End, so the automatic close
    after Pickup/Put/Slice is skipped (ALFRED's `should_keep_door_open`).
    """
    o = args.get("objectId")
    if action in ("PickupObject", "SliceObject"):
        parent = _gating_parent(state, o)
        opened = parent is not None and not state.objects[parent].isOpen
        steps = ([Step("OpenObject", parent)] if opened else []) + [Step(action, o)]
        return steps + ([Step("CloseObject", parent)] if opened and not keep_open else [])
    if action == "PutObject":
        r = args["receptacleObjectId"]
        gate = r if state.objects[r].object_type in GATING_OPENABLE else _gating_parent(state, r)
        opened = gate is not None and not state.objects[gate].isOpen
        steps = ([Step("OpenObject", gate)] if opened else []) + [Step("PutObject", o, r)]
        return steps + ([Step("CloseObject", gate)] if opened and not keep_open else [])
    if action in ("OpenObject", "CloseObject"):
        return [Step(action, o)]
    if action == "ToggleObject":
        return [Step("ToggleObjectOff" if state.objects[o].isToggled else "ToggleObjectOn", o)]
    if action in ("ToggleObjectOn", "ToggleObjectOff"):
        return [Step(action, o)]
    if action == "HeatObject":
        m = args["receptacleObjectId"]
        first = [] if state.objects[m].isOpen else [Step("OpenObject", m)]
        return first + [Step("PutObject", o, m), Step("CloseObject", m), Step("ToggleObjectOn", m),
                        Step("ToggleObjectOff", m), Step("OpenObject", m), Step("PickupObject", o),
                        Step("CloseObject", m)]
    if action == "CoolObject":
        f = args["receptacleObjectId"]
        first = [] if state.objects[f].isOpen else [Step("OpenObject", f)]
        return first + [Step("PutObject", o, f), Step("CloseObject", f), Step("OpenObject", f),
                        Step("PickupObject", o), Step("CloseObject", f)]
    if action == "CleanObject":
        basin = args["receptacleObjectId"]
        faucet = next((fa for fa, b in state.faucet_basin.items() if b == basin), None)
        if faucet is None:
            return [Step("PutObject", o, basin), Step("PickupObject", o)]
        return [Step("PutObject", o, basin), Step("ToggleObjectOn", faucet), Step("ToggleObjectOff", faucet),
                Step("PickupObject", o)]
    raise ValueError(f"no expansion for high-level action {action!r}")
