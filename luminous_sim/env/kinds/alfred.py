"""ALFRED's seven task types, one `TaskKind` class parameterised by the type: ALFRED's room table, its
set-up (for cleaning, every dirtyable object that can be picked up is dirty first, as ALFRED's
`dirty_and_empty` initialisation does), and a task drawn by the planning layer (`planning.draw_task`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.env.goals import Goal, TaskGoal
from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.tasks import alfred_dirty, task_info

if TYPE_CHECKING:
    from luminous_sim.scene import Scene
    from luminous_sim.world import World

class AlfredKind(TaskKind):
    """One ALFRED task type."""

    def rooms(self) -> tuple[str, ...]:
        return tuple(sorted(task_info(self.name).rooms))

    def set_up(self, world: World) -> tuple[str, ...]:
        return alfred_dirty(world.view().state, self.name)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        from luminous_sim.planning import draw_task

        return TaskGoal(draw_task(scene, world.view(), self.name, rng))
