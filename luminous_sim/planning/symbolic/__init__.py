"""The oracle's symbolic planner: a state and a goal in, ALFRED's high-level actions out.

    plan = solve(world_state, goal, names)          # Plan(actions, cost, expanded, seconds)
    plan.actions  # [GotoLocation(CounterTop|1), PickupObject(Apple|1), GotoLocation(Microwave|1),
                  #  HeatObject(Apple|1, Microwave|1), GotoLocation(DiningTable|1), PutObject(...)]
    plan.high_pddl()                                # ALFRED's planner_action/discrete_action records

Goals are any `luminous_sim.cdf.predicates` expression (and/or/not/exists/forall over
inReceptacle, inReceptacleObject, isHot, isCool, isClean, isDirty, isSliced, isOn/isToggled,
isOpen, isFilled, holds, =), judged exactly as `luminous_sim.tasks.expressions.goal_satisfied`
judges them; `close_receptacles=True` adds ALFRED's "every receptacle closed" conjunct. Location
is abstract: GotoLocation(x) puts the agent at x's interaction place (its innermost fixed
container, `semantics.anchor`), and every interaction is done from its target's place.
Heat/Cool/Clean are ALFRED's macros (`expand_macro`); every plan is replayed through
`luminous_sim.states.rules` on the full state before it is returned, and an unreachable goal raises
`PlanningError` with the reason ("no Microwave in the scene: cannot make Mug|1 hot").

Modules: `actions` (HighLevelAction, Plan), `macros` (expansions, replay), `semantics` (goal
meaning, `anchor`), `relevance` (which objects the search sees), `heuristic` (goal distance and
infeasibility), `search` (A*), `solver` (`solve`), `problem` (PDDL problems over
`planning/domain/luminous_domain.pddl`), `external` (Fast Downward backends).

Backend choice: the built-in A* (`astar`) is the default; Fast Downward (`fd`, `up`) are optional
cross-checks. The evidence (`benchmarks/bench_planner.py`) is in docs/planner_backends.md.
"""

from luminous_sim.planning.symbolic.actions import ACTIONS, COSTS, HighLevelAction, Plan, act, goto
from luminous_sim.planning.symbolic.macros import apply_action, expand_macro, replay
from luminous_sim.planning.symbolic.problem import domain_text, to_pddl_problem
from luminous_sim.planning.symbolic.solver import BACKENDS, solve

__all__ = [
    "ACTIONS",
    "BACKENDS",
    "COSTS",
    "HighLevelAction",
    "Plan",
    "act",
    "apply_action",
    "domain_text",
    "expand_macro",
    "goto",
    "replay",
    "solve",
    "to_pddl_problem",
]
