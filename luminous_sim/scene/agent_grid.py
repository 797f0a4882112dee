"""The agent's 0.25 m grid (AI2-THOR's gridSize) in a room, and the part of it the agent can walk to:
points at least AGENT_RADIUS from every wall and floor obstacle, in the largest 4-connected part.

The generator validates layouts with it and the simulator's navigation puts the agent only on these
points, so both agree on where the agent can stand.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.strtree import STRtree

from luminous_sim.assets.catalog import AssetEntry, Catalog, default_catalog
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene.model import Scene, SceneObject
from luminous_sim.scene.pose import footprint
from luminous_sim.scene.raster import label4
from luminous_sim.vocab.agent_body import AGENT_RADIUS

STEP = 0.25
"""Spacing of the agent's grid (AI2-THOR's gridSize), aligned with the world origin."""
AGENT_HEIGHT = 1.8
"""Things whose bottom is higher than this (wall-hung) do not stand in the agent's way."""


def blocks_agent(obj: SceneObject, entry: AssetEntry) -> bool:
    """Whether a placed thing stands in the agent's way: on the floor (furniture, or a small object lying there:
    a basketball in a corner) and lower than its height."""
    if obj.parent is not None:
        return False
    return obj.position[2] + entry.bbox_min[2] < AGENT_HEIGHT


def reachable_grid(shell: RoomShell, obstacles: Iterable[Polygon]) -> np.ndarray:
    """Agent positions on the 0.25 m grid of `shell`, clear of the `obstacles` (floor footprints), in the
    largest connected component."""
    pts = shell.grid_points(STEP, clearance=AGENT_RADIUS, avoid_fixtures=False)
    obstacles = list(obstacles)
    if len(pts) == 0:
        return pts
    if obstacles:
        pidx, _ = STRtree(obstacles).query(shapely.points(pts), predicate="dwithin", distance=AGENT_RADIUS)
        blocked = np.zeros(len(pts), dtype=bool)
        blocked[pidx] = True
        pts = pts[~blocked]
    if len(pts) == 0:
        return pts
    return pts[largest_component(pts)]


def largest_component(pts: np.ndarray) -> np.ndarray:
    """Mask of the points in the largest 4-connected component of grid points `pts` (ties: the component
    holding the earliest point)."""
    keys = np.round(pts / STEP).astype(int)
    keys -= keys.min(axis=0)
    image = np.zeros(tuple(keys.max(axis=0) + 1), dtype=bool)
    image[keys[:, 0], keys[:, 1]] = True
    labels, _ = label4(image)
    of_point = labels[keys[:, 0], keys[:, 1]]
    sizes = np.bincount(of_point)
    best = sizes[of_point] == sizes.max()
    return of_point == of_point[int(np.argmax(best))]


def scene_reachable_grid(scene: Scene, catalog: Catalog | None = None) -> np.ndarray:
    """The reachable 0.25 m grid of a finished scene (the rule the generator validates with)."""
    catalog = catalog or default_catalog()
    obstacles = []
    for o in scene.objects:
        e = catalog.for_object(o)
        if blocks_agent(o, e):
            obstacles.append(footprint(e, o.position[0], o.position[1], o.yaw))
    return reachable_grid(scene.room, obstacles)
