"""OraclePolicy reaches success through the env's own action space (Minigrid's bot test): one id and
seed in the fast suite, every registered id over two seeds in the slow sweep. The second seed turns off
`verify_expert` (where the id allows it: not where the observation describes the expert's plan), so its episode
is not one the reset already proved the oracle solves."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import OraclePolicy, load_entries

IDS = [e.id for e in load_entries()]
SEEDS = (0, 1)
NEEDS_EXPERT = {e.id for e in load_entries() if e.kwargs.get("high_descs") or e.kwargs.get("step_instructions")}
"""Ids whose observation describes the expert's plan: they cannot turn `verify_expert` off (a config error)."""


def run_oracle(env_id: str, seed: int, **kwargs) -> tuple[dict, int, float, int]:
    """(last info, steps, return, discrete actions taken) of the oracle's episode."""
    env = gymnasium.make(env_id, **kwargs)
    policy = OraclePolicy(env)
    obs, info = env.reset(seed=seed)
    steps, total, discrete = 0, 0.0, 0
    terminated = truncated = False
    while not (terminated or truncated):
        action = policy(obs)
        discrete += isinstance(action, (int, np.integer))
        obs, reward, terminated, truncated, info = env.step(action)
        steps, total = steps + 1, total + reward
    env.close()
    return info, steps, total, discrete


def _check(env_id: str, seed: int, **kwargs) -> None:
    info, _steps, total, discrete = run_oracle(env_id, seed, **kwargs)
    assert info["success"], (env_id, seed, info)
    assert info["failures"] == 0 and info["goal_conditions"][0] == info["goal_conditions"][1] > 0
    assert total >= 5 and discrete > 0 and info["subgoal"] == ""


def test_the_oracle_solves_a_small_id():
    _check("Luminous-PickUp-64-v1", 0)


def test_the_oracle_replans_after_the_agent_deviates():
    env = gymnasium.make("Luminous-PickUp-64-v1")
    policy = OraclePolicy(env)
    env.reset(seed=0)
    for action in (1, 1, 0):  # the agent wanders off first
        env.step(action)
    terminated = truncated = False
    while not (terminated or truncated):
        _, _, terminated, truncated, info = env.step(policy())
    assert info["success"] and env.unwrapped.expert.replans == 1
    env.close()


def test_expert_in_info_is_the_policys_action():
    env = gymnasium.make("Luminous-NavToObject-64-v1", expert_in_info=True)
    _, info = env.reset(seed=0)
    assert info["expert_action"] == OraclePolicy(env)()
    env.close()


@pytest.mark.slow
@pytest.mark.parametrize("seed", SEEDS)
@pytest.mark.parametrize("env_id", IDS)
def test_the_oracle_solves_every_registered_id(env_id, seed):
    _check(env_id, seed, verify_expert=seed == SEEDS[0] or env_id in NEEDS_EXPERT)
