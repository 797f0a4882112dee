"""ALFRED's seven task types (and sliced variants) on hand-built states: plan, replay, goal holds."""

from __future__ import annotations

import pytest

from luminous_sim.planning.symbolic import solve
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import goal_for
from tests.planning.helpers import assert_solves, shape
from tests.planning.scenes import bedroom, kitchen

CASES = [
    # (task type, params, scene)
    ("pick_and_place_simple", PddlParams("Potato", "Fridge"), kitchen),
    ("pick_and_place_simple", PddlParams("CellPhone", "Drawer"), bedroom),
    ("pick_and_place_simple", PddlParams("Tomato", "CounterTop", object_sliced=True), kitchen),
    ("pick_two_obj_and_place", PddlParams("Apple", "GarbageCan"), kitchen),
    ("pick_two_obj_and_place", PddlParams("Book", "Dresser"), bedroom),
    ("pick_two_obj_and_place", PddlParams("Bread", "DiningTable", object_sliced=True), kitchen),
    ("look_at_obj_in_light", PddlParams("Book", toggle_target="DeskLamp"), bedroom),
    ("look_at_obj_in_light", PddlParams("CD", toggle_target="DeskLamp"), bedroom),
    ("pick_clean_then_place_in_recep", PddlParams("Mug", "CoffeeMachine"), kitchen),
    (
        "pick_clean_then_place_in_recep",
        PddlParams("Lettuce", "Fridge", object_sliced=True),
        kitchen,
    ),
    ("pick_heat_then_place_in_recep", PddlParams("Potato", "CounterTop"), kitchen),
    (
        "pick_heat_then_place_in_recep",
        PddlParams("Apple", "DiningTable", object_sliced=True),
        kitchen,
    ),
    ("pick_cool_then_place_in_recep", PddlParams("Tomato", "DiningTable"), kitchen),
    (
        "pick_cool_then_place_in_recep",
        PddlParams("Potato", "GarbageCan", object_sliced=True),
        kitchen,
    ),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Apple", "DiningTable", mrecep_target="Plate"),
        kitchen,
    ),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("KeyChain", "SideTable", mrecep_target="Box"),
        bedroom,
    ),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Tomato", "CounterTop", mrecep_target="Bowl", object_sliced=True),
        kitchen,
    ),
]


def _id(case) -> str:
    task, p, _ = case
    mrecep = f"-{p.mrecep_target}" if p.mrecep_target else ""
    return f"{task}-{p.object_type}-{p.parent_target or p.toggle_target}{mrecep}"


@pytest.mark.parametrize("close", [False, True], ids=["open-ok", "all-closed"])
@pytest.mark.parametrize("case", CASES, ids=[_id(c) for c in CASES])
def test_task_types_plan_replays_and_reaches_the_goal(case, close):
    task, params, scene = case
    state = scene()
    goal = goal_for(params, task, closed_receptacles=close)
    plan = solve(state, goal)
    final = assert_solves(state, goal, plan)
    assert plan.cost == sum(a.cost for a in plan.actions)
    assert plan.expanded >= 1 and plan.seconds < 5
    if close:
        assert not [
            k
            for k, o in final.objects.items()
            if o.isOpen
            and o.object_type in ("Fridge", "Cabinet", "Microwave", "Drawer", "Safe", "Box")
        ]


@pytest.mark.parametrize(
    ("task", "params", "expected"),
    [
        (
            "pick_and_place_simple",
            PddlParams("Potato", "CounterTop"),
            ["GotoLocation", "PickupObject", "GotoLocation", "PutObject"],
        ),
        (
            "pick_heat_then_place_in_recep",
            PddlParams("Potato", "CounterTop"),
            [
                "GotoLocation",
                "PickupObject",
                "GotoLocation",
                "HeatObject",
                "GotoLocation",
                "PutObject",
            ],
        ),
        (
            "pick_cool_then_place_in_recep",
            PddlParams("Tomato", "DiningTable"),
            [
                "GotoLocation",
                "PickupObject",
                "GotoLocation",
                "CoolObject",
                "GotoLocation",
                "PutObject",
            ],
        ),
        (
            "pick_clean_then_place_in_recep",
            PddlParams("DishSponge", "CounterTop"),
            [
                "GotoLocation",
                "PickupObject",
                "GotoLocation",
                "CleanObject",
                "GotoLocation",
                "PutObject",
            ],
        ),
        (
            "pick_two_obj_and_place",
            PddlParams("Apple", "GarbageCan"),
            ["GotoLocation", "PickupObject", "GotoLocation", "PutObject"] * 2,
        ),
    ],
)
def test_typical_high_level_sequences(task, params, expected):
    state = kitchen(changes={"Potato|1": {"parent": "DiningTable|1"}})
    plan = solve(state, goal_for(params, task))
    assert shape(plan) == expected, plan.summary()


