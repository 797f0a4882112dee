"""Arbitrary CDF goals: conjunctions, disjunctions, negation, quantifiers, named objects."""

from __future__ import annotations

from luminous_sim.cdf.predicates import parse_expr
from luminous_sim.planning.symbolic import solve
from luminous_sim.states import ObjectState
from tests.planning.helpers import assert_solves, shape
from tests.planning.scenes import bedroom, kitchen

KITCHEN_NAMES = {
    "apple": "Apple|1",
    "egg": "Egg|1",
    "fridge": "Fridge|1",
    "drawer": "Drawer|1",
    "mug": "Mug|1",
    "table": "DiningTable|1",
    "potato": "Potato|1",
    "plate": "Plate|1",
    "knife": "Knife|1",
    "bread": "Bread|1",
}


def _solve(state, text, names=KITCHEN_NAMES, **kw):
    goal = parse_expr(text)
    plan = solve(state, goal, names, **kw)
    return plan, assert_solves(state, goal, plan, names)


def test_two_conjunctive_goals():
    plan, final = _solve(kitchen(), "(and (inReceptacle apple fridge) (isHot potato))")
    assert final["Apple|1"].parent == "Fridge|1" and "Potato|1" in final.heated
    assert shape(plan).count("HeatObject") == 1


def test_disjunction_takes_one_branch():
    plan, final = _solve(kitchen(), "(or (isHot egg) (inReceptacle mug table))")
    assert shape(plan, gotos=False) == ["PickupObject", "PutObject"]  # the cheaper branch
    assert final["Mug|1"].parent == "DiningTable|1"


def test_forall_apples_into_the_fridge():
    plan, final = _solve(kitchen(), "(forall (?a - Apple) (inReceptacle ?a fridge))")
    assert all(final[a].parent == "Fridge|1" for a in ("Apple|1", "Apple|2", "Apple|3"))
    assert shape(plan, gotos=False).count("PutObject") == 2  # Apple|3 is already there


def test_forall_with_everything_closed_closes_the_fridge_at_the_end():
    plan, final = _solve(
        kitchen(), "(forall (?a - Apple) (inReceptacle ?a fridge))", close_receptacles=True
    )
    assert not final["Fridge|1"].isOpen and plan.actions[-1].action == "CloseObject"


def test_negation_takes_the_egg_out_of_the_fridge():
    plan, final = _solve(kitchen(), "(not (inReceptacle egg fridge))")
    assert final["Egg|1"].parent != "Fridge|1"
    assert shape(plan, gotos=False)[:2] == ["OpenObject", "PickupObject"]


def test_exists_clean_mug_other_than_the_named_one():
    _, final = _solve(
        kitchen(), "(exists (?m - Mug) (and (not (= ?m mug)) (isClean ?m) (not (isDirty ?m))))"
    )
    assert "Mug|2" in final.cleaned and not final["Mug|2"].isDirty


def test_open_and_hold_and_switch_on():
    _, final = _solve(kitchen(), "(and (isOpen drawer) (holds knife))")
    assert final["Drawer|1"].isOpen and final.held == "Knife|1"
    _, final = _solve(bedroom(), "(exists (?l - DeskLamp) (isToggled ?l))", names={})
    assert final["DeskLamp|1"].isToggled


def test_slicing_a_named_object_and_placing_its_slices():
    goal = "(and (isSliced apple) (inReceptacle apple plate))"
    _, final = _solve(kitchen(), goal)
    assert any(
        k.startswith("Apple|1|AppleSliced") and final[k].parent == "Plate|1" for k in final.objects
    )


def test_only_the_slices_fit_the_toaster():
    state = kitchen()
    state = state.replace(
        objects={
            **state.objects,
            "Toaster|1": ObjectState("Toaster|1", "Toaster", parent="CounterTop|1"),
        }
    )
    plan, _ = _solve(
        state, "(inReceptacle bread toaster)", names={"bread": "Bread|1", "toaster": "Toaster|1"}
    )
    assert "SliceObject" in shape(plan)


def test_cool_an_object_already_in_the_fridge_by_closing_the_door():
    state = kitchen(changes={"Fridge|1": {"isOpen": True}})
    plan, final = _solve(state, "(isCool egg)")
    assert shape(plan, gotos=False) == ["CloseObject"] and "Egg|1" in final.cooled


def test_goal_already_true_gives_an_empty_plan():
    plan, _ = _solve(kitchen(), "(inReceptacle egg fridge)")
    assert plan.actions == [] and plan.cost == 0


def test_object_ids_work_without_a_name_map():
    state = kitchen()
    goal = parse_expr("(inReceptacle Apple_bar_1 fridge)")
    plan = solve(state, goal, {"Apple_bar_1": "Apple|1", "fridge": "Fridge|1"})
    assert_solves(state, goal, plan, {"Apple_bar_1": "Apple|1", "fridge": "Fridge|1"})
