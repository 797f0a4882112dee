"""What the env measures in an episode, one measure per job (habitat-lab's measures): each is reset with the
episode, updated after every action and says what it puts in `info`. The env's `info` is theirs, in
`MEASURES` order: goal progress, failures, the expert's suggestion (with `expert_in_info`), the episode's
facts (at reset), and the navigation figures for a goal scored so (SPL and what it is made of)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

from luminous_sim.env.config import EnvConfig
from luminous_sim.env.history import Sent
from luminous_sim.env.navscore import NavScore, nav_score
from luminous_sim.env.shaping import RewardShaper
from luminous_sim.episodes import EpisodeSpec
from luminous_sim.errors import FailureCode
from luminous_sim.world import World


class Measured(Protocol):
    """What a measure reads of an env (`LuminousEnv` is one)."""

    config: EnvConfig
    episode: EpisodeSpec | None
    world: World | None
    shaper: RewardShaper
    history: list[Sent]

    def expert_action(self) -> int | dict[str, Any]:
        """The expert's next action in the env's action form."""
        ...


@dataclass(frozen=True)
class Step:
    """One step as the measures see it: whether the action succeeded and why not, and how the episode stands."""

    code: FailureCode | None
    error: str
    terminated: bool = False
    truncated: bool = False

    @property
    def ok(self) -> bool:
        return self.code is None

    @property
    def ended(self) -> bool:
        return self.terminated or self.truncated


def _spec(env: Measured) -> EpisodeSpec:
    assert env.episode is not None, "a measure reads an episode that started"
    return env.episode


class Measure:
    """One measure of an episode (reset, updated after each action, read into `info`); the hooks do nothing by
    default."""

    @classmethod
    def wanted(cls, env: Measured) -> bool:
        """Whether an env measures it (every env, by default)."""
        return True

    def reset(self, env: Measured) -> None:
        """A new episode started (its world at the start)."""

    def update(self, env: Measured, step: Step) -> None:
        """An action was taken (before the reward and the episode's end are known)."""

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        """What it puts in `info` (`step` None at reset; `step.ended` on the last step)."""
        return {}


class GoalProgress(Measure):
    """`success`, ALFRED's `goal_conditions` (met, total), the current `subgoal` and the `task_type`."""

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        goal = _spec(env).goal
        scores = env.shaper.scores
        return {"success": env.shaper.success,
                "goal_conditions": (sum(scores.values()), sum(goal.weights().values())),
                "subgoal": goal.subgoal(scores), "task_type": goal.task_type}


class Failures(Measure):
    """The failed actions so far (`failures`; `max_failures` of them cut the episode off) and the last
    action's `failure_code` (a `FailureCode` value, None on success) and `error`."""

    def __init__(self) -> None:
        self.count = 0

    def reset(self, env: Measured) -> None:
        self.count = 0

    def update(self, env: Measured, step: Step) -> None:
        self.count += not step.ok

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        code = None if step is None else step.code
        return {"failures": self.count, "failure_code": None if code is None else code.value,
                "error": "" if step is None else step.error}


class ExpertSuggestion(Measure):
    """The expert's next action in the env's action form (`expert_action`), with `expert_in_info`."""

    @classmethod
    def wanted(cls, env: Measured) -> bool:
        return bool(env.config.actions.expert_in_info)

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        return {"expert_action": env.expert_action()}


class EpisodeFacts(Measure):
    """At reset: the draws rejected before the episode (`redraws`) and its content key (`episode_key`)."""

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        if step is not None:
            return {}
        spec = _spec(env)
        return {"redraws": spec.redraws, "episode_key": spec.key}


class NavigationScore(Measure):
    """For a goal scored the navigation way (`env.navscore`): the start figures at reset, SPL, soft SPL and
    what they are made of on the last step."""

    def __init__(self) -> None:
        self.score: NavScore | None = None

    def reset(self, env: Measured) -> None:
        assert env.world is not None, "a measure is reset in the episode's world"
        self.score = nav_score(_spec(env).goal, env.world)

    def info(self, env: Measured, step: Step | None) -> dict[str, Any]:
        if self.score is None:
            return {}
        if step is None:
            return self.score.at_start()
        if not step.ended or env.world is None:
            return {}
        return self.score.at_end(env.world.agent, env.history, env.shaper.success)


MEASURES: tuple[type[Measure], ...] = (GoalProgress, Failures, ExpertSuggestion, EpisodeFacts, NavigationScore)
"""Every measure, in the order of `info`'s keys."""


def measures_for(env: Measured) -> list[Measure]:
    """The measures an env takes."""
    return [cls() for cls in MEASURES if cls.wanted(env)]
