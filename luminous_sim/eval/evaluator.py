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

A user's agent runs in a child process of the worker (`sandbox.AgentProcess`, with `sandbox.AgentLimits`): a
`reset()` or `act()` call over the step limit ends its episode as `agent_timeout` (cause `AGENT_FAULT`, a
failure) and the next episode gets a fresh process; an agent that raises, exits, is killed or goes past its
memory limit stops the evaluation (`AgentCrashed`, naming the cause, the episode and the step; a built-in or
in-process agent that raises: `PolicyError`). An agent that returns something that is not an
action (None, an index outside the space, an unknown action, arguments the env cannot decode such as a
malformed mask) ends its episode as `invalid_action` with cause `AGENT_FAULT` and the step and the env's
message in `detail`; a mask that decodes but hits nothing is an ordinary failed action, as in ALFRED.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import itertools
import json
import shutil
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.benchmark import benchmark_entry, benchmark_size
from luminous_sim.data.backends import Backend
from luminous_sim.env import EnvConfig, EpisodeUnavailable, LuminousEnv
from luminous_sim.errors import LuminousError, link_or_kind, read_json_file
from luminous_sim.eval.metrics import (
    AGENT_FAULT,
    BROKEN_TRIAL,
    BUILD,
    BUILD_CRASH,
    EpisodeOutcome,
    Metrics,
    metrics,
    metrics_by_type,
)
from luminous_sim.eval.policies import Agent, PolicyError, ReplayAgent, check_policy, make_agent
from luminous_sim.eval.sandbox import AgentCrashed, AgentLimits, AgentTimeout
from luminous_sim.eval.tracks import agent_info, check_track, object_id_action, track_env
from luminous_sim.eval.trials import trial_problem
from luminous_sim.eval.workers import map_local, map_ordered
from luminous_sim.fileio import shown, write_atomic
from luminous_sim.limits import MAX_EPISODE_FILE_BYTES, MAX_EVAL_EPISODES, MAX_INPUT_BYTES
from luminous_sim.splits import plus_split

EVAL_ENV: dict[str, Any] = {"width": 300, "height": 300, "max_steps": 1000, "max_failures": 10,
                            "verify_expert": True, "expert_in_info": False, "high_descs": True}
"""ALFRED's camera and limits; the expert is proved at reset (it gives L*, the path-length weight); the agent
reads the goal directive (`instruction`) and the step-by-step instructions (`high_descs`), as ALFRED's do."""
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
    trial: str = ""
    """A built trial's folder to play (restored from its files); "" plays the split's entry `index` live."""
    trial_rel: str = ""
    """`trial` relative to the dataset folder (what the outcome records)."""
    unbuilt: str = ""
    """A build job that wrote no trial (its stage and cause): the outcome is `unavailable`, cause `build`."""
    named: tuple[str, str, int] | None = None
    """(task type, floor plan, layout) of an unbuilt job, as the build recorded them."""
    stage: str = ""
    """The build stage an unbuilt job failed at: one of `data.RETRIED_STAGES` makes its outcome `BUILD_CRASH`."""
    broken: str = ""
    """Why the listed trial folder cannot be read (`TrialRef.broken`): the outcome is `unavailable`, cause
    `broken_trial`, and nothing in the folder is read."""
    limits: AgentLimits = field(default_factory=AgentLimits)
    """The limits of a user's agent process (`sandbox.AgentLimits`: step time, memory)."""

    @property
    def path(self) -> Path | None:
        return None if self.out_dir is None else Path(self.out_dir) / "episodes" / f"{self.split}-{self.index}.json"

    def where(self) -> tuple[str, str, int]:
        """(task type, floor plan, layout) of the episode: the frozen entry's, or what the trial's files say."""
        if self.named is not None:
            return self.named
        if not self.trial:
            entry = benchmark_entry(self.split, self.index)
            return entry.task_type, entry.floor_plan, entry.layout
        return _trial_where(self.trial, self.split)


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
    track: str = "rgb"
    """The evaluation's track (`tracks.TRACKS`)."""
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
            "policy": self.policy, "split": self.split, "track": self.track, "seed": self.seed, "env": self.env_kwargs,
            "entries": len(self.outcomes), "drawn": self.overall.episodes, "unavailable": self.unavailable(),
            "overall": self.overall.to_dict(),
            "per_type": {t: m.to_dict() for t, m in self.per_type.items()},
            "episodes": [o.to_dict() for o in self.outcomes],
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> EvalReport:
        return cls(data["policy"], data["split"], data["seed"], data["env"],
                   tuple(EpisodeOutcome.from_dict(o) for o in data["episodes"]), track=data.get("track", "rgb"))


