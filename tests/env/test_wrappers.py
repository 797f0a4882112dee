"""The learning wrappers: InstructionTokens (the Text instruction as token ids over the fixed vocabulary),
ActionFeedback, ActionSubset, FailureLimitEnds, SceneRepeat and NewPlaceBonus."""

from __future__ import annotations

import importlib.util

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import (
    ActionFeedback,
    ActionSubset,
    FailureLimitEnds,
    InstructionTokens,
    NewPlaceBonus,
    SceneRepeat,
)
from luminous_sim.env.vocabulary import PAD, UNK, encode, vocabulary
from luminous_sim.tasks import TEMPLATES


def test_the_vocabulary_covers_the_templates_and_unknown_words_are_unk():
    vocab = vocabulary()
    assert vocab[:2] == (PAD, UNK) and len(set(vocab)) == len(vocab)
    template_words = {w for options in TEMPLATES.values() for t in options for w in t.replace("{", " ").split()
                      if "}" not in w}
    assert template_words <= set(vocab)
    ids = encode("put a hot slice of apple in the zorblax", 12)
    assert len(ids) == 12 and ids[-1] == 0 and ids[8] == 1 and 1 not in ids[:8]
    assert encode("put " * 40, 5) == [vocab.index("put")] * 5


@pytest.mark.parametrize("space", ["multidiscrete", "box"])
def test_wrapped_observations_lie_in_the_space(space):
    env = InstructionTokens(gymnasium.make("Luminous-PickUp-64-v1"), length=16, space=space)
    obs, _ = env.reset(seed=0)
    assert env.observation_space.contains(obs) and obs["instruction"].shape == (16,)
    words = env.unwrapped.episode.goal.instruction.split()
    assert (obs["instruction"] > 1).sum() == len(words)  # every word of the instruction is known
    obs, *_ = env.step(0)
    assert env.observation_space.contains(obs)
    env.close()


@pytest.mark.skipif(importlib.util.find_spec("stable_baselines3") is None, reason="stable-baselines3 not installed")
def test_sb3_multi_input_policy_takes_the_wrapped_env():
    from stable_baselines3 import PPO

    env = InstructionTokens(gymnasium.make("Luminous-NavToObject-64-v1"))
    model = PPO("MultiInputPolicy", env, n_steps=32, batch_size=16, n_epochs=1, seed=0)
    model.learn(64)
    action, _ = model.predict(env.reset(seed=0)[0])
    assert env.action_space.contains(np.int64(action))
    env.close()


def _failing_action(env) -> int:
    """An interaction on the top-left grid point with nothing held: PutObject fails."""
    from luminous_sim.env.actions import ActionTable

    table: ActionTable = env.unwrapped.actions
    return table.index("PutObject", 0)


def test_action_feedback_gives_the_previous_action_and_whether_it_failed():
    env = ActionFeedback(InstructionTokens(gymnasium.make("Luminous-NavToObject-64-v1")))
    n = env.unwrapped.action_space.n
    assert env.observation_space["feedback"] == gymnasium.spaces.MultiDiscrete([n + 1, 2])
    obs, _ = env.reset(seed=0)
    assert obs["feedback"].tolist() == [n, 0] and env.observation_space.contains(obs)
    put = _failing_action(env)
    obs, _, _, _, info = env.step(put)
    assert info["failure_code"] is not None and obs["feedback"].tolist() == [put, 1]
    obs, _, _, _, info = env.step(2)  # RotateRight never fails
    assert info["failure_code"] is None and obs["feedback"].tolist() == [2, 0]
    obs, *_ = env.step({"action": "RotateLeft"})  # the dict form has no index
    assert obs["feedback"].tolist() == [n, 0] and env.observation_space.contains(obs)
    env.close()
    with pytest.raises(TypeError, match="Discrete action space"):
        ActionFeedback(gymnasium.make("CartPole-v1"))


def test_action_feedback_with_a_history_shows_the_last_steps_newest_first():
    env = ActionFeedback(InstructionTokens(gymnasium.make("Luminous-NavToObject-64-v1")), history=3)
    n = env.unwrapped.action_space.n
    assert env.observation_space["feedback"] == gymnasium.spaces.MultiDiscrete([n + 1, 2] * 3)
    obs, _ = env.reset(seed=0)
    assert obs["feedback"].tolist() == [n, 0] * 3
    put = _failing_action(env)
    for a in (1, put, 2):
        obs, *_ = env.step(a)
    assert obs["feedback"].tolist() == [2, 0, put, 1, 1, 0] and env.observation_space.contains(obs)
    obs, *_ = env.step(1)
    assert obs["feedback"].tolist() == [1, 0, 2, 0, put, 1]
    obs, _ = env.reset(seed=1)  # a new episode forgets
    assert obs["feedback"].tolist() == [n, 0] * 3
    env.close()
    with pytest.raises(ValueError, match="history"):
        ActionFeedback(InstructionTokens(gymnasium.make("Luminous-NavToObject-64-v1")), history=0)


