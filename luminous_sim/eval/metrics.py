"""ALFRED's task metrics (spec section 5.1, ALFRED's `models/eval/eval_task.py`), over episode outcomes.

Per episode i: s_i (success), gc_i = met_i / total_i (goal conditions), L*_i (the expert's low-level actions)
and T_i (the agent's low-level actions, Stop not counted); the path-length weight is
w_i = min(1, L*_i / T_i) = L*_i / max(L*_i, T_i) (the paper's form, which also covers T_i = 0).

* SR = #(s_i = 1) / N
* GC = sum(met_i) / sum(total_i)                    (a micro-average, not the mean of gc_i)
* PLW-SR = sum(s_i * w_i * L*_i) / sum(L*_i)
* PLW-GC = sum(gc_i * w_i * L*_i) / sum(L*_i)

These are over the episodes that were drawn (they need a task and an expert). A split entry whose episode
could not be drawn (`EpisodeUnavailable`) is still part of the population: `sr_all` counts it as a failure,
and `entries - episodes` says how many there were.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import asdict, dataclass
from typing import Any

from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES

ENDS: tuple[str, ...] = ("success", "stop", "max_steps", "max_failures", "invalid_action", "agent_timeout",
                         "unavailable")
"""How an episode ended: the goal held, the agent stopped, ALFRED's step or failed-action limit, the agent
returned something that is not an action or a call to it went past the step limit (`sandbox.AgentLimits`;
both the agent's fault, `AGENT_FAULT`, and failures in SR and GC), or the entry's episode could not be
drawn."""
AGENT_FAULT = "agent_fault"
"""The `cause` of an `invalid_action` end: the agent returned None, an index outside the action space, an
unknown action name or arguments the env cannot decode (a malformed mask); `detail` says which, at which
step. A mask that decodes but hits nothing is an ordinary failed action, as in ALFRED. Also the `cause` of an
`agent_timeout` end (`detail`: the call and the step)."""
BUILD = "build"
"""The `cause` of an `unavailable` end for a job the build could not do (no task fits, the oracle failed): part
of the population, a failure in SR all."""
BUILD_CRASH = "build_crash"
"""The `cause` of an `unavailable` end for a job whose build failed through the installation, not the task (a
crash or another episode than the frozen split, `data.RETRIED_STAGES`): never kept as a result, its build is
retried on the next run, and `luminous eval` exits 1 (the population is incomplete)."""
BROKEN_TRIAL = "broken_trial"
"""The `cause` of an `unavailable` end for a trial of a dataset folder that cannot be played: a folder reached
through a symbolic link or outside the dataset folder, a file that is missing, special, oversized or not
JSON, a field missing, of the wrong kind or out of range, or a task its restored scene makes impossible (a
type `pddl_params` names that the scene lacks); `detail` says which. It counts in SR all, and `luminous eval`
exits 1."""


@dataclass(frozen=True)
class EpisodeOutcome:
    """One split entry, evaluated (or found unavailable)."""

    split: str
    index: int
    task_type: str
    floor_plan: str
    layout: int
    end: str
    success: bool = False
    goal_conditions: tuple[int, int] = (0, 0)
    """(met, total) at the end."""
    steps: int = 0
    """T: low-level actions the agent took (Stop not counted)."""
    expert_length: int = 0
    """L*: the expert's low-level actions for this episode."""
    failures: int = 0
    instruction: str = ""
    cause: str = ""
    """Why an unavailable entry has no episode (`env.UNAVAILABLE_CAUSES`, `BUILD`, `BUILD_CRASH`, `BROKEN_TRIAL`),
    `AGENT_FAULT` for an `invalid_action` or `agent_timeout` end; "" otherwise."""
    detail: str = ""
    episode_key: str = ""
    """The episode's content key (`benchmark.episode_key`, from the env's restored world)."""
    trial: str = ""
    """The trial folder played (relative to the dataset folder) when evaluating a built dataset."""

    def __post_init__(self) -> None:
        if self.end not in ENDS:
            raise LuminousError(f"episode outcome end: {self.end!r}; expected one of {', '.join(ENDS)}")
        if self.success != (self.end == "success"):
            raise LuminousError(f"{self.split} episode {self.index}: success {self.success} with end {self.end!r}")
        met, total = self.goal_conditions
        if self.drawn and (total < 1 or not 0 <= met <= total or self.expert_length < 1 or self.steps < 0):
            raise LuminousError(f"{self.split} episode {self.index}: inconsistent outcome (goal conditions "
                                f"{met}/{total}, expert length {self.expert_length}, steps {self.steps})")

    @property
    def drawn(self) -> bool:
        """Whether the entry had an episode (a task and an expert) to evaluate."""
        return self.end != "unavailable"

    @property
    def path_weight(self) -> float:
        """min(1, L* / T)."""
        return self.expert_length / max(self.expert_length, self.steps)

    def to_dict(self) -> dict[str, Any]:
        out = asdict(self)
        out["goal_conditions"] = list(self.goal_conditions)
        return out

    @classmethod
    def from_dict(cls, data: Any, where: str = "episode outcome") -> EpisodeOutcome:
        """An outcome from its `to_dict` form, every field checked (`where` names the source in errors).

        Raises:
            LuminousError: not an object, a field missing, unknown or of the wrong kind, or an inconsistent
                outcome; the message names `where` and the field.
        """
        if not isinstance(data, dict):
            raise LuminousError(f"{where}: expected a JSON object (an episode outcome), got {type(data).__name__}")
        unknown = sorted(set(data) - set(_FIELDS))
        if unknown:
            raise LuminousError(f"{where}: unknown field {unknown[0]!r}; expected {', '.join(_FIELDS)}")
        for name, kind in _FIELDS.items():
            if name not in data:
                if name in _REQUIRED:
                    raise LuminousError(f"{where}: field {name!r} is missing")
                continue
            value = data[name]
            if name == "goal_conditions":
                ok = (isinstance(value, list | tuple) and len(value) == 2
                      and all(isinstance(v, int) and not isinstance(v, bool) and v >= 0 for v in value))
            elif kind is int:
                ok = isinstance(value, int) and not isinstance(value, bool) and value >= 0
            else:
                ok = isinstance(value, kind)
            if not ok:
                shown = repr(value) if len(repr(value)) <= 60 else repr(value)[:57] + "..."
                want = "[met, total], two whole numbers >= 0" if name == "goal_conditions" else (
                    "a whole number >= 0" if kind is int else f"a {kind.__name__}")
                raise LuminousError(f"{where}: field {name!r}: expected {want}, got {shown}")
        try:
            return cls(**{**data, "goal_conditions": tuple(data.get("goal_conditions", (0, 0)))})
        except LuminousError as exc:
            raise LuminousError(f"{where}: {exc}") from None


@dataclass(frozen=True)
class Metrics:
    """ALFRED's metrics over a set of outcomes; None where no episode was drawn."""

    entries: int
    episodes: int
    successes: int
    sr: float | None
    gc: float | None
    plw_sr: float | None
    plw_gc: float | None
    sr_all: float | None
    """Successes over every entry, undrawn ones counted as failures."""

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)


