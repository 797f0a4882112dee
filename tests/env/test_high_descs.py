"""The ALFRED -v2 ids: the step-by-step instructions as their own observation, fixed for the episode."""

from __future__ import annotations

import gymnasium as gym
import pytest
from gymnasium.utils.env_checker import check_env

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import LuminousEnv
from luminous_sim.errors import LuminousError

V2 = ["Luminous-ALFRED-v2", "Luminous-ALFRED-PickPlace-v2", "Luminous-ALFRED-PickTwo-v2",
      "Luminous-ALFRED-LookInLight-v2", "Luminous-ALFRED-PickClean-v2", "Luminous-ALFRED-PickHeat-v2",
      "Luminous-ALFRED-PickCool-v2", "Luminous-ALFRED-PickMovable-v2"]


def test_every_alfred_id_has_a_v2_with_high_descs_and_v1_is_kept():
    for env_id in V2:
        spec = gym.spec(env_id)
        assert spec.kwargs["high_descs"] is True
        assert "high_descs" not in gym.spec(env_id.replace("-v2", "-v1")).kwargs


def test_check_env_passes_on_a_v2_id():
    env = gym.make("Luminous-ALFRED-PickPlace-v2", width=64, height=64).unwrapped
    try:
        check_env(env, skip_render_check=True)
    finally:
        env.close()


def test_high_descs_are_the_expert_plans_steps_one_per_line_the_same_every_step():
    env = LuminousEnv(task_types=["pick_and_place_simple"], width=64, height=64, high_descs=True)
    try:
        obs, _ = env.reset(seed=3)
        steps = env.episode.expert.steps
        assert len(steps) >= 2 and obs["high_descs"].split("\n") == list(steps)
        assert env.observation_space.contains(obs)
        text = obs["high_descs"]
        for _ in range(3):
            obs, *_ = env.step(0)
            assert obs["high_descs"] is text  # made once per episode, not copied each step
    finally:
        env.close()


def test_high_descs_need_the_expert():
    with pytest.raises(LuminousError, match="high_descs: needs verify_expert"):
        LuminousEnv(high_descs=True, verify_expert=False)


def test_reset_options_name_a_bad_trial_and_an_index_outside_the_split(tmp_path):
    env = LuminousEnv(width=64, height=64)
    try:
        with pytest.raises(LuminousError, match="trial: .* holds no traj_data.json"):
            env.reset(options={"trial": str(tmp_path)})
        with pytest.raises(LuminousError, match=r"index: 435; split U\+ holds episodes 0\.\.434"):
            env.reset(options={"split": "U+", "index": 435})
        with pytest.raises(LuminousError, match="exclude each other"):
            env.reset(options={"split": "U+", "trial": str(tmp_path)})
        (tmp_path / "traj_data.json").write_text("{}")
        (tmp_path / "luminous.json").write_text("{}")
        with pytest.raises(LuminousError, match="trial: .*traj_data.json: field 'task_type' is missing"):
            env.reset(options={"trial": str(tmp_path)})
        (tmp_path / "traj_data.json").write_text("[1, 2")
        with pytest.raises(LuminousError, match="traj_data.json: not JSON"):
            env.reset(options={"trial": str(tmp_path)})
    finally:
        env.close()
