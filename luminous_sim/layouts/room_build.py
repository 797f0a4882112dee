"""A layout room from an imported floor outline and openings: moved so that the floor starts at (0, 0),
rounded to the room files' 4 decimals, doors and windows put on the outline edge they lie along."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.layouts.model import LayoutDoor, LayoutRoom, LayoutWindow
from luminous_sim.rooms.geometry import canonical_ring

WALL_REACH = 0.35
"""metres from an outline edge within which an opening's points count as lying in that wall."""
MIN_OPENING = 0.3
"""metres: narrower openings (a sliver of a neighbouring room's door) are ignored."""
DOOR_WIDTH = (0.55, 2.0)
DOOR_HEIGHT = (1.6, 3.0)
DOOR_CLEARANCE = 0.9
"""metres kept free in front of an imported door (3D-FRONT does not say how it swings)."""


@dataclass(frozen=True)
class Opening:
    """A door or window from the source: its points (our frame, the room not yet moved) and its kind."""

    kind: str
    points: np.ndarray
    source: str


def frame_offset(poly: Polygon) -> tuple[float, float]:
    """What is subtracted from source (x, y) so that the room's floor starts at (0, 0)."""
    minx, miny, _, _ = poly.bounds
    return round(minx, 4), round(miny, 4)


def _ring(poly: Polygon, offset: tuple[float, float]) -> list[tuple[float, float]]:
    """The outline moved by `offset`, as room files keep it (4 decimals, from the smallest (y, x))."""
    return canonical_ring((x - offset[0], y - offset[1]) for x, y in poly.exterior.coords)


def build_room(poly: Polygon, room_type: str, name: str, openings: list[Opening], notes: list[str],
               wall_height: float = 2.6, source: str = "") -> tuple[LayoutRoom, tuple[float, float]]:
    """The layout room and the offset applied; what could not be kept (an opening off every wall, a size
    clamped to the room files' limits) is added to `notes`."""
    offset = frame_offset(poly)
    ring = _ring(poly, offset)
    doors: list[LayoutDoor] = []
    windows: list[LayoutWindow] = []
    for op in openings:
        pts = op.points - [offset[0], offset[1], 0.0]
        hit = _on_wall(ring, pts[:, :2])
        if hit is None:
            notes.append(f"{op.kind} {op.source}: not along a wall of the room; ignored")
            continue
        wall, u0, u1 = hit
        z0, z1 = float(pts[:, 2].min()), float(pts[:, 2].max())
        if op.kind == "door":
            width = min(max(u1 - u0, DOOR_WIDTH[0]), DOOR_WIDTH[1])
            height = min(max(z1 - max(z0, 0.0), DOOR_HEIGHT[0]), DOOR_HEIGHT[1], wall_height)
            if abs(width - (u1 - u0)) > 1e-3 or abs(height - (z1 - max(z0, 0.0))) > 1e-3:
                notes.append(f"door {op.source}: {u1 - u0:.2f} x {z1 - z0:.2f} m kept as {width:.2f} x {height:.2f} m "
                             "(the room files' door limits)")
            length = math.dist(ring[wall], ring[(wall + 1) % len(ring)])
            start = min(max(0.0, (u0 + u1 - width) / 2), length - width)
            doors.append(LayoutDoor(wall=wall, offset=round(start, 4), width=round(width, 4), height=round(height, 4),
                                    swing_clearance=DOOR_CLEARANCE))
        else:
            sill = min(max(z0, 0.05), wall_height - 0.2)
            height = max(min(z1, wall_height - 0.05) - sill, 0.1)
            windows.append(LayoutWindow(wall=wall, offset=round(u0, 4), width=round(u1 - u0, 4),
                                        sill_height=round(sill, 4), height=round(height, 4)))
    room = LayoutRoom(name=name, room_type=room_type, outline=tuple(ring), wall_height=wall_height,  # type: ignore[arg-type]
                      doors=tuple(doors), windows=tuple(windows), source=source)
    return room, offset


def _on_wall(ring: list[tuple[float, float]], pts: np.ndarray) -> tuple[int, float, float] | None:
    """(edge index, start, end along it) of the edge the points lie along, or None."""
    best = None
    centre = pts.mean(axis=0)
    for i, a in enumerate(ring):
        b = ring[(i + 1) % len(ring)]
        d = np.subtract(b, a)
        length = float(np.hypot(*d))
        if length < 1e-6:
            continue
        t = d / length
        n = np.array([-t[1], t[0]])
        dist = abs(float((centre - a) @ n))
        u = (pts - a) @ t
        u0, u1 = max(float(u.min()), 0.0), min(float(u.max()), length)
        if dist <= WALL_REACH and u1 - u0 >= MIN_OPENING and (best is None or dist < best[0]):
            best = (dist, i, round(u0, 4), round(u1, 4))
    return None if best is None else best[1:]
