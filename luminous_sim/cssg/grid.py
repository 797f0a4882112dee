"""The dense candidate grid over a room's floor: free-space mask, wall distances and feasibility per
heading, all as numpy arrays (one cell = RES metres)."""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable
from dataclasses import dataclass
from typing import Any

import numpy as np
from shapely import contains_xy
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.scene import distance_transform

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
        dist, idx = distance_transform(padded, return_indices=True)
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
        if getattr(self, "_coords", None) is None:
            self._coords = np.meshgrid(self.xs, self.ys, indexing="xy")
        return self._coords

    def memo(self, key: Hashable, make: Callable[[], Any]) -> Any:
        """A value that depends only on the room (not on what stands in it), computed once."""
        cache = self.__dict__.setdefault("_memo", {})
        if key not in cache:
            cache[key] = make()
        return cache[key]

    def cell(self, x: float, y: float) -> tuple[int, int]:
        return int((y - self.y0) / RES), int((x - self.x0) / RES)

    def _window(self, minx: float, miny: float, maxx: float, maxy: float) -> tuple[slice, slice]:
        """Row and column slices of the cells whose centres lie within RES of the box."""
        h, w = self.shape
        r0 = max(0, math.ceil((miny - RES - self.ys[0]) / RES - 1e-9))
        r1 = min(h, math.floor((maxy + RES - self.ys[0]) / RES + 1e-9) + 1)
        c0 = max(0, math.ceil((minx - RES - self.xs[0]) / RES - 1e-9))
        c1 = min(w, math.floor((maxx + RES - self.xs[0]) / RES + 1e-9) + 1)
        return slice(r0, max(r0, r1)), slice(c0, max(c0, c1))

    def _cells(self, poly: Polygon) -> np.ndarray:
        """Mask of the cells whose centres lie inside `poly`."""
        inside = np.zeros(self.shape, dtype=bool)
        rows, cols = self._window(*poly.bounds)
        inside[rows, cols] = contains_xy(poly, self.xs[None, cols], self.ys[rows, None])
        return inside

    def set_free(self, free: np.ndarray) -> None:
        """Replace the free mask (a restored checkpoint)."""
        self.free = free
        self._changed()

    def _changed(self) -> None:
        self._sat = None
        self._feasible = {}

    def block(self, poly: Polygon) -> None:
        """Mark the cells under `poly` as occupied."""
        self.free &= ~self._cells(poly)
        self._changed()

    def unblock(self, poly: Polygon) -> None:
        """Free the room cells under `poly` again (a removed piece)."""
        self.free |= self._cells(poly) & self.room
        self._changed()

    def feasible(self, entry: AssetEntry, heading: float, margin: float = 0.02) -> np.ndarray:
        """Cells where the asset's origin can go at `heading` with its whole footprint on free floor.

        Read-only: the result is cached until the free mask changes.
        """
        lo = np.array(entry.bbox_min[:2]) - margin
        hi = np.array(entry.bbox_max[:2]) + margin
        c, s = round(math.cos(heading)), round(math.sin(heading))
        corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        rot = corners @ np.array([[c, s], [-s, c]])
        (rx0, ry0), (rx1, ry1) = rot.min(axis=0), rot.max(axis=0)
        # the footprint covers cell offsets r0..r1 (rows, y) and c0..c1 (columns, x) around the origin cell
        c0, c1 = math.floor(rx0 / RES + 0.5), math.ceil(rx1 / RES - 0.5)
        r0, r1 = math.floor(ry0 / RES + 0.5), math.ceil(ry1 / RES - 0.5)
        cache = getattr(self, "_feasible", None)
        if cache is None:
            cache = self._feasible = {}
        key = (r0, r1, c0, c1)
        if key not in cache:
            cache[key] = self._box_free(r0, r1, c0, c1)
            cache[key].flags.writeable = False
        return cache[key]

    def _box_free(self, r0: int, r1: int, c0: int, c1: int) -> np.ndarray:
        """Cells whose box of offsets rows r0..r1, columns c0..c1 holds no occupied cell (summed-area table)."""
        h, w = self.free.shape
        pad = max(abs(c0), abs(c1), abs(r0), abs(r1)) + 1
        if getattr(self, "_sat", None) is None or self._sat[0] < pad:
            occupied = np.pad(~self.free, pad, constant_values=True).astype(np.int32)
            sat = np.zeros((occupied.shape[0] + 1, occupied.shape[1] + 1), dtype=np.int32)
            sat[1:, 1:] = occupied.cumsum(0).cumsum(1)
            self._sat = (pad, sat)
        p, sat = self._sat

        def block(dr: int, dc: int) -> np.ndarray:
            return sat[p + dr:p + dr + h, p + dc:p + dc + w]

        total = block(r1 + 1, c1 + 1) - block(r0, c1 + 1) - block(r1 + 1, c0) + block(r0, c0)
        return total == 0
