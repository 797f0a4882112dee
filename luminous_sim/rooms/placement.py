"""Where along a wall a wall-backed rectangle fits: the search fixtures, doors and windows use."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from luminous_sim.rooms.geometry import is_convex_vertex, mask_to_intervals, polygon_parts
from luminous_sim.rooms.shell import Wall

STEP = 0.05
"""Offsets along walls are multiples of this many metres."""


def _u_bounds(wall: Wall, geom: BaseGeometry) -> list[tuple[float, float]]:
    out = []
    for part in polygon_parts(geom):
        if part.area > 1e-6:
            uv = wall.local(np.asarray(part.exterior.coords))
            out.append((float(uv[:, 0].min()), float(uv[:, 0].max())))
    return out


def blocked_spans(
    wall: Wall,
    v0: float,
    v1: float,
    allowed: BaseGeometry,
    obstacles: Sequence[BaseGeometry] = (),
) -> list[tuple[float, float]]:
    """Spans along `wall` where the band [v0, v1] into the room leaves `allowed` or hits obstacles.

    The spans are conservative (the along-wall extent of each offending piece).
    """
    band = wall.rect(0.0, wall.length, v0, v1)
    shapely.prepare(allowed)
    spans = [] if allowed.contains(band) else _u_bounds(wall, band.difference(allowed))
    for obs in obstacles:
        if band.intersects(obs):
            spans += _u_bounds(wall, band.intersection(obs))
    return spans


def free_offsets(
    wall: Wall,
    width: float,
    depth: float,
    allowed: BaseGeometry,
    obstacles: Sequence[BaseGeometry] = (),
    front: float = 0.0,
    front_allowed: BaseGeometry | None = None,
    front_obstacles: Sequence[BaseGeometry] = (),
    end_margin: float = 0.0,
    step: float = STEP,
) -> np.ndarray:
    """Offsets u (multiples of `step`) where a wall-backed rectangle fits.

    The rectangle [u, u + width] x [0, depth] must lie in `allowed` and avoid `obstacles`; the band
    in front of it, [u, u + width] x [depth, depth + front], must lie in `front_allowed` (default
    `allowed`) and avoid `front_obstacles`; and u keeps `end_margin` from both wall ends.

    Returns:
        Sorted float array of admissible offsets (possibly empty).
    """
    length = wall.length
    lo = np.ceil((end_margin - 1e-9) / step)
    hi = np.floor((length - end_margin - width + 1e-9) / step)
    if hi < lo:
        return np.zeros(0)
    us = np.arange(lo, hi + 1) * step
    spans = blocked_spans(wall, 0.0, depth, allowed, obstacles)
    if front > 0:
        spans += blocked_spans(
            wall,
            depth,
            depth + front,
            allowed if front_allowed is None else front_allowed,
            front_obstacles,
        )
    ok = np.ones(len(us), dtype=bool)
    for a, b in spans:
        ok &= ~((us < b - 1e-6) & (us + width > a + 1e-6))
    return np.round(us[ok], 4) + 0.0


def free_intervals(
    wall: Wall,
    depth: float,
    allowed: BaseGeometry,
    obstacles: Sequence[BaseGeometry] = (),
    front: float = 0.0,
    front_allowed: BaseGeometry | None = None,
    step: float = STEP,
) -> list[tuple[float, float]]:
    """Stretches [a, b] of `wall` along which a band `depth` deep (plus `front`) fits."""
    n = int(np.floor(wall.length / step + 1e-9))
    if n <= 0:
        return []
    us = free_offsets(wall, step, depth, allowed, obstacles, front, front_allowed, step=step)
    mask = np.zeros(n, dtype=bool)
    mask[np.round(us / step).astype(int).clip(0, n - 1)] = True
    return mask_to_intervals(mask, step)


def nearest_wall(
    walls: Sequence[Wall], xy: tuple[float, float], max_v: float = np.inf
) -> tuple[Wall, float, float] | None:
    """The wall nearest to a point inside the room that the point projects onto.

    Returns:
        (wall, u, v): the wall, the point's position along it and its distance into the room;
        None if no wall within `max_v` faces the point.
    """
    best = None
    for w in walls:
        u, v = w.local([xy])[0]
        faces = -1e-6 <= u <= w.length + 1e-6 and -0.05 <= v <= max_v
        if faces and (best is None or v < best[2] - 1e-9):
            best = (w, float(u), float(v))
    return best


def corner_convex(walls: Sequence[Wall], i: int) -> bool:
    """Whether the corner between wall i and wall i+1 is convex (turns left)."""
    a, b = walls[i], walls[(i + 1) % len(walls)]
    return is_convex_vertex(a.start, a.end, b.end)


def footprint(wall: Wall, offset: float, width: float, depth: float) -> Polygon:
    """World polygon of a wall-backed rectangle."""
    return wall.rect(offset, offset + width, 0.0, depth)
