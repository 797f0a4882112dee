"""Whether an interaction is allowed by the object-state rules, in AI2-THOR's spirit.

`check` answers None (allowed) or a message saying why not (`failure` the same with its
`FailureCode`); `effects` (re-exported from
`transitions`) lists what an allowed action changes; `apply` (from `update`) folds effects
into a new state; `step` does all three. Reach and visibility are the world's business, not
these rules'.
"""

from __future__ import annotations

from collections.abc import Callable

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.states.model import WorldState
from luminous_sim.states.tables import CLOSED_TO_SWITCH_ON, GATING_OPENABLE, HIGH_LEVEL_ONLY
from luminous_sim.states.transitions import effects
from luminous_sim.states.update import apply
from luminous_sim.vocab import (
    INTERACTION_ACTIONS,
    SLICING_TOOLS,
    STATE_NEUTRAL_ACTIONS,
    abilities,
    can_contain,
)

__all__ = ["apply", "check", "effects", "enclosing_closed", "failure", "step"]


def enclosing_closed(state: WorldState, object_id: str) -> str | None:
    """The innermost closed receptacle (Fridge, Cabinet, Drawer, ...) shutting the object in."""
    for anc in state.ancestors(object_id):
        a = state.objects.get(anc)
        if a is not None and a.object_type in GATING_OPENABLE and not a.isOpen:
            return anc
    return None


def _shut_in(state: WorldState, object_id: str) -> Failure | None:
    closed = enclosing_closed(state, object_id)
    return (
        Failure(FailureCode.SHUT_IN, f"object {object_id} is inside the closed {closed}")
        if closed
        else None
    )


def _pickup(state: WorldState, target: str, receptacle: str | None) -> Failure | None:
    if not abilities(state[target].object_type).pickupable:
        return Failure(FailureCode.NOT_PICKUPABLE, f"{target} is not pickupable")
    if state.held is not None:
        return Failure(FailureCode.HANDS_FULL, f"hand is full: holding {state.held}")
    return _shut_in(state, target)


def _put(state: WorldState, target: str | None, receptacle: str | None) -> Failure | None:
    held = state.held
    if held is None:
        return Failure(FailureCode.NOT_HOLDING, "nothing is held")
    if target is not None and target != held:
        return Failure(FailureCode.NOT_HOLDING, f"{target} is not held (holding {held})")
    if receptacle is None:
        return Failure(FailureCode.NO_TARGET, "PutObject needs a receptacle")
    if receptacle not in state:
        return Failure(FailureCode.UNKNOWN_OBJECT, f"unknown object id {receptacle!r}")
    if receptacle == held:
        return Failure(FailureCode.INCOMPATIBLE, f"cannot put {held} into itself")
    if held in state.ancestors(receptacle):
        return Failure(FailureCode.INCOMPATIBLE, f"{receptacle} is inside the held {held}")
    r = state[receptacle]
    if not abilities(r.object_type).receptacle:
        return Failure(FailureCode.NOT_A_RECEPTACLE, f"{receptacle} is not a receptacle")
    if r.object_type in GATING_OPENABLE and not r.isOpen:
        return Failure(FailureCode.CLOSED, f"{receptacle} is closed")
    shut = _shut_in(state, receptacle)
    if shut:
        return shut
    if not can_contain(r.object_type, state[held].object_type):
        return Failure(
            FailureCode.INCOMPATIBLE, f"{held} cannot be put in {receptacle} (compatibility table)"
        )
    return None


def _open_close(opening: bool) -> Callable[[WorldState, str, str | None], Failure | None]:
    def rule(state: WorldState, target: str, receptacle: str | None) -> Failure | None:
        obj = state[target]
        if not abilities(obj.object_type).openable:
            return Failure(FailureCode.NOT_OPENABLE, f"{target} is not openable")
        if obj.isOpen == opening:
            return Failure(
                FailureCode.ALREADY_DONE, f"{target} is already {'open' if opening else 'closed'}"
            )
        return _shut_in(state, target)

    return rule


