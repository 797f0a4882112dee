"""The decoration layer on walls: windows in the shell's window openings, blinds and curtains at
windows, and paintings, posters, mirrors, switches and holders on free stretches of wall (above a
named object when a CDF says so)."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.cssg.draft import Placed, SceneDraft
from luminous_sim.cssg.requests import Request
from luminous_sim.cssg.tables import wall_height
from luminous_sim.rooms.shell import Wall
from luminous_sim.scene import footprint, yaw_facing

MARGIN = 0.1
ABOVE_GAP = 0.25
IMPLICIT_ABOVE = {"Mirror": "Sink", "Painting": "Sofa", "ToiletPaperHanger": "Toilet", "TowelHolder": "Bathtub",
                  "Cabinet": "CounterTop"}
"""Where a wall piece goes by default when that fixture or furniture is in the room."""
WALL_MOUNTED_MAX_DEPTH = 0.45
"""Only shallow variants hang on a wall (wall cabinets, not base cabinets)."""


def _origin_for(wall: Wall, entry: AssetEntry, u_center: float, v_back: float) -> tuple[float, float, float]:
    yaw = yaw_facing(wall.normal)
    u0 = u_center - (entry.bbox_min[0] + entry.bbox_max[0]) / 2
    v0 = v_back - entry.bbox_min[1]
    x, y = wall.point(u0, v0)
    return float(x), float(y), yaw


def _openings(draft: SceneDraft, wall: Wall) -> list[tuple[float, float]]:
    spans = [d.span for d in draft.shell.doors if d.wall == wall.id]
    spans += [w.span for w in draft.shell.windows if w.wall == wall.id]
    return spans


def window_strips(draft: SceneDraft, depth: float, widen: float) -> list[Polygon]:
    """Floor strips in front of every window, `depth` into the room and `widen` past each side: where a
    piece standing against the wall would have the window behind it, and nothing could hang above it."""
    walls = {w.id: w for w in draft.shell.walls}
    out = []
    for win in draft.shell.windows:
        wall = walls[win.wall]
        a, b = win.span
        a, b = max(a - widen, 0.0), min(b + widen, wall.length)
        out.append(Polygon([wall.point(a, 0.0), wall.point(b, 0.0), wall.point(b, depth), wall.point(a, depth)]))
    return out


def clashes(draft: SceneDraft, entry: AssetEntry, x: float, y: float, yaw: float, z0: float,
            ignore: str | None = None) -> bool:
    """Whether a wall piece at bottom height z0 would cut into anything placed so far (furniture, things on
    it, another wall piece)."""
    fp = footprint(entry, x, y, yaw, margin=0.02)
    z1 = z0 + entry.dims[2]
    for p in draft.placed:  # furniture, fixtures and the things standing on them
        if p.obj.id == ignore:
            continue
        top = p.obj.position[2] + p.entry.bbox_max[2]
        bottom = p.obj.position[2] + p.entry.bbox_min[2]
        if fp.intersects(p.footprint) and bottom < z1 and top > z0:
            return True
    return False


Accept = Callable[[AssetEntry, float, float, float], bool]
"""Whether a wall piece with its origin at (x, y) and heading yaw meets its floor relations (near, beside)."""


def _add(draft: SceneDraft, req: Request, entry: AssetEntry, wall: Wall, u_center: float, z0: float,
         accept: Accept | None = None) -> bool:
    x, y, yaw = _origin_for(wall, entry, u_center, 0.005)
    if accept is not None and not accept(entry, x, y, yaw):
        return False
    if clashes(draft, entry, x, y, yaw, z0):
        return False
    draft.add(entry, x, y, z0 - entry.bbox_min[2], yaw, "decoration", fixed=True, name=req.name, states=req.states,
              color=req.colour())
    return True


NEAR_OFFSET = (0.35, 0.9)
"""How far along the wall (m) a wall piece that is `near`/`beside` something goes from it."""


def _above_target(draft: SceneDraft, req: Request, by_name: dict[str, str]) -> str | None:
    rel = next((r for r in req.rels if r.relation == "above"), None)
    if rel is not None:
        return by_name.get(rel.anchor or "")
    rel = next((r for r in req.rels if r.relation in ("near", "beside")), None)
    if rel is not None:
        return by_name.get(rel.anchor or "")
    want = IMPLICIT_ABOVE.get(req.type)
    hosts = [p.obj.id for p in draft.placed if p.obj.type == want]
    return hosts[int(draft.rng.integers(len(hosts)))] if hosts else None


BEHIND_SLACK = 0.3
"""How far (m) beyond its depth a host's back may stand from the wall it hangs a piece above."""
ABOVE_JITTER = 0.05
"""How far (m) along the wall a piece hung above something may be drawn off its centre."""
ABOVE_SHIFT = 0.2
"""How far (m) a piece above something may move sideways to stay within its wall (a basin near a corner)."""


def _onto_wall(wall: Wall, entry: AssetEntry, u_center: float, most: float) -> float:
    """`u_center` moved by at most `most` so that the piece's width stays within the wall."""
    half = entry.dims[0] / 2
    inside = min(max(u_center, half), wall.length - half)
    return u_center + max(-most, min(most, inside - u_center))


