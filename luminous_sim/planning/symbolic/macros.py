"""High-level actions as low-level interactions on the pure state (spec 2.3), and their effect.

`expand_macro` gives the low-level interactions of one high-level action, decided against the
state before it (a device that is already open is not opened again, a running faucet is switched
off first, ToggleObject switches whichever way the object is not). `apply_action` runs them through
`luminous_sim.states.rules`, the simulator's own rules, so a plan the search finds is a plan the
rules accept. GotoLocation changes no object state.

The Pickup/Put expansions here do not add ALFRED's automatic door opening: the planner opens doors
with explicit OpenObject actions.
"""

from __future__ import annotations

from typing import Any

from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic.actions import HighLevelAction
from luminous_sim.states import WorldState, rules


def _low(action: str, object_id: str, receptacle_id: str | None = None) -> dict[str, Any]:
    out = {"action": action, "objectId": object_id}
    if receptacle_id is not None:
        out["receptacleObjectId"] = receptacle_id
    return out


def faucet_of(state: WorldState, basin: str) -> str | None:
    """The faucet that serves a sink basin (`WorldState.faucet_basin`), or None."""
    return next(
        (f for f, b in sorted(state.faucet_basin.items()) if b == basin and f in state), None
    )


def expand_macro(action: HighLevelAction, state: WorldState) -> list[dict[str, Any]]:
    """The low-level interactions of a high-level action, as ALFRED api_action-style dicts.

    Args:
        action: the high-level action.
        state: the state before it (decides open/toggle directions and the faucet).

    Returns:
        `{"action", "objectId"[, "receptacleObjectId"]}` dicts; empty for GotoLocation.

    Raises:
        PlanningError: CleanObject on a basin no faucet serves, or an id the state lacks.
    """
    a, o, r = action.action, action.object_id, action.receptacle_id
    if a == "GotoLocation":
        return []
    if a in ("PickupObject", "OpenObject", "CloseObject", "SliceObject"):
        return [_low(a, o)]
    if a == "PutObject":
        return [_low(a, o, r)]
    if a == "ToggleObject":
        return [_low("ToggleObjectOff" if state[o].isToggled else "ToggleObjectOn", o)]
    assert r is not None
    device = state[r]
    first = [] if device.isOpen else [_low("OpenObject", r)]
    if a == "HeatObject":
        return first + [
            _low("PutObject", o, r),
            _low("CloseObject", r),
            _low("ToggleObjectOn", r),
            _low("ToggleObjectOff", r),
            _low("OpenObject", r),
            _low("PickupObject", o),
            _low("CloseObject", r),
        ]
    if a == "CoolObject":
        return first + [
            _low("PutObject", o, r),
            _low("CloseObject", r),
            _low("OpenObject", r),
            _low("PickupObject", o),
            _low("CloseObject", r),
        ]
    if a == "CleanObject":
        faucet = faucet_of(state, r)
        if faucet is None:
            raise PlanningError(f"CleanObject: no faucet serves {r}")
        off = [_low("ToggleObjectOff", faucet)] if state[faucet].isToggled else []
        return [
            _low("PutObject", o, r),
            *off,
            _low("ToggleObjectOn", faucet),
            _low("ToggleObjectOff", faucet),
            _low("PickupObject", o),
        ]
    raise PlanningError(f"no expansion for {a}")


def try_action(state: WorldState, action: HighLevelAction) -> tuple[WorldState, str | None]:
    """Apply a high-level action through the rules.

    Returns:
        (the state after it, None), or (the state before it, why a low-level step was refused).
    """
    try:
        steps = expand_macro(action, state)
    except (PlanningError, KeyError) as exc:
        return state, str(exc)
    after = state
    for step in steps:
        after, why = rules.step(
            after, step["action"], step["objectId"], step.get("receptacleObjectId")
        )
        if why is not None:
            return state, f"{action!r}: {step['action']} refused: {why}"
    return after, None


def apply_action(state: WorldState, action: HighLevelAction) -> WorldState:
    """The state after a high-level action.

    Raises:
        PlanningError: the rules refuse one of its low-level steps (the message says which and why).
    """
    after, why = try_action(state, action)
    if why is not None:
        raise PlanningError(why)
    return after


def replay(state: WorldState, actions: list[HighLevelAction]) -> WorldState:
    """The state after a whole plan (GotoLocation is a no-op on object states).

    Raises:
        PlanningError: an action is refused; the message names its index.
    """
    for i, action in enumerate(actions):
        after, why = try_action(state, action)
        if why is not None:
            raise PlanningError(f"plan step {i}: {why}")
        state = after
    return state
