"""From the y-up frames of 3D-FRONT and ATISS to ours (z up): points, headings and floor outlines.

3D-FRONT's (x, y, z) with y up is our (x, -z, y): a right-handed turn that keeps x. A 3D-FUTURE model
faces its own +z; turned by `theta` about y, its front points along (sin theta, 0, cos theta), which is
our (sin theta, -cos theta): our yaw theta + pi.
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.ops import unary_union

SIMPLIFY = 0.01
"""metres: outline vertices closer than this to the line through their neighbours are dropped."""


def to_ours(points: np.ndarray) -> np.ndarray:
    """(N, 3) y-up points in our frame (x, -z, y)."""
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    return np.stack([p[:, 0], -p[:, 2], p[:, 1]], axis=1)


def yaw_of_angle(theta: float) -> float:
    """Our yaw of a turn `theta` about y (ATISS's angle, 3D-FRONT's z_angle), in [-pi, pi)."""
    return (theta + math.pi + math.pi) % (2 * math.pi) - math.pi


def rotate_by_quaternion(q: tuple[float, float, float, float], v: np.ndarray) -> np.ndarray:
    """`v` (N, 3) turned by the unit quaternion q = (x, y, z, w) (3D-FRONT's `rot` order)."""
    x, y, z, w = q
    n = math.sqrt(x * x + y * y + z * z + w * w) or 1.0
    x, y, z, w = x / n, y / n, z / n, w / n
    r = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])
    return np.asarray(v, dtype=float).reshape(-1, 3) @ r.T


def yaw_and_tilt(q: tuple[float, float, float, float]) -> tuple[float, float]:
    """Our yaw of a model turned by quaternion `q`, and its tilt off upright (radians; 0 for a turn about y)."""
    front, up = rotate_by_quaternion(q, np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]]))
    theta = math.atan2(front[0], front[2])
    return yaw_of_angle(theta), math.acos(max(-1.0, min(1.0, float(up[1]))))


def outline_from_triangles(vertices: np.ndarray, faces: np.ndarray) -> Polygon:
    """The floor outline (our x, y) of a y-up floor mesh: the union of its triangles, the largest part,
    counter-clockwise, near-collinear vertices dropped. Raises ValueError when it has no area."""
    v = to_ours(vertices)[:, :2]
    f = np.asarray(faces, dtype=int).reshape(-1, 3)
    if len(f) == 0 or f.min() < 0 or f.max() >= len(v):
        raise ValueError(f"faces index vertices 0..{len(v) - 1}; got {int(f.min()) if len(f) else '-'}.."
                         f"{int(f.max()) if len(f) else '-'}")
    tris = [Polygon(v[t]) for t in f]
    union = unary_union([t.buffer(1e-6) for t in tris if t.area > 1e-9])
    if union.is_empty:
        raise ValueError("the floor has no area")
    if union.geom_type == "MultiPolygon":
        union = max(union.geoms, key=lambda g: g.area)
    ring = Polygon(union.exterior).simplify(SIMPLIFY)
    return shapely.geometry.polygon.orient(ring, sign=1.0)
