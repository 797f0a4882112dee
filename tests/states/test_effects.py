"""`rules.effects` + `apply`: one row per action, with the exact state changes and bookkeeping it causes."""

from __future__ import annotations

from typing import Any

import pytest

from luminous_sim.states import (
    Attach,
    MoveJoint,
    Record,
    Release,
    SetState,
    ShowVisual,
    Slice,
    apply,
    check,
    rules,
    step,
)
from tests.states.kitchen import diff, kitchen

IN_FRIDGE = {"Plate|1": {"parent": "Fridge|1"}, "Apple|1": {"parent": "Plate|1"}, "Mug|1": {"parent": "Fridge|1"}}
IN_MICROWAVE = {"Potato|1": {"parent": "Microwave|1"}, "Mug|1": {"parent": "Microwave|1"}}
IN_SINK = {
    "Mug|1": {"parent": "SinkBasin|1", "isDirty": True},
    "Bowl|1": {"parent": "SinkBasin|1", "isDirty": True},
    "Apple|1": {"parent": "Bowl|1"},
    "Plate|1": {"parent": "SinkBasin|1"},
}
IN_POT = {"Potato|1": {"parent": "Pot|1"}}
HOT_COOKED = {"temperature": "Hot", "isCooked": True}
SLICED = {"isSliced": True}

