"""The v2 ids (`objectnav`, `objectnav_pickup`): ObjectNav's Stop rule, starts a minimum geodesic distance from
the success region, SPL and soft SPL (`env.navscore`), the held-out seeds in the spec, check_env and the oracle."""

from __future__ import annotations

import math

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import EnvConfig, eval_seeds
from luminous_sim.env.actions import STOP
from luminous_sim.env.alfred_env import LuminousEnv
from luminous_sim.env.kinds import goal_from_dict
from luminous_sim.env.kinds.objectnav import ObjectNavGoal, _views
from luminous_sim.env.navscore import footprint_distance, soft_spl, spl
from luminous_sim.env.registration import read_spec
from luminous_sim.errors import LuminousError
from luminous_sim.world.agent import GRID

NAV, PICK = "Luminous-ObjectNav-64-v2", "Luminous-PickUp-64-v2"
SEEDS = (0, 1, 2)
MIN_START = 2.0


@pytest.fixture(scope="module")
def envs():
    made = {i: gymnasium.make(i).unwrapped for i in (NAV, PICK)}
    yield made
    for env in made.values():
        env.close()


def _oracle_episode(env: LuminousEnv, seed: int) -> tuple[dict, dict, int]:
    _, start = env.reset(seed=seed)
    for n in range(1, env.config.max_steps + 1):
        _, _, terminated, truncated, info = env.step(env.expert_action())
        if terminated or truncated:
            return start, info, n
    raise AssertionError("the episode did not end")


def test_the_v2_ids_fix_their_parameters_and_held_out_seeds_in_the_spec():
    for env_id in (NAV, PICK, "Luminous-ObjectNav-96-v2"):
        spec = gymnasium.spec(env_id)
        config = EnvConfig.from_kwargs(spec.kwargs)
        assert config.task_options["min_start_distance"] == MIN_START and config.max_steps == config.max_failures == 200
        assert eval_seeds(env_id) == tuple(range(1_000_000, 1_000_500))
    assert gymnasium.spec(NAV).kwargs["task_options"]["success_distance"] == 1.0
    assert gymnasium.spec("Luminous-NavToObject-64-v1") and eval_seeds("Luminous-NavToObject-64-v1") == ()
    head = '[family]\nentry_point = "luminous_sim.env.alfred_env:LuminousEnv"\n[[env]]\nid = "X-v0"\n'
    with pytest.raises(LuminousError, match="eval"):
        read_spec(head + "eval = { first_seed = 3 }\n", "x.toml")
    with pytest.raises(LuminousError, match="task_options"):
        EnvConfig(task_types=("goto_object",), task_options={"success_distance": 1.0})


@pytest.mark.parametrize("env_id", [NAV, PICK])
def test_check_env_is_clean(env_id):
    env = gymnasium.make(env_id)
    try:
        check_env(env.unwrapped, skip_render_check=True)
    finally:
        env.close()


@pytest.mark.slow
def test_check_env_is_clean_at_96():
    env = gymnasium.make("Luminous-ObjectNav-96-v2")
    try:
        check_env(env.unwrapped, skip_render_check=True)
    finally:
        env.close()


@pytest.mark.parametrize("env_id", [NAV, PICK])
def test_the_oracle_succeeds_from_a_start_at_least_the_minimum_distance_away(envs, env_id):
    env = envs[env_id]
    for seed in SEEDS:
        start, end, steps = _oracle_episode(env, seed)
        assert start["shortest_path_length"] >= MIN_START and start["start_distance"] >= start["shortest_path_length"]
        assert start["target_instances"] >= 1 and start["distractor_types"] >= 3
        assert end["success"] and end["distance_to_goal"] == 0.0
        assert end["path_length"] >= start["shortest_path_length"]
        assert 0 < end["spl"] <= 1 and end["soft_spl"] == pytest.approx(end["spl"])
        if env_id == NAV:  # ObjectNav's oracle walks the shortest path to the nearest view, and its plan ends with Stop
            assert end["spl"] == 1.0 and end["path_length"] == start["shortest_path_length"]
            assert env.history[-1].api["action"] != STOP and steps == len(env.history) + 1