def episode_seed(seed: int, split: str, index: int) -> int:
    """The seed of the agent's randomness in one episode (the same whichever worker plays it); a split that is
    not one of ours (a user's dataset folder) is told apart by a digest of its name."""
    from luminous_sim.splits import PLUS_SPLITS

    code = PLUS_SPLITS[split].code if split in PLUS_SPLITS else int(hashlib.sha256(split.encode()).hexdigest()[:8], 16)
    return int(np.random.SeedSequence([seed, code, index]).generate_state(1)[0])


def play(env: LuminousEnv, agent: Agent, split: str, index: int, seed: int = 0, *, trial: str = "",
         trial_rel: str = "", object_ids: bool = False) -> EpisodeOutcome:
    """One episode played by `agent` in `env` to its end: entry `index` of the frozen split `split`, or with
    `trial` the built trial in that folder (restored from its files; `split` and `index` then name it). The
    agent reads only `tracks.agent_info` of the env's `info`; an action naming an object id ends the episode
    as an invalid action unless `object_ids` (the built-in oracle's).

    Raises:
        PolicyError: the agent raised (the message names the episode; the agent's error is chained).
    """
    task_type, floor_plan, layout = EpisodeJob("", split, index, 0, "", trial=trial).where()
    own_seed = episode_seed(seed, split, index)
    options: dict[str, Any] = {"trial": trial} if trial else {"split": split, "index": index}
    named: dict[str, Any] = {"split": split, "index": index, "task_type": task_type, "floor_plan": floor_plan,
                             "layout": layout, "trial": trial_rel}
    try:
        obs, info = env.reset(seed=own_seed, options=options)
    except EpisodeUnavailable as exc:
        return EpisodeOutcome(**named, end="unavailable", cause=exc.cause, detail=exc.detail)
    assert env.episode is not None and env.episode.expert is not None, "the evaluation env proves the expert"
    key = str(info["episode_key"])
    steps, terminated, truncated, timed_out = 0, False, False, False
    fault = ""
    try:
        steps_text = obs.get("high_descs", "")
        agent.reset(obs["instruction"], agent_info(info, episode_seed=own_seed,
                                                   high_descs=steps_text.split("\n") if steps_text.strip(".") else []))
    except AgentTimeout as exc:  # the agent's process was killed; the next episode gets a fresh one
        fault, timed_out = f"at reset: {exc}", True
    except AgentCrashed as exc:
        raise exc.on(split, index) from None
    except Exception as exc:
        raise PolicyError(f"the agent raised on {split} episode {index} at reset: {type(exc).__name__}: {exc}") from exc
    while not (terminated or truncated or timed_out):
        try:
            action = agent.act(obs, agent_info(info))
        except AgentTimeout as exc:
            fault, timed_out = f"step {steps + 1}: {exc}", True
            break
        except AgentCrashed as exc:
            raise exc.on(split, index, steps + 1) from None
        except Exception as exc:
            raise PolicyError(f"the agent raised on {split} episode {index} at step {steps}: "
                              f"{type(exc).__name__}: {exc}") from exc
        fault = _not_an_action(action)
        if not fault and not object_ids and object_id_action(action):
            fault = "an evaluated agent names its target by a mask or a point, not by object id"
        if not fault:
            obs, _, terminated, truncated, info = env.step(action)
            if info.get("failure_code") in NOT_AN_ACTION:
                fault = str(info.get("error") or info["failure_code"])
        steps += 1
        if fault:
            fault = f"step {steps}: the agent returned {_shown(action)}, not an action of the env: {fault}"
            break
    stopped = terminated and not info["success"]
    if timed_out:
        end = "agent_timeout"
    elif fault:
        end = "invalid_action"
    elif info["success"]:
        end = "success"
    elif stopped:
        end = "stop"
    else:
        end = "max_failures" if info["failures"] >= env.config.max_failures else "max_steps"
    met, total = info["goal_conditions"]
    return EpisodeOutcome(**named, end=end, success=bool(info["success"]) and not fault,
                          goal_conditions=(int(met), int(total)), steps=steps - stopped,
                          expert_length=len(env.episode.expert.actions), failures=int(info["failures"]),
                          instruction=str(obs["instruction"]), cause=AGENT_FAULT if fault else "", detail=fault,
                          episode_key=key)


