"""The PPO warm start (examples/dagger.py) and the small goal/depth network (examples/nets.py): the expert's labels
are in the agent's action space and solve the episodes they follow, fitting learns the labels, the critic warm-up
keeps the actor still, and train_ppo runs the whole recipe once per output folder."""

from __future__ import annotations

import json

import numpy as np
import pytest

from tests.conftest import load_script

pytest.importorskip("stable_baselines3")

ENV = "Luminous-ObjectNav-64-v2"
OBS = {"goal_mask": True, "depth": True}


@pytest.fixture(scope="module")
def train_ppo():
    yield from load_script("examples/train_ppo.py")


@pytest.fixture(scope="module")
def dagger(train_ppo):
    yield from load_script("examples/dagger.py")


def _env(train_ppo, **kwargs):
    return train_ppo.make_env(ENV, {**OBS, **kwargs}, feedback=True, actions=train_ppo.ACTION_SETS["objectnav"],
                              training=True, new_place_bonus=0.0)


def _model(train_ppo, env, net="goal-depth"):
    from nets import NETS
    from stable_baselines3 import PPO
    from stable_baselines3.common.vec_env import DummyVecEnv

    return PPO("MultiInputPolicy", DummyVecEnv([lambda: env]), seed=0, device="cpu", n_steps=32, batch_size=16,
               n_epochs=1, policy_kwargs={"features_extractor_class": NETS[net]})


def test_following_the_expert_solves_every_episode_with_labels_in_the_agents_space(train_ppo, dagger):
    env = _env(train_ppo)
    try:
        labels = dagger.Labels()
        stats = dagger.collect(env, lambda obs: 0, dagger.expert_index(env), labels, 120, 1.0,
                               np.random.default_rng(0), seed=7)
        obs, actions = labels.arrays()
        assert len(labels) == 120 and set(obs) == set(env.observation_space.spaces)
        assert stats["episodes"] >= 2 and stats["successes"] == stats["episodes"]
        names = train_ppo.ACTION_SETS["objectnav"]
        assert set(actions.tolist()) <= set(range(len(names))) and names.index("Stop") in actions
    finally:
        env.close()


def test_fitting_learns_the_labels_and_the_critic_warmup_keeps_the_actor_still(train_ppo, dagger):
    import torch

    env = _env(train_ppo)
    try:
        model = _model(train_ppo, env)
        labels = dagger.Labels()
        dagger.collect(env, lambda obs: 0, dagger.expert_index(env), labels, 48, 1.0, np.random.default_rng(1), 3)
        before = dagger.fit(model.policy, labels, 1, 1e-3, 16, np.random.default_rng(0))
        after = dagger.fit(model.policy, labels, 20, 3e-3, 16, np.random.default_rng(0))
        assert after["loss"] < 0.6 * before["loss"] and after["accuracy"] >= before["accuracy"] + 0.2, (before, after)

        policy = model.policy
        actor = [p.detach().clone() for p in policy.action_net.parameters()]
        critic = [p.detach().clone() for p in policy.value_net.parameters()]
        model.learn(64, callback=dagger.critic_first(10_000))
        assert all(torch.equal(a, p) for a, p in zip(actor, policy.action_net.parameters(), strict=True))
        assert not all(torch.equal(c, p) for c, p in zip(critic, policy.value_net.parameters(), strict=True))
        model.learn(64, callback=dagger.critic_first(0), reset_num_timesteps=False)
        assert not all(torch.equal(a, p) for a, p in zip(actor, policy.action_net.parameters(), strict=True))
    finally:
        env.close()


def test_goal_depth_net_names_the_observations_it_needs(train_ppo):
    from nets import GoalDepthCNN

    env = train_ppo.make_env(ENV, {"depth": True}, feedback=True)
    try:
        with pytest.raises(ValueError, match=r"\['goal_mask'\].*goal_mask=true"):
            GoalDepthCNN(env.observation_space)
    finally:
        env.close()


def test_rgb_depth_goal_net_takes_the_goal_from_the_instruction(train_ppo):
    """Without goal_mask the net is told the goal only by the instruction: two instructions give two features
    for the same pixels, and it names what it needs."""
    import torch
    from nets import RgbDepthGoalCNN
    from stable_baselines3.common.preprocessing import preprocess_obs

    env = train_ppo.make_env(ENV, {"depth": True}, feedback=True)
    try:
        obs, _ = env.reset(seed=3)
        space = env.observation_space
        torch.manual_seed(0)
        net = RgbDepthGoalCNN(_channel_first(space))

        def features(tokens):
            batch = {k: torch.as_tensor(np.array(v))[None] for k, v in {**obs, "instruction": tokens}.items()}
            batch["rgb"] = batch["rgb"].permute(0, 3, 1, 2)
            with torch.no_grad():
                return net(preprocess_obs(batch, _channel_first(space)))

        tokens = np.array(obs["instruction"])
        other = np.where(tokens > 0, np.arange(5, 5 + len(tokens)), 0)  # the same length, other words
        assert (tokens > 0).any() and not np.array_equal(tokens, other)
        assert not torch.allclose(features(tokens), features(other)), "the instruction does not reach the features"
        assert torch.equal(features(tokens), features(tokens.copy()))
        with pytest.raises(ValueError, match="depth=true"):
            RgbDepthGoalCNN(_channel_first(train_ppo.make_env(ENV, {}, feedback=True).observation_space))
    finally:
        env.close()


def _channel_first(space):
    """The Dict space as SB3 hands it to an extractor: images channel-first."""
    from gymnasium import spaces

    rgb = space.spaces["rgb"]
    return spaces.Dict({**space.spaces, "rgb": spaces.Box(0, 255, (rgb.shape[2], *rgb.shape[:2]), np.uint8)})


def test_bad_warm_start_settings_are_refused(train_ppo, dagger):
    with pytest.raises(ValueError, match="steps >= rounds >= 1"):
        dagger.warm_start(None, None, dagger.WarmStart(steps=2, rounds=3), seed=0)


def test_train_ppo_warm_starts_once_per_output_folder(tmp_path, train_ppo):
    out = tmp_path / "warm"
    args = ["--env", ENV, "--actions", "objectnav", "--env-kwarg", "goal_mask=true", "--net", "goal-depth",
            "--bc-steps", "60", "--bc-rounds", "2", "--bc-epochs", "1", "--critic-warmup", "64",
            "--ppo", "n_steps=32", "--ppo", "batch_size=16", "--ppo", "n_epochs=1", "--eval-episodes", "0",
            "--out", str(out)]
    assert train_ppo.main([*args, "--steps", "64"]) == 0
    assert (out / "model_warm.zip").stat().st_size > 0
    rows = json.loads((out / "warm_start.json").read_text())
    assert [r["round"] for r in rows] == [1, 2] and [r["labels"] for r in rows] == [30, 60]
    assert rows[0]["expert_share"] == 1.0 and rows[0]["successes"] == rows[0]["episodes"] >= 1
    config = json.loads((out / "config.json").read_text())
    assert config["net"] == "goal-depth" and config["warm_start"]["steps"] == 60 and config["critic_warmup"] == 64
    first = (out / "warm_start.json").stat().st_mtime_ns
    assert train_ppo.main([*args, "--steps", "96", "--resume"]) == 0
    assert (out / "warm_start.json").stat().st_mtime_ns == first, "a resumed run imitated again"
    assert json.loads((out / "progress.json").read_text())["timesteps"] >= 96
