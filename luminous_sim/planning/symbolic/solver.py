"""`solve`: a goal and a state in, a checked high-level plan out (or a `PlanningError` saying why).

The default backend is the built-in A* (`search`). The same problem can be handed, as PDDL
(`problem.build_problem` over `luminous_domain.pddl`), to Fast Downward (`backend="fd"`) or to
unified-planning's Fast Downward engine (`backend="up"`); both need the optional up-fast-downward
package (see the package docstring for why pyperplan is not a backend).
Whatever the backend, the plan is replayed through the rules on the full state and the goal is
checked before it is returned.
"""

from __future__ import annotations

import time
from collections.abc import Mapping

from luminous_sim.cdf.predicates import And, Expr
from luminous_sim.errors import FailureCode, PlanningError
from luminous_sim.planning.symbolic.actions import HighLevelAction, Plan
from luminous_sim.planning.symbolic.heuristic import Estimator
from luminous_sim.planning.symbolic.macros import try_action
from luminous_sim.planning.symbolic.relevance import relevance
from luminous_sim.planning.symbolic.search import Node, astar
from luminous_sim.planning.symbolic.semantics import anchor, holds, prepare_goal
from luminous_sim.states import WorldState
from luminous_sim.tasks.types import closed_receptacles_goal
from luminous_sim.vocab import abilities

BACKENDS: tuple[str, ...] = ("astar", "fd", "up")
"""Solvers `solve` can use; "astar" needs nothing beyond the project's dependencies."""


def solve(
    state: WorldState,
    goal: Expr,
    names: Mapping[str, str] | None = None,
    *,
    at: str | None = None,
    backend: str = "astar",
    close_receptacles: bool = False,
    max_expansions: int = 20000,
    timeout: float = 30.0,
) -> Plan:
    """Find a high-level plan that makes `goal` hold.

    Args:
        state: the current object states (what contains what, who holds what).
        goal: any goal expression over the CDF predicates (and/or/not/exists/forall).
        names: goal constant -> object id, for goals that name objects (ids may be used directly).
        at: the object whose place the agent stands at now, if any.
        backend: one of `BACKENDS`.
        close_receptacles: also require every openable receptacle closed at the end (ALFRED's
            planner goal conjunct).
        max_expansions: search budget (nodes expanded) for the built-in search.
        timeout: seconds before giving up.

    Returns:
        The plan, replayed and checked on `state`.

    Raises:
        PlanningError: the goal cannot be reached (with the reason, e.g. "no Microwave in the
            scene: cannot make Apple|1 hot"), no plan was found within the budget, or the backend
            is unknown or not installed.
    """
    if backend not in BACKENDS:
        raise PlanningError(
            f"unknown planner backend {backend!r}; expected one of {', '.join(BACKENDS)}"
        )
    names = dict(names or {})
    if close_receptacles:
        goal = And((goal, closed_receptacles_goal()))
    t0 = time.perf_counter()
    prepared = prepare_goal(goal, state, names)
    movable_types = frozenset(
        o.object_type for o in state.objects.values() if abilities(o.object_type).movable_receptacle
    )
    est = Estimator(prepared, names, movable_types)
    if est(state, at) == float("inf"):
        reasons = list(dict.fromkeys(est.reasons))[:3] or ["unsatisfiable"]
        raise PlanningError(
            f"the goal cannot be reached: {'; '.join(reasons)}", FailureCode.GOAL_UNREACHABLE
        )
    if holds(prepared, state, at, names):
        return Plan([], 0.0, 0, time.perf_counter() - t0, backend)
    if backend != "astar":
        from luminous_sim.planning.symbolic.external import solve_external

        actions, cost = solve_external(backend, state, prepared, names, at=at, timeout=timeout)
        _check(state, at, actions, prepared, names)
        return Plan(actions, cost, 0, time.perf_counter() - t0, backend)

    deadline = t0 + timeout
    expanded = 0
    for full in (False, True):
        rel = relevance(state, prepared, names, full=full)
        start = Node(rel.restrict(state), at)
        result = astar(
            start,
            rel,
            h=lambda n: est(n.world, n.at),
            is_goal=lambda n: holds(prepared, n.world, n.at, names),
            max_expansions=max_expansions,
            deadline=deadline,
        )
        expanded += result.expanded
        if result.actions is not None:
            try:
                _check(state, at, result.actions, prepared, names)
            except PlanningError:
                continue  # the filter dropped something that mattered: search the whole scene
            return Plan(result.actions, result.cost, expanded, time.perf_counter() - t0, backend)
        if not result.exhausted:
            raise PlanningError(
                f"no plan found within the budget ({expanded} nodes expanded, "
                f"{time.perf_counter() - t0:.1f} s)",
                FailureCode.PLAN_BUDGET,
            )
    raise PlanningError(f"no plan reaches the goal (searched {expanded} states)")


def _check(
    state: WorldState,
    at: str | None,
    actions: list[HighLevelAction],
    prepared: Expr,
    names: Mapping[str, str],
) -> None:
    """Replay a plan through the rules on the full state and check the goal at the end."""
    where = at
    for i, a in enumerate(actions):
        if a.action == "GotoLocation":
            where = a.object_id
            continue
        target = a.receptacle_id if a.receptacle_id is not None else a.object_id
        if where != anchor(state, target):
            raise PlanningError(
                f"plan step {i}: {a!r} is not done at {anchor(state, target)} (agent at {where})"
            )
        state, why = try_action(state, a)
        if why is not None:
            raise PlanningError(f"plan step {i}: {why}")
    if not holds(prepared, state, where, names):
        raise PlanningError("the plan does not reach the goal")
