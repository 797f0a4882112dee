"""The text game's expert: the oracle's symbolic plan (`planning.symbolic.solve`, on the game's own state and
the task's goal) said as commands, one at a time against the game as it is then ("go to" the receptacle
where the next thing is shown, "take ... from" where it lies, a device's command where the plan heats, cools
or cleans). A command the game does not admit makes the expert plan again from the state it has reached."""

from __future__ import annotations

from collections.abc import Mapping

from luminous_sim.cdf.predicates import Expr
from luminous_sim.planning.symbolic import HighLevelAction, solve
from luminous_sim.text.game import TextGame

VERBS = {"HeatObject": "heat", "CoolObject": "cool", "CleanObject": "clean"}


class TextExpert:
    """Commands that solve a text game's task (`next_command`), from the symbolic planner's plan."""

    def __init__(self, game: TextGame, goal: Expr, names: Mapping[str, str] | None = None):
        self.game, self.goal, self.names = game, goal, dict(names or {})
        self._plan: list[HighLevelAction] = []
        self._replan()

    def _replan(self) -> None:
        self._plan = list(solve(self.game.state, self.goal, self.names or None).actions)

    def next_command(self) -> str | None:
        """The next command (None when the plan is done)."""
        for attempt in range(2):
            while self._plan:
                command = self._command(self._plan[0])
                if command is None:  # a goto to where the agent already is
                    self._plan.pop(0)
                    continue
                if command in self.game.admissible():
                    if not command.startswith("go to "):
                        self._plan.pop(0)
                    return command
                break
            if not self._plan:
                return None
            if attempt == 0:
                self._replan()
        return None

    def _command(self, a: HighLevelAction) -> str | None:
        g, oid = self.game, a.object_id
        if a.action == "GotoLocation":
            where = self._shown_at(oid)
            if where is None or where == g.at:
                return None
            return f"go to {g.name(where)}"
        here = a.receptacle_id if a.action in (*VERBS, "PutObject") else self._shown_at(oid)
        if a.action == "PutObject" and here is not None:
            here = self._shown_at(here)
        if here is not None and here != g.at:
            return f"go to {g.name(here)}"
        if a.action == "PickupObject":
            return f"take {g.name(oid)} from {g.name(g.at)}" if g.at else None
        if a.action == "PutObject":
            assert a.receptacle_id is not None
            return f"move {g.name(oid)} to {g.name(a.receptacle_id)}"
        if a.action in ("OpenObject", "CloseObject"):
            return f"{'open' if a.action == 'OpenObject' else 'close'} {g.name(oid)}"
        if a.action in ("ToggleObject", "ToggleObjectOn", "ToggleObjectOff"):
            return f"use {g.name(oid)}"
        if a.action == "SliceObject":
            held = g.state.held
            return f"slice {g.name(oid)} with {g.name(held)}" if held else None
        assert a.receptacle_id is not None
        return f"{VERBS[a.action]} {g.name(oid)} with {g.name(a.receptacle_id)}"

    def _shown_at(self, oid: str) -> str | None:
        """The receptacle at which the game shows a thing (a receptacle: itself; held: where the agent is)."""
        g = self.game
        if oid in g.receptacles:
            return oid
        if g.state.held == oid:
            return g.at
        return g.holder(oid)
