"""Keeping TinyRenderer out of its endless loop: no triangle may lie in the plane through the eye.

TinyRenderer clips a triangle against the near plane only where a vertex is behind the eye (clip w < 0). A
triangle lying in the plane through the eye square to the view (w = 0 at every vertex, or within rounding of
it) is seen edge-on, and its back-face test, which should drop it, goes either way on rounding; drawn, it
projects to infinity, its screen box starts at the integer that a float too large for one converts to
(INT_MIN), and the render loops over some two billion columns. Measured: S+ entry 465 (a FloorPlan429
bathroom) with the agent at (0.25, -2.75) facing -x, whose eye plane holds the end face of a door's lintel (a
box from x = -0.65 to 0.25), hung its process for good; grid-aligned walls and grid-aligned agent poses make
such exact coincidences happen (1.4% of the views at the reachable points of four generated rooms). So before
every render of a World (`World.eye_guard`), when a face of a visible structure box or a triangle of an object
link lies within `EYE_PLANE_EPS` of that plane, the camera moves `EYE_NUDGE` forward along its view: the
picture moves by far less than a pixel, and only in those frames. Renders outside a World (the asset sheet,
`views`' top-down pictures of a built scene) are not checked.
"""

from __future__ import annotations

import numpy as np

EYE_PLANE_EPS = 1e-6
"""Metres: a vertex nearer than this to the plane through the eye counts as in it."""
EYE_NUDGE = 1e-4
"""Metres the camera moves forward when a triangle lies in the plane through its eye."""


def eye_depth(view: list[float] | np.ndarray, points: np.ndarray) -> np.ndarray:
    """Distance of each point (..., 3) in front of the eye along the view (clip w): `view` is PyBullet's
    column-major view matrix, whose camera looks down its -z axis."""
    row = np.asarray(view, dtype=float).reshape(4, 4).T[2]
    return -(points @ row[:3] + row[3])


def near_eye_plane(view: list[float] | np.ndarray, points: np.ndarray) -> np.ndarray:
    """Whether each of `points` (..., 3) lies within `EYE_PLANE_EPS` of the plane through the eye."""
    return np.abs(eye_depth(view, points)) < EYE_PLANE_EPS


def nudged(eye: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The eye and target moved `EYE_NUDGE` forward along the view."""
    eye, target = np.asarray(eye, dtype=float), np.asarray(target, dtype=float)
    step = EYE_NUDGE * (target - eye) / np.linalg.norm(target - eye)
    return eye + step, target + step
