"""InstructionTokens: the Text instruction as fixed-length token ids over the fixed vocabulary."""

from __future__ import annotations

import importlib.util

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import InstructionTokens
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
    env = InstructionTokens(gymnasium.make("Luminous-PickUp-64-v0"), length=16, space=space)
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

    env = InstructionTokens(gymnasium.make("Luminous-NavToObject-64-v0"))
    model = PPO("MultiInputPolicy", env, n_steps=32, batch_size=16, n_epochs=1, seed=0)
    model.learn(64)
    action, _ = model.predict(env.reset(seed=0)[0])
    assert env.action_space.contains(np.int64(action))
    env.close()
