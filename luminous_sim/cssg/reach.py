"""The agent's reach on the furniture layer's grid: whether every floor piece stays within reach of
the cells the agent can stand on (`lattice.Lattice.walkable`).

Distances are cell-centre to cell-centre, as the Euclidean distance transform (`scene.distance_transform`)
measures them, but computed only in a window around one piece (in closed form when its cells fill a box),
and each piece remembers a walkable cell within its reach so that most checks cost one lookup.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from luminous_sim.cssg.grid import RES
from luminous_sim.scene import REACH, distance_transform, label4


@dataclass
class FloorPiece:
    """The grid cells under one thing on the floor."""

    id: str
    cells: np.ndarray
    """Flat indices of its cells."""
    box: tuple[int, int, int, int]
    """First and last row, first and last column of its cells (inclusive)."""
    full: bool
    """Whether its cells fill the box."""
    witness: int = -1
    """A walkable cell within reach found by the last check (a hint: it is checked again before use)."""
    reach: float = REACH
    """Metres on the floor within which a walkable cell must lie (`horizontal_reach` of its heights)."""

    @classmethod
    def of(cls, piece_id: str, mask: np.ndarray, reach: float = REACH) -> FloorPiece:
        rows, cols = np.nonzero(mask)
        if len(rows) == 0:
            return cls(piece_id, np.zeros(0, dtype=np.intp), (0, -1, 0, -1), True, reach=reach)
        box = (int(rows.min()), int(rows.max()), int(cols.min()), int(cols.max()))
        full = len(rows) == (box[1] - box[0] + 1) * (box[3] - box[2] + 1)
        return cls(piece_id, np.flatnonzero(mask), box, full, reach=reach)

    def distances(self, shape: tuple[int, int], radius: float) -> tuple[slice, slice, np.ndarray]:
        """The window of cells up to `radius` metres from the piece's box and, in it, each cell's distance
        (m) to the nearest cell of the piece."""
        m = math.floor(radius / RES) + 1
        r0, r1, c0, c1 = self.box
        rows = slice(max(r0 - m, 0), min(r1 + m + 1, shape[0]))
        cols = slice(max(c0 - m, 0), min(c1 + m + 1, shape[1]))
        if self.full:
            r = np.arange(rows.start, rows.stop)
            c = np.arange(cols.start, cols.stop)
            dr = np.maximum(np.maximum(r0 - r, r - r1), 0)
            dc = np.maximum(np.maximum(c0 - c, c - c1), 0)
            return rows, cols, np.sqrt((dr[:, None] ** 2 + dc[None, :] ** 2).astype(float)) * RES
        mask = np.zeros(shape, dtype=bool)
        mask.ravel()[self.cells] = True
        return rows, cols, distance_transform(~mask[rows, cols]) * RES

    def reachable(self, walk: np.ndarray) -> bool:
        """Whether a cell of `walk` lies within the piece's reach (a piece without cells is)."""
        if len(self.cells) == 0:
            return True
        if self.witness >= 0 and walk.ravel()[self.witness]:
            return True
        rows, cols, dist = self.distances(walk.shape, self.reach)
        hits = (dist <= self.reach) & walk[rows, cols]
        if not hits.any():
            return False
        r, c = np.unravel_index(int(np.argmax(hits)), hits.shape)
        self.witness = int(np.ravel_multi_index((r + rows.start, c + cols.start), walk.shape))
        return True


def largest_part(ok: np.ndarray) -> np.ndarray:
    """The largest 4-connected part of `ok` (the first by label order among equals)."""
    labels, n = label4(ok)
    if n == 0:
        return ok
    sizes = np.bincount(labels.ravel())[1:]
    return labels == (int(np.argmax(sizes)) + 1)
