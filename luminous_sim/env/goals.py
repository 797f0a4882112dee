"""What an episode asks for, behind one small interface: its named conditions and what meets each, the
current subgoal, the instruction, and the expert's plan from a world's current state.

`TaskGoal` wraps a `TaskInstance` (ALFRED's seven types, and `pickup_object`, a one-condition custom goal);
its conditions are the task's `GoalConditions`, so success, ALFRED's counts, the dense reward and the subgoal
come from one source. `GotoGoal` (`goto_object`) is met when an object of a type is visible within reach;
no goal predicate says that, so it judges the view itself, and its expert walks ALFRED's GotoLocation.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from luminous_sim.cdf.predicates import Atom, Exists, Param
from luminous_sim.errors import PlanningError
from luminous_sim.language import Describer
from luminous_sim.tasks import PLAN_ORDER, PddlParams, TaskInstance
from luminous_sim.world import World, WorldView

GOTO_TEMPLATE = "go to the {obj}"
PICKUP_TEMPLATE = "pick up the {obj}"
ENV_TEMPLATES: tuple[str, ...] = (GOTO_TEMPLATE, PICKUP_TEMPLATE)
"""The instructions of the env's own task kinds (their words are part of the token vocabulary)."""


@dataclass(frozen=True)
class ExpertPlan:
    """The expert's api actions from some state; `exact` when replaying them is known to reproduce its run
    (the oracle met no failure on the way, so nothing it tried and undid is missing from the list)."""

    actions: tuple[dict[str, Any], ...]
    exact: bool = True
    steps: tuple[str, ...] = ()
    """Step-by-step instructions, one per subgoal (the language layer's templates), when known."""


class Goal(Protocol):
    """An episode's goal."""

    task_type: str
    instruction: str

    def weights(self) -> dict[str, int]:
        """Condition name -> how many counts it is worth."""
        ...

    def stages(self) -> dict[str, str]:
        """Condition name -> the action that meets it (`PickupObject`, `GotoLocation`, ...)."""
        ...

    def scores(self, view: WorldView, visible: set[str]) -> dict[str, int]:
        """Condition name -> counts met now."""
        ...

    def subgoal(self, scores: dict[str, int]) -> str:
        """The first condition not yet met, in the order an expert meets them ("" when all are)."""
        ...

    def expert_plan(self, world: World) -> ExpertPlan | None:
        """Reach the goal in `world` from its current state (changing it); the actions, or None on failure."""
        ...

    def to_dict(self) -> dict[str, Any]:
        """Plain data that `goal_from_dict` reads back."""
        ...


class TaskGoal:
    """A task's goal conditions (ALFRED's reading for the seven types, the goal's own for a custom one)."""

    def __init__(self, task: TaskInstance):
        self.task = task
        self.task_type = task.task_type
        self.instruction = task.instruction
        self.conditions = task.conditions()

    def weights(self) -> dict[str, int]:
        return {c.name: c.weight for c in self.conditions.conditions}

    def stages(self) -> dict[str, str]:
        return {c.name: PLAN_ORDER[c.stage] if c.stage < len(PLAN_ORDER) else "Base"
                for c in self.conditions.conditions}

    def scores(self, view: WorldView, visible: set[str]) -> dict[str, int]:
        return self.conditions.scores(view.state, visible)

    def subgoal(self, scores: dict[str, int]) -> str:
        return next((c.name for c in self.conditions.subgoals() if scores[c.name] < c.weight), "")

    def expert_plan(self, world: World) -> ExpertPlan | None:
        from luminous_sim.planning import Oracle

        traj = Oracle(world, record_frames=False).run(self.task.goal, names=dict(self.task.names) or None)
        view = world.view()
        if not traj.success or not self.conditions.success(view.state, set(view.visible_objects())):
            return None
        rng = np.random.default_rng(np.random.SeedSequence([world.scene.seed, 11]))
        steps = tuple(Describer(view, rng).describe(traj, self.instruction).high_descs)
        return ExpertPlan(tuple(a["api_action"] for a in traj.low_actions), exact=not traj.failures, steps=steps)

    def to_dict(self) -> dict[str, Any]:
        return {"kind": "task", "task": self.task.to_dict()}


def pickup_task(object_type: str, scene_seed: int) -> TaskInstance:
    """`pickup_object`: hold any object of a type."""
    goal = Exists((Param("?o", object_type),), Atom("holds", ("?o",)))
    return TaskInstance("pickup_object", PddlParams(object_type), goal, scene_seed,
                        PICKUP_TEMPLATE.format(obj=object_type.lower()), custom=True)


class GotoGoal:
    """`goto_object`: stand where an object of a type is visible and within reach (ALFRED's visibility)."""

    task_type = "goto_object"

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
        return {"kind": "goto", "object_type": self.object_type}


def goal_from_dict(data: dict[str, Any]) -> Goal:
    """A goal from `to_dict` data."""
    if data["kind"] == "goto":
        return GotoGoal(data["object_type"])
    return TaskGoal(TaskInstance.from_dict(data["task"]))