def metrics(outcomes: Iterable[EpisodeOutcome]) -> Metrics:
    """SR, GC, PLW-SR and PLW-GC (over the drawn episodes) and SR over all entries."""
    every = list(outcomes)
    drawn = [o for o in every if o.drawn]
    successes = sum(o.success for o in drawn)
    sr_all = successes / len(every) if every else None
    if not drawn:
        return Metrics(len(every), 0, 0, None, None, None, None, sr_all)
    weight = sum(o.expert_length for o in drawn)
    met = sum(o.goal_conditions[0] for o in drawn)
    total = sum(o.goal_conditions[1] for o in drawn)
    plw_sr = sum(o.success * o.path_weight * o.expert_length for o in drawn) / weight
    plw_gc = sum(o.goal_conditions[0] / o.goal_conditions[1] * o.path_weight * o.expert_length
                 for o in drawn) / weight
    return Metrics(len(every), len(drawn), successes, successes / len(drawn), met / total, plw_sr, plw_gc, sr_all)


def metrics_by_type(outcomes: Sequence[EpisodeOutcome]) -> dict[str, Metrics]:
    """`metrics` per task type, in ALFRED's order, for the types present."""
    return {t: metrics(o for o in outcomes if o.task_type == t)
            for t in ALFRED_TASK_TYPES if any(o.task_type == t for o in outcomes)}


def type_average(per_type: dict[str, Metrics], name: str) -> float | None:
    """The mean over task types of one metric (the paper's Table 4 "Average" row); None if none has it."""
    values = [getattr(m, name) for m in per_type.values() if getattr(m, name) is not None]
    return sum(values) / len(values) if values else None


_FIELDS: dict[str, type] = {"split": str, "index": int, "task_type": str, "floor_plan": str, "layout": int,
                            "end": str, "success": bool, "goal_conditions": tuple, "steps": int,
                            "expert_length": int, "failures": int, "instruction": str, "cause": str, "detail": str,
                            "episode_key": str, "trial": str}
_REQUIRED = ("split", "index", "task_type", "floor_plan", "layout", "end")
