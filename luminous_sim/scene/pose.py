"""Poses and footprints of catalog assets on the floor plan (pure geometry, shapely)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.rooms.shell import Wall


def yaw_facing(direction: tuple[float, float]) -> float:
    """The yaw that turns an asset's front (+y) towards `direction`."""
    return math.atan2(-direction[0], direction[1])


def rotate(xy: np.ndarray, yaw: float) -> np.ndarray:
    c, s = math.cos(yaw), math.sin(yaw)
    return np.asarray(xy, dtype=float) @ np.array([[c, s], [-s, c]])


def footprint(entry: AssetEntry, x: float, y: float, yaw: float, margin: float = 0.0) -> Polygon:
    """The asset's oriented bounding rectangle on the floor, grown by `margin`."""
    lo, hi = np.array(entry.bbox_min[:2]) - margin, np.array(entry.bbox_max[:2]) + margin
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    return Polygon(rotate(corners, yaw) + [x, y])


@dataclass(frozen=True)
class WallPose:
    """Where an asset goes when its back stands against a wall."""

    x: float
    y: float
    yaw: float


def against_wall(wall: Wall, entry: AssetEntry, u_start: float, gap: float = 0.01, v_extra: float = 0.0) -> WallPose:
    """Pose that puts the asset's footprint from `u_start` along `wall`, its back `gap` off the wall.

    The asset's local x runs along the wall and its front (+y) faces into the room.
    """
    yaw = yaw_facing(wall.normal)
    u0 = u_start - entry.bbox_min[0]
    v0 = gap + v_extra - entry.bbox_min[1]
    x, y = wall.point(u0, v0)
    return WallPose(float(x), float(y), yaw)


def local_to_world(x: float, y: float, yaw: float, local: tuple[float, float]) -> tuple[float, float]:
    """A point given in an asset's frame, in world coordinates."""
    p = rotate(np.array([local]), yaw)[0] + [x, y]
    return float(p[0]), float(p[1])


def front_zone(entry: AssetEntry, x: float, y: float, yaw: float, depth: float) -> Polygon:
    """The strip of floor `depth` deep in front of an asset (where a person stands to use it)."""
    lo, hi = entry.bbox_min[:2], entry.bbox_max[:2]
    corners = np.array([[lo[0], hi[1]], [hi[0], hi[1]], [hi[0], hi[1] + depth], [lo[0], hi[1] + depth]])
    return Polygon(rotate(corners, yaw) + [x, y])
