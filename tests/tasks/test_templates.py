"""ALFRED's templated goal descriptions."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.cdf import parse_expr
from luminous_sim.tasks import (
    TEMPLATES,
    PddlParams,
    TaskError,
    TaskInstance,
    goal_for,
    task_description,
)
from luminous_sim.tasks.templates import ALFRED_TEMPLATES, alfred_description
from luminous_sim.tasks.types import TASK_TYPES


def _task(task_type: str, params: PddlParams) -> TaskInstance:
    return TaskInstance(task_type, params, goal_for(params, task_type), 0)


def test_every_goal_key_has_templates_one_for_one_with_alfreds():
    assert set(TEMPLATES) == set(TASK_TYPES) | {t + "_slice" for t in TASK_TYPES} == set(ALFRED_TEMPLATES)
    assert all(len(TEMPLATES[k]) == len(ALFRED_TEMPLATES[k]) for k in TEMPLATES)


def test_templates_are_filled_with_names_in_words_and_drawn_uniformly():
    t = _task("pick_and_place_simple", PddlParams("SprayBottle", "GarbageCan"))
    rng = np.random.default_rng(0)
    seen = [task_description(t, rng) for _ in range(200)]
    assert set(seen) == {"put a spray bottle in the garbage can", "place a spray bottle in the garbage can"}
    assert 70 < seen.count("put a spray bottle in the garbage can") < 130


def test_alfreds_own_templates_are_filled_with_lower_cased_types():
    t = _task("pick_and_place_simple", PddlParams("SprayBottle", "GarbageCan"))
    rng = np.random.default_rng(0)
    seen = {alfred_description(t, rng) for _ in range(60)}
    assert seen == {"put a spraybottle in garbagecan", "put some spraybottle on garbagecan"}


@pytest.mark.parametrize(
    ("task_type", "params", "options"),
    [
        (
            "pick_heat_then_place_in_recep",
            PddlParams("Apple", "CounterTop", object_sliced=True),
            {
                "put a hot slice of apple on the counter",
                "heat a slice of apple and put it on the counter",
            },
        ),
        (
            "look_at_obj_in_light",
            PddlParams("Book", toggle_target="DeskLamp"),
            {"look at a book under the desk lamp", "examine the book by the light of the desk lamp"},
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Pencil", "Shelf", mrecep_target="Mug"),
            {
                "put a pencil in a mug and then put the mug on the shelf",
                "put a mug holding a pencil on the shelf",
                "carry a pencil in a mug to the shelf",
            },
        ),
        (
            "pick_two_obj_and_place",
            PddlParams("KeyChain", "Sofa"),
            {"put two key chains on the sofa", "find two key chains and put them on the sofa"},
        ),
    ],
)
def test_template_filling(task_type, params, options):
    rng = np.random.default_rng(1)
    seen = {task_description(_task(task_type, params), rng) for _ in range(60)}
    assert seen == options


def test_same_seed_same_description():
    t = _task(
        "pick_and_place_with_movable_recep", PddlParams("Pencil", "Shelf", mrecep_target="Mug")
    )
    a = [task_description(t, np.random.default_rng(5)) for _ in range(3)]
    assert len(set(a)) == 1


def test_custom_goals_are_read_out():
    goal = parse_expr("(and (isHot apple) (inReceptacle apple dining_table) (not (isOpen fridge)))")
    t = TaskInstance("custom", PddlParams(""), goal, 0, custom=True)
    assert (
        task_description(t, np.random.default_rng(0))
        == "heat the apple and put the apple on the dining table"
    )
    goal = parse_expr("(exists (?o - Mug) (isClean ?o))")
    t = TaskInstance("custom", PddlParams(""), goal, 0, custom=True)
    assert task_description(t, np.random.default_rng(0)) == "clean the mug"
    goal = parse_expr("(exists (?o - DishSponge) (inReceptacle ?o fridge))")
    t = TaskInstance("custom", PddlParams(""), goal, 0, custom=True)
    assert task_description(t, np.random.default_rng(0)) == "put the dish sponge in the fridge"


def test_unknown_goal_key():
    t = TaskInstance("pick_and_dance", PddlParams("Apple"), parse_expr("(holds a)"), 0)
    with pytest.raises(TaskError, match="no goal templates"):
        task_description(t, np.random.default_rng(0))
