"""Running a policy over episodes of a split with ALFRED's limits (1000 steps, 10 failed actions), in
this process, local worker processes or on a Ray cluster (`data.make_backend`).

Each episode is one job: the split's entry played in a `LuminousEnv` at ALFRED's camera and limits, from
`reset(options={"split": ..., "index": ...})` until the goal holds (the env ends the episode there), the
agent stops, or a limit cuts it off. An entry whose episode cannot be drawn is an outcome too (`end`
"unavailable", with its cause), never dropped. With an output folder every outcome is written as it
finishes (`episodes/<split>-<index>.json`, atomically), so an interrupted evaluation resumes where it
stopped; `run.json` records what the folder holds, and a folder of another evaluation, or a non-empty one
that holds no evaluation, is refused. On resume an episode file is read back only if it is what this
evaluation writes (a regular file within `limits.MAX_EPISODE_FILE_BYTES`, every field checked, the job's
own split entry, and its `check` - a digest of its other fields written with it, as the build manifest's lines
carry - matching them); a damaged or edited one (truncated, `[]`, `{}`, a field of the wrong kind, a field
changed but still well-formed, another episode's, one without a `check`) is played again and overwritten,
and counted in `EvalReport.replayed`.

An agent that raises stops the evaluation (`PolicyError`). An agent that returns something that is not an
action (None, an index outside the space, an unknown action, arguments the env cannot decode such as a
malformed mask) ends its episode as `invalid_action` with cause `AGENT_FAULT` and the step and the env's
message in `detail`; a mask that decodes but hits nothing is an ordinary failed action, as in ALFRED.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import shutil
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.objio import write_atomic
from luminous_sim.data.backends import Backend
from luminous_sim.env import EnvConfig, EpisodeUnavailable, LuminousEnv
from luminous_sim.errors import LuminousError, link_or_kind
from luminous_sim.eval.metrics import AGENT_FAULT, EpisodeOutcome, Metrics, metrics, metrics_by_type
from luminous_sim.eval.policies import Agent, PolicyError, check_policy, make_agent
from luminous_sim.eval.workers import map_local, map_ordered
from luminous_sim.limits import MAX_EPISODE_FILE_BYTES, MAX_EVAL_EPISODES
from luminous_sim.splits import plus_split, split_entry

EVAL_ENV: dict[str, Any] = {"width": 300, "height": 300, "max_steps": 1000, "max_failures": 10,
                            "verify_expert": True, "expert_in_info": False}
"""ALFRED's camera and limits; the expert is proved at reset (it gives L*, the path-length weight)."""
EVAL_SETS = ("split", "cdf")
"""Env options the evaluation sets itself for each episode (`--split`, the split's entries): a value for
them in `env_kwargs` other than the evaluation's own is refused, never silently overridden."""
NOT_AN_ACTION = frozenset({"invalid_argument", "unknown_action"})
"""`info["failure_code"]`s that say the agent's output was not an action at all (see the module docstring)."""
RUN_FILE = "run.json"
EVAL_FILES = frozenset({RUN_FILE, "episodes", "report.json", "table.md", "metrics.png"})
"""What an evaluation folder holds."""


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
    replayed: tuple[str, ...] = ()
    """Episode files found damaged on resume and played again (each with why)."""
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
    fault = ""
    try:
        agent.reset(obs["instruction"], {**info, "episode_seed": own_seed})
    except Exception as exc:
        raise PolicyError(f"the agent raised on {split} episode {index} at reset: {type(exc).__name__}: {exc}") from exc
    while not (terminated or truncated):
        try:
            action = agent.act(obs, info)
        except Exception as exc:
            raise PolicyError(f"the agent raised on {split} episode {index} at step {steps}: "
                              f"{type(exc).__name__}: {exc}") from exc
        fault = _not_an_action(action)
        if not fault:
            obs, _, terminated, truncated, info = env.step(action)
            if info.get("failure_code") in NOT_AN_ACTION:
                fault = str(info.get("error") or info["failure_code"])
        steps += 1
        if fault:
            fault = f"step {steps}: the agent returned {_shown(action)}, not an action of the env: {fault}"
            break
    stopped = terminated and not info["success"]
    if fault:
        end = "invalid_action"
    elif info["success"]:
        end = "success"
    elif stopped:
        end = "stop"
    else:
        end = "max_failures" if info["failures"] >= env.config.max_failures else "max_steps"
    met, total = info["goal_conditions"]
    return EpisodeOutcome(split, index, entry.task_type, entry.floor_plan, entry.layout, end=end,
                          success=bool(info["success"]) and not fault, goal_conditions=(int(met), int(total)),
                          steps=steps - stopped, expert_length=len(env.episode.expert.actions),
                          failures=int(info["failures"]), instruction=str(obs["instruction"]),
                          cause=AGENT_FAULT if fault else "", detail=fault)


