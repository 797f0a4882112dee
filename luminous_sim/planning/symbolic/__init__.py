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

Backend choice, on evidence (`benchmarks/bench_planner.py`, randomized hand-built kitchens and
bedrooms with 1-3 extra instances of every pickupable type, about 50-90 objects, half the goals
with the all-closed conjunct; every plan replayed through the rules and checked with the task
layer's evaluator; 2-core machine, medians over the same states for all backends, 5 per type):

| backend | solved | time median / max | plan cost median by type (simple, two, look, clean, heat, cool, movable) | install |
|---|---|---|---|---|
| astar (built-in, default) | 35/35 | 25 ms / 0.23 s | 2, 12, 10, 10, 17, 10, 12 | nothing |
| fd (Fast Downward lama-first, bundled driver) | 35/35 | 0.71 s / 34 s (heat: median 19 s, translator) | 2, 13, 11, 10, 19, 11, 13 | up-fast-downward wheel, 216 MB |
| up (unified-planning + FD) | 35/35 | 2.5 s / 40 s | as fd | same + unified-planning |
| pyperplan | 0 | parser rejects `:functions`/ADL; UP compilation to STRIPS of one kitchen problem: grounding 5.5 s (353 actions), quantifier removal 81 s, conditional-effect removal killed after 300 s | - | pyperplan |

With 20 states per type the built-in A* solves 140/140: median 13 ms, max 0.52 s; median plan
length by type 5, 9.5, 4, 7, 9, 8, 8 high-level actions (max 19). Against Fast Downward's optimal
configuration (A* with h_max) on 28 further states (`--optimal-gap --trials 4 --seed 1`) its plans
are optimal in 23 and at most 2 cost units above optimal in the rest.
The domain needs conditional effects (what a carried plate holds moves with it,
a microwave heats everything inside, slicing creates slices), which pyperplan cannot express and
which make grounding-based planners slow on scenes with many objects; the built-in search applies
the simulator's own rules, so it cannot drift from them. Hence `astar` is the default and `fd`/`up`
stay as optional cross-checks (`backend="fd"`), used only when their package is installed.
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