def test_action_feedback_can_count_the_failed_actions_up_to_a_cap():
    env = ActionFeedback(gymnasium.make("Luminous-NavToObject-64-v1", max_failures=100), failures=2)
    n = env.unwrapped.action_space.n
    assert env.observation_space["feedback"] == gymnasium.spaces.MultiDiscrete([n + 1, 2, 3])
    obs, _ = env.reset(seed=0)
    assert obs["feedback"].tolist() == [n, 0, 0]
    put = _failing_action(env)
    counts = []
    for a in (put, 2, put, put):
        obs, *_ = env.step(a)
        counts.append(int(obs["feedback"][-1]))
        assert env.observation_space.contains(obs)
    assert counts == [1, 1, 2, 2]  # capped at 2
    assert env.reset(seed=0)[0]["feedback"].tolist() == [n, 0, 0]
    env.close()


def test_failure_limit_ends_turns_that_truncation_into_a_termination():
    wrapped = FailureLimitEnds(gymnasium.make("Luminous-NavToObject-64-v1", max_failures=3))
    plain = gymnasium.make("Luminous-NavToObject-64-v1", max_failures=3)
    for env in (wrapped, plain):
        env.reset(seed=0)
    put = _failing_action(wrapped)
    for i in range(3):
        a = wrapped.step(put)
        b = plain.step(put)
        assert a[1] == b[1] and a[4]["failures"] == b[4]["failures"] == i + 1
    assert a[2:4] == (True, False) and a[4]["failure_limit"]
    assert b[2:4] == (False, True)
    wrapped.reset(seed=0)
    assert wrapped.step(2)[4]["failure_limit"] is False
    for env in (wrapped, plain):
        env.close()


def test_scene_repeat_keeps_the_scene_for_that_many_episodes_then_draws_a_new_one():
    env = SceneRepeat(gymnasium.make("Luminous-NavToObject-64-v1"), repeats=3)
    inner = env.unwrapped
    scenes, goals = [], []
    env.reset(seed=5)
    for _ in range(4):
        scenes.append(inner.episode.scene.seed)
        goals.append(inner.episode.goal.instruction)
        env.reset()
    scenes.append(inner.episode.scene.seed)
    assert scenes[0] == scenes[1] == scenes[2] != scenes[3]
    assert inner.worlds.reuses > 0
    again = SceneRepeat(gymnasium.make("Luminous-NavToObject-64-v1"), repeats=3)
    again.reset(seed=5)
    again_goals = [again.unwrapped.episode.goal.instruction]
    for _ in range(3):
        again.reset()
        again_goals.append(again.unwrapped.episode.goal.instruction)
    assert again_goals == goals  # deterministic from the seed
    env.reset(seed=6)  # a seed starts a new run of repeats
    first = inner.episode.scene.seed
    env.reset()
    assert inner.episode.scene.seed == first
    for e in (env, again):
        e.close()
    with pytest.raises(ValueError, match="positive integer"):
        SceneRepeat(gymnasium.make("Luminous-NavToObject-64-v1"), repeats=0)


def test_action_subset_maps_its_indices_to_the_named_actions():
    from luminous_sim.env.actions import NAVIGATION

    env = ActionSubset(gymnasium.make("Luminous-NavToObject-64-v1"), ["RotateRight", "PutObject@(0,0)"])
    assert env.action_space == gymnasium.spaces.Discrete(2) and env.indices == [2, env.unwrapped.actions.index(
        "PutObject", 0)]
    env.reset(seed=0)
    before = env.unwrapped.world.agent.rotation
    *_, info = env.step(0)
    assert info["failure_code"] is None and env.unwrapped.world.agent.rotation == (before + 90) % 360
    *_, info = env.step(1)
    assert info["failure_code"] is not None and env.unwrapped.history[-1].api["action"] == "PutObject"
    *_, info = env.step(7)  # outside the subset: a failed action, never an exception
    assert info["failure_code"] == "invalid_argument"
    *_, info = env.step({"action": "RotateLeft"})  # the dict form passes through
    assert info["failure_code"] is None
    env.close()
    nav = ActionSubset(gymnasium.make("Luminous-NavToObject-64-v1"))
    assert nav.names == list(NAVIGATION) and nav.indices == [0, 1, 2, 3, 4]
    nav.close()
    with pytest.raises(ValueError, match="Jump"):
        ActionSubset(gymnasium.make("Luminous-NavToObject-64-v1"), ["MoveAhead", "Jump"])


def test_new_place_bonus_rewards_each_grid_position_once_per_episode():
    plain = gymnasium.make("Luminous-NavToObject-64-v1", max_failures=100)
    env = NewPlaceBonus(gymnasium.make("Luminous-NavToObject-64-v1", max_failures=100), bonus=0.5)
    earned, revisits = 0, 0
    for seed in range(5):
        for e in (plain, env):
            e.reset(seed=seed)
        seen = {env.place()}
        action, back = 0, []
        for _ in range(16):  # walk ahead (turning when blocked), then turn round and walk back over the same places
            r0 = plain.step(action)[1]
            _, r1, terminated, _, info = env.step(action)
            cell = env.place()
            assert info["new_place"] == (cell not in seen) and r1 == pytest.approx(r0 + 0.5 * info["new_place"])
            earned += info["new_place"]
            revisits += action == 0 and info["failure_code"] is None and not info["new_place"]
            seen.add(cell)
            if terminated:
                break
            back.append(action)
            action = 2 if info["failure_code"] is not None or len(back) in (4, 5) else 0
        if earned and revisits:
            break
    assert earned >= 1 and revisits >= 1
    env.reset(seed=3)  # a new episode: nothing carried over
    assert env.seen == {env.place()}
    for e in (plain, env):
        e.close()
