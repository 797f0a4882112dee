"""Physical checks of one catalog asset in a fresh PyBullet client (used by the library tests)."""

from __future__ import annotations

import numpy as np
import pybullet as p

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.world.asset_loader import base_link_pose, load_asset, set_joint
from luminous_sim.world.client import add_floor, new_client

CONTAINER_TYPES = {"Mug", "Cup", "Bowl", "Pot", "Pan", "Box", "SinkBasin", "BathtubBasin", "GarbageCan",
                   "Drawer", "LaundryHamper", "Plate"}


def aabb(client, body: int) -> tuple[np.ndarray, np.ndarray]:
    """Collision AABB of a whole multibody, all links."""
    lo, hi = map(np.array, client.getAABB(body, -1))
    for j in range(client.getNumJoints(body)):
        a, b = map(np.array, client.getAABB(body, j))
        lo, hi = np.minimum(lo, a), np.maximum(hi, b)
    return lo, hi


def drop_and_settle(entry: AssetEntry, seconds: float = 2.0) -> dict[str, float]:
    """Drop the asset 2 cm above a floor, let it settle; report how it ended up."""
    client = new_client()
    try:
        add_floor(client)
        z0 = 0.02 - entry.bbox_min[2]
        loaded = load_asset(client, entry, (0.0, 0.0, z0))
        for name in loaded.joint_index:
            set_joint(client, loaded, name, 0.0)
        min_z = np.inf
        steps = int(seconds * 240)
        for i in range(steps):
            client.stepSimulation()
            if i % 10 == 0:
                min_z = min(min_z, aabb(client, loaded.body)[0][2])
        pos, orn = base_link_pose(client, loaded.body)
        up = np.array(client.getMatrixFromQuaternion(orn)).reshape(3, 3)[:, 2]
        lin, ang = client.getBaseVelocity(loaded.body)
        return {
            "tilt_deg": float(np.degrees(np.arccos(np.clip(up[2], -1, 1)))),
            "min_z": float(min_z),
            "drift": float(np.linalg.norm(np.array(pos[:2]))),
            "speed": float(np.linalg.norm(lin)),
            "spin": float(np.linalg.norm(ang)),
        }
    finally:
        client.disconnect()


def measured_bbox(entry: AssetEntry) -> tuple[np.ndarray, np.ndarray]:
    """The collision AABB of the asset loaded at the origin with joints at zero (PyBullet's margin removed)."""
    client = new_client()
    try:
        loaded = load_asset(client, entry, fixed=True)
        lo, hi = aabb(client, loaded.body)
        return lo, hi
    finally:
        client.disconnect()


def joint_sweep(entry: AssetEntry) -> dict[str, tuple[float, float]]:
    """Drive every joint to its upper then lower limit; report the positions reached."""
    client = new_client()
    out = {}
    try:
        loaded = load_asset(client, entry, fixed=True)
        for j in entry.joints:
            if j["kind"] == "fixed":
                continue
            idx = loaded.joint_index[j["name"]]
            reached = []
            for target in (j["upper"], j["lower"]):
                client.setJointMotorControl2(loaded.body, idx, p.POSITION_CONTROL, targetPosition=target, force=500)
                for _ in range(480):
                    client.stepSimulation()
                reached.append(client.getJointState(loaded.body, idx)[0])
            out[j["name"]] = (reached[0], reached[1])
        return out
    finally:
        client.disconnect()


def region_box_in_base(entry: AssetEntry, region: dict) -> tuple[np.ndarray, np.ndarray]:
    """A region's box (surfaces: the free space above) in the asset frame, joints at zero."""
    c = np.array(region["center"]) + np.array(entry.link_origins[region["link"]])
    s = np.array(region["size"])
    if region["kind"] == "surface":
        return c - [s[0] / 2, s[1] / 2, 0], c + [s[0] / 2, s[1] / 2, s[2]]
    return c - s / 2, c + s / 2


def ball_stays_inside(entry: AssetEntry, region: dict) -> tuple[bool, list[float]]:
    """Open the region's joint, drop a small ball at the region centre, settle; is it still inside?"""
    client = new_client()
    try:
        add_floor(client)
        loaded = load_asset(client, entry, (0.0, 0.0, -entry.bbox_min[2]), fixed=True)
        if region.get("requires_open"):
            j = next(j for j in entry.joints if j["name"] == region["requires_open"])
            set_joint(client, loaded, j["name"], j["upper"])
        for _ in range(30):
            client.stepSimulation()
        link = loaded.link_index[region["link"]]
        if link == -1:
            frame_pos, frame_orn = base_link_pose(client, loaded.body)
        else:
            st = client.getLinkState(loaded.body, link, computeForwardKinematics=True)
            frame_pos, frame_orn = st[4], st[5]
        size = np.array(region["size"])
        radius = float(min(0.015, size[0] / 4, size[1] / 4, size[2] / 3))
        center = np.array(region["center"], dtype=float)
        start = client.multiplyTransforms(frame_pos, frame_orn, center.tolist(), [0, 0, 0, 1])[0]
        shape = client.createCollisionShape(2, radius=radius)  # GEOM_SPHERE
        ball = client.createMultiBody(0.02, shape, -1, start)
        for _ in range(480):
            client.stepSimulation()
        pos = client.getBasePositionAndOrientation(ball)[0]
        inv = client.invertTransform(frame_pos, frame_orn)
        local = np.array(client.multiplyTransforms(inv[0], inv[1], pos, [0, 0, 0, 1])[0])
        half = size / 2 + 0.01
        inside = bool(np.all(np.abs(local[:2] - center[:2]) <= half[:2]) and
                      center[2] - half[2] <= local[2] <= center[2] + half[2])
        return inside, local.round(3).tolist()
    finally:
        client.disconnect()