def _trial_where(trial: str, split: str) -> tuple[str, str, int]:
    """(task type, floor plan, layout) of a trial folder: traj_data's task type and floor plan, and the frozen
    entry's layout when the sidecar names a frozen split's entry (else 0)."""
    from luminous_sim.benchmark import FROZEN, benchmark_size

    path = Path(trial)
    what = "a trial's {} (luminous_sim.limits.MAX_INPUT_BYTES)"
    try:  # a trial these cannot be read from is a broken trial (`trials.trial_problem` names why): "" then
        traj = read_json_file(path / "traj_data.json", MAX_INPUT_BYTES, what.format("traj_data.json"))
        task_type, floor_plan = traj["task_type"], traj["scene"]["floor_plan"]
    except (LuminousError, KeyError, TypeError):
        return "", "", 0
    if not isinstance(task_type, str) or not isinstance(floor_plan, str):
        return "", "", 0
    layout = 0
    # Only the layout's number is read here; a damaged sidecar is named where the trial is restored
    # (`benchmark.read_trial`), and its episode is then a broken trial, not an error here.
    with contextlib.suppress(LuminousError, AttributeError):
        bench = read_json_file(path / "luminous.json", MAX_INPUT_BYTES, what.format("luminous.json")).get(
            "benchmark") or {}
        name, i = bench.get("split"), bench.get("index")
        if name in FROZEN and isinstance(i, int) and not isinstance(i, bool) and 0 <= i < benchmark_size(name):
            layout = benchmark_entry(name, i).layout
    return task_type, floor_plan, layout


def _not_an_action(action: Any) -> str:
    """Why `action` cannot be an action of any Luminous env (checked before the env sees it), or ""."""
    if isinstance(action, np.ndarray) and action.shape == () and action.dtype.kind in "iu":
        return ""
    if isinstance(action, (int, np.integer)) and not isinstance(action, bool):
        return ""
    if isinstance(action, dict) and isinstance(action.get("action"), str):
        return ""
    return "an action is an index of the action space or a dict with an 'action' name"


_shown = partial(shown, limit=80)

_RUNNERS: dict[tuple[str, str, AgentLimits], tuple[LuminousEnv, Agent]] = {}
"""This process's env and agent per (policy, env options, agent limits): a user's agent is made once per worker
(its process started once, and again after a timeout)."""


CHECK = "check"
"""The field of an episode file that holds the digest of its other fields (written with it, verified on read)."""


def _digest(fields: dict[str, Any]) -> str:
    canonical = json.dumps(fields, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode()).hexdigest()[:16]


def outcome_record(outcome: EpisodeOutcome) -> dict[str, Any]:
    """What an episode file holds: the outcome's fields and their digest under `CHECK`."""
    fields = outcome.to_dict()
    return {**fields, CHECK: _digest(fields)}


def read_outcome(path: Path, split: str, index: int, job: EpisodeJob | None = None) -> EpisodeOutcome:
    """The outcome an earlier run wrote at `path` for episode `index` of `split`.

    Raises:
        LuminousError: not a regular file (a folder, a link, a device), over `MAX_EPISODE_FILE_BYTES`, not
            JSON, a field missing or of the wrong kind, its `check` missing or not the digest of its other
            fields (an edit), or another episode's outcome; the message names the file and the field.
    """
    data = read_json_file(path, MAX_EPISODE_FILE_BYTES,
                          "an episode outcome file (luminous_sim.limits.MAX_EPISODE_FILE_BYTES)")
    recorded = data.pop(CHECK, None) if isinstance(data, dict) else None
    outcome = EpisodeOutcome.from_dict(data, str(path))
    if recorded is None:
        raise LuminousError(f"{path}: field {CHECK!r} is missing; expected the digest an evaluation writes with each "
                            "outcome")
    if recorded != _digest(data):
        shown = repr(recorded) if len(repr(recorded)) <= 40 else repr(recorded)[:37] + "..."
        raise LuminousError(f"{path}: field {CHECK!r}: {shown} is not the digest of the file's other fields "
                            f"({_digest(data)}); the file was edited or damaged")
    task_type, floor_plan, layout = (job or EpisodeJob("", split, index, 0, "")).where()
    mine = (split, index, task_type, floor_plan, layout, job.trial_rel if job is not None else "")
    for name, value, want in zip(("split", "index", "task_type", "floor_plan", "layout", "trial"),
                                 (outcome.split, outcome.index, outcome.task_type, outcome.floor_plan, outcome.layout,
                                  outcome.trial), mine):
        if value != want:
            raise LuminousError(f"{path}: field {name!r}: {value!r}, but the file is episode {index} of {split}, "
                                f"whose {name} is {want!r}")
    return outcome


