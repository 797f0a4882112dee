"""The PDDL domain and problem generator, and the Fast Downward backends when installed."""

from __future__ import annotations

import re

import pytest

from luminous_sim.cdf.predicates import parse_expr
from luminous_sim.planning.symbolic import solve
from luminous_sim.planning.symbolic.problem import domain_text, pddl_name, to_pddl_problem
from luminous_sim.states import ObjectState, WorldState
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import goal_for
from tests.planning.helpers import assert_solves
from tests.planning.scenes import bedroom, kitchen

ACTIONS = (
    "GotoLocation",
    "OpenObject",
    "CloseObject",
    "PickupObject",
    "PutObject",
    "PutObjectInReceptacleObject",
    "HeatObject",
    "CoolObject",
    "CleanObject",
    "ToggleObjectOn",
    "ToggleObjectOff",
    "SliceObject",
)


def _balanced(text: str) -> bool:
    depth = 0
    for line in text.splitlines():
        for ch in line.split(";", 1)[0]:
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if depth < 0:
                return False
    return depth == 0


def test_domain_is_the_extended_put_task_with_costs():
    text = domain_text()
    assert _balanced(text) and "(define (domain luminous)" in text
    assert ":action-costs" in text and "(total-cost)" in text
    for name in ACTIONS:
        assert f"(:action {name}\n" in text, name
    assert re.search(r"HeatObject.*?increase \(total-cost\) 5", text, re.DOTALL)


def test_alfred_escaping():
    assert (
        pddl_name("Apple|+00.46|+00.82|-02.27")
        == "Apple_bar__plus_00_dot_46_bar__plus_00_dot_82_bar__minus_02_dot_27"
    )
    assert pddl_name("Sink|+01.00|+00.90|-01.50|SinkBasin").endswith("_bar_SinkBasin")


def test_problem_lists_types_compatibility_states_and_goal():
    apple, fridge, counter = (
        "Apple|+00.46|+00.82|+02.27",
        "Fridge|-01.00|+00.00|+01.00",
        "CounterTop|+00.00|+00.90|+00.00",
    )
    state = WorldState.of(
        [
            ObjectState(counter, "CounterTop"),
            ObjectState(fridge, "Fridge", isOpen=True),
            ObjectState(apple, "Apple", parent=counter),
        ]
    )
    goal = goal_for(
        PddlParams("Apple", "Fridge"), "pick_cool_then_place_in_recep", closed_receptacles=True
    )
    text = to_pddl_problem(state, goal, "apple_cool")
    assert _balanced(text) and "(define (problem apple_cool)" in text
    a, f = pddl_name(apple), pddl_name(fridge)
    assert f"{a} - item" in text and f"{f} - receptacle" in text
    assert f"(objectType {a} AppleType)" in text and f"(receptacleType {f} FridgeType)" in text
    assert (
        "(canContain FridgeType AppleType)" in text
        and "(canContain CounterTopType AppleType)" in text
    )
    assert f"(opened {f})" in text and f"(openable {f})" in text and f"(gating {f})" in text
    assert f"(inReceptacle {a} {pddl_name(counter)})" in text
    assert f"(objectAtLocation {a} loc_{pddl_name(counter)})" in text
    assert "(atLocation agent0 loc_start)" in text and "(:metric minimize (total-cost))" in text
    goal_text = text.split("(:goal", 1)[1]
    assert "(isCool ?o)" in goal_text and "(objectType ?o AppleType)" in goal_text
    assert "(not (opened ?c))" in goal_text


def test_named_sliceable_object_stands_for_its_slices():
    text = to_pddl_problem(
        kitchen(),
        parse_expr("(inReceptacle apple plate)"),
        names={"apple": "Apple|1", "plate": "Plate|1"},
    )
    assert "(sliceOf Apple_bar_1_bar_AppleSliced_1 Apple_bar_1)" in text
    assert "(removed Apple_bar_1_bar_AppleSliced_1)" in text
    assert (
        "(inReceptacleObject Apple_bar_1_bar_AppleSliced_6 Plate_bar_1)"
        in text.split("(:goal", 1)[1]
    )


FD_CASES = [
    ("pick_heat_then_place_in_recep", PddlParams("Potato", "CounterTop"), kitchen),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Apple", "DiningTable", mrecep_target="Plate"),
        kitchen,
    ),
    (
        "pick_cool_then_place_in_recep",
        PddlParams("Apple", "CounterTop", object_sliced=True),
        kitchen,
    ),
    ("look_at_obj_in_light", PddlParams("CD", toggle_target="DeskLamp"), bedroom),
]


@pytest.mark.parametrize("case", FD_CASES, ids=[c[0] for c in FD_CASES])
def test_fast_downward_backend_plans_replay(case):
    pytest.importorskip("up_fast_downward", reason="the 'fd' backend needs up-fast-downward")
    task, params, scene = case
    state = scene()
    goal = goal_for(params, task, closed_receptacles=True)
    plan = solve(state, goal, backend="fd", timeout=120)
    assert plan.backend == "fd"
    assert_solves(state, goal, plan)