def _wall_behind(draft: SceneDraft, host: Placed) -> tuple[Wall, float]:
    """The wall at the back of `host` (facing the way it faces, within its depth and a little), with the
    host's position along it; else the wall nearest to it."""
    x, y = host.obj.position[0], host.obj.position[1]
    front = (-math.sin(host.obj.yaw), math.cos(host.obj.yaw))
    best = None
    for w in draft.shell.walls:
        if w.normal[0] * front[0] + w.normal[1] * front[1] < 0.99:
            continue
        u, v = w.local(np.array([[x, y]]))[0]
        if 0.0 <= u <= w.length and -0.05 <= v <= host.entry.dims[1] + BEHIND_SLACK and (best is None or v < best[2]):
            best = (w, float(u), float(v))
    return (best[0], best[1]) if best is not None else _nearest_wall(draft, x, y)


def _nearest_wall(draft: SceneDraft, x: float, y: float) -> tuple[Wall, float]:
    best = None
    for w in draft.shell.walls:
        u, v = w.local(np.array([[x, y]]))[0]
        if -0.2 <= u <= w.length + 0.2 and (best is None or abs(v) < best[2]):
            best = (w, float(u), abs(v))
    assert best is not None
    return best[0], best[1]


def place_wall_piece(draft: SceneDraft, req: Request, by_name: dict[str, str], tries: int = 40,
                     relations: bool = True, accept: Accept | None = None) -> bool:
    """Place one wall-layer request; False if no wall stretch has room.

    With `relations` off (the baseline) nothing is put above anything on purpose; `accept` turns down
    spots that break the piece's floor relations.
    """
    rng = draft.rng
    variants = [e for e in req.variants(draft.catalog) if e.dims[1] <= WALL_MOUNTED_MAX_DEPTH]
    if not variants:
        return False
    walls = {w.id: w for w in draft.shell.walls}
    if req.type in ("Window", "Blinds", "Curtains"):
        windows = list(draft.shell.windows)
        rng.shuffle(windows)
        for win in windows:
            wall = walls[win.wall]
            fitting = [e for e in variants if e.dims[0] <= win.width + (0.5 if req.type == "Curtains" else 0.02)
                       and (req.type == "Curtains" or e.dims[2] <= win.height + 0.01)]
            if not fitting:
                continue
            entry = fitting[int(rng.integers(len(fitting)))]
            if req.type == "Window":  # centred in the opening
                z0 = win.sill_height + (win.height - entry.dims[2]) / 2
            else:
                z0 = 0.0 if req.type == "Curtains" else win.sill_height + 0.02
            if req.type == "Window":
                x, y, yaw = _origin_for(wall, entry, win.offset + win.width / 2, -draft.shell.wall_thickness / 2
                                        - (entry.dims[1] / 2))
                draft.add(entry, x, y, z0 - entry.bbox_min[2], yaw, "decoration", fixed=True, name=req.name)
                return True
            if _add(draft, req, entry, wall, win.offset + win.width / 2, z0):
                return True
        return False
    target = _above_target(draft, req, by_name) if relations else None
    for attempt in range(tries):
        entry = variants[int(rng.integers(len(variants)))]
        if target is not None and attempt < tries // 2:
            host = next(p for p in draft.placed if p.obj.id == target)
            wall, u = _wall_behind(draft, host)
            top = host.obj.position[2] + host.entry.bbox_max[2]
            beside = any(r.relation in ("near", "beside") for r in req.rels) or req.type == "ToiletPaperHanger"
            if beside:  # at its usual height, to one side of the anchor
                z0 = wall_height(req.type)
                side = 1.0 if rng.random() < 0.5 else -1.0
                u_center = u + side * (host.entry.dims[0] / 2 + float(rng.uniform(*NEAR_OFFSET)) * 0.5)
            else:
                z0 = max(wall_height(req.type), top + ABOVE_GAP)
                u_center = _onto_wall(wall, entry, u + float(rng.uniform(-ABOVE_JITTER, ABOVE_JITTER)), ABOVE_SHIFT)
        else:
            lengths = np.array([w.length for w in draft.shell.walls])
            wall = draft.shell.walls[int(rng.choice(len(lengths), p=lengths / lengths.sum()))]
            half = entry.dims[0] / 2
            if wall.length < 2 * (half + MARGIN):
                continue
            u_center = float(rng.uniform(half + MARGIN, wall.length - half - MARGIN))
            z0 = wall_height(req.type)
            if req.type == "LightSwitch" and draft.shell.doors:
                door = draft.shell.doors[int(rng.integers(len(draft.shell.doors)))]
                wall = walls[door.wall]
                u_center = door.offset - 0.2 if door.offset > 0.4 else door.offset + door.width + 0.2
        half = entry.dims[0] / 2
        if any(a - MARGIN < u_center + half and u_center - half < b + MARGIN for a, b in _openings(draft, wall)):
            continue
        if not (half <= u_center <= wall.length - half):
            continue
        if z0 + entry.dims[2] > draft.shell.wall_height - 0.05:
            continue
        if _add(draft, req, entry, wall, u_center, z0, accept):
            return True
    return False