def test_stop_where_the_target_is_not_in_view_fails_and_ends_the_episode(envs):
    env = envs[NAV]
    _, start = env.reset(seed=SEEDS[0])
    _, _, terminated, truncated, info = env.step(env.actions.index(STOP))
    assert terminated and not truncated and not info["success"]
    assert info["spl"] == 0.0 and info["soft_spl"] == 0.0 and info["path_length"] == 0.0
    assert info["distance_to_goal"] == start["shortest_path_length"]


def test_stop_with_the_target_in_view_beyond_the_success_distance_fails(envs):
    env = envs[NAV]
    for seed in SEEDS:
        env.reset(seed=seed)
        goal = env.episode.goal
        assert isinstance(goal, ObjectNavGoal)
        world = env.world
        view = world.view()
        found = None
        for oid in goal.instances(view):
            box = view.aabb(oid)
            keys = sorted(k for k in view.nav.keys
                          if 1.25 < footprint_distance(_pose(k), box) <= view.config.visibility_distance)
            for key in keys:
                for _, pose in _views(view, oid, key):
                    world.step(pose.to_alfred())  # the test puts the agent there (agents cannot teleport)
                    if oid in world.visible_objects():
                        found = oid
                        break
                if found:
                    break
            if found:
                break
        if found is None:
            continue
        assert footprint_distance(world.agent, view.aabb(found)) > goal.success_distance
        _, _, terminated, _, info = env.step(env.actions.index(STOP))
        assert terminated and not info["success"] and info["spl"] == 0.0
        return
    pytest.fail("no seed has a view of the target from beyond the success distance")


def _pose(key):
    from luminous_sim.world import AgentPose

    return AgentPose(key[0] * GRID, key[1] * GRID)


def test_being_in_view_within_the_distance_without_stop_is_not_success(envs):
    env = envs[NAV]
    env.reset(seed=SEEDS[1])
    plan = env.episode.expert.actions
    for api in plan:
        _, _, terminated, _, info = env.step(env.action_for(api))
        assert not terminated and not info["success"]
    assert info["goal_conditions"] == (1, 1)  # the view is there, the Stop is not
    _, _, terminated, _, info = env.step(env.actions.index(STOP))
    assert terminated and info["success"] and info["spl"] == 1.0


def test_spl_and_soft_spl_follow_their_definitions():
    assert spl(True, 2.0, 2.0) == 1.0 and spl(True, 2.0, 4.0) == 0.5 and spl(False, 2.0, 2.0) == 0.0
    assert spl(True, 2.0, 1.0) == 1.0  # a path can be no shorter than l; max(p, l) keeps SPL <= 1
    assert soft_spl(0.0, 2.0, 4.0) == 0.5 and soft_spl(1.0, 2.0, 2.0) == 0.5 and soft_spl(3.0, 2.0, 2.0) == 0.0
    assert soft_spl(math.inf, 2.0, 2.0) == 0.0


def test_goals_read_back_with_their_parameters():
    goal = goal_from_dict(ObjectNavGoal("Bed", 0.75).to_dict())
    assert isinstance(goal, ObjectNavGoal) and goal.success_distance == 0.75 and goal.instruction == "find the bed"
    from luminous_sim.env.kinds.objectnav_pickup import PickupNavGoal

    pick = goal_from_dict(PickupNavGoal("Book", 4).to_dict())
    assert isinstance(pick, PickupNavGoal) and pick.task_type == "objectnav_pickup" and not pick.stop_to_succeed


def test_the_start_is_a_function_of_the_seed(envs):
    env = envs[PICK]
    _, a = env.reset(seed=5)
    pose_a = env.world.agent
    _, b = env.reset(seed=5)
    assert env.world.agent == pose_a and a["shortest_path_length"] == b["shortest_path_length"]
    assert np.isfinite(a["start_distance"])


def test_a_pickled_episode_ends_with_the_same_figures(envs):
    import pickle

    env = envs[NAV]
    env.reset(seed=SEEDS[2])
    for _ in range(3):
        env.step(env.expert_action())
    copy = pickle.loads(pickle.dumps(env))
    try:
        ends = []
        for e in (env, copy):
            while True:
                _, _, terminated, truncated, info = e.step(e.expert_action())
                if terminated or truncated:
                    break
            ends.append({k: info[k] for k in ("success", "spl", "soft_spl", "path_length", "distance_to_goal")})
        assert ends[0] == ends[1] and ends[0]["success"]
    finally:
        copy.close()
