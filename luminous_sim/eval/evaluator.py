"""Running a policy over episodes of a split with ALFRED's limits (1000 steps, 10 failed actions), in
this process, local worker processes or on a Ray cluster (`data.make_backend`).

Each episode is one job: the split's entry played in a `LuminousEnv` at ALFRED's camera and limits, from
`reset(options={"split": ..., "index": ...})` until the goal holds (the env ends the episode there), the
agent stops, or a limit cuts it off. An entry whose episode cannot be drawn is an outcome too (`end`
"unavailable", with its cause), never dropped. With an output folder every outcome is written as it
finishes (`episodes/<split>-<index>.json`, atomically), so an interrupted evaluation resumes where it
stopped; `run.json` records what the folder holds, and a folder of another evaluation is refused.
"""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.objio import write_atomic
from luminous_sim.data.backends import Backend
from luminous_sim.env import EnvConfig, EpisodeUnavailable, LuminousEnv
from luminous_sim.errors import LuminousError
from luminous_sim.eval.metrics import EpisodeOutcome, Metrics, metrics, metrics_by_type
from luminous_sim.eval.policies import Agent, PolicyError, check_policy, make_agent
from luminous_sim.eval.workers import map_local, map_ordered
from luminous_sim.splits import plus_split, split_entry

EVAL_ENV: dict[str, Any] = {"width": 300, "height": 300, "max_steps": 1000, "max_failures": 10,
                            "verify_expert": True, "expert_in_info": False}
"""ALFRED's camera and limits; the expert is proved at reset (it gives L*, the path-length weight)."""


@dataclass(frozen=True)
class EpisodeJob:
    """One episode to evaluate (plain data: it crosses process boundaries)."""

    policy: str
    split: str
    index: int
    seed: int
    env_json: str
    """The env's options (`EnvConfig.to_kwargs`) as JSON."""
    out_dir: str | None = None

    @property
    def path(self) -> Path | None:
        return None if self.out_dir is None else Path(self.out_dir) / "episodes" / f"{self.split}-{self.index}.json"


