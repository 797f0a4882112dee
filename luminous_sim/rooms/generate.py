"""Procedural room shells for the four ALFRED room types: rectangles, L-shapes and two-zone rooms.

`generate_shell` draws the outline, then doors, then (for kitchens and bathrooms) fixtures, then
windows, and redraws until `shell_problems` finds nothing. Every draw comes from the Generator it is
given, so the same seed gives the same shell, byte for byte. Sizes and probabilities are data
(`ROOM_SPECS`).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.errors import RoomError
from luminous_sim.rooms.checks import shell_problems
from luminous_sim.rooms.fixtures import plan_fixtures
from luminous_sim.rooms.geometry import canonical_ring, r4, rect_polygon, snap
from luminous_sim.rooms.placement import STEP, free_offsets
from luminous_sim.rooms.shell import (
    Door,
    RoomShell,
    Wall,
    Window,
    Zone,
    make_shell,
    walls_from_outline,
    zone_polygon,
)
from luminous_sim.vocab import ROOM_TYPES

SHAPES: tuple[str, ...] = ("rect", "L", "two_zone")
SNAP = 0.05
MAX_ATTEMPTS = 200


@dataclass(frozen=True)
class RoomSpec:
    """What a room type's shells look like (metres, square metres, probabilities)."""

    area: tuple[float, float]
    aspect: tuple[float, float]
    min_side: float
    zones: tuple[str, str]
    shape_weights: tuple[float, float, float]  # rect, L, two_zone
    door_count_p: tuple[float, ...]  # P(1 door), P(2 doors)
    window_count_p: tuple[float, ...]  # P(0), P(1), ...
    window_width: tuple[float, float]
    window_sill: tuple[float, float]
    window_height: tuple[float, float]


ROOM_SPECS: dict[str, RoomSpec] = {
    "Kitchen": RoomSpec(
        (8.0, 20.0),
        (1.0, 1.7),
        2.5,
        ("work", "dining"),
        (0.5, 0.25, 0.25),
        (0.8, 0.2),
        (0.1, 0.7, 0.2),
        (0.8, 1.5),
        (1.0, 1.15),
        (0.9, 1.2),
    ),
    "LivingRoom": RoomSpec(
        (15.0, 35.0),
        (1.0, 1.8),
        3.2,
        ("lounge", "dining"),
        (0.45, 0.3, 0.25),
        (0.6, 0.4),
        (0.05, 0.45, 0.35, 0.15),
        (1.0, 2.0),
        (0.5, 0.9),
        (1.2, 1.6),
    ),
    "Bedroom": RoomSpec(
        (9.0, 20.0),
        (1.0, 1.6),
        2.7,
        ("sleep", "study"),
        (0.5, 0.25, 0.25),
        (0.9, 0.1),
        (0.05, 0.7, 0.25),
        (0.9, 1.6),
        (0.7, 0.9),
        (1.1, 1.5),
    ),
    "Bathroom": RoomSpec(
        (4.0, 9.0),
        (1.0, 1.8),
        1.7,
        ("bath", "vanity"),
        (0.6, 0.2, 0.2),
        (1.0,),
        (0.4, 0.6),
        (0.5, 0.9),
        (1.2, 1.5),
        (0.5, 0.8),
    ),
}
TWO_ZONE_ASPECT = (1.4, 2.0)
WALL_HEIGHT = (2.5, 2.7)
WALL_THICKNESS = (0.1, 0.15)
DOOR_WIDTH = (0.8, 0.9)
DOOR_HEIGHT = (2.0, 2.1)
DOOR_CLEARANCE_EXTRA = 0.1
CORNER_MARGIN = 0.2
WINDOW_GAP = 0.3
HEAD_ROOM = 0.2
MIRROR_SPAN = 0.6
"""Width (m) of wall above a bathroom sink kept free of windows (and WINDOW_GAP either side), for
its mirror."""


def snake(room_type: str) -> str:
    """`LivingRoom` -> `living_room`."""
    return "".join(
        "_" + c.lower() if c.isupper() and i else c.lower() for i, c in enumerate(room_type)
    )


def snapped_uniform(rng: np.random.Generator, lo_hi: tuple[float, float], step: float = SNAP) -> float:
    return snap(rng.uniform(*lo_hi), step)


def _in_range(area: float, spec: RoomSpec) -> bool:
    return spec.area[0] - 1e-9 <= area <= spec.area[1] + 1e-9


def _rect_dims(
    rng: np.random.Generator, spec: RoomSpec, area: tuple[float, float], aspect: tuple[float, float]
) -> tuple[float, float] | None:
    a, r = rng.uniform(*area), rng.uniform(*aspect)
    long_, short = snap(math.sqrt(a * r), SNAP), snap(math.sqrt(a / r), SNAP)
    if short < spec.min_side or not _in_range(long_ * short, spec):
        return None
    return (long_, short) if rng.random() < 0.5 else (short, long_)


