"""`rules.check`: one row per rule, each with the state it starts from and the message it expects."""

from __future__ import annotations

from typing import Any

import pytest

from luminous_sim.states import StateError, check, enclosing_closed, rules
from tests.states.kitchen import kitchen

IN_CLOSED_FRIDGE = {"Plate|1": {"parent": "Fridge|1"}, "Apple|1": {"parent": "Plate|1"}}
IN_OPEN_FRIDGE = {**IN_CLOSED_FRIDGE, "Fridge|1": {"isOpen": True}}

# (case id, changes, held, action, target, receptacle, expected error substring or None when allowed)
ROWS: list[tuple[str, dict[str, dict[str, Any]], str | None, str, str | None, str | None, str | None]] = [
    # PickupObject
    ("pickup ok", {}, None, "PickupObject", "Apple|1", None, None),
    ("pickup plate with apple", {"Apple|1": {"parent": "Plate|1"}}, None, "PickupObject", "Plate|1", None, None),
    ("pickup fixed", {}, None, "PickupObject", "Fridge|1", None, "Fridge|1 is not pickupable"),
    ("pickup hand full", {}, "Mug|1", "PickupObject", "Apple|1", None, "hand is full: holding Mug|1"),
    ("pickup held again", {}, "Mug|1", "PickupObject", "Mug|1", None, "hand is full: holding Mug|1"),
    ("pickup closed drawer", {}, None, "PickupObject", "Knife|1", None,
     "object Knife|1 is inside the closed Drawer|1"),
    ("pickup open drawer", {"Drawer|1": {"isOpen": True}}, None, "PickupObject", "Knife|1", None, None),
    ("pickup closed fridge nested", IN_CLOSED_FRIDGE, None, "PickupObject", "Apple|1", None,
     "object Apple|1 is inside the closed Fridge|1"),
    ("pickup open fridge nested", IN_OPEN_FRIDGE, None, "PickupObject", "Apple|1", None, None),
    ("pickup closed box in closed cabinet", {}, None, "PickupObject", "CD|1", None,
     "object CD|1 is inside the closed Box|1"),
    ("pickup open box in closed cabinet", {"Box|1": {"isOpen": True}}, None, "PickupObject", "CD|1", None,
     "object CD|1 is inside the closed Cabinet|1"),
    ("pickup open laptop is fine", {"Laptop|1": {"isOpen": True}}, None, "PickupObject", "Laptop|1", None, None),
    ("pickup unknown", {}, None, "PickupObject", "Apple|9", None, "unknown object id 'Apple|9'"),
    ("pickup no target", {}, None, "PickupObject", None, None, "PickupObject needs a target object"),
    # PutObject
    ("put ok", {}, "Apple|1", "PutObject", "Apple|1", "CounterTop|1", None),
    ("put target None means held", {}, "Apple|1", "PutObject", None, "Plate|1", None),
    ("put on movable receptacle", {}, "Apple|1", "PutObject", "Apple|1", "Bowl|1", None),
    ("put nothing held", {}, None, "PutObject", "Apple|1", "CounterTop|1", "nothing is held"),
    ("put not the held one", {}, "Mug|1", "PutObject", "Apple|1", "CounterTop|1", "Apple|1 is not held (holding Mug|1)"),  # noqa: E501
    ("put no receptacle", {}, "Apple|1", "PutObject", "Apple|1", None, "PutObject needs a receptacle"),
    ("put unknown receptacle", {}, "Apple|1", "PutObject", "Apple|1", "Shelf|7", "unknown object id 'Shelf|7'"),
    ("put closed fridge", {}, "Apple|1", "PutObject", "Apple|1", "Fridge|1", "Fridge|1 is closed"),
    ("put open fridge", {"Fridge|1": {"isOpen": True}}, "Apple|1", "PutObject", "Apple|1", "Fridge|1", None),
    ("put closed drawer", {}, "ButterKnife|1", "PutObject", None, "Drawer|1", "Drawer|1 is closed"),
    ("put closed box", {"Cabinet|1": {"isOpen": True}}, "Mug|1", "PutObject", None, "Box|1", "Box|1 is closed"),
    ("put on plate in closed fridge", IN_CLOSED_FRIDGE | {"Apple|1": {}}, "Apple|1", "PutObject", None, "Plate|1",
     "object Plate|1 is inside the closed Fridge|1"),
    ("put incompatible toaster", {}, "Cup|1", "PutObject", "Cup|1", "Toaster|1",
     "Cup|1 cannot be put in Toaster|1 (compatibility table)"),
    ("put incompatible fridge", {"Fridge|1": {"isOpen": True}}, "Knife|1", "PutObject", None, "Fridge|1",
     "Knife|1 cannot be put in Fridge|1 (compatibility table)"),
    ("put incompatible cup in cup", {}, "Apple|1", "PutObject", None, "Cup|1",
     "Apple|1 cannot be put in Cup|1 (compatibility table)"),
    ("put mug in coffee machine", {}, "Mug|1", "PutObject", None, "CoffeeMachine|1", None),
    ("put cup in coffee machine", {}, "Cup|1", "PutObject", None, "CoffeeMachine|1",
     "Cup|1 cannot be put in CoffeeMachine|1 (compatibility table)"),
    ("put pot on burner", {"Pot|1": {"parent": "CounterTop|1"}}, "Pot|1", "PutObject", None, "StoveBurner|1", None),
    ("put not a receptacle", {}, "Apple|1", "PutObject", None, "Egg|1", "Egg|1 is not a receptacle"),
    ("put into itself", {}, "Plate|1", "PutObject", None, "Plate|1", "cannot put Plate|1 into itself"),
    ("put into what it carries", {"Mug|1": {"parent": "Bowl|1"}}, "Bowl|1", "PutObject", None, "Mug|1",
     "Mug|1 is inside the held Bowl|1"),
    # OpenObject / CloseObject
    ("open fridge", {}, None, "OpenObject", "Fridge|1", None, None),
    ("open not openable", {}, None, "OpenObject", "CounterTop|1", None, "CounterTop|1 is not openable"),
    ("open already open", {"Fridge|1": {"isOpen": True}}, None, "OpenObject", "Fridge|1", None,
     "Fridge|1 is already open"),
    ("close already closed", {}, None, "CloseObject", "Fridge|1", None, "Fridge|1 is already closed"),
    ("close open fridge", {"Fridge|1": {"isOpen": True}}, None, "CloseObject", "Fridge|1", None, None),
    ("open box in closed cabinet", {}, None, "OpenObject", "Box|1", None, "object Box|1 is inside the closed Cabinet|1"),  # noqa: E501
    ("open held laptop", {}, "Laptop|1", "OpenObject", "Laptop|1", None, None),
    # ToggleObjectOn / ToggleObjectOff
    ("toggle on microwave", {}, None, "ToggleObjectOn", "Microwave|1", None, None),
    ("toggle not toggleable", {}, None, "ToggleObjectOn", "Apple|1", None, "Apple|1 is not toggleable"),
    ("toggle on twice", {"Faucet|1": {"isToggled": True}}, None, "ToggleObjectOn", "Faucet|1", None,
     "Faucet|1 is already on"),
    ("toggle off twice", {}, None, "ToggleObjectOff", "Faucet|1", None, "Faucet|1 is already off"),
    ("toggle on open microwave", {"Microwave|1": {"isOpen": True}}, None, "ToggleObjectOn", "Microwave|1", None,
     "Microwave|1 must be closed to switch it on"),
    ("toggle off open microwave", {"Microwave|1": {"isOpen": True, "isToggled": True}}, None, "ToggleObjectOff",
     "Microwave|1", None, None),
    ("toggle open laptop on", {"Laptop|1": {"isOpen": True}}, None, "ToggleObjectOn", "Laptop|1", None, None),
    # SliceObject
    ("slice with knife", {}, "Knife|1", "SliceObject", "Apple|1", None, None),
    ("slice with butter knife", {}, "ButterKnife|1", "SliceObject", "Bread|1", None, None),
    ("slice egg", {}, "Knife|1", "SliceObject", "Egg|1", None, None),
    ("slice empty hand", {}, None, "SliceObject", "Apple|1", None,
     "SliceObject needs a Knife or ButterKnife in hand (nothing is held)"),
    ("slice holding mug", {}, "Mug|1", "SliceObject", "Apple|1", None,
     "SliceObject needs a Knife or ButterKnife in hand (holding Mug|1)"),
    ("slice not sliceable", {}, "Knife|1", "SliceObject", "Mug|1", None, "Mug|1 is not sliceable"),
    ("slice sliced egg", {"Egg|1": {"isSliced": True}}, "Knife|1", "SliceObject", "Egg|1", None,
     "Egg|1 is already sliced"),
    ("slice in closed fridge", IN_CLOSED_FRIDGE, "Knife|1", "SliceObject", "Apple|1", None,
     "object Apple|1 is inside the closed Fridge|1"),
    # action names
    ("heat is high level", {}, "Apple|1", "HeatObject", "Apple|1", None, "HeatObject is a planner action"),
    ("cool is high level", {}, "Apple|1", "CoolObject", "Apple|1", None, "CoolObject is a planner action"),
    ("clean is high level", {}, "Mug|1", "CleanObject", "Mug|1", None, "CleanObject is a planner action"),
    ("unknown action", {}, None, "Jump", "Apple|1", None, "unknown action 'Jump'"),
    ("navigation passes", {}, None, "MoveAhead", None, None, None),
]