def test_heat_macro_targets_the_microwave_and_puts_back():
    state = kitchen()
    plan = solve(
        state, goal_for(PddlParams("Potato", "CounterTop"), "pick_heat_then_place_in_recep")
    )
    heat = next(a for a in plan.actions if a.action == "HeatObject")
    assert heat.object_id == "Potato|1" and heat.receptacle_id == "Microwave|1"
    assert plan.actions[-1].action == "PutObject" and plan.actions[-1].receptacle_id.startswith(
        "CounterTop"
    )


def test_look_at_object_in_light_ends_beside_the_lit_lamp():
    state = bedroom()
    plan = solve(
        state, goal_for(PddlParams("Book", toggle_target="DeskLamp"), "look_at_obj_in_light")
    )
    assert shape(plan) == ["GotoLocation", "PickupObject", "GotoLocation", "ToggleObject"], (
        plan.summary()
    )
    assert plan.actions[-2].object_id == "DeskLamp|1"


def test_movable_receptacle_sequence_object_first_then_receptacle():
    state = kitchen()
    goal = goal_for(
        PddlParams("Apple", "DiningTable", mrecep_target="Plate"),
        "pick_and_place_with_movable_recep",
    )
    plan = solve(state, goal)
    assert shape(plan, gotos=False) == ["PickupObject", "PutObject", "PickupObject", "PutObject"], (
        plan.summary()
    )
    obj, into, mrecep, onto = [a for a in plan.actions if a.action != "GotoLocation"]
    assert obj.object_id.startswith("Apple") and into.receptacle_id == mrecep.object_id
    assert mrecep.object_id.startswith("Plate") and onto.receptacle_id == "DiningTable|1"


def test_object_already_in_the_movable_receptacle_only_moves_the_receptacle():
    state = kitchen(changes={"Apple|1": {"parent": "Plate|1"}})
    goal = goal_for(
        PddlParams("Apple", "DiningTable", mrecep_target="Plate"),
        "pick_and_place_with_movable_recep",
    )
    plan = solve(state, goal)
    assert shape(plan, gotos=False) == ["PickupObject", "PutObject"], plan.summary()
    assert plan.actions[1].object_id == "Plate|1"


def test_sliced_variant_fetches_knife_slices_sets_knife_down_and_takes_a_slice():
    state = kitchen()
    goal = goal_for(
        PddlParams("Apple", "DiningTable", object_sliced=True), "pick_heat_then_place_in_recep"
    )
    plan = solve(state, goal)
    names = [a.action for a in plan.actions if a.action != "GotoLocation"]
    assert names[:4] == ["OpenObject", "PickupObject", "SliceObject", "PutObject"], plan.summary()
    pick_knife, put_knife = (
        plan.actions[2],
        next(a for a in plan.actions if a.action == "PutObject"),
    )
    assert pick_knife.object_id == "Knife|1" and put_knife.object_id == "Knife|1"
    picks = [a.object_id for a in plan.actions if a.action == "PickupObject"]
    assert "AppleSliced" in picks[1]


def test_object_in_a_closed_fridge_is_opened_first_and_closed_when_asked():
    state = kitchen()
    for close in (False, True):
        goal = goal_for(
            PddlParams("Egg", "CounterTop"), "pick_and_place_simple", closed_receptacles=close
        )
        plan = solve(state, goal)
        assert shape(plan)[:3] == ["GotoLocation", "OpenObject", "PickupObject"], plan.summary()
        assert plan.actions[1].object_id == "Fridge|1"
        final = assert_solves(state, goal, plan)
        assert final["Fridge|1"].isOpen is (not close)
        if close:
            assert plan.actions[3].action == "CloseObject"  # closed right away, before leaving


def test_end_state_is_consistent_with_a_held_start():
    state = kitchen(held="Knife|1")
    goal = goal_for(PddlParams("Potato", "CounterTop"), "pick_heat_then_place_in_recep")
    plan = solve(state, goal)
    assert plan.actions[0].action in ("GotoLocation", "PutObject")
    assert_solves(state, goal, plan)
