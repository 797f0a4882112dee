"""ALFRED's expansions of high-level actions into low-level interactions (spec 2.3), decided against
the current object state, including the rule that keeps a door open when the next high-level action
interacts with the same place again."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from luminous_sim.errors import PlanningError
from luminous_sim.states.model import WorldState
from luminous_sim.states.tables import GATING_OPENABLE


@dataclass(frozen=True)
class Step:
    """One low-level interaction of an expansion: action, target, receptacle (PutObject)."""

    action: str
    object_id: str
    receptacle_id: str | None = None


def gating_parent(state: WorldState, oid: str) -> str | None:
    """The closest openable container (Fridge, Cabinet, Microwave, Drawer, Safe, Box) holding `oid`."""
    parent = state.objects[oid].parent if oid in state.objects else None
    while parent is not None:
        if state.objects[parent].object_type in GATING_OPENABLE:
            return parent
        parent = state.objects[parent].parent
    return None


def expand(action: str, args: Mapping[str, str], state: WorldState, keep_open: bool = False,
           auto_doors: bool = True) -> list[Step]:
    """Low-level steps of one high-level action, given the state before it.

    `keep_open`: the next high-level action is neither GotoLocation nor End, so the automatic close
    after Pickup/Put/Slice is skipped (ALFRED's `should_keep_door_open`).
    `auto_doors`: Pickup/Put/Slice open (and close) the container they reach into, as ALFRED's
    expansions do; the symbolic planner, which opens doors with explicit actions, turns this off.

    Raises:
        PlanningError: no `objectId`, CleanObject at a basin no faucet serves, or an unknown action.
    """
    o = args.get("objectId")
    if o is None:
        raise PlanningError(f"{action} needs an objectId")
    if action in ("PickupObject", "SliceObject", "PutObject"):
        r = args.get("receptacleObjectId")
        if r is None:
            gate = gating_parent(state, o)
        else:
            gate = r if state.objects[r].object_type in GATING_OPENABLE else gating_parent(state, r)
        if auto_doors and gate is not None and not state.objects[gate].isOpen:
            close = [] if keep_open else [Step("CloseObject", gate)]
            return [Step("OpenObject", gate), Step(action, o, r), *close]
        return [Step(action, o, r)]
    if action in ("OpenObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff"):
        return [Step(action, o)]
    if action == "ToggleObject":
        return [Step("ToggleObjectOff" if state.objects[o].isToggled else "ToggleObjectOn", o)]
    if action in ("HeatObject", "CoolObject"):
        m = args["receptacleObjectId"]
        first = [] if state.objects[m].isOpen else [Step("OpenObject", m)]
        run = [Step("ToggleObjectOn", m), Step("ToggleObjectOff", m)] if action == "HeatObject" else []
        return first + [Step("PutObject", o, m), Step("CloseObject", m), *run, Step("OpenObject", m),
                        Step("PickupObject", o), Step("CloseObject", m)]
    if action == "CleanObject":
        basin = args["receptacleObjectId"]
        faucet = faucet_of(state, basin)
        if faucet is None:
            raise PlanningError(f"CleanObject: no faucet serves {basin}")
        off = [Step("ToggleObjectOff", faucet)] if state.objects[faucet].isToggled else []
        return [Step("PutObject", o, basin), *off, Step("ToggleObjectOn", faucet), Step("ToggleObjectOff", faucet),
                Step("PickupObject", o)]
    raise PlanningError(f"no expansion for high-level action {action!r}")


def faucet_of(state: WorldState, basin: str) -> str | None:
    """The faucet that serves a sink basin (`WorldState.faucet_basin`), or None."""
    return next((f for f, b in sorted(state.faucet_basin.items()) if b == basin and f in state), None)