@pytest.mark.parametrize(
    ("changes", "held", "action", "target", "receptacle", "expected"),
    [pytest.param(*row[1:], id=row[0]) for row in ROWS],
)
def test_check(changes, held, action, target, receptacle, expected):
    state = kitchen(changes, held=held)
    assert not state.problems()
    got = check(action, state, target, receptacle)
    if expected is None:
        assert got is None
        rules.effects(action, state, target, receptacle)  # allowed actions have effects without raising
    else:
        assert got is not None and expected in got, got


@pytest.mark.parametrize("row", [r for r in ROWS if r[-1] is not None], ids=lambda r: r[0])
def test_effects_refuses_what_check_rejects(row):
    _, changes, held, action, target, receptacle, _expected = row
    with pytest.raises(StateError, match="is not allowed"):
        rules.effects(action, kitchen(changes, held=held), target, receptacle)


def test_enclosing_closed_is_innermost():
    state = kitchen({"Box|1": {"isOpen": False}})
    assert enclosing_closed(state, "CD|1") == "Box|1"
    assert enclosing_closed(state.with_object("Box|1", isOpen=True), "CD|1") == "Cabinet|1"
    assert enclosing_closed(kitchen({"Box|1": {"isOpen": True}, "Cabinet|1": {"isOpen": True}}), "CD|1") is None
    assert enclosing_closed(state, "Apple|1") is None


def test_messages_are_plain_sentences():
    """Every rejection names the object(s), with no traceback-like noise."""
    for row in ROWS:
        _, changes, held, action, target, receptacle, _expected = row
        got = check(action, kitchen(changes, held=held), target, receptacle)
        if got is not None:
            assert "\n" not in got and "Traceback" not in got and len(got) < 200
