"""ALFRED's seven task types, one `TaskKind` class parameterised by the type: ALFRED's room table, its
set-up (for cleaning, every dirtyable object that can be picked up is dirty first, as ALFRED's
`dirty_and_empty` initialisation does), and a task drawn by the planning layer (`planning.draw_task`).

Options (`EnvConfig.task_options`): `house` 1 plays each episode in a house generated from its seed (the house
of `luminous generate --house`, with its front door) instead of one room; `cross_room_share` is then the share
of episodes whose task's object lies in another room than its receptacle (or lamp) (`tasks.rooms_apart`; where
the house has no such task, any task of the type)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.episodes import Goal, TaskGoal
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

    def generate_scene(self, room_type: str, seed: int) -> Scene:
        if not self.options["house"]:
            return super().generate_scene(room_type, seed)
        from luminous_sim.env.kinds.house_objectnav import house_scene

        return house_scene(seed)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        from luminous_sim.planning import draw_task
        from luminous_sim.tasks import TaskSamplingError, rooms_apart

        view = world.view()
        if scene.room.house is not None and rng.random() < self.options["cross_room_share"]:
            try:
                return TaskGoal(draw_task(scene, view, self.name, rng, keep=rooms_apart(scene, view.state)))
            except TaskSamplingError:
                pass  # no task of the type crosses rooms in this house: any task of it
        return TaskGoal(draw_task(scene, view, self.name, rng))
