"""Wrappers for learning libraries: the instruction as token ids, the previous action's feedback, a subset of
the actions, and for training, the failure limit as a termination and scenes repeated over several episodes."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Literal

import gymnasium
import numpy as np
from gymnasium import spaces

from luminous_sim.env.vocabulary import encode, vocabulary
from luminous_sim.errors import LuminousError
from luminous_sim.limits import MAX_INSTRUCTION_TOKENS
from luminous_sim.scene import STEP


class WrapperArgumentError(LuminousError, ValueError):
    """A wrapper given a bad argument; the message names the wrapper and the argument (a ValueError too, as
    before)."""


class InstructionTokens(gymnasium.ObservationWrapper, gymnasium.utils.RecordConstructorArgs):
    """The `instruction` observation as a fixed-length vector of token ids over a fixed vocabulary
    (`luminous_sim.env.vocabulary`), so that stable-baselines3's `MultiInputPolicy` takes it unchanged.

    The wrapper is recorded in the wrapped env's `spec` (`additional_wrappers`), so `gymnasium.make(env.spec)`
    rebuilds it (as Minari's `recover_environment` does).

    Args:
        env: an env whose observation is a Dict with a `Text` `instruction`.
        length: tokens kept (longer instructions are cut, shorter ones padded with `<pad>`, id 0), 1 to
            `limits.MAX_INSTRUCTION_TOKENS`.
        space: `multidiscrete` (SB3 one-hot encodes each token) or `box` (int64 ids).
    """

    def __init__(self, env: gymnasium.Env, length: int = 32, space: Literal["multidiscrete", "box"] = "multidiscrete"):
        gymnasium.utils.RecordConstructorArgs.__init__(self, length=length, space=space)
        gymnasium.ObservationWrapper.__init__(self, env)
        if space not in ("multidiscrete", "box"):
            raise WrapperArgumentError(f"InstructionTokens space: expected 'multidiscrete' or 'box', got {space!r}")
        if isinstance(length, bool) or not isinstance(length, (int, np.integer)) or not \
                1 <= length <= MAX_INSTRUCTION_TOKENS:
            raise WrapperArgumentError(f"InstructionTokens length: expected a whole number from 1 to "
                                       f"{MAX_INSTRUCTION_TOKENS} (luminous_sim.limits.MAX_INSTRUCTION_TOKENS), "
                                       f"got {length!r}")
        length = int(length)
        self.length = length
        n = len(vocabulary())
        tokens: spaces.Space = (spaces.MultiDiscrete(np.full(length, n, dtype=np.int64)) if space == "multidiscrete"
                                else spaces.Box(0, n - 1, (length,), np.int64))
        inner = env.observation_space
        assert isinstance(inner, spaces.Dict) and "instruction" in inner.spaces, "needs a Dict with an instruction"
        self.observation_space = spaces.Dict({**inner.spaces, "instruction": tokens})
        self._text: str | None = None
        self._tokens = np.zeros(length, np.int64)

    def observation(self, observation: dict[str, Any]) -> dict[str, Any]:
        text = observation["instruction"]
        if text != self._text:  # the instruction is fixed for an episode: encoded once, not every step
            self._text, self._tokens = text, np.array(encode(text, self.length), np.int64)
            self._tokens.flags.writeable = False
        return {**observation, "instruction": self._tokens}


class ActionFeedback(gymnasium.Wrapper, gymnasium.utils.RecordConstructorArgs):
    """Adds a `feedback` observation: the last `history` actions' indices and whether each failed, as ALFRED's
    agents see `lastActionSuccess`. A policy without memory then knows that the step it just took hit a wall or
    a look limit, or that it has turned four times in a row, and can choose otherwise.

    `feedback` is a `MultiDiscrete([n + 1, 2] * history)` (SB3 one-hot encodes it): `[action, failed]` for the
    last step, then the one before, ...; `action` is n (the action space's size) before the episode's first
    steps and after an action given in the dict form. With `failures` > 0 one more entry follows: the episode's
    failed actions so far (`info["failures"]`), at most `failures`, so a policy can see the failure limit coming.

    Args:
        env: an env with a `Discrete` action space and a `Dict` observation (a `LuminousEnv`, wrapped or not).
        history: how many past steps to show.
        failures: show the count of failed actions up to this (0: not shown).
    """

    def __init__(self, env: gymnasium.Env, history: int = 1, failures: int = 0):
        gymnasium.utils.RecordConstructorArgs.__init__(self, history=history, failures=failures)
        gymnasium.Wrapper.__init__(self, env)
        if not isinstance(env.action_space, spaces.Discrete) or not isinstance(env.observation_space, spaces.Dict):
            raise TypeError("ActionFeedback needs a Discrete action space and a Dict observation space, got "
                            f"{env.action_space} and {type(env.observation_space).__name__}")
        if isinstance(history, bool) or not isinstance(history, int) or history < 1:
            raise WrapperArgumentError(f"ActionFeedback history: expected a positive integer, got {history!r}")
        if isinstance(failures, bool) or not isinstance(failures, int) or failures < 0:
            raise WrapperArgumentError(f"ActionFeedback failures: expected an integer >= 0, got {failures!r}")
        self.none = int(env.action_space.n)
        self.history, self.failures = history, failures
        self._past = np.tile(np.array([self.none, 0], np.int64), history)
        self._failed = 0
        nvec = np.tile([self.none + 1, 2], history)
        if failures:
            nvec = np.append(nvec, failures + 1)
        self.observation_space = spaces.Dict({**env.observation_space.spaces, "feedback": spaces.MultiDiscrete(nvec)})

    def _with(self, observation: dict[str, Any]) -> dict[str, Any]:
        feedback = np.append(self._past, min(self._failed, self.failures)) if self.failures else self._past.copy()
        return {**observation, "feedback": feedback}

    def reset(self, **kwargs: Any) -> tuple[dict[str, Any], dict[str, Any]]:
        observation, info = self.env.reset(**kwargs)
        self._past = np.tile(np.array([self.none, 0], np.int64), self.history)
        self._failed = 0
        return self._with(observation), info

    def step(self, action: Any) -> tuple[dict[str, Any], Any, bool, bool, dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        index = int(action) if isinstance(action, (int, np.integer, np.ndarray)) and np.ndim(action) == 0 else self.none
        index = index if 0 <= index < self.none else self.none
        failed = info.get("failure_code") is not None
        self._past = np.concatenate([[index, int(failed)], self._past[:-2]])
        self._failed = int(info.get("failures", self._failed + failed))
        return self._with(observation), reward, terminated, truncated, info


class FailureLimitEnds(gymnasium.Wrapper, gymnasium.utils.RecordConstructorArgs):
    """For training: an episode cut off by the failure limit (`max_failures`) ends as `terminated`, not
    `truncated`, and `info["failure_limit"]` says so.

    Learners bootstrap a truncated episode's value as if it went on (a time limit is not the agent's doing);
    an episode cut off by its own failed actions does not go on, and the reward it would have reached is lost.
    Reporting it as a termination lets a learner see that cost, so it learns to avoid failing 10 times.
    Evaluation should use the env unwrapped (success and lengths are the same either way).
    """

    def __init__(self, env: gymnasium.Env):
        gymnasium.utils.RecordConstructorArgs.__init__(self)
        gymnasium.Wrapper.__init__(self, env)
        self.limit = int(env.unwrapped.config.max_failures)  # type: ignore[attr-defined]

    def step(self, action: Any) -> tuple[Any, Any, bool, bool, dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        hit = truncated and not terminated and info.get("failures", 0) >= self.limit
        if hit:
            terminated, truncated = True, False
        return observation, reward, terminated, truncated, {**info, "failure_limit": hit}


class SceneRepeat(gymnasium.Wrapper, gymnasium.utils.RecordConstructorArgs):
    """For training: each scene serves `repeats` episodes in a row (new goals drawn in it, from the world's start
    pose), so most resets reuse the built world (`WorldPool`) and cost about a third of a new scene's.

    A reset given `options` (a scene, a split entry, a CDF) or a new `seed` passes through unchanged and starts
    a new run of repeats. The scene distribution the agent trains on is the env's own, each scene `repeats`
    times; evaluate without this wrapper.

    Args:
        env: a `LuminousEnv`, wrapped or not.
        repeats: episodes per scene (1: the wrapper does nothing).
    """

    def __init__(self, env: gymnasium.Env, repeats: int = 4):
        gymnasium.utils.RecordConstructorArgs.__init__(self, repeats=repeats)
        gymnasium.Wrapper.__init__(self, env)
        if isinstance(repeats, bool) or not isinstance(repeats, int) or repeats < 1:
            raise WrapperArgumentError(f"SceneRepeat repeats: expected a positive integer, got {repeats!r}")
        self.repeats = repeats
        self._left = 0

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        episode = getattr(self.env.unwrapped, "episode", None)
        if seed is None and not options and self._left > 0 and episode is not None:
            self._left -= 1
            return self.env.reset(options={"scene": episode.scene})
        self._left = self.repeats - 1
        return self.env.reset(seed=seed, options=options)


class ActionSubset(gymnasium.ActionWrapper, gymnasium.utils.RecordConstructorArgs):
    """A `Discrete` space over some of the env's actions, by name (`ActionTable.labels`): action i is the
    env's action named `names[i]`. For an agent that needs only some actions, e.g. the navigation ones in
    `goto_object`, whose goal is met by walking and where Stop only ends an episode early.

    The ALFRED dict form still passes through to the env unchanged.

    Args:
        env: a `LuminousEnv`, wrapped or not.
        names: the actions kept, in order (`NAVIGATION` by default: MoveAhead, RotateLeft, RotateRight,
            LookUp, LookDown).
    """

    def __init__(self, env: gymnasium.Env, names: Sequence[str] | None = None):
        from luminous_sim.env.actions import NAVIGATION

        names = list(NAVIGATION if names is None else names)
        gymnasium.utils.RecordConstructorArgs.__init__(self, names=names)
        gymnasium.ActionWrapper.__init__(self, env)
        labels = env.unwrapped.actions.labels()  # type: ignore[attr-defined]
        unknown = [n for n in names if n not in labels]
        if not names or unknown or len(set(names)) != len(names):
            raise WrapperArgumentError(f"ActionSubset names: {unknown or names} are not distinct names of this env's "
                                       f"actions (e.g. {', '.join(labels[:7])}, ...)")
        self.names = names
        self.indices = [labels.index(n) for n in names]
        self.action_space = spaces.Discrete(len(names))

    def action(self, action: Any) -> Any:
        if isinstance(action, dict):
            return action
        index = int(action)
        if not 0 <= index < len(self.indices):  # outside the subset: an index outside the env's space, a failure
            return int(self.env.action_space.n)  # type: ignore[attr-defined]
        return self.indices[index]


class NewPlaceBonus(gymnasium.Wrapper, gymnasium.utils.RecordConstructorArgs):
    """For training: `bonus` added to the reward of each step that takes the agent to a grid position (0.25 m
    cells, the agent grid's `STEP`) it has not stood on before in the episode, a coverage reward as navigation
    agents are often trained with. Without it, an agent that fears failed actions learns to turn in place
    (turning never fails), which finds only what is around the start. `info["new_place"]` says whether the
    step earned it.

    Args:
        env: a `LuminousEnv`, wrapped or not.
        bonus: the reward per new position.
    """

    def __init__(self, env: gymnasium.Env, bonus: float = 0.1):
        gymnasium.utils.RecordConstructorArgs.__init__(self, bonus=bonus)
        gymnasium.Wrapper.__init__(self, env)
        self.bonus = float(bonus)
        self.seen: set[tuple[int, int]] = set()
        """The grid positions the agent has stood on in this episode."""

    def place(self) -> tuple[int, int]:
        """The agent's grid position now (x and y in `STEP` cells)."""
        agent = self.env.unwrapped.world.agent  # type: ignore[attr-defined]
        return round(agent.x / STEP), round(agent.y / STEP)

    def reset(self, **kwargs: Any) -> tuple[Any, dict[str, Any]]:
        observation, info = self.env.reset(**kwargs)
        self.seen = {self.place()}
        return observation, info

    def step(self, action: Any) -> tuple[Any, Any, bool, bool, dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        cell = self.place()
        new = cell not in self.seen
        self.seen.add(cell)
        return observation, float(reward) + (self.bonus if new else 0.0), terminated, truncated, \
            {**info, "new_place": new}
