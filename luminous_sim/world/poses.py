"""Interaction poses: grid poses from which an object is visible and within reach (ALFRED's planner
computes the same kind of target `loc|x|z|rot|horizon` for GotoLocation)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.world.agent import CAMERA_HEIGHT, HORIZON_MAX, HORIZON_MIN, AgentPose
from luminous_sim.world.client import body_aabb
from luminous_sim.world.doors import hits_agent, swept_boxes

if TYPE_CHECKING:
    from luminous_sim.world.world import KeptFrame, World


def candidate_poses(world: World, object_id: str, reach: float | None = None) -> list[AgentPose]:
    """Grid poses near the object, facing it (cardinal heading), pitched at it; nearest first."""
    reach = reach or world.config.visibility_distance
    body = world.built.objects[object_id].body
    lo, hi = body_aabb(world.client, body)
    center = (lo + hi) / 2
    out = []
    for x, y in world.nav.points():
        d = math.hypot(center[0] - x, center[1] - y)
        if d > reach + 0.3:
            continue
        yaw = math.degrees(math.atan2(center[0] - x, center[1] - y)) % 360
        rot = round(yaw / 90) % 4 * 90
        off = (yaw - rot + 180) % 360 - 180
        # an object 20-45 degrees off the nearest heading may sit at the edge of the 60-degree view:
        # the other heading beside it is tried too, after the straight-on poses at that distance
        headings = [(rot, 0.0)] + ([((rot + (90 if off > 0 else -90)) % 360, 0.25)] if abs(off) > 20 else [])
        pitch = math.degrees(math.atan2(CAMERA_HEIGHT - center[2], max(d, 0.05)))
        base = int(np.clip(round(pitch / 15) * 15, HORIZON_MIN, HORIZON_MAX))
        for r, penalty in headings:
            for h in dict.fromkeys([base, min(base + 15, HORIZON_MAX), max(base - 15, HORIZON_MIN)]):
                out.append((abs(d - 1.0) + penalty, d, AgentPose(float(x), float(y), r, h)))
    out.sort(key=lambda t: (t[0], t[1], t[2].x, t[2].y, t[2].rotation, t[2].horizon))
    return [p for _, _, p in out]


PREVIEW = 100
"""Side of the cheap segmentation preview used to rule candidate poses out before a full render."""


def _seen_in_preview(world: World, pose: AgentPose, body: int) -> bool:
    from luminous_sim.world.camera import render

    eye = np.array(pose.eye())
    frame = render(world.client, eye, eye + np.array(pose.view_direction()), width=PREVIEW, height=PREVIEW,
                   fov=world.config.fov, near=0.05, far=20.0, guard=world.eye_guard)
    seg = frame.seg
    return bool(((seg >= 0) & ((seg & ((1 << 24) - 1)) == body)).any())


def find_interaction_pose(world: World, object_id: str, limit: int = 80,
                          prefer: Callable[[AgentPose], bool] | None = None) -> AgentPose | None:
    """The first candidate pose from which the object is visible (>= 10 px at full size) and within reach,
    and, for a closed door, drawer or lid, clear of its swing; with `prefer`, the first such pose that
    passes it (else the first such pose).

    Candidates are screened with a 100x100 segmentation preview; only those that show the object at
    all get the full-size visibility check.
    """
    saved = world.agent
    body = world.built.objects[object_id].body
    held = world.interactions.held
    state = world.interactions.state.objects.get(object_id)
    sweep = swept_boxes(world, object_id) if state is not None and not state.isOpen else []
    fallback = found = None
    seen: dict[AgentPose, KeptFrame] = {}
    try:
        for pose in candidate_poses(world, object_id)[:limit]:
            if sweep and hits_agent(sweep, pose.x, pose.y):
                continue  # it will be opened from here: its door must swing clear of the agent
            world.agent = pose
            if held is not None:  # what the agent carries hangs in front of the camera and may hide it
                world.interactions.carry(held)
            if not _seen_in_preview(world, pose, body):
                continue
            world.invalidate_frame()
            if object_id in world.visible_objects():
                seen[pose] = world.frame_memo()
                if prefer is None or prefer(pose):
                    found = pose
                    break
                fallback = fallback or pose
        found = found or fallback
        return found
    finally:
        world.agent = saved
        if held is not None:
            world.interactions.carry(held)
        world.invalidate_frame()
        if found is not None:
            world.keep_frame(seen[found])  # the agent walks there next: its frame need not be rendered again


FAR = 5.0
"""Metres: how far `receptacle_places` looks for a place facing a receptacle no place within reach sees."""


def receptacle_places(world: World) -> dict[str, AgentPose]:
    """Each fixed receptacle's place to stand (ALFWorld's `receptacleAtLocation`): its interaction pose
    (`find_interaction_pose`), else the nearest candidate facing it within reach when no pose sees it, else
    the nearest facing it within `FAR` (a big sofa whose middle is out of reach of every reachable point); a
    receptacle with none is left out."""
    from luminous_sim.vocab import abilities

    out = {}
    for oid, o in sorted(world.interactions.state.objects.items()):
        ab = abilities(o.object_type)
        if not ab.receptacle or ab.pickupable:
            continue
        pose = (find_interaction_pose(world, oid) or next(iter(candidate_poses(world, oid)), None)
                or next(iter(candidate_poses(world, oid, reach=FAR)), None))
        if pose is not None:
            out[oid] = pose
    return out
