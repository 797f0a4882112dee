"""Given a task, ask CSSG for a scene that supports it (slow: runs the generator)."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.tasks import (
    cdf_for_task,
    feasible_params,
    goal_conditions,
    names_from_scene,
    sample_task,
    state_from_scene,
    task_from_cdf,
)
from tests.tasks.test_cdf_bridge import IDS, TASKS

pytestmark = pytest.mark.slow

CASES = TASKS


@pytest.mark.parametrize(("task_type", "params", "room"), CASES, ids=IDS)
def test_generated_scene_supports_the_task(task_type, params, room):
    from luminous_sim.cssg import generate

    doc = cdf_for_task(task_type, params, room)
    scene = generate(doc, seed=1).scene
    state = state_from_scene(scene)
    assert params in feasible_params(scene, state, task_type)
    task = task_from_cdf(doc, names_from_scene(scene), scene.seed)
    done, total = goal_conditions(task, state)
    assert done < total
    assert sample_task(scene, state, task_type, np.random.default_rng(0)).task_type == task_type