def _outline(rng: np.random.Generator, spec: RoomSpec, shape: str):
    """(outline polygon, zones as {name: polygon}) or None to draw again."""
    if shape == "rect":
        dims = _rect_dims(rng, spec, spec.area, spec.aspect)
        return None if dims is None else (rect_polygon(0, 0, *dims), {})
    if shape == "two_zone":
        lo, hi = spec.area
        dims = _rect_dims(rng, spec, (lo + 0.45 * (hi - lo), hi), TWO_ZONE_ASPECT)
        if dims is None:
            return None
        w, d = dims
        along_x = w >= d
        long_ = max(w, d)
        cut = snap(rng.uniform(0.45, 0.6) * long_, SNAP)
        if along_x:
            first, second = rect_polygon(0, 0, cut, d), rect_polygon(cut, 0, w, d)
        else:
            first, second = rect_polygon(0, 0, w, cut), rect_polygon(0, cut, w, d)
        if rng.random() < 0.5:
            first, second = second, first
        return rect_polygon(0, 0, w, d), {spec.zones[0]: first, spec.zones[1]: second}
    # L: a rectangle with one corner rectangle removed.
    frac = rng.uniform(0.12, 0.3)
    outer = rng.uniform(*spec.area) / (1 - frac)
    r = rng.uniform(*spec.aspect)
    w, d = snap(math.sqrt(outer * r), SNAP), snap(math.sqrt(outer / r), SNAP)
    if rng.random() < 0.5:
        w, d = d, w
    cw = snap(rng.uniform(0.3, 0.55) * w, SNAP)
    cd = snap(frac * w * d / max(cw, SNAP), SNAP)
    arm = max(1.5, 0.75 * spec.min_side)
    if cd > 0.65 * d or w - cw < arm or d - cd < arm or cw < 0.6 or cd < 0.6:
        return None
    corner = int(rng.integers(4))
    x0 = 0.0 if corner in (0, 3) else w - cw
    y0 = 0.0 if corner in (0, 1) else d - cd
    poly = rect_polygon(0, 0, w, d).difference(rect_polygon(x0, y0, x0 + cw, y0 + cd))
    if not _in_range(poly.area, spec) or min(w, d) < spec.min_side:
        return None
    return poly, {}


def _doors(
    walls: Sequence[Wall],
    floor: Polygon,
    rng: np.random.Generator,
    spec: RoomSpec,
    thickness: float,
) -> list[Door] | None:
    count = 1 + int(rng.choice(len(spec.door_count_p), p=spec.door_count_p))
    doors: list[Door] = []
    zones: list[Polygon] = []
    used: set[str] = set()
    margin = max(CORNER_MARGIN, thickness + SNAP)
    for k in range(count):
        width, height = snapped_uniform(rng, DOOR_WIDTH), snapped_uniform(rng, DOOR_HEIGHT)
        clear = r4(width + DOOR_CLEARANCE_EXTRA)
        opts = []
        for w in walls:
            if w.id in used:
                continue
            for u in free_offsets(w, width, clear, floor, zones, end_margin=margin):
                opts.append((w, float(u)))
        if not opts:
            return None if k == 0 else doors
        lengths = np.array([o[0].length for o in opts])
        w, u = opts[int(rng.choice(len(opts), p=lengths / lengths.sum()))]
        hinge = "start" if rng.random() < 0.5 else "end"
        doors.append(
            Door(
                id=f"Door_{k}",
                wall=w.id,
                offset=u,
                width=width,
                height=height,
                swing_clearance=clear,
                hinge=hinge,
            )
        )
        zones.append(w.rect(u, u + width, 0.0, clear))
        used.add(w.id)
    return doors