def crashed_build(outcome: EpisodeOutcome) -> bool:
    """Whether an outcome is `unavailable` because its build crashed or made another episode (`BUILD_CRASH`: the
    installation's fault), not because the task could not be built."""
    return not outcome.drawn and outcome.cause == BUILD_CRASH


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
            kept = read_outcome(path, job.split, job.index, job)
            if not crashed_build(kept):  # an entry whose build crashed is never kept as a result: its build is retried
                return kept, ""
            path.unlink()
        except LuminousError as exc:
            damaged = str(exc)
            if path.is_dir() and not path.is_symlink():
                shutil.rmtree(path)
            else:
                path.unlink()
    broken = job.broken or (trial_problem(job.trial) if job.trial and not job.unbuilt else "")
    if job.unbuilt or broken:  # an unbuilt job, or a trial that cannot be read or whose task is impossible
        from luminous_sim.data import RETRIED_STAGES

        task_type, floor_plan, layout = job.where()
        cause = (BUILD_CRASH if job.stage in RETRIED_STAGES else BUILD) if job.unbuilt else BROKEN_TRIAL
        outcome = EpisodeOutcome(job.split, job.index, task_type, floor_plan, layout, end="unavailable",
                                 cause=cause, detail=job.unbuilt or broken,
                                 trial=job.trial_rel)
        if path is not None:
            write_atomic(path, json.dumps(outcome_record(outcome), indent=1) + "\n")
        return outcome, damaged
    key = (job.policy, job.env_json, job.limits)
    if key not in _RUNNERS:
        env = LuminousEnv(**json.loads(job.env_json))
        _RUNNERS[key] = (env, make_agent(job.policy, env, job.limits))
    env, agent = _RUNNERS[key]
    if job.trial and job.policy == "oracle":
        agent = _replay_agent(job.trial)
    try:
        outcome = play(env, agent, job.split, job.index, job.seed, trial=job.trial, trial_rel=job.trial_rel,
                       object_ids=job.policy == "oracle")
    finally:
        env.close()  # frees the episode's simulator; the next reset builds a new one
    if path is not None:
        write_atomic(path, json.dumps(outcome_record(outcome), indent=1) + "\n")
    return outcome, damaged


def _replay_agent(trial: str) -> ReplayAgent:
    """The oracle of a built trial: its recorded actions, replayed through the agent interface."""
    from luminous_sim.benchmark import read_trial

    agent = ReplayAgent()
    agent.load(read_trial(Path(trial)).low_actions)
    return agent


def _claim(out_dir: Path, run: dict[str, Any]) -> None:
    """Record what `out_dir` holds (`check_output` first)."""
    if check_output(out_dir, run):
        write_atomic(Path(out_dir) / RUN_FILE, json.dumps(run, indent=1) + "\n")


def data_run(policy: str, data_dir: Path, split: str, seed: int, env_kwargs: dict[str, Any] | None,
             limits: AgentLimits | None = None, track: str = "rgb") -> dict[str, Any]:
    """What an evaluation of a dataset folder records in its `run.json` (`evaluate_data`'s arguments; the agent's
    limits too, since they decide which episodes end as `agent_timeout`: a resume with others is refused)."""
    return {"policy": policy, "data": str(Path(data_dir).resolve()), "split": split, "track": track, "seed": seed,
            "env": _env_config(split, env_kwargs, track).to_kwargs(), "limits": _limits_record(limits)}


def _limits_record(limits: AgentLimits | None) -> dict[str, Any]:
    return dataclasses.asdict(limits or AgentLimits())


