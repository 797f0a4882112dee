"""Against ALFRED's own valid_seen trajectories (skipped where the data is absent)."""

from __future__ import annotations

import json

import numpy as np

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
        assert params.object_target.lower() in desc
        seen.add(task.goal_key)
    assert len(seen) >= 12  # all seven types, and sliced variants of most
