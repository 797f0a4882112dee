"""Goals that cannot be reached raise PlanningError at once, saying why."""

from __future__ import annotations

import time

import pytest

from luminous_sim.cdf.predicates import parse_expr
from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic import solve
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import goal_for
from tests.planning.scenes import bedroom, kitchen


@pytest.mark.parametrize(
    ("state", "goal", "names", "message"),
    [
        (
            bedroom(),
            "(exists (?o - Mug) (isHot ?o))",
            {},
            "no Microwave in the scene: cannot make Mug|1 hot",
        ),
        (
            kitchen(drop=("Fridge|1", "Apple|3", "Egg|1")),
            "(isCool apple)",
            {"apple": "Apple|1"},
            "no Fridge",
        ),
        (
            kitchen(drop=("SinkBasin|1",)),
            "(isClean mug)",
            {"mug": "Mug|1"},
            "no SinkBasin with a Faucet",
        ),
        (
            kitchen(drop=("Knife|1",)),
            "(isSliced apple)",
            {"apple": "Apple|1"},
            "no Knife or ButterKnife",
        ),
        (kitchen(), "(inReceptacle pot mug)", {"pot": "Pot|1", "mug": "Mug|1"}, "cannot be put in"),
        (
            kitchen(),
            "(isDirty plate)",
            {"plate": "DishSponge|1"},
            "nothing makes DishSponge|1 dirty",
        ),
        (kitchen(), "(isSliced mug)", {"mug": "Mug|1"}, "cannot be sliced"),
        (
            kitchen(changes={"Apple|1": {"isSliced": True}}),
            "(not (isSliced apple))",
            {"apple": "Apple|1"},
            "cannot be undone",
        ),
        (kitchen(), "(holds counter)", {"counter": "CounterTop|1"}, "cannot be picked up"),
        (bedroom(), "(exists (?f - Fridge) (isOpen ?f))", {}, "no binding"),
    ],
)
def test_unreachable_goal_raises_with_the_reason(state, goal, names, message):
    t0 = time.perf_counter()
    with pytest.raises(PlanningError, match=message.replace("|", r"\|")):
        solve(state, parse_expr(goal), names)
    assert time.perf_counter() - t0 < 1.0


def test_pick_two_with_a_single_instance_is_refused():
    state = kitchen(drop=("Apple|2", "Apple|3"))
    with pytest.raises(PlanningError, match="cannot be reached"):
        solve(state, goal_for(PddlParams("Apple", "GarbageCan"), "pick_two_obj_and_place"))


def test_unknown_name_and_unknown_backend():
    with pytest.raises(PlanningError, match="neither a mapped name"):
        solve(kitchen(), parse_expr("(isHot banana)"))
    with pytest.raises(PlanningError, match="unknown planner backend"):
        solve(kitchen(), parse_expr("(isHot apple)"), {"apple": "Apple|1"}, backend="ff")


def test_budget_exhaustion_is_a_planning_error():
    goal = parse_expr(
        "(forall (?a - Apple) (and (isHot ?a) (isCool ?a) (isClean ?a) (inReceptacle ?a table)))"
    )
    with pytest.raises(PlanningError, match="budget"):
        solve(kitchen(), goal, {"table": "DiningTable|1"}, max_expansions=3)


def test_a_forbidden_receptacle_that_is_the_only_one_is_refused_at_once():
    """The oracle forbids a receptacle that turned out full; with no other of its type the planner
    must say so at once, not search until its budget runs out."""
    from luminous_sim.cdf.predicates import Atom, Not
    from luminous_sim.planning.oracle import with_forbidden

    goal = goal_for(PddlParams("KeyChain", "Shelf", mrecep_target="Box"), "pick_and_place_with_movable_recep")
    forbidden = with_forbidden(goal, [Not(Atom("inReceptacle", ("Box|1", "Shelf|1")))])
    t0 = time.perf_counter()
    with pytest.raises(PlanningError, match=r"and its negation|no binding"):
        solve(bedroom(), forbidden)
    assert time.perf_counter() - t0 < 1.0
    solve(bedroom(), goal)  # without the forbidden pair it is solvable


def test_with_forbidden_keeps_the_goal_equivalent():
    from luminous_sim.cdf.predicates import And, Atom, Exists, Not, to_sexpr
    from luminous_sim.planning.oracle import with_forbidden

    goal = goal_for(PddlParams("Apple", "Fridge"), "pick_and_place_simple")
    ban = Not(Atom("inReceptacle", ("Apple|1", "Fridge|1")))
    assert with_forbidden(goal, []) is goal
    pushed = with_forbidden(goal, [ban])
    assert isinstance(pushed, Exists) and ban in pushed.body.args
    wrapped = with_forbidden(And((Atom("isOpen", ("Fridge|1",)), goal)), [ban])
    assert isinstance(wrapped.args[1], Exists) and ban in wrapped.args[1].body.args
    assert to_sexpr(with_forbidden(Atom("isOpen", ("Fridge|1",)), [ban])).startswith("(and")
    state = kitchen()
    plan = solve(state, pushed)
    assert "Fridge|1" not in {a.args.get("receptacleObjectId") for a in plan.actions if a.action == "PutObject"} \
        or len(state.of_type("Apple")) > 1