def _not_an_action(action: Any) -> str:
    """Why `action` cannot be an action of any Luminous env (checked before the env sees it), or ""."""
    if isinstance(action, np.ndarray) and action.shape == () and action.dtype.kind in "iu":
        return ""
    if isinstance(action, (int, np.integer)) and not isinstance(action, bool):
        return ""
    if isinstance(action, dict) and isinstance(action.get("action"), str):
        return ""
    return "an action is an index of the action space or a dict with an 'action' name"


def _shown(action: Any) -> str:
    text = repr(action)
    return text if len(text) <= 80 else text[:77] + "..."


_RUNNERS: dict[tuple[str, str], tuple[LuminousEnv, Agent]] = {}
"""This process's env and agent per (policy, env options): a user's agent is made once per worker."""


CHECK = "check"
"""The field of an episode file that holds the digest of its other fields (written with it, verified on read)."""


def _digest(fields: dict[str, Any]) -> str:
    canonical = json.dumps(fields, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode()).hexdigest()[:16]


def outcome_record(outcome: EpisodeOutcome) -> dict[str, Any]:
    """What an episode file holds: the outcome's fields and their digest under `CHECK`."""
    fields = outcome.to_dict()
    return {**fields, CHECK: _digest(fields)}


def read_outcome(path: Path, split: str, index: int) -> EpisodeOutcome:
    """The outcome an earlier run wrote at `path` for episode `index` of `split`.

    Raises:
        LuminousError: not a regular file (a folder, a link, a device), over `MAX_EPISODE_FILE_BYTES`, not
            JSON, a field missing or of the wrong kind, its `check` missing or not the digest of its other
            fields (an edit), or another episode's outcome; the message names the file and the field.
    """
    if path.is_symlink() or not path.is_file():
        raise LuminousError(f"{path}: {link_or_kind(path)}; expected an episode outcome file")
    size = path.stat().st_size
    if size > MAX_EPISODE_FILE_BYTES:
        raise LuminousError(f"{path}: {size} bytes; an episode outcome file holds at most {MAX_EPISODE_FILE_BYTES} "
                            "(luminous_sim.limits.MAX_EPISODE_FILE_BYTES)")
    try:
        data = json.loads(path.read_bytes())
    except (ValueError, RecursionError) as exc:
        raise LuminousError(f"{path}: not JSON ({exc})") from None
    recorded = data.pop(CHECK, None) if isinstance(data, dict) else None
    outcome = EpisodeOutcome.from_dict(data, str(path))
    if recorded is None:
        raise LuminousError(f"{path}: field {CHECK!r} is missing; expected the digest an evaluation writes with each "
                            "outcome")
    if recorded != _digest(data):
        shown = repr(recorded) if len(repr(recorded)) <= 40 else repr(recorded)[:37] + "..."
        raise LuminousError(f"{path}: field {CHECK!r}: {shown} is not the digest of the file's other fields "
                            f"({_digest(data)}); the file was edited or damaged")
    entry = split_entry(split, index)
    mine = (split, index, entry.task_type, entry.floor_plan, entry.layout)
    for name, value, want in zip(("split", "index", "task_type", "floor_plan", "layout"),
                                 (outcome.split, outcome.index, outcome.task_type, outcome.floor_plan, outcome.layout),
                                 mine):
        if value != want:
            raise LuminousError(f"{path}: field {name!r}: {value!r}, but the file is episode {index} of {split}, "
                                f"whose {name} is {want!r}")
    return outcome


def run_job(job: EpisodeJob) -> EpisodeOutcome:
    """One job's outcome: read back from the output folder if an earlier run finished it (and its file is
    intact), else played."""
    return _run_job(job)[0]


def _run_job(job: EpisodeJob) -> tuple[EpisodeOutcome, str]:
    """`run_job`, and why the file an earlier run left was damaged and the episode played again ("": it was
    not)."""
    path = job.path
    damaged = ""
    if path is not None and (path.exists() or path.is_symlink()):
        try:
            return read_outcome(path, job.split, job.index), ""
        except LuminousError as exc:
            damaged = str(exc)
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            else:
                path.unlink()
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
        write_atomic(path, json.dumps(outcome_record(outcome), indent=1) + "\n")
    return outcome, damaged


