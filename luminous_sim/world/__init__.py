"""Layer L2: the only package that imports pybullet (building, rendering, physics, actions).

`World(scene)` builds a scene into its own PyBullet client; `World.step(action)` runs ALFRED's
low-level actions and returns a `StepResult` (a failure carries a `FailureCode` beside its message);
`World.view()` is the read-only `WorldView` that planning, tasks and language use.

Public names are loaded on first use, so that pure helpers (`world.masks`, `world.agent`) stay
importable without pybullet.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.errors import Failure, FailureCode
    from luminous_sim.world.agent import AgentPose
    from luminous_sim.world.camera import Frame
    from luminous_sim.world.config import WorldConfig
    from luminous_sim.world.masks import bbox_from_mask, interaction_args, mask_to_rle, rle_to_mask
    from luminous_sim.world.navigation import NavGrid
    from luminous_sim.world.physics_check import (
        CollisionMeasure,
        PhysicsReport,
        check_physics,
        object_collisions,
        scene_collisions,
    )
    from luminous_sim.world.placement import Spot
    from luminous_sim.world.poses import receptacle_places
    from luminous_sim.world.results import StepResult
    from luminous_sim.world.scene_builder import BuiltScene, build_scene
    from luminous_sim.world.view import LiveView, WorldView
    from luminous_sim.world.views import egocentric, top_down
    from luminous_sim.world.world import World

_WHERE = {
    "Failure": "luminous_sim.errors", "FailureCode": "luminous_sim.errors",
    "AgentPose": "luminous_sim.world.agent",
    "Frame": "luminous_sim.world.camera",
    "WorldConfig": "luminous_sim.world.config",
    "bbox_from_mask": "luminous_sim.world.masks", "interaction_args": "luminous_sim.world.masks",
    "mask_to_rle": "luminous_sim.world.masks", "rle_to_mask": "luminous_sim.world.masks",
    "NavGrid": "luminous_sim.world.navigation",
    "PhysicsReport": "luminous_sim.world.physics_check", "check_physics": "luminous_sim.world.physics_check",
    "CollisionMeasure": "luminous_sim.world.physics_check", "object_collisions": "luminous_sim.world.physics_check",
    "scene_collisions": "luminous_sim.world.physics_check",
    "Spot": "luminous_sim.world.placement",
    "receptacle_places": "luminous_sim.world.poses",
    "StepResult": "luminous_sim.world.results",
    "BuiltScene": "luminous_sim.world.scene_builder", "build_scene": "luminous_sim.world.scene_builder",
    "LiveView": "luminous_sim.world.view", "WorldView": "luminous_sim.world.view",
    "egocentric": "luminous_sim.world.views", "top_down": "luminous_sim.world.views",
    "World": "luminous_sim.world.world",
}

__all__ = [
    "AgentPose",
    "BuiltScene",
    "CollisionMeasure",
    "Failure",
    "FailureCode",
    "Frame",
    "LiveView",
    "NavGrid",
    "PhysicsReport",
    "Spot",
    "StepResult",
    "World",
    "WorldConfig",
    "WorldView",
    "bbox_from_mask",
    "build_scene",
    "check_physics",
    "egocentric",
    "interaction_args",
    "mask_to_rle",
    "object_collisions",
    "receptacle_places",
    "rle_to_mask",
    "scene_collisions",
    "top_down",
]


__getattr__ = lazy_getattr(__name__, _WHERE)
