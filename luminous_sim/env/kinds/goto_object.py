"""`goto_object`: stand where an object of a type is visible and within reach (ALFRED's visibility). No goal
predicate says that, so its goal (`GotoGoal`) judges the view itself, and its expert walks ALFRED's
GotoLocation to the nearest pose that sees such an object."""

from __future__ import annotations

from typing import Any

import numpy as np

from luminous_sim.env.kinds.base import TaskKind, unseen_type
from luminous_sim.episodes import ExpertPlan, Goal
from luminous_sim.errors import PlanningError
from luminous_sim.scene import Scene
from luminous_sim.vocab import abilities
from luminous_sim.world import World, WorldView

GOTO_TEMPLATE = "go to the {obj}"


class GotoGoal:
    """Be where an object of a type is visible within reach; one condition, met by a GotoLocation."""

    task_type = "goto_object"
    stop_to_succeed = False

    def __init__(self, object_type: str):
        self.object_type = object_type
        self.instruction = GOTO_TEMPLATE.format(obj=object_type.lower())
        self.name = f"sees({object_type})"

    def weights(self) -> dict[str, int]:
        return {self.name: 1}

    def stages(self) -> dict[str, str]:
        return {self.name: "GotoLocation"}

    def scores(self, view: WorldView, visible: set[str]) -> dict[str, int]:
        state = view.state
        return {self.name: int(any(state.objects[o].object_type == self.object_type for o in visible
                                   if o in state.objects))}

    def subgoal(self, scores: dict[str, int]) -> str:
        return "" if scores[self.name] else self.name

    def expert_plan(self, world: World) -> ExpertPlan | None:
        from luminous_sim.env.actions import nav_api
        from luminous_sim.planning import NavGraph, goto_actions

        view = world.view()
        graph = NavGraph(view.nav)
        best: list[str] | None = None
        for oid in view.state.of_type(self.object_type):
            pose = view.interaction_pose(oid)
            if pose is None:
                continue
            try:
                steps = goto_actions(graph, view.agent, pose)
            except PlanningError:  # that one is walled off
                continue
            if best is None or len(steps) < len(best):
                best = steps
        if best is None:
            return None
        actions = tuple(nav_api(a) for a in best)
        for api in actions:
            if not world.step(api).success:
                return None
        met = self.scores(view, set(view.visible_objects()))[self.name]
        return ExpertPlan(actions) if met else None

    def to_dict(self) -> dict[str, Any]:
        return {"kind": self.task_type, "object_type": self.object_type}


def _worth_finding(object_type: str) -> bool:
    ab = abilities(object_type)
    return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable


class GotoObject(TaskKind):
    """Go to an object of a type: any the agent can interact with."""

    templates = (GOTO_TEMPLATE,)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        return GotoGoal(unseen_type(world, scene, self.name, _worth_finding, rng))

    def goal_from_dict(self, data: dict[str, Any]) -> Goal:
        return GotoGoal(data["object_type"])
