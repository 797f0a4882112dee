"""A* over the agent's own map (never the scene's): states are (node, heading), a move or a turn costs 1, and
the search runs on the nodes the map does not block (unknown ones count as open, as FILM's planner does; a
move that fails is remembered and never planned again)."""

from __future__ import annotations

import heapq
from collections.abc import Callable, Iterable

from luminous_sim.agents.own_pose import HEADINGS
from luminous_sim.agents.semantic_map import Node, SemanticMap

State = tuple[Node, int]
UNKNOWN_COST = 4
"""A move onto a node the map has no evidence of costs this much (known floor is preferred: a blocked move is a
failed action, and ALFRED allows 10)."""
MARGIN = 2
"""Nodes beyond the known part of the map the search may plan through."""
MAX_EXPANDED = 40_000
"""States one search expands at most (a 15 m house has under 15,000)."""


def plan_path(world_map: SemanticMap, start: State, goals: Iterable[State],
              open_node: Callable[[Node], bool] | None = None) -> list[str] | None:
    """The shortest action sequence (MoveAhead, RotateLeft, RotateRight) from `start` to any of `goals`; None
    when none is reachable on the map."""
    goal_set = set(goals)
    if not goal_set:
        return None
    if start in goal_set:
        return []
    known = world_map.known_nodes() + [g[0] for g in goal_set] + [start[0]]
    lo_x, hi_x = min(n[0] for n in known) - MARGIN, max(n[0] for n in known) + MARGIN
    lo_y, hi_y = min(n[1] for n in known) - MARGIN, max(n[1] for n in known) + MARGIN

    def is_open(n: Node) -> bool:  # within the known part of the map and its margin: a search that ends
        if not (lo_x <= n[0] <= hi_x and lo_y <= n[1] <= hi_y):
            return False
        return open_node(n) if open_node is not None else not world_map.blocked(n)
    goal_nodes = {g[0] for g in goal_set}
    targets = sorted(goal_nodes)

    def h(node: Node) -> int:
        return min(abs(node[0] - t[0]) + abs(node[1] - t[1]) for t in targets)

    frontier: list[tuple[int, int, State]] = [(h(start[0]), 0, start)]
    came: dict[State, tuple[State, str]] = {}
    cost = {start: 0}
    expanded = 0
    while frontier and expanded < MAX_EXPANDED:
        _, g, state = heapq.heappop(frontier)
        if g > cost.get(state, 1 << 30):
            continue
        if state in goal_set:
            return _actions(came, start, state)
        expanded += 1
        node, heading = state
        dx, dy = HEADINGS[heading]
        ahead = (node[0] + dx, node[1] + dy)
        steps: list[tuple[State, str]] = [((node, (heading + 1) % 4), "RotateRight"),
                                          ((node, (heading - 1) % 4), "RotateLeft")]
        if world_map.passable(node, heading) and (ahead in goal_nodes or is_open(ahead)):
            steps.append(((ahead, heading), "MoveAhead"))
        for nxt, action in steps:
            step = UNKNOWN_COST if action == "MoveAhead" and not world_map.known(nxt[0]) else 1
            if g + step < cost.get(nxt, 1 << 30):
                cost[nxt] = g + step
                came[nxt] = (state, action)
                heapq.heappush(frontier, (g + step + h(nxt[0]), g + step, nxt))
    return None


def _actions(came: dict[State, tuple[State, str]], start: State, end: State) -> list[str]:
    out: list[str] = []
    while end != start:
        end, action = came[end]
        out.append(action)
    return out[::-1]
