"""`make_vector_env`: the same episodes as one process, token ids in shared memory, per-step info cut to a few
keys (whole on reset and on an episode's last step), SB3's `SubprocVecEnv` over the same envs, bad arguments
named; `InstructionTokens` encodes an episode's instruction once."""

from __future__ import annotations

import importlib.util

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import InstructionTokens, StepInfo, make_vector_env
from luminous_sim.env.actions import STOP
from luminous_sim.env.vector import STEP_KEYS, wrapped_env
from luminous_sim.env.vocabulary import encode
from luminous_sim.env.wrappers import WrapperArgumentError
from luminous_sim.errors import LuminousError

ID = "Luminous-ObjectNav-64-v2"
FAST = {"verify_expert": False}
ACTIONS = [[0, 1], [2, 0], [1, 4], [3, 2], [0, 0]]


def _stop_index() -> int:
    env = gymnasium.make(ID, **FAST)
    index = env.unwrapped.actions.index(STOP)  # type: ignore[attr-defined]
    env.close()
    return int(index)


def _single(seed: int, actions: list[int]) -> tuple[list[np.ndarray], np.ndarray]:
    env = wrapped_env(ID, **FAST)
    obs, _ = env.reset(seed=seed)
    frames = [obs["rgb"]]
    for a in actions:
        obs, *_ = env.step(a)
        frames.append(obs["rgb"])
    env.close()
    return frames, obs["instruction"]


def test_async_vector_env_plays_the_single_process_episodes():
    envs = make_vector_env(ID, 2, **FAST)
    try:
        obs, info = envs.reset(seed=[5, 6])
        assert obs["rgb"].shape == (2, 64, 64, 3) and obs["instruction"].shape == (2, 32)
        assert "episode_key" in info  # reset's info is whole
        frames = [obs["rgb"]]
        for pair in ACTIONS:
            obs, _, terminated, truncated, info = envs.step(np.array(pair))
            assert not (terminated.any() or truncated.any())
            assert set(info) - {f"_{k}" for k in info} <= set(STEP_KEYS)  # cut to the step keys
            frames.append(obs["rgb"])
        for i, seed in enumerate((5, 6)):
            single, tokens = _single(seed, [p[i] for p in ACTIONS])
            for got, want in zip(frames, single, strict=True):
                np.testing.assert_array_equal(got[i], want)
            np.testing.assert_array_equal(obs["instruction"][i], tokens)
        stop = _stop_index()
        _, _, terminated, _, info = envs.step(np.array([stop, 0]))
        assert terminated.tolist() == [True, False]
        assert info["_spl"].tolist() == [True, False]  # the ending step's info is whole (SPL is in it)
        obs, _, terminated, _, info = envs.step(np.array([0, 0]))  # autoreset of env 0 in its worker
        assert not terminated.any() and obs["rgb"].shape == (2, 64, 64, 3)
    finally:
        envs.close()


def test_step_info_keeps_the_named_keys_until_the_episode_ends():
    env = StepInfo(gymnasium.make(ID, **FAST), keys=("success",))
    _, info = env.reset(seed=1)
    assert "start_distance" in info
    _, _, _, _, info = env.step(1)
    assert set(info) == {"success"}
    _, _, terminated, _, info = env.step(env.unwrapped.actions.index(STOP))  # type: ignore[attr-defined]
    assert terminated and {"success", "spl", "soft_spl", "failures"} <= set(info)
    env.close()


def test_instruction_tokens_are_encoded_once_an_episode():
    env = InstructionTokens(gymnasium.make(ID, **FAST))
    obs, _ = env.reset(seed=2)
    text = env.unwrapped.episode.goal.instruction  # type: ignore[attr-defined]
    np.testing.assert_array_equal(obs["instruction"], encode(text, 32))
    first = obs["instruction"]
    obs, *_ = env.step(1)
    assert obs["instruction"] is first and not first.flags.writeable  # no copy per step, and none can change it
    obs, _ = env.reset(seed=3)
    text = env.unwrapped.episode.goal.instruction  # type: ignore[attr-defined]
    np.testing.assert_array_equal(obs["instruction"], encode(text, 32))
    env.close()


@pytest.mark.skipif(importlib.util.find_spec("stable_baselines3") is None, reason="stable-baselines3 not installed")
def test_subproc_backend_is_sb3_over_the_same_envs():
    envs = make_vector_env(ID, 2, backend="subproc", **FAST)
    try:
        envs.seed(5)
        obs = envs.reset()
        assert obs["rgb"].shape == (2, 64, 64, 3) and obs["instruction"].shape == (2, 32)
        _, _, done, infos = envs.step(np.array([1, 2]))
        assert done.tolist() == [False, False]
        assert all(set(i) - {"TimeLimit.truncated"} <= set(STEP_KEYS) for i in infos)
    finally:
        envs.close()


@pytest.mark.parametrize(("kwargs", "words"), [
    ({"backend": "threads"}, "backend: expected one of async, sync, subproc"),
    ({"num_envs": 0}, "num_envs: expected a positive whole number"),
])
def test_bad_arguments_are_named(kwargs, words):
    with pytest.raises(WrapperArgumentError, match=words):
        make_vector_env(ID, **{"num_envs": 2, **kwargs})


def test_step_info_refuses_a_string_of_keys():
    with pytest.raises(WrapperArgumentError, match="StepInfo keys"):
        StepInfo(gymnasium.make(ID, **FAST), keys="success")


def test_grouped_workers_play_the_single_process_episodes_and_autoreset():
    envs = make_vector_env(ID, 4, workers=2, **FAST)
    try:
        assert [len(g) for g in envs.unwrapped.groups] == [2, 2] and len(envs.unwrapped.processes) == 2
        seeds = [5, 6, 7, 8]
        obs, info = envs.reset(seed=seeds)
        assert obs["rgb"].shape == (4, 64, 64, 3) and info["_episode_key"].all()
        frames = [obs["rgb"]]
        moves = [[0, 1, 2, 3], [2, 0, 1, 1], [1, 4, 0, 2]]
        for row in moves:
            obs, _, terminated, truncated, info = envs.step(np.array(row))
            assert not (terminated.any() or truncated.any())
            frames.append(obs["rgb"])
        for i, seed in enumerate(seeds):
            single, tokens = _single(seed, [m[i] for m in moves])
            for got, want in zip(frames, single, strict=True):
                np.testing.assert_array_equal(got[i], want)
            np.testing.assert_array_equal(obs["instruction"][i], tokens)
        stop = _stop_index()
        _, _, terminated, _, info = envs.step(np.array([0, 0, stop, 0]))
        assert terminated.tolist() == [False, False, True, False] and info["_spl"].tolist() == [False, False, True,
                                                                                                 False]
        _, reward, terminated, _, _ = envs.step(np.array([0, 0, 0, 0]))  # env 2 resets in its worker
        assert not terminated.any() and reward[2] == 0.0
    finally:
        envs.close()


def test_a_worker_error_is_raised_here_naming_the_env():
    from luminous_sim.env.grouped_vector import VectorWorkerError

    envs = make_vector_env(ID, 2, workers=1, **FAST)
    try:
        with pytest.raises(VectorWorkerError, match="env 0 of the vector env raised in its worker"):
            envs.reset(seed=[1, 2], options={"no_such_option": 1})
    finally:
        envs.close()


def test_grouped_workers_must_be_between_one_and_the_envs():
    with pytest.raises(LuminousError, match="GroupedVectorEnv workers: expected a whole number from 1 to 2"):
        make_vector_env(ID, 2, workers=3, **FAST)
