"""The oracle solves a sampled task of every ALFRED task type in a small generated room (in the
style of Minigrid's bot test), and the same seed gives the same low-level trajectory.

The room is the first room type the task type allows in alphabetical order (Bathroom and Bedroom,
which hold the fewest objects, come first); the scene and episode seed is the first seed, 0.
Neither is chosen to make a type pass: every type must pass on this first seed.
"""

from __future__ import annotations

from typing import Any

import pytest

from luminous_sim.data import scene_for_task
from luminous_sim.episode import EpisodeResult, run_episode
from luminous_sim.planning.trajectory import Trajectory
from luminous_sim.tasks import TASK_TYPES, task_info

SEED = 0


def _room(task_type: str) -> str:
    return min(task_info(task_type).rooms)


def _episode(task_type: str) -> tuple[EpisodeResult, Trajectory]:
    scene = scene_for_task(task_type, _room(task_type), SEED)
    result, record = run_episode(scene, task_type, seed=SEED, record_frames=False, extra_annotations=0)
    return result, record.trajectory


def _low_actions(traj: Trajectory) -> list[dict[str, Any]]:
    return [a["api_action"] for a in traj.low_actions]


@pytest.mark.parametrize("task_type", TASK_TYPES)
def test_oracle_solves_a_sampled_task_and_replays(task_type: str) -> None:
    result, traj = _episode(task_type)
    done, total = result.goal_conditions
    assert result.success, f"{task_type} in a {_room(task_type)}: {result.goal}: {traj.failures}"
    assert total > 0 and done == total, (result.goal, result.goal_conditions)
    assert result.low_actions == len(traj.low_actions) > 0
    repeat, again = _episode(task_type)
    assert repeat.goal == result.goal and _low_actions(again) == _low_actions(traj)
