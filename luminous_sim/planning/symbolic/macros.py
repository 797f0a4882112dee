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
from luminous_sim.planning.expand import expand
from luminous_sim.planning.symbolic.actions import HighLevelAction
from luminous_sim.states import WorldState, rules


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
    if action.action == "GotoLocation":
        return []
    args = {"objectId": action.object_id}
    if action.receptacle_id is not None:
        args["receptacleObjectId"] = action.receptacle_id
    out = []
    for step in expand(action.action, args, state, auto_doors=False):
        low = {"action": step.action, "objectId": step.object_id}
        if step.receptacle_id is not None:
            low["receptacleObjectId"] = step.receptacle_id
        out.append(low)
    return out


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
