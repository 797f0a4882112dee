"""`solve`: whether the expert solves an episode from its start, the only copy of the check (ALFRED's generator
keeps only tasks its planner solves; the freeze keeps only split entries the oracle solves; the env keeps only
episodes its expert solves, in its own camera). The plan is computed in a world of its own from the source; a
plan that met a failure on the way (not `exact`) is replayed in another, and counts only if the replay meets
every condition too."""

from __future__ import annotations

from dataclasses import dataclass

from luminous_sim.episodes.goals import ExpertPlan, TaskGoal
from luminous_sim.episodes.initial_state import WorldSource
from luminous_sim.episodes.spec import EpisodeSpec

REPLAY = "replay"
"""The cause when the expert's plan met the goal but replaying its actions did not."""


@dataclass(frozen=True)
class Solution:
    """The expert's plan from the spec's start (None when it does not solve it) and why not (`cause`)."""

    plan: ExpertPlan | None
    cause: str = ""
    """"" when solved; else the oracle's first failure's code (a `FailureCode` value), `goal_conditions` (its plan
    ran but left a condition unmet), `replay` (see `REPLAY`) or `expert` (a kind's own goal had no plan)."""


def solve(spec: EpisodeSpec, worlds: WorldSource, replay: bool = True) -> Solution:
    """The expert's attempt at `spec` in a world of its own; with `replay`, a plan that is not `exact` counts
    only if replaying its actions meets every condition (the plan is then marked exact)."""
    shadow = worlds.get(spec.scene, spec.dirty, spec.start)
    try:
        if isinstance(spec.goal, TaskGoal):
            plan, cause = spec.goal.expert_attempt(shadow)
        else:
            plan = spec.goal.expert_plan(shadow)
            cause = "" if plan is not None else "expert"
    finally:
        worlds.put(shadow)
    if plan is None or plan.exact or not replay:
        return Solution(plan, cause)
    world = worlds.get(spec.scene, spec.dirty, spec.start)
    try:
        ok = all(world.step(a).success for a in plan.actions)
        view = world.view()
        ok = ok and spec.goal.scores(view, set(view.visible_objects())) == spec.goal.weights()
    finally:
        worlds.put(world)
    return Solution(ExpertPlan(plan.actions, exact=True, steps=plan.steps), "") if ok else Solution(None, REPLAY)