# (case id, changes, held, action, target, receptacle, extra state kwargs,
#  expected field changes per object, expected held afterwards, expected bookkeeping {kind: ids})
ROWS: list[tuple[Any, ...]] = [
    ("pickup", {}, None, "PickupObject", "Apple|1", None, {},
     {"Apple|1": {"isPickedUp": True, "parent": None}}, "Apple|1", {}),
    ("pickup carries contents", {"Apple|1": {"parent": "Plate|1"}}, None, "PickupObject", "Plate|1", None, {},
     {"Plate|1": {"isPickedUp": True, "parent": None}}, "Plate|1", {}),
    ("put on plate", {}, "Apple|1", "PutObject", "Apple|1", "Plate|1", {},
     {"Apple|1": {"isPickedUp": False, "parent": "Plate|1"}}, None, {}),
    ("put into running stove does not heat", {"StoveBurner|2": {"isToggled": True}, "StoveKnob|2": {"isToggled": True}},
     "Pan|1", "PutObject", None, "StoveBurner|2", {},
     {"Pan|1": {"isPickedUp": False, "parent": "StoveBurner|2"}}, None, {}),
    ("open fridge keeps temperatures", {**IN_FRIDGE, "Apple|1": {"parent": "Plate|1", "temperature": "Cold"}},
     None, "OpenObject", "Fridge|1", None, {}, {"Fridge|1": {"isOpen": True}}, None, {}),
    ("close fridge cools recursively", {**IN_FRIDGE, "Fridge|1": {"isOpen": True}}, None, "CloseObject", "Fridge|1",
     None, {},
     {"Fridge|1": {"isOpen": False}, "Plate|1": {"temperature": "Cold"}, "Apple|1": {"temperature": "Cold"},
      "Mug|1": {"temperature": "Cold"}},
     None, {"cooled": {"Plate|1", "Apple|1", "Mug|1"}}),
    ("close empty fridge", {"Fridge|1": {"isOpen": True}}, None, "CloseObject", "Fridge|1", None, {},
     {"Fridge|1": {"isOpen": False}}, None, {}),
    ("close cabinet does not cool", {"Cabinet|1": {"isOpen": True}}, None, "CloseObject", "Cabinet|1", None, {},
     {"Cabinet|1": {"isOpen": False}}, None, {}),
    ("microwave on heats and cooks", IN_MICROWAVE, None, "ToggleObjectOn", "Microwave|1", None, {},
     {"Microwave|1": {"isToggled": True}, "Potato|1": HOT_COOKED, "Mug|1": {"temperature": "Hot"}},
     None, {"heated": {"Potato|1", "Mug|1"}}),
    ("microwave on heats nested", {"Plate|1": {"parent": "Microwave|1"}, "Egg|1": {"parent": "Plate|1"}}, None,
     "ToggleObjectOn", "Microwave|1", None, {},
     {"Microwave|1": {"isToggled": True}, "Plate|1": {"temperature": "Hot"}, "Egg|1": HOT_COOKED},
     None, {"heated": {"Plate|1", "Egg|1"}}),
    ("microwave on empty", {}, None, "ToggleObjectOn", "Microwave|1", None, {},
     {"Microwave|1": {"isToggled": True}}, None, {}),
    ("microwave off", {**IN_MICROWAVE, "Microwave|1": {"isToggled": True}}, None, "ToggleObjectOff", "Microwave|1",
     None, {}, {"Microwave|1": {"isToggled": False}}, None, {}),
    ("opening a running microwave stops it", {"Microwave|1": {"isToggled": True}}, None, "OpenObject", "Microwave|1",
     None, {}, {"Microwave|1": {"isOpen": True, "isToggled": False}}, None, {}),
    ("knob heats its burner's pot", IN_POT, None, "ToggleObjectOn", "StoveKnob|1", None, {},
     {"StoveKnob|1": {"isToggled": True}, "StoveBurner|1": {"isToggled": True},
      "Pot|1": {"temperature": "Hot"}, "Potato|1": HOT_COOKED},
     None, {"heated": {"Pot|1", "Potato|1"}}),
    ("other knob heats nothing", IN_POT, None, "ToggleObjectOn", "StoveKnob|2", None, {},
     {"StoveKnob|2": {"isToggled": True}, "StoveBurner|2": {"isToggled": True}}, None, {}),
    ("unmapped knob only toggles", IN_POT, None, "ToggleObjectOn", "StoveKnob|1", None, {"controls": {}},
     {"StoveKnob|1": {"isToggled": True}}, None, {}),
    ("burner on directly", IN_POT, None, "ToggleObjectOn", "StoveBurner|1", None, {},
     {"StoveBurner|1": {"isToggled": True}, "Pot|1": {"temperature": "Hot"}, "Potato|1": HOT_COOKED},
     None, {"heated": {"Pot|1", "Potato|1"}}),
    ("knob off switches burner off", {"StoveKnob|1": {"isToggled": True}, "StoveBurner|1": {"isToggled": True}}, None,
     "ToggleObjectOff", "StoveKnob|1", None, {},
     {"StoveKnob|1": {"isToggled": False}, "StoveBurner|1": {"isToggled": False}}, None, {}),
    ("burner off switches its knob off", {"StoveKnob|1": {"isToggled": True}, "StoveBurner|1": {"isToggled": True}},
     None, "ToggleObjectOff", "StoveBurner|1", None, {},
     {"StoveKnob|1": {"isToggled": False}, "StoveBurner|1": {"isToggled": False}}, None, {}),
    ("faucet cleans and fills its basin", IN_SINK, None, "ToggleObjectOn", "Faucet|1", None, {},
     {"Faucet|1": {"isToggled": True}, "Mug|1": {"isDirty": False, "isFilledWithLiquid": True},
      "Bowl|1": {"isDirty": False, "isFilledWithLiquid": True}},
     None, {"cleaned": {"Mug|1", "Bowl|1", "Apple|1", "Plate|1"}}),
    ("faucet with no basin only runs", IN_SINK, None, "ToggleObjectOn", "Faucet|2", None, {},
     {"Faucet|2": {"isToggled": True}}, None, {}),
    ("faucet off", {**IN_SINK, "Faucet|1": {"isToggled": True}}, None, "ToggleObjectOff", "Faucet|1", None, {},
     {"Faucet|1": {"isToggled": False}}, None, {}),
    ("slice egg marks it only", {}, "Knife|1", "SliceObject", "Egg|1", None, {}, {"Egg|1": SLICED}, "Knife|1", {}),
    ("slice apple into default count", {}, "Knife|1", "SliceObject", "Apple|1", None, {},
     {"Apple|1": {"removed": True}} | {f"Apple|1|AppleSliced_{k}": {"added": "AppleSliced"} for k in range(1, 7)},
     "Knife|1", {}),
    ("slice bread into the world's count", {}, "ButterKnife|1", "SliceObject", "Bread|1", None,
     {"slice_counts": {"Bread|1": 3}},
     {"Bread|1": {"removed": True}} | {f"Bread|1|BreadSliced_{k}": {"added": "BreadSliced"} for k in range(1, 4)},
     "ButterKnife|1", {}),
    ("laptop opens", {}, None, "OpenObject", "Laptop|1", None, {}, {"Laptop|1": {"isOpen": True}}, None, {}),
    ("navigation changes nothing", {}, "Mug|1", "MoveAhead", None, None, {}, {}, "Mug|1", {}),
]