def _claim(out_dir: Path, run: dict[str, Any]) -> None:
    """Record what `out_dir` holds, or refuse a folder that holds another evaluation, one that is not empty
    and holds no evaluation, and one whose files are not what an evaluation writes (a folder or a link
    where `run.json` belongs, `episodes` a link or a file)."""
    out_dir = Path(out_dir)
    if out_dir.exists() and not out_dir.is_dir():
        raise LuminousError(f"{out_dir}: exists and is not a folder; expected an evaluation's output folder")
    path = out_dir / RUN_FILE
    episodes = out_dir / "episodes"
    if episodes.is_symlink() or (episodes.exists() and not episodes.is_dir()):
        raise LuminousError(f"{episodes}: {'a symbolic link' if episodes.is_symlink() else 'not a folder'}; "
                            "expected the folder of episode outcomes")
    if path.exists() or path.is_symlink():
        if path.is_symlink() or not path.is_file():
            raise LuminousError(f"{path}: {link_or_kind(path)}; "
                                "expected the evaluation's run.json")
        try:
            old = json.loads(path.read_bytes()[:MAX_EPISODE_FILE_BYTES])
        except (ValueError, RecursionError) as exc:
            raise LuminousError(f"{path}: not JSON ({exc}); is this an evaluation folder?") from None
        if not isinstance(old, dict):
            raise LuminousError(f"{path}: expected a JSON object (what the folder's evaluation ran), "
                                f"got {type(old).__name__}")
        if old != run:
            diff = ", ".join(f"{k} {old.get(k)!r} (asked {run[k]!r})" for k in run if old.get(k) != run[k])
            raise LuminousError(f"{out_dir} holds another evaluation ({diff}); choose another output folder")
        return
    others = sorted(p.name for p in out_dir.iterdir() if p.name not in EVAL_FILES) if out_dir.is_dir() else []
    if others:
        more = " ..." if len(others) > 5 else ""
        raise LuminousError(f"{out_dir} is not empty and holds no evaluation ({RUN_FILE} missing; it has "
                            f"{', '.join(others[:5])}{more}); choose a new or empty folder")
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
    if isinstance(episodes, int) and not 1 <= episodes <= MAX_EVAL_EPISODES:
        raise LuminousError(f"episodes: expected 1 to {MAX_EVAL_EPISODES} (luminous_sim.limits.MAX_EVAL_EPISODES), "
                            f"got {episodes}")
    indices: Sequence[int] = range(episodes) if isinstance(episodes, int) else list(
        itertools.islice(episodes, MAX_EVAL_EPISODES + 1))
    if not indices:
        raise LuminousError("episodes: expected at least one episode")
    if len(indices) > MAX_EVAL_EPISODES:
        raise LuminousError(f"episodes: more than {MAX_EVAL_EPISODES} (luminous_sim.limits.MAX_EVAL_EPISODES)")
    for i in indices:
        split_entry(split, i)
    for name in EVAL_SETS:
        value = (env_kwargs or {}).get(name)
        if name == "split" and value not in (None, "", split):
            raise LuminousError(f"env option split={value!r}: the evaluation plays split {split} (its --split); "
                                "leave the env option out or give the same split")
        if name == "cdf" and value not in (None, "", [], ()):
            raise LuminousError(f"env option cdf={value!r}: an evaluation plays the entries of split {split}, "
                                "not CDF scenes; leave the env option out")
    kwargs = {**EVAL_ENV, **(env_kwargs or {})}
    config = EnvConfig.from_kwargs(kwargs)
    if not config.verify_expert:
        raise LuminousError("env option verify_expert: an evaluation needs the expert's length (PLW metrics)")
    env_json = json.dumps(config.to_kwargs(), sort_keys=True)
    if out_dir is not None:
        _claim(out_dir, {"policy": policy, "split": split, "seed": seed, "env": config.to_kwargs()})
    jobs = [EpisodeJob(policy, split, i, seed, env_json, None if out_dir is None else str(out_dir)) for i in indices]
    outcomes, replayed = [], []
    runs = map_local(_run_job, jobs, workers) if backend is None else map_ordered(_run_job, jobs, backend)
    for outcome, damaged in runs:
        outcomes.append(outcome)
        if damaged:
            replayed.append(damaged)
        if progress is not None:
            progress(outcome)
    return EvalReport(policy, split, seed, config.to_kwargs(), tuple(outcomes), tuple(replayed))
