"""Navigation for the oracle: a graph of the agent's grid poses (x, y, rotation) with ALFRED's
MoveAhead/RotateLeft/RotateRight edges, Dijkstra shortest paths, and ALFRED's GotoLocation expansion
(look to 45 degrees, walk the shortest path, look to the target horizon)."""

from __future__ import annotations

from functools import cached_property
from itertools import pairwise

import networkx as nx

from luminous_sim.errors import FailureCode, PlanningError
from luminous_sim.world import NavGrid
from luminous_sim.world.agent import HORIZON_STEP, AgentPose

WALK_HORIZON = 45
"""ALFRED's planner walks with the camera 45 degrees down."""

Node = tuple[int, int, int]  # grid x, grid y, rotation in degrees


def _ahead(node: Node) -> Node:
    gx, gy, rot = node
    dx, dy = {0: (0, 1), 90: (1, 0), 180: (0, -1), 270: (-1, 0)}[rot]
    return (gx + dx, gy + dy, rot)


class NavGraph:
    """Directed graph of poses; every edge is one low-level action of cost 1."""

    def __init__(self, grid: NavGrid):
        self.grid = grid

    @cached_property
    def graph(self) -> nx.DiGraph:
        g = nx.DiGraph()
        for gx, gy in sorted(self.grid.keys):
            for rot in (0, 90, 180, 270):
                node = (gx, gy, rot)
                g.add_edge(node, (gx, gy, (rot + 90) % 360), action="RotateRight")
                g.add_edge(node, (gx, gy, (rot - 90) % 360), action="RotateLeft")
                nxt = _ahead(node)
                if nxt[:2] in self.grid.keys:
                    g.add_edge(node, nxt, action="MoveAhead")
        return g

    @staticmethod
    def node(pose: AgentPose) -> Node:
        gx, gy = pose.grid_key()
        return (gx, gy, pose.rotation % 360)

    def path(self, start: AgentPose, goal: AgentPose) -> list[str]:
        """Shortest list of MoveAhead/Rotate actions from `start` to `goal` (horizon ignored).

        Raises:
            PlanningError: (code NO_PATH) the goal is walled off, or either pose is off the graph.
        """
        a, b = self.node(start), self.node(goal)
        if a == b:
            return []
        try:
            nodes = nx.dijkstra_path(self.graph, a, b)
        except (nx.NetworkXNoPath, nx.NodeNotFound) as exc:
            raise PlanningError(f"no path from {start} to {goal}: {exc}", FailureCode.NO_PATH) from None
        return [self.graph.edges[u, v]["action"] for u, v in pairwise(nodes)]

    def distance(self, start: AgentPose, goal: AgentPose) -> int:
        try:
            return len(self.path(start, goal))
        except PlanningError:
            return 10**9


def look_steps(from_horizon: int, to_horizon: int) -> list[str]:
    """LookUp/LookDown actions that change the horizon from one value to another (15 degree steps)."""
    n = (to_horizon - from_horizon) // HORIZON_STEP
    return ["LookDown"] * n if n > 0 else ["LookUp"] * (-n)


def goto_actions(graph: NavGraph, start: AgentPose, goal: AgentPose) -> list[str]:
    """ALFRED's GotoLocation expansion: look to 45 degrees, walk, look to the goal's horizon."""
    walk = graph.path(start, goal)
    if not walk:
        return look_steps(start.horizon, goal.horizon)
    return look_steps(start.horizon, WALK_HORIZON) + walk + look_steps(WALK_HORIZON, goal.horizon)
