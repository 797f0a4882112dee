"""ALFRED's navigation reward (spec/alfred.md section 5.2, the `GotoLocationAction` checker): while a go-to
subgoal is current, each step earns `0.2 x (distance before - distance after)`, the distance being the
shortest-path length in the agent's pose graph (`planning.NavGraph.distance`: MoveAhead and Rotate steps)
from the agent to the subgoal's location (computed once per go-to, from the location over the reversed
graph, so a step costs a look-up); once that distance is under 3 the subgoal is done and earns
GotoLocationAction's +4.

The go-to locations are the expert's (as ALFRED's are its planner's `location`): the plan proved at reset,
cut into segments of navigation actions followed by the interactions done from there; each segment's last
pose is a go-to location (replayed from the start pose, navigation being deterministic). After a go-to is
done, its interactions are the current subgoal: the next go-to becomes current once the agent has
succeeded at actions of those names, in order (ALFRED's checkers for those subgoals). A trailing walk
with no interaction after it (the whole plan of `goto_object`) is shaped the same way, but its reaching is
paid by the task's own goal condition, not twice.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import networkx as nx

from luminous_sim.env.actions import NAVIGATION
from luminous_sim.errors import LuminousError
from luminous_sim.planning import NavGraph
from luminous_sim.world import AgentPose

UNREACHABLE = 10**9
"""`NavGraph.distance` of a pose with no path to the target."""


@dataclass(frozen=True)
class GotoTarget:
    """A go-to subgoal: where the expert stood, and the interactions it did from there (by action name);
    `walked` is False for interactions done from the start pose (no go-to subgoal before them)."""

    pose: AgentPose
    interactions: tuple[str, ...]
    walked: bool = True


def walk(pose: AgentPose, action: str) -> AgentPose:
    """The pose after a successful navigation action (as `World` moves the agent)."""
    if action == "MoveAhead":
        return pose.moved()
    if action in ("RotateLeft", "RotateRight"):
        return pose.rotated(-1 if action == "RotateLeft" else 1)
    looked = pose.looked(-1 if action == "LookUp" else 1)
    if looked is None:
        raise LuminousError(f"expert plan: {action} from horizon {pose.horizon} leaves -30..60 degrees")
    return looked


def goto_targets(start: AgentPose, actions: tuple[dict[str, Any], ...]) -> list[GotoTarget]:
    """The expert plan's go-to subgoals, in order.

    Raises:
        LuminousError: the plan has an action that moves the agent other than ALFRED's navigation ones.
    """
    targets: list[GotoTarget] = []
    pose, walked = start, False
    done: list[str] = []
    for api in actions:
        name = api["action"]
        if name in NAVIGATION:
            if done:  # the interactions of the last go-to are over: a new walk starts
                targets[-1] = GotoTarget(targets[-1].pose, tuple(done), targets[-1].walked)
                done = []
            pose, walked = walk(pose, name), True
            continue
        if name.startswith("Teleport"):
            raise LuminousError(f"expert plan: {name} has no go-to location")
        if walked or not targets:
            targets.append(GotoTarget(pose, (), walked))
            walked = False
        done.append(name)
    if done:
        targets[-1] = GotoTarget(targets[-1].pose, tuple(done), targets[-1].walked)
    if walked:
        targets.append(GotoTarget(pose, ()))
    return targets


class GotoReward:
    """The go-to subgoal state of one episode and its reward per step."""

    def __init__(self, graph: NavGraph, targets: list[GotoTarget], agent: AgentPose, *, shaping: float,
                 reach: float, bonus: float):
        self.graph, self.targets = graph, targets
        self.shaping, self.reach, self.bonus = shaping, reach, bonus
        self.index = 0
        """The current go-to (len(targets) when all are done)."""
        self.reached = bool(targets) and not targets[0].walked
        """Whether the current go-to is reached (its interactions are the current subgoal)."""
        self._done = 0
        self._field: dict = {}
        self._aim()
        self._distance = self._to_target(agent)

    def _aim(self) -> None:
        """Path lengths to the current go-to location from every pose (unit steps: breadth-first)."""
        self._field = {}
        if self.index < len(self.targets):
            goal = NavGraph.node(self.targets[self.index].pose)
            if goal in self.graph.graph:
                self._field = nx.single_source_shortest_path_length(self.graph.graph.reverse(copy=False), goal)

    def _to_target(self, agent: AgentPose) -> int:
        """`NavGraph.distance` from the agent to the current go-to location."""
        if self.index >= len(self.targets):
            return UNREACHABLE
        node = NavGraph.node(agent)
        return 0 if node == NavGraph.node(self.targets[self.index].pose) else self._field.get(node, UNREACHABLE)

    @property
    def distance(self) -> int | None:
        """Steps from the agent to the current go-to location (None when none is current or no path)."""
        return None if self.reached or self._distance >= UNREACHABLE else self._distance

    def step(self, agent: AgentPose, action: str | None, ok: bool) -> float:
        """The reward of a step that left the agent at `agent` after `action` (its name; None when nothing was
        sent) succeeded or not."""
        if self.index >= len(self.targets):
            return 0.0
        target = self.targets[self.index]
        if self.reached:
            if ok and action == target.interactions[self._done]:
                self._done += 1
                if self._done == len(target.interactions):
                    self.index, self.reached, self._done = self.index + 1, False, 0
                    self._aim()
                    self._distance = self._to_target(agent)
            return 0.0
        before, after = self._distance, self._to_target(agent)
        self._distance = after
        if before >= UNREACHABLE or after >= UNREACHABLE:
            return 0.0
        reward = self.shaping * (before - after)
        if after < self.reach and target.interactions:
            self.reached = True
            reward += self.bonus
        return float(reward)
