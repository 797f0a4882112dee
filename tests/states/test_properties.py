"""Random action sequences through check() + effects() + apply() never raise and keep the invariants."""

from __future__ import annotations

from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from luminous_sim.states import WorldState, apply, check, rules
from luminous_sim.states.tables import HIGH_LEVEL_ONLY
from luminous_sim.vocab import INTERACTION_ACTIONS, abilities
from tests.states.kitchen import LAYOUT, kitchen

ACTIONS = (*INTERACTION_ACTIONS, *INTERACTION_ACTIONS, *HIGH_LEVEL_ONLY, "MoveAhead", "Jump")
OPENABLE = [k for k, (t, _) in LAYOUT.items() if t in ("Fridge", "Microwave", "Cabinet", "Drawer", "Box", "Laptop")]
TOGGLEABLE = [k for k, (t, _) in LAYOUT.items() if t in ("Microwave", "Faucet", "StoveKnob", "StoveBurner", "Laptop")]
DIRTYABLE = ["Mug|1", "Bowl|1", "Plate|1", "Cup|1", "Pot|1", "Pan|1"]
ABILITY_OF = {"PickupObject": "pickupable", "OpenObject": "openable", "CloseObject": "openable",
              "ToggleObjectOn": "toggleable", "ToggleObjectOff": "toggleable", "SliceObject": "sliceable"}


def _pick(data: st.DataObject, state: WorldState, ability: str | None) -> str | None:
    """Mostly an object with the ability the action needs (so sequences get somewhere), sometimes anything."""
    ids = sorted(state.objects)
    fitting = [k for k in ids if ability and getattr(abilities(state[k].object_type), ability)]
    if fitting and data.draw(st.integers(0, 9)) < 8:
        return data.draw(st.sampled_from(fitting))
    return data.draw(st.none() | st.sampled_from([*ids, "Nothing|1"]))


def _invariants(state: WorldState) -> None:
    held = [k for k, o in state.objects.items() if o.isPickedUp]
    assert len(held) <= 1 and held == ([state.held] if state.held else [])
    if state.held is not None:
        assert state[state.held].parent is None
    for k, o in state.objects.items():
        assert o.parent is None or o.parent in state.objects, (k, o.parent)
        seen, p = {k}, o.parent
        while p is not None:
            assert p not in seen, f"{k} is its own ancestor"
            seen.add(p)
            p = state[p].parent
    assert not state.problems()


@st.composite
def initial(draw: st.DrawFn) -> WorldState:
    changes = {k: {"isOpen": draw(st.booleans())} for k in OPENABLE}
    for k in TOGGLEABLE:
        changes.setdefault(k, {})["isToggled"] = draw(st.booleans())
    for k in DIRTYABLE:
        changes.setdefault(k, {})["isDirty"] = draw(st.booleans())
    return kitchen(changes, held=draw(st.sampled_from([None, None, "Knife|1", "ButterKnife|1", "Plate|1"])))


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(initial(), st.data())
def test_random_sequences_keep_invariants(state: WorldState, data: st.DataObject) -> None:
    for _ in range(data.draw(st.integers(1, 30))):
        action = data.draw(st.sampled_from(ACTIONS))
        target = _pick(data, state, ABILITY_OF.get(action))
        receptacle = _pick(data, state, "receptacle")
        if action == "PutObject" and data.draw(st.integers(0, 9)) < 8:
            target = state.held
        why = check(action, state, target, receptacle)
        if why is not None:
            assert isinstance(why, str) and why
            continue
        before = state
        event(action)
        state = apply(state, rules.effects(action, state, target, receptacle))
        _invariants(state)
        if action == "PickupObject":
            assert state.held == target
        elif action == "PutObject":
            assert state.held is None and state[before.held].parent == receptacle
        if action == "OpenObject":
            assert state[target].isOpen and not (state[target].object_type == "Microwave" and state[target].isToggled)
        assert before.heated <= state.heated and before.cooled <= state.cooled and before.cleaned <= state.cleaned


@settings(max_examples=100, deadline=None)
@given(initial(), st.sampled_from(sorted(LAYOUT)), st.sampled_from(INTERACTION_ACTIONS))
def test_allowed_interactions_change_something(state: WorldState, target: str, action: str) -> None:
    if action == "PutObject":
        state = kitchen(held="Apple|1")
    if check(action, state, target, target) is None:
        assert rules.effects(action, state, target, target)