@dataclass(frozen=True)
class EvalReport:
    """A policy's outcomes on episodes of a split, and ALFRED's metrics over them."""

    policy: str
    split: str
    seed: int
    env_kwargs: dict[str, Any]
    outcomes: tuple[EpisodeOutcome, ...]
    per_type: dict[str, Metrics] = field(init=False)
    overall: Metrics = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "per_type", metrics_by_type(self.outcomes))
        object.__setattr__(self, "overall", metrics(self.outcomes))

    def unavailable(self) -> dict[str, int]:
        """Undrawn entries per cause."""
        return dict(sorted(Counter(o.cause for o in self.outcomes if not o.drawn).items()))

    def to_dict(self) -> dict[str, Any]:
        return {
            "policy": self.policy, "split": self.split, "seed": self.seed, "env": self.env_kwargs,
            "entries": len(self.outcomes), "drawn": self.overall.episodes, "unavailable": self.unavailable(),
            "overall": self.overall.to_dict(),
            "per_type": {t: m.to_dict() for t, m in self.per_type.items()},
            "episodes": [o.to_dict() for o in self.outcomes],
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> EvalReport:
        return cls(data["policy"], data["split"], data["seed"], data["env"],
                   tuple(EpisodeOutcome.from_dict(o) for o in data["episodes"]))


def episode_seed(seed: int, split: str, index: int) -> int:
    """The seed of the agent's randomness in one episode (the same whichever worker plays it)."""
    return int(np.random.SeedSequence([seed, plus_split(split).code, index]).generate_state(1)[0])


def play(env: LuminousEnv, agent: Agent, split: str, index: int, seed: int = 0) -> EpisodeOutcome:
    """One episode of a split, played by `agent` in `env` to its end.

    Raises:
        PolicyError: the agent raised (the message names the episode; the agent's error is chained).
    """
    entry = split_entry(split, index)
    own_seed = episode_seed(seed, split, index)
    try:
        obs, info = env.reset(seed=own_seed, options={"split": split, "index": index})
    except EpisodeUnavailable as exc:
        return EpisodeOutcome(split, index, entry.task_type, entry.floor_plan, entry.layout, end="unavailable",
                              cause=exc.cause, detail=exc.detail)
    assert env.episode is not None and env.episode.expert is not None, "the evaluation env proves the expert"
    steps, terminated, truncated = 0, False, False
    try:
        agent.reset(obs["instruction"], {**info, "episode_seed": own_seed})
        while not (terminated or truncated):
            action = agent.act(obs, info)
            obs, _, terminated, truncated, info = env.step(action)
            steps += 1
    except Exception as exc:
        raise PolicyError(f"the agent raised on {split} episode {index} at step {steps}: "
                          f"{type(exc).__name__}: {exc}") from exc
    stopped = terminated and not info["success"]
    if info["success"]:
        end = "success"
    elif stopped:
        end = "stop"
    else:
        end = "max_failures" if info["failures"] >= env.config.max_failures else "max_steps"
    met, total = info["goal_conditions"]
    return EpisodeOutcome(split, index, entry.task_type, entry.floor_plan, entry.layout, end=end,
                          success=bool(info["success"]), goal_conditions=(int(met), int(total)),
                          steps=steps - stopped, expert_length=len(env.episode.expert.actions),
                          failures=int(info["failures"]), instruction=str(obs["instruction"]))


_RUNNERS: dict[tuple[str, str], tuple[LuminousEnv, Agent]] = {}
"""This process's env and agent per (policy, env options): a user's agent is made once per worker."""


def run_job(job: EpisodeJob) -> EpisodeOutcome:
    """One job's outcome: read back from the output folder if an earlier run finished it, else played."""
    path = job.path
    if path is not None and path.is_file():
        return EpisodeOutcome.from_dict(json.loads(path.read_text()))
    key = (job.policy, job.env_json)
    if key not in _RUNNERS:
        env = LuminousEnv(**json.loads(job.env_json))
        _RUNNERS[key] = (env, make_agent(job.policy, env))
    env, agent = _RUNNERS[key]
    try:
        outcome = play(env, agent, job.split, job.index, job.seed)
    finally:
        env.close()  # frees the episode's simulator; the next reset builds a new one
    if path is not None:
        write_atomic(path, json.dumps(outcome.to_dict(), indent=1) + "\n")
    return outcome


def _claim(out_dir: Path, run: dict[str, Any]) -> None:
    """Record what `out_dir` holds, or refuse a folder that holds another evaluation."""
    path = out_dir / "run.json"
    if path.is_file():
        try:
            old = json.loads(path.read_text())
        except json.JSONDecodeError as exc:
            raise LuminousError(f"{path}: not JSON ({exc}); is this an evaluation folder?") from None
        if old != run:
            diff = ", ".join(f"{k} {old.get(k)!r} (asked {run[k]!r})" for k in run if old.get(k) != run[k])
            raise LuminousError(f"{out_dir} holds another evaluation ({diff}); choose another output folder")
    else:
        write_atomic(path, json.dumps(run, indent=1) + "\n")


def evaluate(policy: str, split: str, episodes: int | Iterable[int], *, seed: int = 0, workers: int = 1,
             out_dir: Path | None = None, env_kwargs: dict[str, Any] | None = None,
             progress: Callable[[EpisodeOutcome], None] | None = None,
             backend: Backend | None = None) -> EvalReport:
    """Run `policy` (`oracle`, `random` or `MODULE:CALLABLE`) on episodes of `split`.

    Args:
        policy: the policy spec (see `luminous_sim.eval.policies`).
        split: S+, U+ or U+test.
        episodes: a count N (entries 0 .. N-1) or the entry indices.
        seed: the agents' randomness (the episodes themselves are fixed by the split).
        workers: local processes (when no `backend` is given).
        out_dir: where each outcome is written as it finishes (an interrupted run resumes there).
        env_kwargs: env options over ALFRED's (`EVAL_ENV`), e.g. `targets="objects"`.
        progress: called with each outcome, in order.
        backend: where the episodes run instead (`data.make_backend("ray", workers, address)` for a Ray
            cluster); the outcomes are the same whatever the backend. With Ray, a user's agent module must
            be importable by the workers (on `PYTHONPATH`, or installed on every node).

    Raises:
        PolicyError, SplitError, LuminousError: a bad policy spec, split, index or env option (before any work).
    """
    check_policy(policy)
    plus_split(split)
    indices: Sequence[int] = range(episodes) if isinstance(episodes, int) else list(episodes)
    if not indices:
        raise LuminousError("episodes: expected at least one episode")
    for i in indices:
        split_entry(split, i)
    kwargs = {**EVAL_ENV, **(env_kwargs or {})}
    config = EnvConfig.from_kwargs(kwargs)
    if not config.verify_expert:
        raise LuminousError("env option verify_expert: an evaluation needs the expert's length (PLW metrics)")
    env_json = json.dumps(config.to_kwargs(), sort_keys=True)
    if out_dir is not None:
        _claim(out_dir, {"policy": policy, "split": split, "seed": seed, "env": config.to_kwargs()})
    jobs = [EpisodeJob(policy, split, i, seed, env_json, None if out_dir is None else str(out_dir)) for i in indices]
    outcomes = []
    runs = map_local(run_job, jobs, workers) if backend is None else map_ordered(run_job, jobs, backend)
    for outcome in runs:
        outcomes.append(outcome)
        if progress is not None:
            progress(outcome)
    return EvalReport(policy, split, seed, config.to_kwargs(), tuple(outcomes))
