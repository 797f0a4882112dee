"""The culling as it was before it was vectorised, one box and one opening at a time, kept as the reference the
vectorised `world.culling` and `world.portals` are tested against (tests/world/test_culling_vectorised.py)."""

from __future__ import annotations

import numpy as np
from shapely.geometry import Point

from luminous_sim.world.culling import _corners, link_visual_bounds
from luminous_sim.world.portals import MIN_EYE_DEPTH, openings


def quat_matrix(q) -> np.ndarray:
    """A quaternion (x, y, z, w) as a 3x3 rotation matrix."""
    x, y, z, w = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def box_outside(corners: np.ndarray, view_proj: np.ndarray, margin: tuple[float, float]) -> bool:
    """Whether one box (8, 3) lies wholly beyond one plane of the frustum, corner by corner."""
    mx, my = margin
    clip = [view_proj @ np.array([*c, 1.0]) for c in corners]
    tests = [lambda x, y, z, w: x < -mx * w, lambda x, y, z, w: x > mx * w, lambda x, y, z, w: y < -my * w,
             lambda x, y, z, w: y > my * w, lambda x, y, z, w: z < -w, lambda x, y, z, w: z > w,
             lambda x, y, z, w: w <= 0]
    return any(all(test(*c) for c in clip) for test in tests)


def link_boxes(client, objects) -> list[tuple[object, str, np.ndarray]]:
    """Every object link with a bounded visual and its box's world corners, asked of PyBullet link by link."""
    out = []
    for loaded in objects.values():
        bounds = link_visual_bounds(str(loaded.entry.urdf_for(loaded.lod)))
        s = loaded.entry.scale
        if "base" in bounds:
            pos, orn = client.getBasePositionAndOrientation(loaded.body)
            local_pos, local_orn = client.getDynamicsInfo(loaded.body, -1)[3:5]
            inv_pos, inv_orn = client.invertTransform(local_pos, local_orn)
            rot = quat_matrix(orn)
            pos, rot = rot @ np.array(inv_pos) + np.array(pos), rot @ quat_matrix(inv_orn)
            out.append((loaded, "base", _corners(bounds["base"][0] * s, bounds["base"][1] * s) @ rot.T + pos))
        for name, j in loaded.link_index.items():
            if name == "base" or name not in bounds:
                continue
            st = client.getLinkState(loaded.body, j, computeForwardKinematics=1)
            local = _corners(bounds[name][0] * s, bounds[name][1] * s)
            out.append((loaded, name, local @ quat_matrix(st[5]).T + np.array(st[4])))
    return out


def outside_links(client, objects, view_proj: np.ndarray, margin: tuple[float, float]) -> list[tuple[object, str]]:
    """The (asset, link) pairs whose box lies wholly beyond one plane of the frustum."""
    return [(loaded, name) for loaded, name, corners in link_boxes(client, objects)
            if box_outside(corners, view_proj, margin)]


def outdoors_hidden(room, boxes: np.ndarray, eye: np.ndarray, view_proj: np.ndarray,
                    margin: tuple[float, float]) -> np.ndarray:
    """Whether each outdoor box (n, 8, 3) is out of sight: one opening and one box at a time."""
    n = len(boxes)
    if not room.polygon().contains(Point(float(eye[0]), float(eye[1]))):
        return np.zeros(n, dtype=bool)
    seen = np.array([box_outside(b, view_proj, margin) for b in boxes])
    hidden = np.ones(n, dtype=bool)
    for op in openings(room):
        if box_outside(op.corners, view_proj, margin):
            continue
        if op.depth(eye) < MIN_EYE_DEPTH:
            return seen
        for k, box in enumerate(boxes):
            hidden[k] &= any(all(float((c - eye) @ plane) < 0 for c in box) for plane in _cone_planes(op, eye))
    return hidden | seen


def _cone_planes(op, eye: np.ndarray) -> list[np.ndarray]:
    """The 8 side planes (inward normals through the eye) of the cones from `eye` through an opening's faces."""
    planes = []
    for face in op.faces:
        edges = face - eye
        centre = edges.mean(axis=0)
        for i in range(4):
            normal = np.cross(edges[i], edges[(i + 1) % 4])
            planes.append(-normal if normal @ centre < 0 else normal)
    return planes


def look_at(eye, target, up=(0.0, 0.0, 1.0)) -> np.ndarray:
    """The OpenGL view matrix (4x4, row-major, to be applied to column vectors), as PyBullet makes it."""
    eye, target, up = (np.asarray(v, dtype=float) for v in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fov_deg: float, aspect: float, near: float, far: float) -> np.ndarray:
    """The OpenGL projection matrix (4x4, row-major)."""
    f = 1.0 / np.tan(np.radians(fov_deg) / 2)
    return np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)], [0, 0, -1, 0]])
