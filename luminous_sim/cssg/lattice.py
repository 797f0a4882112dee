"""The agent's 0.25 m grid inside the room, as the furniture layer tracks it while placing pieces.

The validation and the simulator's navigation put the agent only on these points (`scene.reachable_grid`),
each at least AGENT_RADIUS from every wall and floor obstacle. Tracking the same points with the same
exact distances while placing furniture means a passage the layout keeps open is one the
agent can really walk through, not one the fine placement grid only believes wide enough.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from luminous_sim.cssg.grid import RES, FloorGrid
from luminous_sim.cssg.reach import largest_part
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import STEP
from luminous_sim.vocab.agent_body import AGENT_RADIUS


@dataclass(frozen=True)
class Lattice:
    """The agent's grid points clear of the walls, their places in a 2-D lattice image and the cells of
    the fine placement grid under them."""

    points: np.ndarray
    """(N, 2) positions, metres."""
    geoms: np.ndarray
    """The same as shapely points."""
    ij: np.ndarray
    """(N, 2) x and y index of each point in the lattice image."""
    shape: tuple[int, int]
    cells: np.ndarray
    """(N,) flat index of the fine-grid cell under each point."""
    grid_shape: tuple[int, int]

    @classmethod
    def of(cls, shell: RoomShell, grid: FloorGrid) -> Lattice:
        pts = shell.grid_points(STEP, clearance=AGENT_RADIUS, avoid_fixtures=False).reshape(-1, 2)
        keys = np.round(pts / STEP).astype(int)
        # x-major like the points, so that among equally large parts the first labelled is the one
        # holding the first point: `scene.reachable_grid`'s choice
        ij = keys - keys.min(axis=0) if len(pts) else np.zeros((0, 2), dtype=int)
        shape = tuple(int(v) for v in ij.max(axis=0) + 1) if len(pts) else (0, 0)
        rows = np.clip(np.floor((pts[:, 1] - grid.y0) / RES).astype(int), 0, grid.shape[0] - 1)
        cols = np.clip(np.floor((pts[:, 0] - grid.x0) / RES).astype(int), 0, grid.shape[1] - 1)
        cells = np.ravel_multi_index((rows, cols), grid.shape) if len(pts) else np.zeros(0, dtype=np.intp)
        return cls(pts, shapely.points(pts), ij, shape, cells, grid.shape)

    def near(self, footprint) -> np.ndarray:
        """Points within AGENT_RADIUS of `footprint` (the agent would bump into it there)."""
        return shapely.dwithin(footprint, self.geoms, AGENT_RADIUS)

    def open_among(self, footprints) -> np.ndarray:
        """Points clear of every footprint in `footprints`."""
        out = np.ones(len(self.points), dtype=bool)
        for fp in footprints:
            out &= ~self.near(fp)
        return out

    def connected_share(self, open_: np.ndarray) -> float:
        """Share of the open points in the largest 4-connected part (1.0 when none is open): the free floor
        the agent reaches, the rest being dead zones it cannot walk into."""
        total = int(open_.sum())
        if total == 0:
            return 1.0
        image = np.zeros(self.shape, dtype=bool)
        image[self.ij[:, 0], self.ij[:, 1]] = open_
        return int(largest_part(image).sum()) / total

    def walkable(self, open_: np.ndarray) -> np.ndarray:
        """Fine-grid mask of the cells under the open points of the largest 4-connected part."""
        image = np.zeros(self.shape, dtype=bool)
        image[self.ij[:, 0], self.ij[:, 1]] = open_
        part = largest_part(image)[self.ij[:, 0], self.ij[:, 1]] & open_
        walk = np.zeros(self.grid_shape, dtype=bool)
        walk.ravel()[self.cells[part]] = True
        return walk