@pytest.mark.parametrize(
    ("changes", "held", "action", "target", "receptacle", "extra", "expected", "held_after", "records"),
    [pytest.param(*row[1:], id=row[0]) for row in ROWS],
)
def test_effects(changes, held, action, target, receptacle, extra, expected, held_after, records):
    before = kitchen(changes, held=held, **extra)
    after, why = step(before, action, target, receptacle)
    assert why is None
    assert diff(before, after) == expected
    assert after.held == held_after
    for kind in ("heated", "cooled", "cleaned"):
        assert set(getattr(after, kind)) == records.get(kind, set()), kind
    assert not after.problems()


def test_effect_values_for_the_world():
    """The physical effects come with their state counterparts, in the order the world applies them."""
    s = kitchen({"Fridge|1": {"isOpen": True}, "Apple|1": {"parent": "Fridge|1"}})
    assert rules.effects("CloseObject", s, "Fridge|1") == [
        MoveJoint("Fridge|1", False), SetState("Fridge|1", "isOpen", False),
        SetState("Apple|1", "temperature", "Cold"), Record("cooled", "Apple|1"),
    ]
    assert rules.effects("PickupObject", s, "Mug|1") == [
        Attach("Mug|1", "agent"), SetState("Mug|1", "isPickedUp", True), SetState("Mug|1", "parent", None),
    ]
    h = kitchen(held="Mug|1")
    assert rules.effects("PutObject", h, "Mug|1", "CounterTop|1") == [
        Release("Mug|1", "CounterTop|1"), SetState("Mug|1", "parent", "CounterTop|1"),
        SetState("Mug|1", "isPickedUp", False),
    ]
    assert rules.effects("ToggleObjectOn", s, "Microwave|1") == [
        SetState("Microwave|1", "isToggled", True), ShowVisual("Microwave|1", "on", True),
    ]
    d = kitchen({"Mug|1": {"parent": "SinkBasin|1", "isDirty": True, "isFilledWithLiquid": True}})
    assert rules.effects("ToggleObjectOn", d, "Faucet|1") == [
        SetState("Faucet|1", "isToggled", True), ShowVisual("Faucet|1", "on", True),
        SetState("Mug|1", "isDirty", False), ShowVisual("Mug|1", "dirty", False), Record("cleaned", "Mug|1"),
    ]
    k = kitchen(held="Knife|1")
    assert rules.effects("SliceObject", k, "Tomato|1") == [
        SetState("Tomato|1", "isSliced", True), Slice("Tomato|1", "TomatoSliced", 5),
    ]


def test_slices_inherit_place_and_temperature_not_bookkeeping():
    s = kitchen({"Apple|1": {"parent": "Plate|1", "temperature": "Hot", "isCooked": True}},
                held="Knife|1", heated={"Apple|1"})
    after, why = step(s, "SliceObject", "Apple|1")
    assert why is None
    pieces = after.of_type("AppleSliced")
    assert len(pieces) == 6 and "Apple|1" not in after
    for pid in pieces:
        p = after[pid]
        assert (p.parent, p.temperature, p.isCooked, p.isSliced) == ("Plate|1", "Hot", True, True)
    assert after.heated == {"Apple|1"}  # ALFRED's sets hold ids; slices are new objects
    assert after.contents("Plate|1") == pieces


def _run(state, *actions):
    for a in actions:
        state, why = step(state, *a)
        assert why is None, (a, why)
    return state


def test_heat_only_what_is_inside_at_switch_on():
    s = _run(kitchen(), ("PickupObject", "Apple|1"), ("OpenObject", "Microwave|1"),
             ("PutObject", "Apple|1", "Microwave|1"), ("CloseObject", "Microwave|1"),
             ("ToggleObjectOn", "Microwave|1"))
    assert s.heated == {"Apple|1"} and s["Apple|1"].temperature == "Hot"
    # Opening switches it off, so nothing can be put into a running microwave; what goes in afterwards is cold
    s = _run(s, ("OpenObject", "Microwave|1"))
    assert not s["Microwave|1"].isToggled
    s = _run(s, ("PickupObject", "Potato|1"), ("PutObject", "Potato|1", "Microwave|1"), ("CloseObject", "Microwave|1"))
    assert s["Potato|1"].temperature == "RoomTemp" and s.heated == {"Apple|1"}
    s = _run(s, ("ToggleObjectOn", "Microwave|1"))
    assert s["Potato|1"].temperature == "Hot" and s.heated == {"Apple|1", "Potato|1"}