def draw_windows(shell: RoomShell, rng: np.random.Generator, spec: RoomSpec,
             outside: Collection[str] | None = None) -> list[Window]:
    """Windows drawn by the spec's counts and sizes; only on the walls in `outside` when it is given (a
    house's room has windows on its outside walls only)."""
    count = int(rng.choice(len(spec.window_count_p), p=spec.window_count_p))
    heights = {c.id: c.height for c in shell.fixtures.counters}
    heights.update({s.id: s.height for s in shell.fixtures.slots})
    feet = shell.fixture_footprints()
    margin = max(CORNER_MARGIN, shell.wall_thickness + SNAP)
    spans: dict[str, list[tuple[float, float]]] = {}
    for d in shell.doors:
        spans.setdefault(d.wall, []).append(d.span)
    windows: list[Window] = []
    sink = shell.fixtures.slot("Sink")
    if sink is not None and shell.room_type == "Bathroom":  # the wall above it takes a mirror
        mid = sink.offset + sink.width / 2
        spans.setdefault(sink.wall, []).append((mid - MIRROR_SPAN / 2, mid + MIRROR_SPAN / 2))
        sink = None
    for k in range(count):
        width, sill = snapped_uniform(rng, spec.window_width), snapped_uniform(rng, spec.window_sill)
        height = min(snapped_uniform(rng, spec.window_height), snap(shell.wall_height - HEAD_ROOM - sill, SNAP))
        if height < 0.4:
            continue
        opts: list[tuple[Wall, float]] = []
        for w in shell.walls:
            if outside is not None and w.id not in outside:
                continue
            lo, hi = margin, w.length - margin - width
            if hi < lo:
                continue
            us = np.round(
                np.arange(math.ceil(lo / STEP - 1e-9), math.floor(hi / STEP + 1e-9) + 1) * STEP, 4
            )
            ok = np.ones(len(us), dtype=bool)
            blocked = [(a - WINDOW_GAP, b + WINDOW_GAP) for a, b in spans.get(w.id, [])]
            band = w.rect(0.0, w.length, 0.0, 0.05)
            for fid, poly in feet.items():
                if heights[fid] > sill - 0.05 and band.intersects(poly):
                    piece = band.intersection(poly)
                    if piece.area > 1e-6:
                        uv = w.local(np.asarray(piece.exterior.coords))
                        blocked.append((uv[:, 0].min(), uv[:, 0].max()))
            for a, b in blocked:
                ok &= ~((us < b - 1e-6) & (us + width > a + 1e-6))
            opts += [(w, float(u)) for u in us[ok]]
        if not opts:
            continue
        choice = None
        if sink is not None and rng.random() < 0.6:
            target = sink.offset + sink.width / 2 - width / 2
            over = [o for o in opts if o[0].id == sink.wall]
            if over:
                choice = min(over, key=lambda o: (abs(o[1] - target), o[1]))
        if choice is None:
            lengths = np.array([o[0].length for o in opts])
            choice = opts[int(rng.choice(len(opts), p=lengths / lengths.sum()))]
        w, u = choice
        windows.append(
            Window(
                id=f"Window_{k}", wall=w.id, offset=u, width=width, sill_height=sill, height=height
            )
        )
        spans.setdefault(w.id, []).append((u, u + width))
    return windows


def generate_shell(
    room_type: str,
    rng: np.random.Generator,
    shape: str | None = None,
    name: str | None = None,
) -> RoomShell:
    """Draw a room shell of a type and shape.

    Args:
        room_type: one of Kitchen, LivingRoom, Bedroom, Bathroom.
        rng: source of every random draw.
        shape: "rect", "L", "two_zone", or None to draw one (per-type weights).
        name: the shell's name; default `<room_type>_<shape>` in snake case.

    Returns:
        A shell with at least one door that passes `shell_problems`.

    Raises:
        RoomError: an unknown room type or shape, or no valid shell within the attempt budget.
    """
    if room_type not in ROOM_TYPES:
        raise RoomError(f"unknown room type {room_type!r}; expected one of {', '.join(ROOM_TYPES)}")
    spec = ROOM_SPECS[room_type]
    if shape is None:
        shape = SHAPES[
            int(rng.choice(len(SHAPES), p=np.asarray(spec.shape_weights) / sum(spec.shape_weights)))
        ]
    if shape not in SHAPES:
        raise RoomError(f"unknown room shape {shape!r}; expected one of {', '.join(SHAPES)}")
    name = name or f"{snake(room_type)}_{shape}"
    last = "no outline fitted"
    for _ in range(MAX_ATTEMPTS):
        drawn = _outline(rng, spec, shape)
        if drawn is None:
            continue
        poly, zones = drawn
        height, thickness = snapped_uniform(rng, WALL_HEIGHT), snapped_uniform(rng, WALL_THICKNESS, 0.01)
        ring = canonical_ring(poly.exterior.coords)
        walls = walls_from_outline(ring)
        floor = Polygon(ring)
        doors = _doors(walls, floor, rng, spec, thickness)
        if doors is None:
            last = "no door fitted"
            continue
        keep = [
            walls_by_id(walls)[d.wall].rect(d.offset, d.offset + d.width, 0.0, d.swing_clearance)
            for d in doors
        ]
        plan = plan_fixtures(room_type, walls, floor, rng, keep, [zones.get(z) for z in spec.zones])
        if plan is None:
            last = "no fixture plan fitted"
            continue
        shell = make_shell(
            name=name,
            room_type=room_type,
            shape=shape,
            source="procedural",
            outline=ring,
            wall_height=height,
            wall_thickness=thickness,
            doors=tuple(doors),
            fixtures=plan,
            zones=tuple(Zone(name=k, polygon=zone_polygon(v)) for k, v in zones.items()),
        )
        windows = draw_windows(shell, rng, spec)
        shell = shell.model_copy(update={"windows": tuple(windows)})
        shell = RoomShell.from_dict(shell.model_dump(), where=f"room {name!r}")
        problems = shell_problems(shell)
        if not problems:
            return shell
        last = "; ".join(problems)
    raise RoomError(f"could not generate a {shape} {room_type} in {MAX_ATTEMPTS} attempts ({last})")


def walls_by_id(walls: Sequence[Wall]) -> dict[str, Wall]:
    """Walls keyed by id."""
    return {w.id: w for w in walls}
