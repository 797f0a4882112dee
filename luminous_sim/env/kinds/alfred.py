"""ALFRED's seven task types, one `TaskKind` class parameterised by the type: ALFRED's room table, its
set-up (for cleaning, every dirtyable object that can be picked up is dirty first, as ALFRED's
`dirty_and_empty` initialisation does), and a task drawn by the planning layer (`planning.draw_task`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.env.goals import Goal, TaskGoal
from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.tasks import task_info
from luminous_sim.vocab import abilities

if TYPE_CHECKING:
    from luminous_sim.scene import Scene
    from luminous_sim.world import World

DIRTY_FIRST: frozenset[str] = frozenset({"pick_clean_then_place_in_recep"})
"""The types whose set-up makes things dirty (the cleaning task)."""


class AlfredKind(TaskKind):
    """One ALFRED task type."""

    def rooms(self) -> tuple[str, ...]:
        return tuple(sorted(task_info(self.name).rooms))

    def set_up(self, world: World) -> tuple[str, ...]:
        if self.name not in DIRTY_FIRST:
            return ()
        return tuple(sorted(oid for oid, st in world.view().state.objects.items()
                            if abilities(st.object_type).dirtyable and abilities(st.object_type).pickupable))

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        from luminous_sim.planning import draw_task

        return TaskGoal(draw_task(scene, world.view(), self.name, rng))
