"""One PyBullet physics client per World, DIRECT by default, with the project's deterministic settings."""

from __future__ import annotations

import pybullet as p
from pybullet_utils.bullet_client import BulletClient

TIME_STEP = 1.0 / 240.0
GRAVITY = -9.81


def new_client(gui: bool = False) -> BulletClient:
    """A fresh client: fixed time step, gravity, deterministic overlapping pairs, no GUI unless asked."""
    client = BulletClient(connection_mode=p.GUI if gui else p.DIRECT)
    client.setPhysicsEngineParameter(
        fixedTimeStep=TIME_STEP, deterministicOverlappingPairs=1, numSolverIterations=50
    )
    client.setGravity(0, 0, GRAVITY)
    return client


def add_floor(client: BulletClient, half_extent: float = 20.0) -> int:
    """A static floor slab whose top is at z = 0."""
    shape = client.createCollisionShape(p.GEOM_BOX, halfExtents=[half_extent, half_extent, 0.05])
    visual = client.createVisualShape(p.GEOM_BOX, halfExtents=[half_extent, half_extent, 0.05],
                                      rgbaColor=[0.62, 0.55, 0.47, 1])
    body = client.createMultiBody(0, shape, visual, [0, 0, -0.05])
    client.changeDynamics(body, -1, lateralFriction=0.9)
    return body
