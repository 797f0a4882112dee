"""`GroupedVectorEnv`: N envs in W worker processes, each worker stepping its share of the envs in turn.

Why: on two cores, gymnasium's `AsyncVectorEnv` (one process per env) runs a 64 px env at about 1.2-1.35x one
process, while two independent env processes reach 1.97x (docs/benchmarks.md, "Environment speed"). Measured
per vector step of two workers: each worker computes for about 2.0 ms, yet the step takes 2.9 ms; the rest is
waiting in lock step (a failed move renders nothing and returns at once, while the other worker renders) and
waking processes (a VM's idle cores wake slowly). More processes than cores do not help (4 and 8 gave the same
rate: they pay in context switches what they save in waiting). A worker that steps k envs in turn waits once
per k steps, and the lengths of k steps vary less, relatively, than one's.

Semantics are gymnasium's `AsyncVectorEnv` with shared memory: the observations in a shared buffer (returned
as views unless `copy`), infos merged per key with `_key` masks, next-step autoreset in the worker. A worker
that raises sends the error back; the call raises it in this process, naming the env. It offers `reset`,
`step` and `close` (what a training loop calls), not `AsyncVectorEnv`'s `call`/`set_attr`.
"""

from __future__ import annotations

import multiprocessing as mp
import traceback
from collections.abc import Callable, Sequence
from copy import deepcopy
from typing import Any

import gymnasium
import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space, create_shared_memory, read_from_shared_memory, write_to_shared_memory

from luminous_sim.errors import LuminousError


class VectorWorkerError(LuminousError):
    """An env in a worker process raised; the message names the env and carries the worker's traceback."""


def _worker(indices: list[int], makers: list[Callable[[], gymnasium.Env]], pipe: Any, shared: Any,
            space: gymnasium.Space) -> None:
    envs: list[gymnasium.Env] = []
    autoreset: list[bool] = []
    current = indices[0]
    try:
        for i, make in zip(indices, makers, strict=True):
            current = i
            envs.append(make())
            autoreset.append(False)
        pipe.send(("ok", None))
        while True:
            command, data = pipe.recv()
            if command == "close":
                break
            out: list[Any] = []
            for j, (i, env) in enumerate(zip(indices, envs, strict=True)):
                current = i
                if command == "reset":
                    seed, options = data[j]
                    obs, info = env.reset(seed=seed, options=options)
                    autoreset[j] = False
                    out.append(info)
                elif autoreset[j]:
                    obs, info = env.reset()
                    autoreset[j] = False
                    out.append((0.0, False, False, info))
                else:
                    obs, reward, terminated, truncated, info = env.step(data[j])
                    autoreset[j] = bool(terminated or truncated)
                    out.append((reward, terminated, truncated, info))
                write_to_shared_memory(space, i, obs, shared)
            pipe.send(("ok", out))
    except Exception:  # sent back whole: the caller raises it, naming the env
        pipe.send(("error", (current, traceback.format_exc())))
    finally:
        for env in envs:
            env.close()
        pipe.close()


class GroupedVectorEnv(VectorEnv):
    """`len(env_fns)` envs in `workers` processes (envs split as evenly as possible, in order).

    Args:
        env_fns: picklable env makers (the same spaces).
        workers: worker processes (at most the number of envs).
        copy: return copies of the observations (False: views of the shared buffer, overwritten by the next
            call).
        context: a `multiprocessing` start method (default fork, where the platform has it).
    """

    def __init__(self, env_fns: Sequence[Callable[[], gymnasium.Env]], workers: int, *, copy: bool = True,
                 context: str | None = None):
        n = len(env_fns)
        if isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= n:
            raise LuminousError(f"GroupedVectorEnv workers: expected a whole number from 1 to {n} (the envs), "
                                f"got {workers!r}")
        self.metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP}
        probe = env_fns[0]()
        self.single_observation_space, self.single_action_space = probe.observation_space, probe.action_space
        self.spec, self.render_mode = probe.spec, probe.render_mode
        probe.close()
        self.num_envs, self.copy = n, copy
        self.observation_space = batch_space(self.single_observation_space, n)
        self.action_space = batch_space(self.single_action_space, n)
        ctx: Any = mp.get_context(context or ("fork" if "fork" in mp.get_all_start_methods() else None))
        self._shared = create_shared_memory(self.single_observation_space, n, ctx=ctx)
        self._observations = read_from_shared_memory(self.single_observation_space, self._shared, n)
        self.groups = [list(map(int, g)) for g in np.array_split(np.arange(n), workers)]
        self._pipes, self.processes = [], []
        for group in self.groups:
            parent, child = ctx.Pipe()
            proc = ctx.Process(target=_worker, daemon=True, name=f"luminous-vector-{group[0]}",
                               args=(group, [env_fns[i] for i in group], child, self._shared,
                                     self.single_observation_space))
            proc.start()
            child.close()
            self._pipes.append(parent)
            self.processes.append(proc)
        self.closed = False
        self._receive()

    def _receive(self) -> list[Any]:
        replies = [pipe.recv() for pipe in self._pipes]
        errors = [data for status, data in replies if status == "error"]
        if errors:
            index, trace = errors[0]
            self.close(terminate=True)
            raise VectorWorkerError(f"env {index} of the vector env raised in its worker:\n{trace}")
        return [data for _, data in replies]

    def _observation(self) -> Any:
        return deepcopy(self._observations) if self.copy else self._observations

    def reset(self, *, seed: int | list[int | None] | None = None,
              options: dict[str, Any] | None = None) -> tuple[Any, dict[str, Any]]:
        seeds = seed if isinstance(seed, list) else [None if seed is None else seed + i for i in range(self.num_envs)]
        if len(seeds) != self.num_envs:
            raise LuminousError(f"reset seed: expected {self.num_envs} seeds, got {len(seeds)}")
        for pipe, group in zip(self._pipes, self.groups, strict=True):
            pipe.send(("reset", [(seeds[i], options) for i in group]))
        infos: dict[str, Any] = {}
        for group, out in zip(self.groups, self._receive(), strict=True):
            for i, info in zip(group, out, strict=True):
                infos = self._add_info(infos, info, i)
        return self._observation(), infos

    def step(self, actions: Any) -> tuple[Any, np.ndarray, np.ndarray, np.ndarray, dict[str, Any]]:
        actions = list(actions)
        for pipe, group in zip(self._pipes, self.groups, strict=True):
            pipe.send(("step", [actions[i] for i in group]))
        rewards = np.zeros(self.num_envs, np.float64)
        terminated = np.zeros(self.num_envs, np.bool_)
        truncated = np.zeros(self.num_envs, np.bool_)
        infos: dict[str, Any] = {}
        for group, out in zip(self.groups, self._receive(), strict=True):
            for i, (reward, term, trunc, info) in zip(group, out, strict=True):
                rewards[i], terminated[i], truncated[i] = reward, term, trunc
                infos = self._add_info(infos, info, i)
        return self._observation(), rewards, terminated, truncated, infos

    def close_extras(self, *, terminate: bool = False, **kwargs: Any) -> None:
        for pipe, proc in zip(self._pipes, self.processes, strict=True):
            if terminate or not proc.is_alive():
                proc.terminate()
                continue
            try:
                pipe.send(("close", None))
            except (BrokenPipeError, OSError):
                proc.terminate()
        for proc in self.processes:
            proc.join(timeout=10)
        for pipe in self._pipes:
            pipe.close()
