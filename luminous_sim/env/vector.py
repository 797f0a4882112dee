"""Vectorised Luminous envs for learners: `make_vector_env` runs N envs in worker processes with what a training
loop needs per step and nothing more.

Two workers of a 64 px env stepped through a plain `AsyncVectorEnv` gained 1.2x on two cores (docs/benchmarks.md,
"Environment speed"): the main process has to be nearly idle for two workers to use both cores. So:

- the observation crosses as numbers in shared memory (gymnasium's `shared_memory=True`): the instruction as
  token ids (`InstructionTokens`, encoded once an episode, not per step), never as text through the pipe;
- per step, `info` carries only `step_keys` (by default `success`, `failures`, `failure_code`): gymnasium
  pickles every step's info in the worker and merges it key by key in the main process, which cost about a
  quarter of the main process's time per step with the env's full info (13 keys, lists and strings); the full
  info still comes on `reset` and on the step that ends an episode (`StepInfo`);
- autoreset happens in the worker (gymnasium's next-step mode): the step after an episode ends resets it there,
  and the main process only reads the new observation from shared memory.

With `workers` fewer than the envs, each worker process steps its share of the envs in turn
(`GroupedVectorEnv`): lock-step waiting and process wake-ups are paid once per worker, not per env, which is
what lets two workers use two cores (docs/benchmarks.md, "Environment speed").

`backend="subproc"` gives stable-baselines3's `SubprocVecEnv` over the same wrapped envs (SB3's own vector
API: `reset()` returns only observations, autoreset in the same step), for SB3 users.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import partial
from typing import Any

import gymnasium

from luminous_sim.env.wrappers import InstructionTokens, WrapperArgumentError

STEP_KEYS: tuple[str, ...] = ("success", "failures", "failure_code")
"""The info keys every step keeps by default (`StepInfo`)."""
BACKENDS = ("async", "sync", "subproc")


class StepInfo(gymnasium.Wrapper, gymnasium.utils.RecordConstructorArgs):
    """Per step, `info` keeps only `keys`; the info of `reset` and of the step that ends an episode (terminated
    or truncated) is passed whole.

    Args:
        env: a Luminous env, wrapped or not.
        keys: the info keys kept on the other steps.
    """

    def __init__(self, env: gymnasium.Env, keys: Sequence[str] = STEP_KEYS):
        if isinstance(keys, str) or not all(isinstance(k, str) for k in keys):
            raise WrapperArgumentError(f"StepInfo keys: expected a sequence of info key names, got {keys!r}")
        gymnasium.utils.RecordConstructorArgs.__init__(self, keys=tuple(keys))
        gymnasium.Wrapper.__init__(self, env)
        self.keys = tuple(keys)

    def step(self, action: Any) -> tuple[Any, Any, bool, bool, dict[str, Any]]:
        observation, reward, terminated, truncated, info = self.env.step(action)
        if not (terminated or truncated):
            info = {k: info[k] for k in self.keys if k in info}
        return observation, reward, terminated, truncated, info


def wrapped_env(env_id: str, *, tokens: int = 32, step_keys: Sequence[str] | None = STEP_KEYS,
                **kwargs: Any) -> gymnasium.Env:
    """`gymnasium.make(env_id, **kwargs)` with the instruction as `tokens` token ids (0: left as text) and
    per-step info cut to `step_keys` (None: whole): one worker's env of `make_vector_env`."""
    env = gymnasium.make(env_id, **kwargs)
    if tokens:
        env = InstructionTokens(env, tokens)
    return env if step_keys is None else StepInfo(env, step_keys)


def env_makers(env_id: str, num_envs: int, **kwargs: Any) -> list[Callable[[], gymnasium.Env]]:
    """`num_envs` picklable makers of `wrapped_env(env_id, **kwargs)`."""
    if isinstance(num_envs, bool) or not isinstance(num_envs, int) or num_envs < 1:
        raise WrapperArgumentError(f"num_envs: expected a positive whole number, got {num_envs!r}")
    return [partial(wrapped_env, env_id, **kwargs) for _ in range(num_envs)]


def make_vector_env(env_id: str, num_envs: int = 2, *, backend: str = "async", workers: int | None = None,
                    tokens: int = 32, step_keys: Sequence[str] | None = STEP_KEYS, copy: bool = True,
                    **kwargs: Any) -> Any:
    """`num_envs` copies of a registered id in worker processes (see the module docstring).

    Args:
        env_id: a registered id; `kwargs` are its env options (`EnvConfig`).
        num_envs: how many envs (one worker process each, unless `workers`; `sync`: all in this process).
        backend: `async` (gymnasium's `AsyncVectorEnv`, shared memory), `sync` (`SyncVectorEnv`, for
            debugging) or `subproc` (stable-baselines3's `SubprocVecEnv`; needs the `learn` extra).
        workers: `async`: worker processes, each stepping its share of the envs in turn (`GroupedVectorEnv`);
            None: one per env (gymnasium's `AsyncVectorEnv`).
        tokens: instruction length in token ids (0: the instruction stays text, and `async` copies it each step).
        step_keys: info keys kept on steps that do not end an episode (None: the env's whole info).
        copy: `async`: return copies of the observations (False: views into the shared buffers, overwritten by
            the next step; cheaper, for a loop that copies them into its own buffers at once).
    """
    if backend not in BACKENDS:
        raise WrapperArgumentError(f"backend: expected one of {', '.join(BACKENDS)}, got {backend!r}")
    makers = env_makers(env_id, num_envs, tokens=tokens, step_keys=step_keys, **kwargs)
    if backend == "sync":
        return gymnasium.vector.SyncVectorEnv(makers)
    if backend == "subproc":
        from stable_baselines3.common.vec_env import SubprocVecEnv

        return SubprocVecEnv(makers, start_method="fork")
    if workers is not None and workers != num_envs:
        from luminous_sim.env.grouped_vector import GroupedVectorEnv

        return GroupedVectorEnv(makers, workers, copy=copy)
    return gymnasium.vector.AsyncVectorEnv(makers, shared_memory=True, copy=copy, context="fork")
