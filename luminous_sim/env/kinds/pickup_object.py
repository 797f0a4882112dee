"""`pickup_object`: hold any object of a type, one that can be picked up and is not in view at the start
(a one-condition custom task, so its goal is a `TaskGoal`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.cdf.predicates import Atom, Exists, Param
from luminous_sim.env.kinds.base import TaskKind, unseen_type
from luminous_sim.episodes import Goal, TaskGoal
from luminous_sim.tasks import PddlParams, TaskInstance
from luminous_sim.vocab import abilities

if TYPE_CHECKING:
    from luminous_sim.scene import Scene
    from luminous_sim.world import World

PICKUP_TEMPLATE = "pick up the {obj}"


def pickup_task(object_type: str, scene_seed: int) -> TaskInstance:
    """The task of holding any object of a type."""
    goal = Exists((Param("?o", object_type),), Atom("holds", ("?o",)))
    return TaskInstance("pickup_object", PddlParams(object_type), goal, scene_seed,
                        PICKUP_TEMPLATE.format(obj=object_type.lower()), custom=True)


class PickupObject(TaskKind):
    """Pick up an object of a type."""

    templates = (PICKUP_TEMPLATE,)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        object_type = unseen_type(world, scene, self.name, lambda t: abilities(t).pickupable, rng)
        return TaskGoal(pickup_task(object_type, scene.seed))
