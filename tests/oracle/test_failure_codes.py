"""Planning failures carry codes, and the episode redraws a task by code, not by message."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.errors import FailureCode, PlanningError
from luminous_sim.planning import Oracle
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import goal_for
from luminous_sim.world import AgentPose
from tests.world.conftest import obj


def test_a_goal_the_planner_proves_impossible(world):
    traj = Oracle(world, record_frames=False).run(goal_for(PddlParams("Apple", "Toilet"), "pick_and_place_simple"))
    assert not traj.success and traj.failure_code == FailureCode.GOAL_UNREACHABLE
    assert traj.failure_codes == [FailureCode.GOAL_UNREACHABLE] and "cannot be reached" in traj.failure


def test_a_search_out_of_budget(world):
    from luminous_sim.planning.symbolic import solve

    goal = goal_for(PddlParams("Apple", "Microwave"), "pick_heat_then_place_in_recep")
    with pytest.raises(PlanningError) as failed:
        solve(world.view().state, goal, max_expansions=1)
    assert failed.value.code == FailureCode.PLAN_BUDGET


def test_a_planning_error_without_a_code_means_no_plan():
    assert PlanningError("the plan does not reach the goal").code == FailureCode.NO_PLAN


def test_an_object_no_pose_can_see(world, kitchen_scene):
    apple = obj(kitchen_scene, "apple")
    body = world.built.objects[apple].body
    _, orn = world.client.getBasePositionAndOrientation(body)
    far = world.nav.points().max(axis=0) + 3.0  # beyond the room, out of every pose's reach
    world.client.resetBasePositionAndOrientation(body, (float(far[0]), float(far[1]), 0.9), orn)
    traj = Oracle(world, record_frames=False, max_replans=0).run(
        goal_for(PddlParams("Apple", "Microwave"), "pick_and_place_simple"))
    assert not traj.success and traj.failure_codes[0] == FailureCode.NO_POSE and traj.unreachable == [apple]


def test_a_pose_off_the_navigation_graph(world, kitchen_scene, monkeypatch):
    oracle = Oracle(world, record_frames=False, max_replans=0)
    monkeypatch.setattr(type(oracle.view), "interaction_pose", lambda self, *a, **k: AgentPose(99.0, 99.0, 0, 30))
    traj = oracle.run(goal_for(PddlParams("Apple", "Microwave"), "pick_and_place_simple"))
    assert not traj.success and traj.failure_codes[0] == FailureCode.NO_PATH


def test_the_episode_redraws_by_code():
    from luminous_sim.episode import REDRAW_ON

    assert all(isinstance(c, FailureCode) for c in REDRAW_ON)
    assert {FailureCode.RECEPTACLE_FULL, FailureCode.NO_POSE, FailureCode.GOAL_UNREACHABLE} <= REDRAW_ON
    assert FailureCode.NO_SPOT_IN_REACH not in REDRAW_ON  # room elsewhere, out of reach from one pose: kept


def test_every_failure_of_an_oracle_run_has_a_code(world, kitchen_scene):
    traj = Oracle(world, record_frames=False).run(goal_for(PddlParams("Apple", "Fridge"), "pick_and_place_simple"))
    assert traj.success and traj.failure_code is None
    assert len(traj.failure_codes) == len(traj.failures)
    assert np.all([isinstance(c, FailureCode) for c in traj.failure_codes])
