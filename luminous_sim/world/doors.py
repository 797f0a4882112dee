"""Where opening a door, drawer or lid sweeps: the agent may not stand there when it opens one (AI2-THOR
refuses an OpenObject whose door would hit the agent, and ALFRED's planner picks poses clear of it)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.vocab.agent_body import AGENT_RADIUS, CAMERA_HEIGHT

if TYPE_CHECKING:
    from luminous_sim.world.world import World

SWING_SAMPLES = 4
"""Positions along a door's travel whose link boxes make up its sweep (closed excluded)."""
MOVING = ("door", "drawer", "lid")


def swept_boxes(world: World, object_id: str) -> list[tuple[np.ndarray, np.ndarray]]:
    """World AABBs of the object's moving links at points along their travel from closed to open.

    The joints are put back where they were; nothing else moves.
    """
    loaded = world.built.objects[object_id]
    c = world.client
    joints = [j for j in loaded.entry.joints if j["role"] in MOVING]
    if not joints:
        return []
    saved = {j["name"]: c.getJointState(loaded.body, loaded.joint_index[j["name"]])[0] for j in joints}
    boxes = []
    try:
        for k in range(1, SWING_SAMPLES + 1):
            for j in joints:
                value = j["lower"] + (j["upper"] - j["lower"]) * k / SWING_SAMPLES
                c.resetJointState(loaded.body, loaded.joint_index[j["name"]], value)
            for j in joints:
                lo, hi = c.getAABB(loaded.body, loaded.link_index[j["child"]])
                boxes.append((np.array(lo), np.array(hi)))
    finally:
        for name, value in saved.items():
            c.resetJointState(loaded.body, loaded.joint_index[name], value)
    return boxes


def hits_agent(boxes: list[tuple[np.ndarray, np.ndarray]], x: float, y: float) -> bool:
    """Whether any box reaches into the agent's cylinder standing at (x, y)."""
    for lo, hi in boxes:
        if hi[2] <= 0.0 or lo[2] >= CAMERA_HEIGHT:
            continue
        nx, ny = min(max(x, lo[0]), hi[0]), min(max(y, lo[1]), hi[1])
        if (nx - x) ** 2 + (ny - y) ** 2 < AGENT_RADIUS**2:
            return True
    return False
