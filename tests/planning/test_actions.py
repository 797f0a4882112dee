"""High-level actions: ALFRED's planner/discrete forms, the plan record, macro expansions."""

from __future__ import annotations

import pytest

from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic import HighLevelAction, Plan, apply_action, expand_macro
from luminous_sim.planning.symbolic.actions import act, goto
from tests.planning.scenes import kitchen


def test_planner_and_discrete_forms_follow_alfred():
    put = act("PutObject", "Apple|1|AppleSliced_2", "DiningTable|1")
    assert put.to_planner_action() == {
        "action": "PutObject",
        "objectId": "Apple|1|AppleSliced_2",
        "receptacleObjectId": "DiningTable|1",
        "forceVisible": True,
    }
    assert put.to_discrete_action() == {"action": "PutObject", "args": ["apple", "diningtable"]}
    heat = act("HeatObject", "Potato|1", "Microwave|1")
    assert heat.to_planner_action() == {
        "action": "HeatObject",
        "objectId": "Microwave|1",
        "forceVisible": True,
    }
    assert heat.to_discrete_action() == {"action": "HeatObject", "args": ["potato"]}
    clean = act("CleanObject", "Mug|1", "Sink|1|SinkBasin")
    assert clean.to_planner_action()["cleanObjectId"] == "Mug|1"
    assert clean.to_planner_action()["objectId"] == "Sink|1|SinkBasin"
    g = goto("CounterTop|1")
    assert g.to_planner_action() == {"action": "GotoLocation", "objectId": "CounterTop|1"}
    assert g.to_discrete_action(heat) == {"action": "GotoLocation", "args": ["microwave"]}
    assert g.to_discrete_action(act("PickupObject", "Apple|1")) == {
        "action": "GotoLocation",
        "args": ["apple"],
    }


def test_actions_are_frozen_hashable_and_validated():
    a, b = act("PickupObject", "Apple|1"), act("PickupObject", "Apple|1")
    assert a == b and hash(a) == hash(b) and len({a, b}) == 1
    with pytest.raises(TypeError):
        a.args["objectId"] = "x"  # type: ignore[index]
    with pytest.raises(PlanningError, match="unknown high-level action"):
        HighLevelAction("Teleport", {"objectId": "x"})
    with pytest.raises(PlanningError, match="receptacleObjectId"):
        HighLevelAction("PutObject", {"objectId": "x"})


def test_plan_high_pddl_ends_with_end():
    plan = Plan([goto("CounterTop|1"), act("PickupObject", "Apple|1")], 2.0, 3, 0.01)
    hp = plan.high_pddl()
    assert [h["high_idx"] for h in hp] == [0, 1, 2]
    assert hp[0]["discrete_action"] == {"action": "GotoLocation", "args": ["apple"]}
    assert hp[-1] == {
        "high_idx": 2,
        "planner_action": {"action": "End", "value": 1},
        "discrete_action": {"action": "NoOp", "args": []},
    }


def _names(steps):
    return [(s["action"], s["objectId"]) for s in steps]


def test_heat_cool_clean_expand_as_in_alfred():
    s = kitchen(held="Potato|1")
    assert _names(expand_macro(act("HeatObject", "Potato|1", "Microwave|1"), s)) == [
        ("OpenObject", "Microwave|1"),
        ("PutObject", "Potato|1"),
        ("CloseObject", "Microwave|1"),
        ("ToggleObjectOn", "Microwave|1"),
        ("ToggleObjectOff", "Microwave|1"),
        ("OpenObject", "Microwave|1"),
        ("PickupObject", "Potato|1"),
        ("CloseObject", "Microwave|1"),
    ]
    assert _names(expand_macro(act("CoolObject", "Potato|1", "Fridge|1"), s)) == [
        ("OpenObject", "Fridge|1"),
        ("PutObject", "Potato|1"),
        ("CloseObject", "Fridge|1"),
        ("OpenObject", "Fridge|1"),
        ("PickupObject", "Potato|1"),
        ("CloseObject", "Fridge|1"),
    ]
    assert _names(expand_macro(act("CleanObject", "Potato|1", "SinkBasin|1"), s)) == [
        ("PutObject", "Potato|1"),
        ("ToggleObjectOn", "Faucet|1"),
        ("ToggleObjectOff", "Faucet|1"),
        ("PickupObject", "Potato|1"),
    ]
    assert expand_macro(goto("Fridge|1"), s) == []


def test_expansions_depend_on_the_state():
    s = kitchen(
        changes={"Microwave|1": {"isOpen": True}, "Faucet|1": {"isToggled": True}}, held="Potato|1"
    )
    assert expand_macro(act("HeatObject", "Potato|1", "Microwave|1"), s)[0]["action"] == "PutObject"
    assert _names(expand_macro(act("CleanObject", "Potato|1", "SinkBasin|1"), s))[1] == (
        "ToggleObjectOff",
        "Faucet|1",
    )
    assert expand_macro(act("ToggleObject", "Faucet|1"), s)[0]["action"] == "ToggleObjectOff"


def test_apply_action_uses_the_rules():
    s = kitchen(held="Potato|1")
    after = apply_action(s, act("HeatObject", "Potato|1", "Microwave|1"))
    assert (
        after.held == "Potato|1"
        and "Potato|1" in after.heated
        and after["Potato|1"].temperature == "Hot"
    )
    assert not after["Microwave|1"].isOpen and not after["Microwave|1"].isToggled
    with pytest.raises(PlanningError, match="closed"):
        apply_action(s, act("PutObject", "Potato|1", "Fridge|1"))
    with pytest.raises(PlanningError, match="no faucet"):
        apply_action(
            kitchen(held="Potato|1", faucet_basin={}), act("CleanObject", "Potato|1", "SinkBasin|1")
        )