def check_output(out_dir: Path, run: dict[str, Any]) -> bool:
    """Whether `out_dir` can take the evaluation `run` (True: new, its run.json is still to be written; False:
    it holds this same evaluation, which resumes); nothing is written.

    Raises:
        LuminousError: a folder that holds another evaluation, one that is not empty and holds no evaluation,
            or one whose files are not what an evaluation writes (a folder or a link where `run.json`
            belongs, `episodes` a link or a file).
    """
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
        old = read_json_file(path, MAX_EPISODE_FILE_BYTES, "the evaluation's run.json "
                             "(luminous_sim.limits.MAX_EPISODE_FILE_BYTES); is this an evaluation folder?")
        if not isinstance(old, dict):
            raise LuminousError(f"{path}: expected a JSON object (what the folder's evaluation ran), "
                                f"got {type(old).__name__}")
        if old != run:
            diff = ", ".join(f"{k} {old.get(k)!r} (asked {run[k]!r})" for k in run if old.get(k) != run[k])
            raise LuminousError(f"{out_dir} holds another evaluation ({diff}); choose another output folder")
        return False
    others = sorted(p.name for p in out_dir.iterdir() if p.name not in EVAL_FILES) if out_dir.is_dir() else []
    if others:
        more = " ..." if len(others) > 5 else ""
        raise LuminousError(f"{out_dir} is not empty and holds no evaluation ({RUN_FILE} missing; it has "
                            f"{', '.join(others[:5])}{more}); choose a new or empty folder")
    return True


def _env_config(split: str, env_kwargs: dict[str, Any] | None, track: str = "rgb") -> EnvConfig:
    """ALFRED's env (`EVAL_ENV`) with the user's options and the track's observations, refusing the ones the
    evaluation sets itself and those the track does not allow (`tracks.track_env`)."""
    env_kwargs = track_env(track, env_kwargs)
    for name in EVAL_SETS:
        value = (env_kwargs or {}).get(name)
        if name == "split" and value not in (None, "", split):
            raise LuminousError(f"env option split={value!r}: the evaluation plays split {split} (its --split); "
                                "leave the env option out or give the same split")
        if name == "cdf" and value not in (None, "", [], ()):
            raise LuminousError(f"env option cdf={value!r}: an evaluation plays the entries of split {split}, "
                                "not CDF scenes; leave the env option out")
    config = EnvConfig.from_kwargs({**EVAL_ENV, **(env_kwargs or {})})
    if not config.verify_expert:
        raise LuminousError("env option verify_expert: an evaluation needs the expert's length (PLW metrics)")
    return config


def _indices(episodes: int | Iterable[int], size: int, split: str) -> Sequence[int]:
    """The entry indices asked for (a count N: 0 .. N-1), checked against the split's size and the limit."""
    if isinstance(episodes, int) and not 1 <= episodes <= MAX_EVAL_EPISODES:
        raise LuminousError(f"episodes: expected 1 to {MAX_EVAL_EPISODES} (luminous_sim.limits.MAX_EVAL_EPISODES), "
                            f"got {episodes}")
    indices: Sequence[int] = range(episodes) if isinstance(episodes, int) else list(
        itertools.islice(episodes, MAX_EVAL_EPISODES + 1))
    if not indices:
        raise LuminousError("episodes: expected at least one episode")
    if len(indices) > MAX_EVAL_EPISODES:
        raise LuminousError(f"episodes: more than {MAX_EVAL_EPISODES} (luminous_sim.limits.MAX_EVAL_EPISODES)")
    bad = [i for i in indices if not 0 <= i < size]
    if bad:
        raise LuminousError(f"episodes: split {split} holds episodes 0..{size - 1}; {bad[0]} is not one of them")
    return indices


def _run_all(policy: str, split: str, seed: int, config: EnvConfig, jobs: list[EpisodeJob],
             progress: Callable[[EpisodeOutcome], None] | None, workers: int,
             backend: Backend | None, track: str) -> EvalReport:
    outcomes, replayed = [], []
    runs = map_local(_run_job, jobs, workers) if backend is None else map_ordered(_run_job, jobs, backend)
    for outcome, damaged in runs:
        outcomes.append(outcome)
        if damaged:
            replayed.append(damaged)
        if progress is not None:
            progress(outcome)
    return EvalReport(policy, split, seed, config.to_kwargs(), tuple(outcomes), tuple(replayed), track)


