"""The dense candidate grid over a room's floor: free-space mask, wall distances and feasibility per
heading, all as numpy arrays (one cell = RES metres)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage
from shapely import contains_xy
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry

RES = 0.05
"""Grid resolution in metres."""
HEADINGS = (0.0, math.pi / 2, math.pi, 3 * math.pi / 2)
"""Furniture stands square to the (rectilinear) room: front towards +y, -x, -y, +x."""


@dataclass
class FloorGrid:
    """Cell centres `xs`, `ys` (1-D), the room mask and the current free mask (room minus obstacles)."""

    x0: float
    y0: float
    xs: np.ndarray
    ys: np.ndarray
    room: np.ndarray
    free: np.ndarray
    wall_dist: np.ndarray
    wall_normal: np.ndarray  # (H, W, 2): unit vector from the nearest wall into the room

    @classmethod
    def from_polygon(cls, poly: Polygon) -> FloorGrid:
        minx, miny, maxx, maxy = poly.bounds
        xs = np.arange(minx + RES / 2, maxx, RES)
        ys = np.arange(miny + RES / 2, maxy, RES)
        gx, gy = np.meshgrid(xs, ys, indexing="xy")
        room = contains_xy(poly, gx, gy)
        padded = np.pad(room, 1, constant_values=False)
        dist, idx = ndimage.distance_transform_edt(padded, return_indices=True)
        dist, idx = dist[1:-1, 1:-1], idx[:, 1:-1, 1:-1] - 1
        h, w = room.shape
        rows, cols = np.mgrid[0:h, 0:w]
        vec = np.stack([cols - idx[1], rows - idx[0]], axis=-1).astype(float)
        norm = np.linalg.norm(vec, axis=-1, keepdims=True)
        normal = np.divide(vec, norm, out=np.zeros_like(vec), where=norm > 0)
        return cls(minx, miny, xs, ys, room, room.copy(), (dist - 0.5) * RES, normal)

    @property
    def shape(self) -> tuple[int, int]:
        return self.room.shape

    def coords(self) -> tuple[np.ndarray, np.ndarray]:
        return np.meshgrid(self.xs, self.ys, indexing="xy")

    def cell(self, x: float, y: float) -> tuple[int, int]:
        return int((y - self.y0) / RES), int((x - self.x0) / RES)

    def block(self, poly: Polygon) -> None:
        """Mark the cells under `poly` as occupied."""
        gx, gy = self.coords()
        minx, miny, maxx, maxy = poly.bounds
        sel = (gx >= minx - RES) & (gx <= maxx + RES) & (gy >= miny - RES) & (gy <= maxy + RES)
        inside = np.zeros_like(self.free)
        inside[sel] = contains_xy(poly, gx[sel], gy[sel])
        self.free &= ~inside

    def feasible(self, entry: AssetEntry, heading: float, margin: float = 0.02) -> np.ndarray:
        """Cells where the asset's origin can go at `heading` with its whole footprint on free floor."""
        lo = np.array(entry.bbox_min[:2]) - margin
        hi = np.array(entry.bbox_max[:2]) + margin
        c, s = round(math.cos(heading)), round(math.sin(heading))
        corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        rot = corners @ np.array([[c, s], [-s, c]])
        (rx0, ry0), (rx1, ry1) = rot.min(axis=0), rot.max(axis=0)
        # structuring element covering the footprint, offset so its origin is the asset origin
        c0, c1 = math.floor(rx0 / RES), math.ceil(rx1 / RES)
        r0, r1 = math.floor(ry0 / RES), math.ceil(ry1 / RES)
        kernel = np.ones((r1 - r0 + 1, c1 - c0 + 1), dtype=bool)
        origin = (-(r1 + r0) // 2, -(c1 + c0) // 2)
        try:
            return ndimage.binary_erosion(self.free, structure=kernel, origin=origin, border_value=0)
        except ValueError:  # footprint larger than the room
            return np.zeros_like(self.free)
