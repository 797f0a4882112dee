"""Against ALFRED's own valid_seen trajectories (skipped where the data is absent)."""

from __future__ import annotations

import json

import numpy as np

from luminous_sim.language.names import plural, spoken
from luminous_sim.states import WorldState
from luminous_sim.tasks import (
    TEMPLATES,
    PddlParams,
    TaskInstance,
    goal_for,
    params_problems,
    task_description,
)


def _trajectories(root):
    for path in sorted((root / "valid_seen").glob("*/*/traj_data.json")):
        yield path.parts[-3], json.loads(path.read_text())


def test_every_alfred_task_round_trips_and_meets_our_constraints(shared_alfred):
    seen = set()
    for task_dir, traj in _trajectories(shared_alfred):
        params = PddlParams.from_json(traj["pddl_params"])
        assert params.to_json() == traj["pddl_params"], task_dir
        assert params_problems(traj["task_type"], params) == [], task_dir
        ttype, obj, mrecep, last = task_dir.split("-")[:4]
        assert (ttype, obj, mrecep) == (
            traj["task_type"],
            params.object_type,
            params.mrecep_target or "None",
        )
        assert last == (params.parent_target or params.toggle_target)
        task = TaskInstance(ttype, params, goal_for(params, ttype), 0)
        assert task.goal_key in TEMPLATES
        desc = task_description(task, np.random.default_rng(0))
        assert spoken(params.object_target) in desc or plural(params.object_target) in desc
        seen.add(task.goal_key)
    assert len(seen) >= 12  # all seven types, and sliced variants of most


SPEC_TOTALS = {  # spec/alfred.md section 1.2: total conditions `ts`, and what a sliced task adds
    "pick_and_place_simple": (1, 1),
    "pick_two_obj_and_place": (2, 2),
    "look_at_obj_in_light": (2, 1),
    "pick_clean_then_place_in_recep": (3, 1),
    "pick_heat_then_place_in_recep": (3, 1),
    "pick_cool_then_place_in_recep": (3, 1),
    "pick_and_place_with_movable_recep": (3, 1),
}


def test_every_alfred_task_compiles_to_alfreds_number_of_goal_conditions(shared_alfred):
    """The counts come from each real task's goal conjuncts and give ALFRED's totals."""
    empty = WorldState.of([])
    n = 0
    for task_dir, traj in _trajectories(shared_alfred):
        params = PddlParams.from_json(traj["pddl_params"])
        task = TaskInstance(traj["task_type"], params, goal_for(params, traj["task_type"]), 0)
        base, sliced = SPEC_TOTALS[task.task_type]
        expected = base + (sliced if params.object_sliced else 0)
        assert task.conditions().alfred_counts(empty) == (0, expected), task_dir
        n += 1
    assert n == 251
