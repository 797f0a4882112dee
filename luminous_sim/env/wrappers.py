"""Wrappers for learning libraries."""

from __future__ import annotations

from typing import Any, Literal

import gymnasium
import numpy as np
from gymnasium import spaces

from luminous_sim.env.vocabulary import encode, vocabulary


class InstructionTokens(gymnasium.ObservationWrapper, gymnasium.utils.RecordConstructorArgs):
    """The `instruction` observation as a fixed-length vector of token ids over a fixed vocabulary
    (`luminous_sim.env.vocabulary`), so that stable-baselines3's `MultiInputPolicy` takes it unchanged.

    The wrapper is recorded in the wrapped env's `spec` (`additional_wrappers`), so `gymnasium.make(env.spec)`
    rebuilds it (as Minari's `recover_environment` does).

    Args:
        env: an env whose observation is a Dict with a `Text` `instruction`.
        length: tokens kept (longer instructions are cut, shorter ones padded with `<pad>`, id 0).
        space: `multidiscrete` (SB3 one-hot encodes each token) or `box` (int64 ids).
    """

    def __init__(self, env: gymnasium.Env, length: int = 32, space: Literal["multidiscrete", "box"] = "multidiscrete"):
        gymnasium.utils.RecordConstructorArgs.__init__(self, length=length, space=space)
        gymnasium.ObservationWrapper.__init__(self, env)
        if space not in ("multidiscrete", "box"):
            raise ValueError(f"space {space!r}: expected 'multidiscrete' or 'box'")
        self.length = length
        n = len(vocabulary())
        tokens: spaces.Space = (spaces.MultiDiscrete(np.full(length, n, dtype=np.int64)) if space == "multidiscrete"
                                else spaces.Box(0, n - 1, (length,), np.int64))
        inner = env.observation_space
        assert isinstance(inner, spaces.Dict) and "instruction" in inner.spaces, "needs a Dict with an instruction"
        self.observation_space = spaces.Dict({**inner.spaces, "instruction": tokens})

    def observation(self, observation: dict[str, Any]) -> dict[str, Any]:
        return {**observation, "instruction": np.array(encode(observation["instruction"], self.length), np.int64)}
