"""ALFRED's reward configuration (spec section 5.2) applied to goal-condition progress."""

from __future__ import annotations

import pytest

from luminous_sim.env.rewards import POSITIVE, RewardConfig, step_reward
from luminous_sim.errors import LuminousError

STAGES = {"isHot(Apple)": "HeatObject", "inReceptacle(Apple, Fridge)": "PutObject", "x": "Base"}
NONE = dict.fromkeys(STAGES, 0)


def reward(before, after, cfg=None, **kw):
    args = {"reached": False, "action_ok": True, "step": 1, "expert_length": 10, **kw}
    return step_reward(cfg or RewardConfig(), before, after, STAGES, **args)


def test_a_met_condition_earns_its_actions_positive_reward_and_losing_it_costs_it_back():
    hot = {**NONE, "isHot(Apple)": 1}
    assert reward(NONE, hot) == POSITIVE["HeatObjectAction"] == 2
    assert reward(hot, NONE) == -2
    assert reward(NONE, {**NONE, "x": 1}) == POSITIVE["BaseAction"]
    assert reward(NONE, {**NONE, "inReceptacle(Apple, Fridge)": 2}) == 4  # a weight-2 condition, both counts


def test_goal_failure_and_step_penalty_terms():
    assert reward(NONE, NONE, reached=True) == 5
    assert reward(NONE, NONE, action_ok=False) == pytest.approx(-0.05)
    assert reward(NONE, NONE, step=11) == pytest.approx(-0.01)
    assert reward(NONE, NONE, step=10) == 0


def test_sparse_pays_the_goal_only_and_overrides_apply():
    sparse = RewardConfig.of("sparse", {})
    assert reward(NONE, {**NONE, "x": 1}, sparse, action_ok=False, step=99) == 0
    assert reward(NONE, NONE, sparse, reached=True) == 5
    cfg = RewardConfig.of("dense", {"goal_reward": 10, "HeatObjectAction": 3})
    assert reward(NONE, {**NONE, "isHot(Apple)": 1}, cfg, reached=True) == 13
    with pytest.raises(LuminousError, match="unknown term"):
        RewardConfig.of("dense", {"bonus": 1})


def test_failed_stop_costs_only_a_wrong_stop_of_a_stop_judged_goal():
    import gymnasium

    import luminous_sim  # noqa: F401  (registers the ids)
    from luminous_sim.env.actions import STOP

    plain = gymnasium.make("Luminous-ObjectNav-64-v2").unwrapped
    costly = gymnasium.make("Luminous-ObjectNav-64-v2", reward={"failed_stop": -1.0}).unwrapped
    stop = plain.actions.index(STOP)
    rewards = []
    for env in (plain, costly):
        env.reset(seed=5)
        _, reward, terminated, _, info = env.step(stop)  # starts are >= 2 m from success: a wrong Stop
        assert terminated and not info["success"]
        rewards.append(reward)
    assert rewards[1] == rewards[0] - 1.0
    costly.reset(seed=5)
    info: dict = {}
    while not info.get("success"):
        _, reward, _, truncated, info = costly.step(costly.expert_action())
        assert not truncated
    assert reward >= 5.0 - 0.01  # the right Stop earns the goal (less ALFRED's step penalty), no cost
    for env in (plain, costly):
        env.close()
