"""The agent's navigable grid: 0.25 m points clear of furniture and fixtures, largest connected part
(ALFRED ships the same kind of precomputed grid per scene, `FloorPlanN-layout.npy`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from luminous_sim.scene import Scene
from luminous_sim.world.agent import GRID, AgentPose


@dataclass(frozen=True)
class NavGrid:
    """Reachable grid points, as integer keys (round(x / 0.25), round(y / 0.25))."""

    keys: frozenset[tuple[int, int]]

    @classmethod
    def from_scene(cls, scene: Scene) -> NavGrid:
        from luminous_sim.scene import scene_reachable_grid

        pts = scene_reachable_grid(scene)
        return cls(frozenset((round(x / GRID), round(y / GRID)) for x, y in pts))

    def __contains__(self, key: tuple[int, int]) -> bool:
        return key in self.keys

    def points(self) -> np.ndarray:
        """(N, 2) metres, sorted."""
        return np.array(sorted(self.keys), dtype=float) * GRID

    def can_move(self, pose: AgentPose) -> bool:
        """Whether MoveAhead from `pose` lands on a reachable point."""
        return pose.moved().grid_key() in self.keys
