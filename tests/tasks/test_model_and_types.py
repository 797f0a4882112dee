"""PddlParams / TaskInstance values, the task-type table and the goals it builds."""

from __future__ import annotations

import json
from dataclasses import FrozenInstanceError

import pytest

from luminous_sim.cdf import parse_expr, to_sexpr
from luminous_sim.tasks import (
    TASK_TYPES,
    PddlParams,
    TaskError,
    TaskInstance,
    closed_receptacles_goal,
    goal_for,
    goal_satisfied,
    params_problems,
)
from luminous_sim.vocab import ALFRED_TASK_ROOMS
from tests.tasks.helpers import KITCHEN, state_of


def test_pddl_params_json_is_alfreds_dict():
    p = PddlParams("Apple", "CounterTop", object_sliced=True)
    assert p.to_json() == {
        "mrecep_target": "",
        "object_sliced": True,
        "object_target": "Apple",
        "parent_target": "CounterTop",
        "toggle_target": "",
    }
    assert list(p.to_json()) == sorted(p.to_json())  # ALFRED's files have sorted keys
    assert PddlParams.from_json(p.to_json()) == p
    assert p.object_type == "AppleSliced"
    with pytest.raises(FrozenInstanceError):
        p.object_target = "Mug"  # type: ignore[misc]


def test_from_json_folds_a_sliced_type_and_rejects_junk():
    assert PddlParams.from_json({"object_target": "AppleSliced"}) == PddlParams(
        "Apple", object_sliced=True
    )
    with pytest.raises(TaskError, match="unknown key"):
        PddlParams.from_json({"object_target": "Apple", "colour": "red"})
    with pytest.raises(TaskError, match="object_sliced"):
        PddlParams.from_json({"object_target": "Apple", "object_sliced": "yes"})


def test_task_instance_goal_key_and_round_trip():
    p = PddlParams("Potato", "GarbageCan", object_sliced=True)
    t = TaskInstance(
        "pick_heat_then_place_in_recep",
        p,
        goal_for(p, "pick_heat_then_place_in_recep"),
        3,
        "put a hot slice of potato in garbagecan",
    )
    assert t.goal_key == "pick_heat_then_place_in_recep_slice"
    d = t.to_dict()
    assert json.loads(json.dumps(d)) == d
    assert d["pddl_params"] == p.to_json() and d["goal_key"] == t.goal_key
    assert TaskInstance.from_dict(d) == t
    assert hash(t) == hash(TaskInstance.from_dict(d))
    plain = TaskInstance("pick_and_place_simple", PddlParams("Apple", "Fridge"), t.goal, 0)
    assert plain.goal_key == "pick_and_place_simple"
    with pytest.raises(TaskError, match="missing key 'goal'"):
        TaskInstance.from_dict({k: v for k, v in d.items() if k != "goal"})


def test_task_types_table_matches_alfred():
    assert list(TASK_TYPES) == [
        "pick_and_place_simple",
        "pick_two_obj_and_place",
        "look_at_obj_in_light",
        "pick_clean_then_place_in_recep",
        "pick_heat_then_place_in_recep",
        "pick_cool_then_place_in_recep",
        "pick_and_place_with_movable_recep",
    ]
    everywhere = {"Kitchen", "LivingRoom", "Bedroom", "Bathroom"}
    assert {k: v.rooms for k, v in TASK_TYPES.items()} == {  # ALFRED's table (spec section 1)
        "pick_and_place_simple": everywhere, "pick_two_obj_and_place": everywhere,
        "look_at_obj_in_light": {"LivingRoom", "Bedroom"}, "pick_clean_then_place_in_recep": {"Kitchen", "Bathroom"},
        "pick_heat_then_place_in_recep": {"Kitchen"}, "pick_cool_then_place_in_recep": {"Kitchen"},
        "pick_and_place_with_movable_recep": {"Kitchen", "LivingRoom", "Bedroom"},
    }
    assert ALFRED_TASK_ROOMS == {k: v.rooms for k, v in TASK_TYPES.items()}  # one table, read by the CDF checker
    assert [k for k, v in TASK_TYPES.items() if not v.sliced] == ["look_at_obj_in_light"]


