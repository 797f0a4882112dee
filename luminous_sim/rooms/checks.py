"""Semantic checks of a RoomShell beyond its schema: what a usable room must satisfy."""

from __future__ import annotations

import numpy as np
import shapely

from luminous_sim.rooms.geometry import inside, overlaps
from luminous_sim.rooms.shell import RoomShell

OPENING_STRIP = 0.05
"""Depth of the floor strip in front of an opening used to find fixtures under a window."""

REACH = 1.0
"""Most distance from an agent grid point to a fixture footprint for the fixture to be usable."""

REQUIRED_SLOTS: dict[str, tuple[tuple[str, ...], ...]] = {
    "Kitchen": (("Sink",), ("StoveBurner",), ("Fridge",)),
    "Bathroom": (("Sink",), ("Toilet",), ("Bathtub", "Shower")),
}
"""Slot types a room type must hold; each inner tuple lists alternatives."""


def shell_problems(shell: RoomShell, reach: float = REACH) -> list[str]:
    """Everything wrong with a shell as a place to generate scenes in; empty when it is fine.

    Checks: at least one door; openings keep a wall thickness from wall ends and do not overlap;
    fixtures lie inside the floor and do not overlap (a slot may sit in its own counter); door
    clearance zones lie inside the floor and are free of fixtures; a window above a fixture clears
    it; kitchens and bathrooms hold their fixtures; there are agent grid points, and each fixture
    has one within `reach` metres.
    """
    out: list[str] = []
    floor = shell.polygon()
    t = shell.wall_thickness
    if not shell.doors:
        out.append("no door")
    openings = [(d.id, d.wall, d.span) for d in shell.doors] + [
        (w.id, w.wall, w.span) for w in shell.windows
    ]
    for oid, wid, (a, b) in openings:
        if a < t - 1e-6 or b > shell.wall(wid).length - t + 1e-6:
            out.append(f"{oid}: closer than the wall thickness to the end of wall {wid}")
    for i, (oid, wid, (a, b)) in enumerate(openings):
        for oid2, wid2, (a2, b2) in openings[i + 1 :]:
            if wid == wid2 and a < b2 - 1e-6 and a2 < b - 1e-6:
                out.append(f"{oid} overlaps {oid2} on wall {wid}")
    feet = shell.fixture_footprints()
    for fid, poly in feet.items():
        if not inside(poly, floor):
            out.append(f"{fid}: footprint leaves the floor")
    hosts = {s.id: s.counter for s in shell.fixtures.slots}
    ids = list(feet)
    for i, fa in enumerate(ids):
        for fb in ids[i + 1 :]:
            slot, host = (fa, fb) if hosts.get(fa) == fb else (fb, fa) if hosts.get(fb) == fa else ("", "")
            if slot:
                if not inside(feet[slot], feet[host]):
                    out.append(f"{slot}: not inside its counter {host}")
                continue
            if overlaps(feet[fa], feet[fb]):
                out.append(f"{fa} overlaps {fb}")
    for door, zone in zip(shell.doors, shell.door_clearance_zones()):
        if not inside(zone, floor):
            out.append(f"{door.id}: clearance zone leaves the floor")
        for fid, poly in feet.items():
            if overlaps(zone, poly):
                out.append(f"{door.id}: clearance zone overlaps {fid}")
    heights = {c.id: c.height for c in shell.fixtures.counters}
    heights.update({s.id: s.height for s in shell.fixtures.slots})
    for win in shell.windows:
        strip = shell.wall(win.wall).rect(win.offset, win.offset + win.width, 0.0, OPENING_STRIP)
        for fid, poly in feet.items():
            if overlaps(strip, poly, tol=1e-5) and win.sill_height < heights[fid] - 1e-6:
                out.append(f"{win.id}: sill {win.sill_height} below {fid} (height {heights[fid]})")
    present = {s.type for s in shell.fixtures.slots}
    for alternatives in REQUIRED_SLOTS.get(shell.room_type, ()):
        if not present.intersection(alternatives):
            out.append(f"{shell.room_type} without a {'/'.join(alternatives)} slot")
    if shell.room_type == "Kitchen" and not shell.fixtures.counters:
        out.append("Kitchen without a counter run")
    pts = shell.grid_points()
    if len(pts) == 0:
        out.append("no agent grid points")
    else:
        for s in shell.fixtures.slots:
            d = shapely.distance(feet[s.id], shapely.points(pts))
            if float(np.min(d)) > reach + 1e-6:
                out.append(f"{s.id}: no agent grid point within {reach} m")
    return out
