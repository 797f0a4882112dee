"""What an allowed action changes: state fields, ALFRED's bookkeeping, devices' consequences.

Devices act at the moment of the action only (ALFRED's `update_states`): a microwave heats what is
inside when it is switched on, a fridge cools what is inside when its door closes, a faucet cleans
what is in its basin when it is switched on. Putting something into a device that is already running
does nothing to it.
"""

from __future__ import annotations

from typing import Any

from luminous_sim.states.effects import (
    Attach,
    Effect,
    MoveJoint,
    Record,
    Release,
    SetState,
    ShowVisual,
    Slice,
)
from luminous_sim.states.model import StateError, WorldState
from luminous_sim.states.tables import (
    DEFAULT_SLICE_COUNTS,
    FOOD_COOKABLE,
    OFF_WHEN_OPENED,
    SLICE_OF,
)
from luminous_sim.vocab import FILLABLE, STATE_NEUTRAL_ACTIONS


def _set(state: WorldState, object_id: str, field: str, value: Any) -> list[Effect]:
    """A SetState, or nothing when the field already has the value."""
    return [] if getattr(state[object_id], field) == value else [SetState(object_id, field, value)]


def _switch(state: WorldState, object_id: str, on: bool) -> list[Effect]:
    if state[object_id].isToggled == on:
        return []
    return [SetState(object_id, "isToggled", on), ShowVisual(object_id, "on", on)]


def _heat(state: WorldState, container: str) -> list[Effect]:
    out: list[Effect] = []
    for oid in state.contents(container, recursive=True):
        out += _set(state, oid, "temperature", "Hot")
        if state[oid].object_type in FOOD_COOKABLE:
            out += _set(state, oid, "isCooked", True)
        out.append(Record("heated", oid))
    return out


def _cool(state: WorldState, container: str) -> list[Effect]:
    out: list[Effect] = []
    for oid in state.contents(container, recursive=True):
        out += _set(state, oid, "temperature", "Cold")
        out.append(Record("cooled", oid))
    return out


def _wash(state: WorldState, basin: str) -> list[Effect]:
    out: list[Effect] = []
    for oid in state.contents(basin, recursive=True):
        if state[oid].isDirty:
            out += [SetState(oid, "isDirty", False), ShowVisual(oid, "dirty", False)]
        if state[oid].object_type in FILLABLE:
            out += _set(state, oid, "isFilledWithLiquid", True)
        out.append(Record("cleaned", oid))
    return out


def _knobs_of(state: WorldState, burner: str) -> list[str]:
    return [k for k, b in state.controls.items() if b == burner and k in state]


def _toggle_on(state: WorldState, target: str) -> list[Effect]:
    kind = state[target].object_type
    out = _switch(state, target, True)
    if kind in ("Microwave", "StoveBurner"):
        out += _heat(state, target)
    elif kind == "StoveKnob" and state.controls.get(target) in state:
        burner = state.controls[target]
        out += _switch(state, burner, True) + _heat(state, burner)
    elif kind == "Faucet" and state.faucet_basin.get(target) in state:
        out += _wash(state, state.faucet_basin[target])
    return out


def _toggle_off(state: WorldState, target: str) -> list[Effect]:
    kind = state[target].object_type
    out = _switch(state, target, False)
    if kind == "StoveKnob" and state.controls.get(target) in state:
        out += _switch(state, state.controls[target], False)
    elif kind == "StoveBurner":
        for knob in _knobs_of(state, target):
            out += _switch(state, knob, False)
    return out


def _open(state: WorldState, target: str) -> list[Effect]:
    out: list[Effect] = [MoveJoint(target, True), SetState(target, "isOpen", True)]
    if state[target].object_type in OFF_WHEN_OPENED:
        out += _switch(state, target, False)
    return out


def _close(state: WorldState, target: str) -> list[Effect]:
    out: list[Effect] = [MoveJoint(target, False), SetState(target, "isOpen", False)]
    if state[target].object_type == "Fridge":
        out += _cool(state, target)
    return out


def _slice(state: WorldState, target: str) -> list[Effect]:
    out: list[Effect] = [SetState(target, "isSliced", True)]
    kind = state[target].object_type
    if kind in SLICE_OF:
        count = state.slice_counts.get(target, DEFAULT_SLICE_COUNTS.get(kind, 1))
        out.append(Slice(target, SLICE_OF[kind], count))
    return out


def _pickup(state: WorldState, target: str) -> list[Effect]:
    return [
        Attach(target, "agent"),
        SetState(target, "isPickedUp", True),
        SetState(target, "parent", None),
    ]


def effects(
    action: str, state: WorldState, target: str | None, receptacle: str | None = None
) -> list[Effect]:
    """The effects of an action that `rules.check` allowed, in the order to apply them.

    Args:
        action: an ALFRED low-level action name.
        state: the state before the action.
        target: the object acted on (PutObject: the held object, or None for it).
        receptacle: PutObject's receptacle.

    Returns:
        The effects; empty for navigation actions.

    Raises:
        StateError: the rules do not allow the action (the message says why).
    """
    from luminous_sim.states.rules import check  # rules imports this module

    why = check(action, state, target, receptacle)
    if why is not None:
        raise StateError(f"{action} is not allowed: {why}")
    if action in STATE_NEUTRAL_ACTIONS:
        return []
    if action == "PutObject":
        held, recep = state.held, receptacle
        assert held is not None and recep is not None  # check() guarantees both
        return [
            Release(held, recep),
            SetState(held, "parent", recep),
            SetState(held, "isPickedUp", False),
        ]
    assert target is not None
    handlers = {
        "PickupObject": _pickup,
        "OpenObject": _open,
        "CloseObject": _close,
        "ToggleObjectOn": _toggle_on,
        "ToggleObjectOff": _toggle_off,
        "SliceObject": _slice,
    }
    return handlers[action](state, target)