def _toggle(on: bool) -> Callable[[WorldState, str, str | None], Failure | None]:
    def rule(state: WorldState, target: str, receptacle: str | None) -> Failure | None:
        obj = state[target]
        if not abilities(obj.object_type).toggleable:
            return Failure(FailureCode.NOT_TOGGLEABLE, f"{target} is not toggleable")
        if obj.isToggled == on:
            return Failure(FailureCode.ALREADY_DONE, f"{target} is already {'on' if on else 'off'}")
        if on and obj.object_type in CLOSED_TO_SWITCH_ON and obj.isOpen:
            return Failure(FailureCode.MUST_BE_CLOSED, f"{target} must be closed to switch it on")
        return _shut_in(state, target)

    return rule


def _slice(state: WorldState, target: str, receptacle: str | None) -> Failure | None:
    obj = state[target]
    if not abilities(obj.object_type).sliceable:
        return Failure(FailureCode.NOT_SLICEABLE, f"{target} is not sliceable")
    if obj.isSliced:
        return Failure(FailureCode.ALREADY_DONE, f"{target} is already sliced")
    held = state.get(state.held)
    if held is None or held.object_type not in SLICING_TOOLS:
        holding = f"holding {state.held}" if held is not None else "nothing is held"
        return Failure(
            FailureCode.NEEDS_TOOL, f"SliceObject needs a Knife or ButterKnife in hand ({holding})"
        )
    return _shut_in(state, target)


_RULES: dict[str, Callable[[WorldState, str, str | None], Failure | None]] = {
    "PickupObject": _pickup,
    "OpenObject": _open_close(True),
    "CloseObject": _open_close(False),
    "ToggleObjectOn": _toggle(True),
    "ToggleObjectOff": _toggle(False),
    "SliceObject": _slice,
}


def check(
    action: str, state: WorldState, target: str | None, receptacle: str | None = None
) -> str | None:
    """Whether the object-state rules allow an action: None, or the message of its `failure`."""
    why = failure(action, state, target, receptacle)
    return None if why is None else why.message


def failure(
    action: str, state: WorldState, target: str | None, receptacle: str | None = None
) -> Failure | None:
    """Whether the object-state rules allow an action.

    Args:
        action: an ALFRED low-level action name (`vocab.INTERACTION_ACTIONS`); navigation actions are
            always allowed.
        state: the current state.
        target: the object acted on; for PutObject the held object (None means "the held one").
        receptacle: for PutObject, the receptacle id.

    Returns:
        None if allowed, else the failure: its code, and a message naming the objects involved and
        what is wrong.
    """
    if action in STATE_NEUTRAL_ACTIONS:
        return None
    if action in HIGH_LEVEL_ONLY:
        return Failure(
            FailureCode.UNKNOWN_ACTION,
            f"{action} is a planner action, not a low-level one: use {HIGH_LEVEL_ONLY[action]}",
        )
    if action == "PutObject":
        return _put(state, target, receptacle)
    rule = _RULES.get(action)
    if rule is None:
        return Failure(
            FailureCode.UNKNOWN_ACTION,
            f"unknown action {action!r}; expected one of {', '.join(INTERACTION_ACTIONS)}",
        )
    if target is None:
        return Failure(FailureCode.NO_TARGET, f"{action} needs a target object")
    if target not in state:
        return Failure(FailureCode.UNKNOWN_OBJECT, f"unknown object id {target!r}")
    return rule(state, target, receptacle)


def step(
    state: WorldState, action: str, target: str | None, receptacle: str | None = None
) -> tuple[WorldState, str | None]:
    """Check an action and, when allowed, apply its effects.

    Returns:
        (new state, None) when allowed, else (the same state, the message).
    """
    why = check(action, state, target, receptacle)
    if why is not None:
        return state, why
    return apply(state, effects(action, state, target, receptacle)), None
