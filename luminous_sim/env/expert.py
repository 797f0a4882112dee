"""`Expert`: the oracle's next action for one episode, from explicit inputs: the episode's scene and goal,
its set-up (the objects made dirty, the agent's start), the plan proved at reset if any, a source of worlds,
and the actions sent so far. It keeps its plan while the agent follows it and recomputes it when not.

A plan is computed in a world of its own (a shadow) from the world source: a world of the scene, set up the
same way, and replayed through every action sent so far, so it starts where the agent stands. Building
takes a fraction of a second (putting a kept world back, a millisecond); replaying is cheap. While the
agent takes the suggested actions and they succeed, the next suggestion is the plan's next step at no cost.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from luminous_sim.env.history import Sent
from luminous_sim.episodes import Goal, WorldSource
from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose

if TYPE_CHECKING:
    from luminous_sim.episodes import EpisodeSpec


def same_action(a: Any, b: Any) -> bool:
    """Whether two env actions are the same (an int, or an ALFRED dict, possibly holding arrays)."""
    if isinstance(a, dict) != isinstance(b, dict):
        return False
    try:
        return bool(a == b)
    except (ValueError, TypeError):  # dicts of numpy arrays
        return False


class Expert:
    """Answers one episode's next expert api action for the actions sent so far.

    Args:
        scene: the episode's scene.
        goal: what the episode asks for (its `expert_plan` is the oracle).
        worlds: where shadow worlds come from and go back to.
        dirty: the objects made dirty before the first step (the episode's initial state).
        start: the agent's start (None: the world's default start).
        plan: the plan proved from the start, if known (None: plan on the first question).
    """

    def __init__(self, scene: Scene, goal: Goal, worlds: WorldSource, *, dirty: tuple[str, ...] = (),
                 start: AgentPose | None = None, plan: tuple[dict[str, Any], ...] | None = None):
        self.scene, self.goal, self.worlds = scene, goal, worlds
        self.dirty, self.start = dirty, start
        self._plan = plan
        self._cursor = 0
        self._at = 0 if plan is not None else -1
        """Length of the history that the plan's cursor corresponds to (-1: no plan)."""
        self._pending: tuple[int, Any] | None = None
        self.replans = 0
        """Plans computed since the start (the proved plan aside)."""

    @classmethod
    def for_episode(cls, episode: EpisodeSpec, worlds: WorldSource) -> Expert:
        """The expert of an env episode (its proved plan, if any, to start with)."""
        return cls(episode.scene, episode.goal, worlds, dirty=episode.dirty, start=episode.start,
                   plan=episode.expert.actions if episode.expert is not None else None)

    def suggested(self, at: int, action: Any) -> None:
        """Note the action handed out (in the env's form) when the history had `at` entries: if the next
        entry is that action and it succeeded, the agent followed the plan."""
        self._pending = (at, action)

    def next_api(self, history: Sequence[Sent]) -> dict[str, Any] | None:
        """The expert's next api action (object ids, as the oracle sends them) after `history`, the actions
        sent so far; None when it has none (the goal is reached, or no plan reaches it from here)."""
        if self._pending is not None and self._at == self._pending[0] and len(history) == self._at + 1:
            last = history[-1]
            if last.ok and same_action(last.given, self._pending[1]):
                self._cursor += 1
                self._at += 1
        self._pending = None
        if self._at != len(history):
            self._replan(history)
        if self._plan is None or self._cursor >= len(self._plan):
            return None
        return self._plan[self._cursor]

    def _replan(self, history: Sequence[Sent]) -> None:
        shadow = self.worlds.get(self.scene, self.dirty, self.start)
        try:
            for step in history:
                shadow.step(step.api)
            plan = self.goal.expert_plan(shadow)
        finally:
            self.worlds.put(shadow)
        self._plan = plan.actions if plan is not None else None
        self._cursor, self._at = 0, len(history)
        self.replans += 1
