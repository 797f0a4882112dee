"""The built-in planner: A* over (object states, agent place), with macro actions from the rules.

A search node is a (relevance-filtered) `WorldState` and the place the agent stands at. An edge is
one interaction, preceded by a GotoLocation to its place when the agent is elsewhere; its effect
is computed by `macros.try_action`, i.e. by `luminous_sim.states.rules`, so every plan is accepted
by the simulator's rules. Interchangeable objects (same type, state, container and contents, not
named by the goal) are tried once: only the first of them is picked up or put into.
"""

from __future__ import annotations

import heapq
import itertools
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass

from luminous_sim.planning.symbolic.actions import COSTS, HighLevelAction, act, goto
from luminous_sim.planning.symbolic.macros import try_action
from luminous_sim.planning.symbolic.relevance import Relevance
from luminous_sim.planning.symbolic.semantics import anchor, signature
from luminous_sim.states import WorldState, enclosing_closed
from luminous_sim.tasks.meanings import MACRO_ACTIONS
from luminous_sim.vocab import SLICING_TOOLS, abilities, can_contain

_MACROS = tuple((action, pred) for pred, action in MACRO_ACTIONS.items())
"""(device macro, the predicate it makes true), from the predicate table."""


@dataclass(frozen=True)
class Node:
    """A search state: object states and where the agent stands (None: nowhere yet)."""

    world: WorldState
    at: str | None


@dataclass
class SearchResult:
    """What a search returns: the actions (None when none was found), cost and effort."""

    actions: list[HighLevelAction] | None
    cost: float
    expanded: int
    exhausted: bool


def _distinct(state: WorldState, ids: list[str], named: frozenset[str]) -> list[str]:
    """The ids with interchangeable objects reduced to their first."""
    seen: set[tuple] = set()
    out = []
    for oid in ids:
        if oid not in named:
            sig = signature(state, oid)
            if sig in seen:
                continue
            seen.add(sig)
        out.append(oid)
    return out


def candidate_actions(node: Node, rel: Relevance) -> Iterator[HighLevelAction]:
    """Interactions worth trying from a node (each is checked against the rules when applied)."""
    s = node.world
    held = s.held
    if held is None:
        pick = [
            k
            for k, o in s.objects.items()
            if abilities(o.object_type).pickupable and enclosing_closed(s, k) is None
        ]
        for oid in _distinct(s, pick, rel.named):
            yield act("PickupObject", oid)
    else:
        htype = s[held].object_type
        dests = [
            r
            for r in s.objects
            if r in rel.destinations and r != held and can_contain(s[r].object_type, htype)
        ]
        for r in _distinct(s, dests, rel.named):
            yield act("PutObject", held, r)
        for name, pred in _MACROS:
            for d in rel.devices.get(pred, ()):
                if d in s and can_contain(s[d].object_type, htype):
                    yield act(name, held, d)
        if htype in SLICING_TOOLS:
            for k, o in s.objects.items():
                if abilities(o.object_type).sliceable and not o.isSliced and k in rel.objects:
                    yield act("SliceObject", k)
    for k, o in s.objects.items():
        ab = abilities(o.object_type)
        if ab.openable:
            if o.isOpen:
                yield act("CloseObject", k)
            elif k in rel.openers:
                yield act("OpenObject", k)
        if ab.toggleable and k in rel.toggles:
            yield act("ToggleObject", k)


def successors(node: Node, rel: Relevance) -> Iterator[tuple[list[HighLevelAction], float, Node]]:
    """(actions, cost, next node) for every applicable interaction, with its GotoLocation."""
    for a in candidate_actions(node, rel):
        # where the action happens: its receptacle or device (every PutObject has one), else its object
        place = anchor(node.world, a.receptacle_id or a.object_id)
        after, why = try_action(node.world, a)
        if why is not None:
            continue
        if node.at == place:
            yield [a], COSTS[a.action], Node(after, place)
        else:
            yield [goto(place), a], COSTS["GotoLocation"] + COSTS[a.action], Node(after, place)


def astar(
    start: Node,
    rel: Relevance,
    h: Callable[[Node], float],
    is_goal: Callable[[Node], bool],
    max_expansions: int = 20000,
    deadline: float | None = None,
    weight: float = 1.0,
) -> SearchResult:
    """A* (f = g + weight * h) from `start`; ties go to the node with the smaller h.

    Returns:
        The plan found, or `actions=None` with `exhausted=True` when the whole reachable space was
        searched (no plan exists under the relevance filter) and False when a budget ran out.
    """
    tie = itertools.count()
    h0 = h(start)
    if h0 == float("inf"):
        return SearchResult(None, 0.0, 0, True)
    frontier: list[tuple[float, float, int, Node]] = [(weight * h0, h0, next(tie), start)]
    best_g: dict[Node, float] = {start: 0.0}
    parent: dict[Node, tuple[Node, list[HighLevelAction]]] = {}
    closed: set[Node] = set()
    expanded = 0
    while frontier:
        _, hn, _, node = heapq.heappop(frontier)
        if node in closed:
            continue
        closed.add(node)
        g = best_g[node]
        if hn == 0 and is_goal(node):
            return SearchResult(_path(parent, node), g, expanded, False)
        expanded += 1
        if expanded > max_expansions or (
            deadline is not None and expanded % 64 == 0 and time.perf_counter() > deadline
        ):
            return SearchResult(None, 0.0, expanded, False)
        for actions, cost, nxt in successors(node, rel):
            g2 = g + cost
            if g2 >= best_g.get(nxt, float("inf")):
                continue
            h2 = h(nxt)
            if h2 == float("inf"):
                continue
            best_g[nxt] = g2
            parent[nxt] = (node, actions)
            heapq.heappush(frontier, (g2 + weight * h2, h2, next(tie), nxt))
    return SearchResult(None, 0.0, expanded, True)


def _path(
    parent: dict[Node, tuple[Node, list[HighLevelAction]]], node: Node
) -> list[HighLevelAction]:
    out: list[HighLevelAction] = []
    while node in parent:
        node, actions = parent[node]
        out[:0] = actions
    return out
