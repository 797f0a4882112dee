"""`objectnav_pickup`: pick up an object of a named type, under the ObjectNav start and SPL protocol (the
`-v2` pick-up ids). The start is drawn at least `min_start_distance` m (geodesic, on the agent's grid) from
every point within ALFRED's interaction reach of a target instance (1.5 m, camera to the object's nearest
point), its success region (`navscore`); the target may be any pickupable type that some reachable pose can
see. Success is holding an object of the type, and it ends the episode at once (no Stop needed: the pick-up
is itself the deliberate act, as ALFRED's goal check ends its episode when the goal is satisfied); Stop before
that ends the episode as a failure. The expert is ALFRED's oracle (`planning.Oracle`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.env.kinds.objectnav import nav_start, seeable_instances, target_types
from luminous_sim.env.kinds.pickup_object import PICKUP_TEMPLATE, pickup_task
from luminous_sim.env.navscore import Key, region_of, start_keys
from luminous_sim.episodes import Goal, TaskGoal
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskSamplingError
from luminous_sim.vocab import abilities
from luminous_sim.world import AgentPose, World, WorldView


class PickupNavGoal(TaskGoal):
    """Hold an object of a type (the pick-up task's goal), scored with a success region."""

    def __init__(self, object_type: str, scene_seed: int):
        super().__init__(pickup_task(object_type, scene_seed))
        self.task_type = "objectnav_pickup"
        self.object_type = object_type
        self.scene_seed = scene_seed

    def instances(self, view: WorldView) -> tuple[str, ...]:
        return seeable_instances(view, self.object_type, shut_in=True)

    def region(self, view: WorldView) -> frozenset[Key]:
        return region_of(view, self.instances(view), within=None, reach=view.config.visibility_distance)

    def to_dict(self) -> dict[str, Any]:
        return {"kind": self.task_type, "object_type": self.object_type, "scene_seed": self.scene_seed}


class ObjectNavPickup(TaskKind):
    """Pick up an object of a type, starting far from every one."""

    templates = (PICKUP_TEMPLATE,)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        view = world.view()
        types = target_types(view, lambda t: abilities(t).pickupable, shut_in=True)
        for i in rng.permutation(len(types)):
            goal = PickupNavGoal(types[int(i)], scene.seed)
            if start_keys(view, goal.region(view), self.options["min_start_distance"]):
                return goal
        raise TaskSamplingError(f"no objectnav_pickup target in {scene.room.name} (seed {scene.seed}) with a "
                                f"start {self.options['min_start_distance']:g} m from it")

    def draw_start(self, world: World, goal: Goal, rng: np.random.Generator) -> AgentPose | None:
        return nav_start(world, goal, rng, self.options["min_start_distance"], self.name)

    def goal_from_dict(self, data: dict[str, Any]) -> Goal:
        return PickupNavGoal(data["object_type"], int(data["scene_seed"]))