def test_stove_heats_only_at_switch_on():
    s = _run(kitchen({"Pot|1": {"parent": "CounterTop|1"}}), ("ToggleObjectOn", "StoveKnob|1"))
    s = _run(s, ("PickupObject", "Pot|1"), ("PutObject", "Pot|1", "StoveBurner|1"))
    assert s["Pot|1"].temperature == "RoomTemp" and not s.heated
    s = _run(s, ("ToggleObjectOff", "StoveKnob|1"), ("ToggleObjectOn", "StoveKnob|1"))
    assert s["Pot|1"].temperature == "Hot" and s.heated == {"Pot|1"}


def test_apple_on_plate_in_fridge_is_cooled_when_door_closes():
    s = _run(kitchen({"Apple|1": {"parent": "Plate|1"}}), ("PickupObject", "Plate|1"), ("OpenObject", "Fridge|1"),
             ("PutObject", "Plate|1", "Fridge|1"))
    assert not s.cooled and s["Apple|1"].temperature == "RoomTemp"
    s = _run(s, ("CloseObject", "Fridge|1"))
    assert s.cooled == {"Plate|1", "Apple|1"} and s["Apple|1"].temperature == "Cold"
    s = _run(s, ("OpenObject", "Fridge|1"), ("PickupObject", "Apple|1"), ("CloseObject", "Fridge|1"),
             ("PutObject", "Apple|1", "CounterTop|1"))
    assert s["Apple|1"].temperature == "Cold" and "Apple|1" in s.cooled  # the sets outlive the visit


def test_clean_in_sink_only_when_the_faucet_turns_on():
    s = _run(kitchen({"Mug|1": {"isDirty": True}}), ("PickupObject", "Mug|1"), ("PutObject", "Mug|1", "SinkBasin|1"))
    assert s["Mug|1"].isDirty and not s.cleaned
    s = _run(s, ("ToggleObjectOn", "Faucet|1"))
    assert not s["Mug|1"].isDirty and s["Mug|1"].isFilledWithLiquid and s.cleaned == {"Mug|1"}
    s = _run(s, ("ToggleObjectOff", "Faucet|1"), ("PickupObject", "Mug|1"), ("PutObject", "Mug|1", "CounterTop|1"))
    assert s.cleaned == {"Mug|1"}


def test_put_into_sink_with_faucet_running_does_not_clean():
    s = _run(kitchen({"Mug|1": {"isDirty": True}, "Faucet|1": {"isToggled": True}}), ("PickupObject", "Mug|1"),
             ("PutObject", "Mug|1", "SinkBasin|1"))
    assert s["Mug|1"].isDirty and not s.cleaned


def test_toggling_twice_fails():
    s = _run(kitchen(), ("ToggleObjectOn", "Faucet|1"))
    assert step(s, "ToggleObjectOn", "Faucet|1")[1] == "Faucet|1 is already on"
    s = _run(s, ("ToggleObjectOff", "Faucet|1"))
    assert step(s, "ToggleObjectOff", "Faucet|1")[1] == "Faucet|1 is already off"


def test_sliced_task_end_to_end():
    s = _run(kitchen({"Drawer|1": {"isOpen": True}}), ("PickupObject", "Knife|1"), ("SliceObject", "Tomato|1"),
             ("PutObject", "Knife|1", "CounterTop|1"), ("PickupObject", "Tomato|1|TomatoSliced_1"),
             ("OpenObject", "Fridge|1"), ("PutObject", None, "Fridge|1"), ("CloseObject", "Fridge|1"))
    assert s.cooled == {"Tomato|1|TomatoSliced_1"}
    assert step(s, "SliceObject", "Egg|1")[1].startswith("SliceObject needs a Knife")


def test_rejected_step_returns_the_same_state():
    s = kitchen()
    assert step(s, "PutObject", None, "CounterTop|1") == (s, "nothing is held")


def test_apply_is_pure():
    s = kitchen({"Fridge|1": {"isOpen": True}, "Apple|1": {"parent": "Fridge|1"}})
    fx = rules.effects("CloseObject", s, "Fridge|1")
    a, b = apply(s, fx), apply(s, fx)
    assert a == b and hash(a) == hash(b)
    assert s["Fridge|1"].isOpen and not s.cooled
    assert check("CloseObject", s, "Fridge|1") is None
