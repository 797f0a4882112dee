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
from luminous_sim.tasks.types import TASK_TYPES


def _task(task_type: str, params: PddlParams) -> TaskInstance:
    return TaskInstance(task_type, params, goal_for(params, task_type), 0)


def test_every_goal_key_has_templates():
    assert set(TEMPLATES) == set(TASK_TYPES) | {t + "_slice" for t in TASK_TYPES}


def test_templates_are_filled_with_lower_cased_types_and_drawn_uniformly():
    t = _task("pick_and_place_simple", PddlParams("SprayBottle", "GarbageCan"))
    rng = np.random.default_rng(0)
    seen = [task_description(t, rng) for _ in range(200)]
    assert set(seen) == {"put a spraybottle in garbagecan", "put some spraybottle on garbagecan"}
    assert 70 < seen.count("put a spraybottle in garbagecan") < 130


@pytest.mark.parametrize(
    ("task_type", "params", "options"),
    [
        (
            "pick_heat_then_place_in_recep",
            PddlParams("Apple", "CounterTop", object_sliced=True),
            {
                "put a hot slice of apple in countertop",
                "heat some sliced apple and put it in countertop",
            },
        ),
        (
            "look_at_obj_in_light",
            PddlParams("Book", toggle_target="DeskLamp"),
            {"look at book under the desklamp", "examine the book with the desklamp"},
        ),
        (
            "pick_and_place_with_movable_recep",
            PddlParams("Pencil", "Shelf", mrecep_target="Mug"),
            {
                "put pencil in a mug and then put them in shelf",
                "put a mug of pencil in shelf",
                "put pencil mug in shelf",
            },
        ),
        (
            "pick_two_obj_and_place",
            PddlParams("KeyChain", "Sofa"),
            {"put two keychain in sofa", "find two keychain and put them in sofa"},
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
        == "heat the apple and put the apple in the dining table"
    )
    goal = parse_expr("(exists (?o - Mug) (isClean ?o))")
    t = TaskInstance("custom", PddlParams(""), goal, 0, custom=True)
    assert task_description(t, np.random.default_rng(0)) == "clean the mug"


def test_unknown_goal_key():
    t = TaskInstance("pick_and_dance", PddlParams("Apple"), parse_expr("(holds a)"), 0)
    with pytest.raises(TaskError, match="no goal templates"):
        task_description(t, np.random.default_rng(0))