GOALS = {
    (
        "pick_and_place_simple",
        PddlParams("Apple", "Fridge"),
    ): "(exists (?o - Apple ?r - Fridge) (and (inReceptacle ?o ?r)))",
    (
        "pick_and_place_simple",
        PddlParams("Apple", "Fridge", object_sliced=True),
    ): "(exists (?o - AppleSliced ?r - Fridge) (and (inReceptacle ?o ?r) (isSliced ?o)))",
    (
        "pick_two_obj_and_place",
        PddlParams("Mug", "Cabinet"),
    ): "(exists (?r - Cabinet ?o1 - Mug ?o2 - Mug) (and (not (= ?o1 ?o2)) (inReceptacle ?o1 ?r) "
    "(inReceptacle ?o2 ?r)))",
    (
        "pick_two_obj_and_place",
        PddlParams("Bread", "Fridge", object_sliced=True),
    ): "(exists (?r - Fridge ?o1 - BreadSliced ?o2 - BreadSliced) (and (not (= ?o1 ?o2)) "
    "(inReceptacle ?o1 ?r) (inReceptacle ?o2 ?r) (isSliced ?o1) (isSliced ?o2)))",
    (
        "look_at_obj_in_light",
        PddlParams("Book", toggle_target="DeskLamp"),
    ): "(exists (?t - DeskLamp ?o - Book) (and (isToggled ?t) (holds ?o)))",
    (
        "pick_clean_then_place_in_recep",
        PddlParams("Mug", "Cabinet"),
    ): "(exists (?o - Mug ?r - Cabinet) (and (isClean ?o) (inReceptacle ?o ?r)))",
    (
        "pick_heat_then_place_in_recep",
        PddlParams("Egg", "DiningTable"),
    ): "(exists (?o - Egg ?r - DiningTable) (and (isHot ?o) (inReceptacle ?o ?r)))",
    (
        "pick_cool_then_place_in_recep",
        PddlParams("Tomato", "CounterTop", object_sliced=True),
    ): "(exists (?o - TomatoSliced ?r - CounterTop) (and (isCool ?o) (inReceptacle ?o ?r) (isSliced ?o)))",
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Pencil", "Shelf", mrecep_target="Mug"),
    ): "(exists (?r - Shelf ?o - Pencil ?m - Mug) (and (inReceptacleObject ?o ?m) (inReceptacle ?m ?r)))",
}


@pytest.mark.parametrize(
    ("key", "text"), GOALS.items(), ids=[k[0] + "/" + k[1].object_type for k in GOALS]
)
def test_goal_for(key, text):
    goal = goal_for(key[1], key[0])
    assert to_sexpr(goal) == text
    assert parse_expr(text) == goal
    assert params_problems(*key) == []


def test_closed_receptacles_option():
    p = PddlParams("Apple", "CounterTop")
    goal = goal_for(p, "pick_and_place_simple", closed_receptacles=True)
    assert "(forall (?c - Fridge) (not (isOpen ?c)))" in to_sexpr(goal)
    assert "Laptop" not in to_sexpr(closed_receptacles_goal())  # openable, but not a receptacle
    s = state_of(KITCHEN)
    assert goal_satisfied(goal, s)
    assert not goal_satisfied(goal, s.with_object("Cabinet|1", isOpen=True))
    assert goal_satisfied(
        goal_for(p, "pick_and_place_simple"), s.with_object("Cabinet|1", isOpen=True)
    )


def test_goal_for_errors():
    with pytest.raises(TaskError, match="unknown task type 'pick_and_dance'; expected one of"):
        goal_for(PddlParams("Apple", "Fridge"), "pick_and_dance")
    with pytest.raises(TaskError, match="needs parent_target"):
        goal_for(PddlParams("Apple"), "pick_heat_then_place_in_recep")
    with pytest.raises(TaskError, match="needs parent_target, mrecep_target"):
        goal_for(PddlParams("Apple"), "pick_and_place_with_movable_recep")


@pytest.mark.parametrize(
    ("task_type", "params", "message"),
    [
        ("pick_and_place_simple", PddlParams("Sofa", "Bed"), "not one of ALFRED's pickup types"),
        ("pick_and_place_simple", PddlParams("Apple", "Toaster"), "never a final receptacle"),
        ("pick_and_place_simple", PddlParams("Apple", "Bed"), "Bed does not accept Apple"),
        (
            "pick_and_place_simple",
            PddlParams("Mug", "Fridge", object_sliced=True),
            "a sliced task needs one of",
        ),
        ("pick_two_obj_and_place", PddlParams("Mug", "CoffeeMachine"), "may not use CoffeeMachine"),
        (
            "pick_heat_then_place_in_recep",
            PddlParams("Lettuce", "CounterTop"),
            "Lettuce is not heatable",
        ),
        (
            "pick_heat_then_place_in_recep",
            PddlParams("Apple", "Microwave"),
            "may not use its device Microwave",
        ),
        (
            "pick_cool_then_place_in_recep",
            PddlParams("Apple", "Fridge"),
            "may not use its device Fridge",
        ),
        (
            "pick_clean_then_place_in_recep",
            PddlParams("Apple", "SinkBasin"),
            "may not use its device SinkBasin",
        ),
        ("pick_clean_then_place_in_recep", PddlParams("Book", "Shelf"), "Book is not cleanable"),
        (
            "look_at_obj_in_light",
            PddlParams("Book", "Bed", toggle_target="DeskLamp"),
            "takes no parent_target",
        ),
        (
            "look_at_obj_in_light",
            PddlParams("Book", toggle_target="Microwave"),
            "toggle_target must be one of",
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Bowl", "CounterTop", mrecep_target="Plate"),
            "may not itself be a movable receptacle",
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Apple", "Plate", mrecep_target="Bowl"),
            "may not be a movable receptacle",
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Apple", "CounterTop", mrecep_target="Mug"),
            "Mug does not accept Apple",
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Pencil", "Drawer", mrecep_target="Mug"),
            "Drawer does not accept Mug",
        ),
    ],
)
def test_params_problems(task_type, params, message):
    assert any(message in m for m in params_problems(task_type, params)), params_problems(
        task_type, params
    )
