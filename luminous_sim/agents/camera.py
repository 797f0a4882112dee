"""The agent's camera as documented constants (ALFRED's: 60 degrees of vertical field of view, square pixels, the
eye 1.576 m above the floor) and the unprojection of a depth image into points of the agent's own frame.

The own frame is the agent's start: the origin at its start position, +y the way it faced, +x to its right, z up
from the floor. Depth is the distance along the camera's axis (the env's `depth`), as a pinhole camera's z.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from luminous_sim.vocab.agent_body import CAMERA_HEIGHT

FOV_DEGREES = 60.0
"""The vertical field of view (AI2-THOR's and ALFRED's)."""


@dataclass(frozen=True)
class Intrinsics:
    """A pinhole camera of `width` x `height` pixels with the vertical field of view `fov` (degrees)."""

    width: int
    height: int
    fov: float = FOV_DEGREES

    @property
    def focal(self) -> float:
        """The focal length in pixels (the same both ways: square pixels)."""
        return (self.height / 2) / math.tan(math.radians(self.fov) / 2)

    def rays(self, rows: np.ndarray, cols: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Each pixel's offset from the axis per metre of depth: rightwards and upwards."""
        right = (cols + 0.5 - self.width / 2) / self.focal
        up = (self.height / 2 - rows - 0.5) / self.focal
        return right, up


def unproject(depth: np.ndarray, rows: np.ndarray, cols: np.ndarray, intrinsics: Intrinsics, x: float, y: float,
              yaw: float, horizon: float) -> np.ndarray:
    """The own-frame points (N, 3) seen at pixels (`rows`, `cols`) with axis depth `depth` (metres), from a
    camera at (`x`, `y`) on the floor, turned `yaw` degrees clockwise from +y, looking `horizon` degrees down."""
    right, up = intrinsics.rays(rows, cols)
    a, p = math.radians(yaw), math.radians(horizon)
    fx, fy = math.sin(a), math.cos(a)  # forward on the floor
    rx, ry = math.cos(a), -math.sin(a)  # right on the floor
    along = depth * math.cos(p) + depth * up * math.sin(p)  # forward on the floor
    rise = -depth * math.sin(p) + depth * up * math.cos(p)
    side = depth * right
    return np.stack([x + along * fx + side * rx, y + along * fy + side * ry, CAMERA_HEIGHT + rise], axis=-1)
