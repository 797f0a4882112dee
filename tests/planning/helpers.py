"""Replaying plans through the object-state rules and checking goals, for the planner tests."""

from __future__ import annotations

from collections.abc import Mapping

from luminous_sim.cdf.predicates import Expr
from luminous_sim.planning.symbolic import Plan, expand_macro
from luminous_sim.planning.symbolic.semantics import anchor
from luminous_sim.states import WorldState, rules
from luminous_sim.tasks.evaluate import goal_satisfied


def replay(state: WorldState, plan: Plan) -> tuple[WorldState, str | None]:
    """Run a plan low-level step by low-level step through `rules.check/effects/apply`.

    GotoLocation moves the agent (no object state changes); every other action must be done at the
    place of its target (a receptacle's place for PutObject and the devices).

    Returns:
        (final state, where the agent ends).
    """
    at: str | None = None
    for i, action in enumerate(plan.actions):
        if action.action == "GotoLocation":
            at = action.object_id
            continue
        target = action.receptacle_id or action.object_id
        assert at == anchor(state, target), (
            f"step {i} {action!r}: agent at {at}, not at {anchor(state, target)}"
        )
        for step in expand_macro(action, state):
            why = rules.check(
                step["action"], state, step["objectId"], step.get("receptacleObjectId")
            )
            assert why is None, f"step {i} {action!r}: {step['action']} refused: {why}"
            state = rules.apply(
                state,
                rules.effects(
                    step["action"], state, step["objectId"], step.get("receptacleObjectId")
                ),
            )
    return state, at


def assert_solves(
    state: WorldState, goal: Expr, plan: Plan, names: Mapping[str, str] | None = None
) -> WorldState:
    """The plan replays under the rules and the goal holds at the end (task layer's evaluator)."""
    final, _ = replay(state, plan)
    assert not final.problems(), final.problems()
    assert goal_satisfied(goal, final, names), f"goal not reached by {plan.summary()}"
    return final


def shape(plan: Plan, gotos: bool = True) -> list[str]:
    """The plan's action names (optionally without GotoLocation)."""
    return [a.action for a in plan.actions if gotos or a.action != "GotoLocation"]
