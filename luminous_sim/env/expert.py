"""The expert's next action for an environment's current state: the oracle's plan, kept while the agent
follows it and recomputed when it does not.

A plan is computed in a world of its own (a shadow): one of the env's worlds of the episode's scene, set
up the same way, and replayed through every action the env has sent so far, so it starts where the agent
stands. Building takes a fraction of a second (putting a kept world back, a millisecond); replaying is
cheap. While the agent takes the suggested actions and they succeed, the next suggestion is the plan's next
step at no cost.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from luminous_sim.env.alfred_env import LuminousEnv


def same_action(a: Any, b: Any) -> bool:
    """Whether two env actions are the same (an int, or an ALFRED dict, possibly holding arrays)."""
    if isinstance(a, dict) != isinstance(b, dict):
        return False
    try:
        return bool(a == b)
    except (ValueError, TypeError):  # dicts of numpy arrays
        return False


class Expert:
    """Follows one env's episode and answers its expert's next api action."""

    def __init__(self) -> None:
        self._plan: tuple[dict[str, Any], ...] | None = None
        self._cursor = 0
        self._at = -1
        """Length of the env's history that the plan's cursor corresponds to (-1: no plan)."""
        self._pending: tuple[int, Any] | None = None
        self.replans = 0

    def start(self, plan: tuple[dict[str, Any], ...] | None) -> None:
        """A new episode, with the plan proved at reset (None: plan on the first question)."""
        self._plan, self._cursor, self._at, self._pending = plan, 0, 0 if plan is not None else -1, None

    def suggested(self, at: int, action: Any) -> None:
        """Note the env-form action handed out when the history had `at` entries."""
        self._pending = (at, action)

    def next_api(self, env: LuminousEnv) -> dict[str, Any] | None:
        """The expert's next api action (object ids, as the oracle sends them), or None when it has none
        (the goal is reached, or no plan reaches it from here)."""
        history = env.history
        if self._pending is not None and self._at == self._pending[0] and len(history) == self._at + 1:
            last = history[-1]
            if last.ok and same_action(last.given, self._pending[1]):
                self._cursor += 1
                self._at += 1
        self._pending = None
        if self._at != len(history):
            self._replan(env)
        if self._plan is None or self._cursor >= len(self._plan):
            return None
        return self._plan[self._cursor]

    def _replan(self, env: LuminousEnv) -> None:
        episode = env.episode
        assert episode is not None, "reset the env first"
        shadow = env.worlds.get(episode.scene, episode.dirty, episode.start)
        try:
            for step in env.history:
                shadow.step(step.api)
            plan = episode.goal.expert_plan(shadow)
        finally:
            env.worlds.put(shadow)
        self._plan = plan.actions if plan is not None else None
        self._cursor, self._at = 0, len(env.history)
        self.replans += 1
