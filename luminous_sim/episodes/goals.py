"""What an episode asks for, behind one small interface (`Goal`): its named conditions and what meets each,
the current subgoal, the instruction, and the expert's plan from a world's current state.

`TaskGoal` wraps a `TaskInstance` (ALFRED's seven types, a CDF's task, and `pickup_object`, a one-condition
custom goal); its conditions are the task's `GoalConditions`, so success, ALFRED's counts, the dense reward and
the subgoal come from one source. A task kind may bring a goal of its own (`env.kinds.goto_object.GotoGoal`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from luminous_sim.language import Describer
from luminous_sim.tasks import PLAN_ORDER, TaskInstance
from luminous_sim.world import World, WorldView


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
    stop_to_succeed: bool
    """Whether the goal counts only when the agent calls Stop with its conditions met (ObjectNav's rule);
    otherwise the episode succeeds the moment they are met."""

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
        """Plain data that `kinds.goal_from_dict` reads back (`kind`: "task", or the task kind's name)."""
        ...


class TaskGoal:
    """A task's goal conditions (ALFRED's reading for the seven types, the goal's own for a custom one)."""

    stop_to_succeed = False

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
        return self.expert_attempt(world)[0]

    def expert_attempt(self, world: World) -> tuple[ExpertPlan | None, str]:
        """`expert_plan`, and why it is None: the oracle's first failure's code (a `FailureCode` value), or
        `goal_conditions` when its plan ran but left a condition unmet; "" with a plan."""
        from luminous_sim.planning import Oracle

        traj = Oracle(world, record_frames=False).run(self.task.goal, names=dict(self.task.names) or None)
        view = world.view()
        if not traj.success or not self.conditions.success(view.state, set(view.visible_objects())):
            return None, traj.failure_codes[0].value if traj.failure_codes else "goal_conditions"
        rng = np.random.default_rng(np.random.SeedSequence([world.scene.seed, 11]))
        steps = tuple(Describer(view, rng).describe(traj, self.instruction).high_descs)
        plan = ExpertPlan(tuple(a["api_action"] for a in traj.low_actions), exact=not traj.failures, steps=steps)
        return plan, ""

    def to_dict(self) -> dict[str, Any]:
        return {"kind": "task", "task": self.task.to_dict()}
