"""The agent's hand: a held object (and what rests in it) floats, without collisions, ahead of and
below the camera and moves with the agent, as AI2-THOR shows it; putting it down makes it a body again."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.states.model import WorldState
from luminous_sim.world.asset_loader import base_link_pose

if TYPE_CHECKING:
    from luminous_sim.world.world import World

HAND_AHEAD, HAND_DROP = 0.45, 0.35
"""Where a held object floats: ahead of and below the camera, as AI2-THOR shows it."""


def family(world: World, state: WorldState, oid: str) -> list[str]:
    """The object and everything resting in or on it, recursively."""
    out = [oid]
    for c in state.contents(oid, recursive=True):
        if c in world.built.objects:
            out.append(c)
    return out


def move_rigidly(world: World, oids: list[str], old: tuple, new: tuple) -> None:
    """Move bodies as one rigid group from frame `old` to frame `new` (pos, orn)."""
    c = world.client
    inv = c.invertTransform(*old)
    for oid in oids:
        body = world.built.objects[oid].body
        pos, orn = c.getBasePositionAndOrientation(body)
        rel = c.multiplyTransforms(inv[0], inv[1], pos, orn)
        npos, norn = c.multiplyTransforms(new[0], new[1], rel[0], rel[1])
        c.resetBasePositionAndOrientation(body, npos, norn)
        c.resetBaseVelocity(body, [0, 0, 0], [0, 0, 0])


def set_held_physics(world: World, oid: str, held: bool) -> None:
    """A held body collides with nothing and has no mass; a released one gets both back."""
    c = world.client
    loaded = world.built.objects[oid]
    links = [-1] + list(range(c.getNumJoints(loaded.body)))
    for link in links:
        c.setCollisionFilterGroupMask(loaded.body, link, 0 if held else 1, 0 if held else -1)
    mass = 0.0 if held else loaded.entry.mass
    c.changeDynamics(loaded.body, -1, mass=mass)


def hand_frame(world: World) -> tuple:
    """The hand's (position, orientation) for the agent's pose now."""
    pose = world.agent
    fx_, fy_ = pose.forward()
    eye = np.array(pose.eye())
    pos = eye + np.array([fx_, fy_, 0.0]) * HAND_AHEAD - np.array([0, 0, HAND_DROP])
    orn = world.client.getQuaternionFromEuler([0, 0, -math.radians(pose.rotation)])
    return tuple(pos), orn


def grab(world: World, state: WorldState, oid: str) -> None:
    """Take the object (with what rests in it) into the hand."""
    group = family(world, state, oid)
    for o in group:
        set_held_physics(world, o, True)
    body = world.built.objects[oid].body
    old = base_link_pose(world.client, body)
    move_rigidly(world, group, old, hand_frame(world))


def carry(world: World, state: WorldState, oid: str) -> None:
    """Keep the held object (and what it carries) in front of the camera after the agent moves."""
    body = world.built.objects[oid].body
    move_rigidly(world, family(world, state, oid), base_link_pose(world.client, body), hand_frame(world))


def release(world: World, state: WorldState, oid: str, pose: tuple[float, float, float, float]) -> None:
    """Set the held object (with what rests in it) down at `pose` (x, y, z, yaw) as bodies again."""
    x, y, z, yaw = pose
    body = world.built.objects[oid].body
    c = world.client
    new = ((x, y, z), c.getQuaternionFromEuler([0, 0, yaw]))
    group = family(world, state, oid)
    move_rigidly(world, group, base_link_pose(c, body), new)
    for o in group:
        set_held_physics(world, o, False)