def evaluate(policy: str, split: str, episodes: int | Iterable[int], *, seed: int = 0, workers: int = 1,
             out_dir: Path | None = None, env_kwargs: dict[str, Any] | None = None,
             progress: Callable[[EpisodeOutcome], None] | None = None,
             backend: Backend | None = None, limits: AgentLimits | None = None, track: str = "rgb") -> EvalReport:
    """Run `policy` (`oracle`, `random` or `MODULE:CALLABLE`) on entries of the frozen split `split`, each
    played live: `reset(options={"split": split, "index": i})`, the episode `episodes.entry_spec` defines
    (the oracle is the env's expert, replanning from the env's state). `evaluate_data` plays a build's trials
    instead (the oracle then replays the recorded actions); `luminous eval --split` builds the canonical split
    and evaluates that.

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
        limits: a user's agent's limits (`sandbox.AgentLimits`: seconds per call, memory); it runs in a child
            process of each worker, and its module is never imported in this process.
        track: `rgb` (ALFRED's rules) or `privileged` (with the simulator's depth and segmentation;
            `luminous_sim.eval.tracks`).

    Raises:
        PolicyError, SplitError, LuminousError: a bad policy spec, split, index or env option (before any work).
        AgentCrashed: a user's agent raised, exited, was killed or went past its memory limit (the evaluation
            stops; the episodes finished before stay in `out_dir`). A call over the step limit is no crash: its
            episode ends as `agent_timeout` and the evaluation goes on.
    """
    limits = limits or AgentLimits()
    check_track(track)
    check_policy(policy, limits)
    plus_split(split)
    indices = _indices(episodes, benchmark_size(split), split)
    config = _env_config(split, env_kwargs, track)
    env_json = json.dumps(config.to_kwargs(), sort_keys=True)
    if out_dir is not None:
        _claim(out_dir, {"policy": policy, "split": split, "track": track, "seed": seed, "env": config.to_kwargs(),
                         "limits": _limits_record(limits)})
    jobs = [EpisodeJob(policy, split, i, seed, env_json, None if out_dir is None else str(out_dir), limits=limits)
            for i in indices]
    return _run_all(policy, split, seed, config, jobs, progress, workers, backend, track)


def evaluate_data(policy: str, data_dir: Path, *, split: str | None = None,
                  episodes: int | Iterable[int] | None = None, seed: int = 0, workers: int = 1,
                  out_dir: Path | None = None, env_kwargs: dict[str, Any] | None = None,
                  progress: Callable[[EpisodeOutcome], None] | None = None,
                  backend: Backend | None = None, limits: AgentLimits | None = None,
                  track: str = "rgb") -> EvalReport:
    """Run `policy` on the trials of a built dataset folder, as ALFRED's evaluation iterates over a split's
    traj_data.json files: each trial restored from its files alone (`reset(options={"trial": folder})`), the
    agent reading annotation 0; the `oracle` replays the trial's recorded low-level actions through the agent
    interface (`ReplayAgent`), so its success rate measures replay fidelity.

    Args:
        data_dir: the dataset folder (`luminous dataset build` output, or ALFRED's layout with our sidecars).
        split: evaluate only this split's trials (the folder's `splits.json` key); None for every trial.
        episodes: a count N (the split's first N trials) or their indices; None for all.
        (the others as for `evaluate`)

    Raises:
        PolicyError, LuminousError: a bad policy spec, data folder, index or env option (before any work).
        AgentCrashed: as for `evaluate`.
    """
    from luminous_sim.eval.trials import list_trials

    limits = limits or AgentLimits()
    check_track(track)
    check_policy(policy, limits)
    refs = list_trials(Path(data_dir), split)
    if not refs:
        raise LuminousError(f"{data_dir}: holds no trial{f' of split {split}' if split else ''}")
    if episodes is not None:
        chosen = set(_indices(episodes, len(refs), split or "(all)"))
        refs = [r for k, r in enumerate(refs) if k in chosen]
    names = sorted({r.split for r in refs})
    label = split or "+".join(names)
    config = _env_config(label, env_kwargs, track)
    env_json = json.dumps(config.to_kwargs(), sort_keys=True)
    if out_dir is not None:
        _claim(out_dir, data_run(policy, data_dir, label, seed, env_kwargs, limits, track))
    jobs = [EpisodeJob(policy, r.split, r.index, seed, env_json, None if out_dir is None else str(out_dir),
                       trial="" if r.unbuilt or r.broken else str(r.path), trial_rel=r.rel, unbuilt=r.unbuilt,
                       named=r.named, stage=r.stage, broken=r.broken, limits=limits)
            for r in refs]
    return _run_all(policy, label, seed, config, jobs, progress, workers, backend, track)
