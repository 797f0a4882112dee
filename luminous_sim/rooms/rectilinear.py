"""Simplifying rectilinear (axis-aligned) polygons to few vertices, keeping a required area inside.

The simplification slides one edge at a time along its normal until a neighbouring edge vanishes
(which removes a step, notch or bump), always choosing the slide that changes the least area, and
stops when every remaining slide would change more than `max_cost` square metres or would leave
part of the required area outside.
"""

from __future__ import annotations

import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry
from shapely.ops import nearest_points

from luminous_sim.rooms.geometry import (
    EPS,
    Vec2,
    area_of,
    canonical_ring,
    polygon_parts,
    rect_polygon,
    snap,
)


def close_square(geom: BaseGeometry, radius: float) -> BaseGeometry:
    """Morphological closing with an axis-aligned square of half-side `radius` (mitred buffers)."""
    return geom.buffer(radius, join_style="mitre").buffer(-radius, join_style="mitre")


def fill_holes(poly: Polygon) -> Polygon:
    """The polygon without its interior rings."""
    return Polygon(poly.exterior.coords)


def bridge_parts(geom: BaseGeometry) -> Polygon:
    """Join the parts of a MultiPolygon into one polygon with axis-aligned bridges.

    Each smaller part is joined to the growing main part by the bounding box of the part and the
    nearest point of the main part.
    """
    parts = polygon_parts(geom)
    if not parts:
        raise ValueError("empty geometry")
    main = parts[0]
    rest = parts[1:]
    while rest:
        rest.sort(key=lambda p: (main.distance(p), p.bounds))
        part = rest.pop(0)
        near_main, _ = nearest_points(main, part)
        x0, y0, x1, y1 = part.bounds
        bridge = rect_polygon(
            min(x0, near_main.x), min(y0, near_main.y), max(x1, near_main.x), max(y1, near_main.y)
        )
        merged = shapely.union_all([main, part, bridge])
        main = polygon_parts(merged)[0] if merged.geom_type != "Polygon" else merged
    return main


def snap_polygon(poly: Polygon, step: float) -> Polygon:
    """Polygon with every vertex rounded to a multiple of `step` (kept valid)."""
    ring = [(snap(x, step), snap(y, step)) for x, y in poly.exterior.coords]
    out = Polygon(canonical_ring(ring))
    return out if out.is_valid else polygon_parts(out.buffer(0))[0]


def _slides(ring: list[Vec2]) -> list[list[Vec2]]:
    n = len(ring)
    out = []
    for i in range(n):
        p_prev, p0, p1, p_next = ring[i - 1], ring[i], ring[(i + 1) % n], ring[(i + 2) % n]
        for t in ((p_prev[0] - p0[0], p_prev[1] - p0[1]), (p_next[0] - p1[0], p_next[1] - p1[1])):
            new = list(ring)
            new[i] = (p0[0] + t[0], p0[1] + t[1])
            new[(i + 1) % n] = (p1[0] + t[0], p1[1] + t[1])
            out.append(new)
    return out


def simplify_rectilinear(
    poly: Polygon,
    required: BaseGeometry,
    max_cost: float,
    min_vertices: int = 4,
) -> Polygon:
    """Greedily remove steps, notches and bumps from a rectilinear polygon.

    Args:
        poly: an axis-aligned polygon without holes.
        required: area that must stay inside the result.
        max_cost: largest area change (square metres) one slide may make.
        min_vertices: stop at this many vertices.

    Returns:
        The simplified polygon, counter-clockwise, in canonical vertex order.
    """
    ring = canonical_ring(poly.exterior.coords)
    current = Polygon(ring)
    while len(ring) > min_vertices:
        best: tuple[float, tuple, list[Vec2], Polygon] | None = None
        for cand in _slides(ring):
            try:
                new_ring = canonical_ring(cand)
            except (IndexError, ValueError):
                continue
            if len(new_ring) < 4 or len(new_ring) >= len(ring):
                continue
            new = Polygon(new_ring)
            if not new.is_valid or new.area <= EPS:
                continue
            cost = area_of(new.symmetric_difference(current))
            if cost > max_cost + EPS or (best is not None and cost > best[0] + EPS):
                continue
            if area_of(required.difference(new)) > 1e-6:
                continue
            key = (round(cost, 6), tuple(new_ring))
            if best is None or key < (round(best[0], 6), best[1]):
                best = (cost, tuple(new_ring), new_ring, new)
        if best is None:
            break
        ring, current = best[2], best[3]
    return current


def rectilinear_outline(
    required: BaseGeometry,
    preferred: BaseGeometry,
    grid: float,
    close_radius: float,
    max_cost: float,
    max_cost_fraction: float = 0.0,
) -> Polygon:
    """A simple rectilinear outline with few vertices that holds `required` and roughly `preferred`.

    Steps: union, bridge separate parts, close gaps narrower than twice `close_radius`, drop holes,
    snap to `grid`, then `simplify_rectilinear` with a slide limit of `max_cost` square metres or
    `max_cost_fraction` of the area, whichever is larger.
    """
    merged = shapely.union_all([required, preferred])
    merged = bridge_parts(merged) if merged.geom_type != "Polygon" else merged
    closed = close_square(merged, close_radius)
    closed = bridge_parts(closed) if closed.geom_type != "Polygon" else closed
    poly = snap_polygon(fill_holes(closed), grid)
    if area_of(required.difference(poly)) > 1e-6:
        poly = snap_polygon(fill_holes(bridge_parts(shapely.union_all([poly, required]))), grid)
    return simplify_rectilinear(poly, required, max(max_cost, max_cost_fraction * poly.area))
