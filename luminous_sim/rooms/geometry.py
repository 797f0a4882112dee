"""Small geometry helpers shared by the room modules: rings, snapping, intervals along a wall."""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

Vec2 = tuple[float, float]

EPS = 1e-6
"""Tolerance, in metres (or square metres), for geometric comparisons."""


def r4(value: float) -> float:
    """Round to 4 decimals, turning -0.0 into 0.0 (the canonical float in room files)."""
    return round(float(value), 4) + 0.0


def snap(value: float, step: float) -> float:
    """Round `value` to the nearest multiple of `step` (then to 4 decimals)."""
    return r4(round(value / step) * step)


def snap_down(value: float, step: float) -> float:
    """The largest multiple of `step` not above `value` (tolerant of float noise)."""
    return r4(math.floor(value / step + 1e-9) * step)


def snap_up(value: float, step: float) -> float:
    """The smallest multiple of `step` not below `value` (tolerant of float noise)."""
    return r4(math.ceil(value / step - 1e-9) * step)


def canonical_ring(coords: Iterable[Sequence[float]]) -> list[Vec2]:
    """A polygon ring as counter-clockwise vertices, without repeats or collinear points.

    The ring starts at the vertex with the smallest (y, x), so equal shapes give equal lists.
    """
    pts = [(r4(x), r4(y)) for x, y in coords]
    if len(pts) > 1 and pts[0] == pts[-1]:
        pts = pts[:-1]
    dedup: list[Vec2] = []
    for p in pts:
        if not dedup or p != dedup[-1]:
            dedup.append(p)
    while len(dedup) > 1 and dedup[0] == dedup[-1]:
        dedup.pop()
    changed = True
    while changed and len(dedup) > 3:
        changed = False
        for i in range(len(dedup)):
            a, b, c = dedup[i - 1], dedup[i], dedup[(i + 1) % len(dedup)]
            cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])
            if abs(cross) < 1e-9:
                del dedup[i]
                changed = True
                break
    if signed_area(dedup) < 0:
        dedup.reverse()
    start = min(range(len(dedup)), key=lambda i: (dedup[i][1], dedup[i][0]))
    return dedup[start:] + dedup[:start]


def signed_area(ring: Sequence[Vec2]) -> float:
    """Shoelace area: positive for a counter-clockwise ring."""
    total = 0.0
    for i in range(len(ring)):
        x0, y0 = ring[i - 1]
        x1, y1 = ring[i]
        total += x0 * y1 - x1 * y0
    return total / 2.0


def is_convex_vertex(prev: Vec2, here: Vec2, nxt: Vec2) -> bool:
    """Whether the corner at `here` turns left (is convex) in a counter-clockwise ring."""
    cross = (here[0] - prev[0]) * (nxt[1] - here[1]) - (here[1] - prev[1]) * (nxt[0] - here[0])
    return cross > 0


def area_of(geom: BaseGeometry) -> float:
    """Area of any geometry (0 for empty)."""
    return 0.0 if geom.is_empty else float(geom.area)


def overlaps(a: BaseGeometry, b: BaseGeometry, tol: float = EPS) -> bool:
    """Whether two areas share more than `tol` square metres (touching edges do not count)."""
    if not a.intersects(b):
        return False
    return area_of(a.intersection(b)) > tol


def inside(a: BaseGeometry, b: BaseGeometry, tol: float = EPS) -> bool:
    """Whether `a` lies within `b` up to `tol` square metres."""
    return area_of(a.difference(b)) <= tol


def merge_intervals(
    spans: Iterable[tuple[float, float]], gap: float = 0.0
) -> list[tuple[float, float]]:
    """Merge overlapping (or closer than `gap`) intervals; returns them sorted."""
    out: list[tuple[float, float]] = []
    for a, b in sorted(spans):
        if out and a <= out[-1][1] + gap + EPS:
            out[-1] = (out[-1][0], max(out[-1][1], b))
        else:
            out.append((a, b))
    return out


def mask_to_intervals(
    mask: np.ndarray, step: float, origin: float = 0.0
) -> list[tuple[float, float]]:
    """Runs of True cells in a boolean row of cells `step` wide, as (start, end) intervals."""
    out: list[tuple[float, float]] = []
    start = None
    for i, ok in enumerate(mask.tolist() + [False]):
        if ok and start is None:
            start = i
        elif not ok and start is not None:
            out.append((r4(origin + start * step), r4(origin + i * step)))
            start = None
    return out


def rect_polygon(x0: float, y0: float, x1: float, y1: float) -> Polygon:
    """An axis-aligned rectangle."""
    return shapely.box(min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))


def polygon_parts(geom: BaseGeometry) -> list[Polygon]:
    """The polygons of a Polygon/MultiPolygon/GeometryCollection, largest first."""
    parts = [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, Polygon) and not g.is_empty]
    return sorted(parts, key=lambda g: (-g.area, g.bounds))
