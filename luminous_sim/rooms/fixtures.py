"""Procedural fixture places: kitchen counter runs (I, L or U), sink, stove, fridge; bathrooms.

One of the two sources of the plan builder `fixture_plan`: the planners here choose where each
fixture goes among the free wall stretches, drawing every random choice from the Generator they are
given, and return None when the room cannot take a plan (the caller then redraws the room or its
doors). Dimensions are data (`fixture_plan.KITCHEN`, `BATHROOM`); offsets are multiples of 5 cm.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from luminous_sim.rooms.fixture_plan import (
    BATHROOM,
    KITCHEN,
    BathroomDims,
    KitchenDims,
    Place,
    Span,
    bathroom_plan,
    centred,
    cut_run_end,
    kitchen_plan,
    offset_grid,
    offsets_clear_of,
)
from luminous_sim.rooms.geometry import r4
from luminous_sim.rooms.placement import (
    STEP,
    corner_convex,
    footprint,
    free_intervals,
    free_offsets,
)
from luminous_sim.rooms.shell import FixturePlan, Wall


@dataclass(frozen=True)
class _Run:
    wall: Wall
    start: float
    end: float
    corner_start: bool  # the run starts against the corner square of the previous run
    corner_end: bool  # the run ends with a corner square (the next run starts against it)


def _pick(rng: np.random.Generator, items: Sequence, p: Sequence[float] | None = None):
    if p is not None:
        w = np.asarray(p, dtype=float)
        return items[int(rng.choice(len(items), p=w / w.sum()))]
    return items[int(rng.integers(len(items)))]


def _kitchen_candidates(
    walls: Sequence[Wall], avail: list[list[tuple[float, float]]], d: KitchenDims
):
    """Every I, L and U layout the free wall stretches allow, as lists of _Run."""
    n = len(walls)
    cd = d.counter_depth
    cands: dict[str, list[list[_Run]]] = {"I": [], "L": [], "U": []}
    longest = [
        max(avail[i], key=lambda s: (s[1] - s[0], -s[0])) if avail[i] else None for i in range(n)
    ]
    for i, w in enumerate(walls):
        s = longest[i]
        if s and s[1] - s[0] >= 2.4:
            cands["I"].append([_Run(w, s[0], s[1], False, False)])

    def ends_at_end(i: int) -> tuple[float, float] | None:
        return next((s for s in avail[i] if s[1] >= walls[i].length - 1e-6), None)

    def starts_at_zero(i: int) -> tuple[float, float] | None:
        return next((s for s in avail[i] if s[0] <= 1e-6), None)

    for i in range(n):
        j = (i + 1) % n
        if n < 3 or not corner_convex(walls, i):
            continue
        a, b = ends_at_end(i), starts_at_zero(j)
        if a and b and a[1] - a[0] >= d.min_run and b[1] - cd >= d.min_run:
            cands["L"].append(
                [_Run(walls[i], a[0], a[1], False, True), _Run(walls[j], cd, b[1], True, False)]
            )
        k = (j + 1) % n
        if n >= 4 and corner_convex(walls, j):
            full = next(
                (s for s in avail[j] if s[0] <= 1e-6 and s[1] >= walls[j].length - 1e-6), None
            )
            c = starts_at_zero(k)
            if a and full and c and a[1] - a[0] >= d.min_run and c[1] - cd >= d.min_run:
                cands["U"].append(
                    [
                        _Run(walls[i], a[0], a[1], False, True),
                        _Run(walls[j], cd, full[1], True, True),
                        _Run(walls[k], cd, c[1], True, False),
                    ]
                )
    return cands


def _trim_runs(runs: list[_Run], rng: np.random.Generator, d: KitchenDims) -> list[_Run]:
    """Shorten free run ends at random (a run need not fill its whole wall)."""
    out = []
    for r in runs:
        start, end = r.start, r.end
        length = end - start
        spare = max(0.0, length - max(d.min_run, 2.4 if len(runs) == 1 else d.min_run))
        cut = r4(np.floor(rng.uniform(0, min(spare, 1.0)) / STEP) * STEP) if spare > 0 else 0.0
        if not r.corner_start and not r.corner_end:
            first = r4(np.floor(rng.uniform(0, cut) / STEP) * STEP) if cut > 0 else 0.0
            start, end = start + first, end - (cut - first)
        elif not r.corner_start:
            start += cut
        elif not r.corner_end:
            end -= cut
        out.append(_Run(r.wall, r4(start), r4(end), r.corner_start, r.corner_end))
    return out


def _usable(run: _Run, d: KitchenDims) -> tuple[float, float]:
    """Part of a run where an appliance can go: away from corner squares and run ends."""
    a = run.start + d.end_gap
    b = run.end - d.end_gap - (d.counter_depth if run.corner_end else 0.0)
    return a, b


def _plan_kitchen(
    walls: Sequence[Wall],
    floor: Polygon,
    rng: np.random.Generator,
    region: BaseGeometry | None,
    keepouts: Sequence[BaseGeometry],
    dims: KitchenDims = KITCHEN,
) -> FixturePlan | None:
    """Counter runs in an I, L or U layout, a sink, a stove and a fridge; None if no layout fits."""
    d = dims
    region = floor if region is None else region.intersection(floor)
    avail = [
        free_intervals(w, d.counter_depth, region, keepouts, front=d.aisle, front_allowed=floor)
        for w in walls
    ]
    cands = _kitchen_candidates(walls, avail, d)
    kinds = [k for k in ("I", "L", "U") if cands[k]]
    if not kinds:
        return None
    weights = {"I": 1.0, "L": 1.5, "U": 1.0 if floor.area >= 11 else 0.3}
    kind = _pick(rng, kinds, [weights[k] for k in kinds])
    runs = _trim_runs(list(_pick(rng, cands[kind])), rng, d)

    # The fridge stands at a free end of a run, which gets shorter by its width.
    fw = float(_pick(rng, d.fridge_widths))
    ends = [
        (i, e)
        for i, r in enumerate(runs)
        for e in ("start", "end")
        if not getattr(r, f"corner_{e}")
    ]
    rng.shuffle(ends)
    fridge = None
    for i, e in ends:
        r = runs[i]
        if r.end - r.start - fw < d.min_run - 1e-6:
            continue
        u, rest = cut_run_end(Span(r.wall.id, r.start, r.end), e, fw)
        ok = free_offsets(
            r.wall, fw, d.fridge_depth, region, keepouts, front=d.fridge_front, front_allowed=floor
        )
        if not np.any(np.isclose(ok, u)):
            continue
        fridge = Place(r.wall.id, u, fw)
        runs[i] = _Run(r.wall, rest.start, rest.end, r.corner_start, r.corner_end)
        break
    if fridge is None:
        return None

    # The U layout needs an aisle between facing runs.
    if kind == "U":
        a = footprint(runs[0].wall, runs[0].start, runs[0].end - runs[0].start, d.counter_depth)
        c = footprint(runs[2].wall, runs[2].start, runs[2].end - runs[2].start, d.counter_depth)
        if a.distance(c) < d.aisle - 1e-6:
            return None

    sink_w = float(_pick(rng, d.sink_widths))
    stove_w = float(_pick(rng, d.stove_widths))
    order = list(range(len(runs)))
    rng.shuffle(order)
    sink = None
    for i in order:
        us = offset_grid(*_usable(runs[i], d), sink_w)
        if len(us):
            sink = Place(runs[i].wall.id, float(_pick(rng, list(us))), sink_w, run=i)
            break
    if sink is None:
        return None
    stove_opts: list[tuple[int, float]] = []
    for i, r in enumerate(runs):
        a, b = _usable(r, d)
        a, b = max(a, r.start + d.stove_side), min(b, r.end - d.stove_side)
        near = sink if i == sink.run else None
        stove_opts += [(i, u) for u in offsets_clear_of(a, b, stove_w, near, d.sink_stove_gap)]
    if not stove_opts:
        return None
    other = [o for o in stove_opts if o[0] != sink.run]
    pool = other if other and rng.random() < 0.7 else stove_opts
    ti, tu = _pick(rng, pool)
    stove = Place(runs[ti].wall.id, tu, stove_w, run=ti)
    spans = [Span(r.wall.id, r.start, r.end) for r in runs]
    return kitchen_plan(kind, spans, sink, stove, fridge, d)


def _beside(
    option: tuple[Wall, float], tub_wall: Wall, tub_u: float, tub_len: float, d: BathroomDims
) -> bool:
    """Whether a toilet slot at `option` stands right beside the bathtub slot, on the same wall."""
    w, u = option
    if w.id != tub_wall.id:
        return False
    gap = max(u - (tub_u + tub_len), tub_u - (u + d.toilet_width))
    return -1e-6 <= gap <= d.beside_gap + 1e-6


def _sink_offset(rng: np.random.Generator, u: float, width: float, d: BathroomDims) -> float:
    """Where the sink slot goes in a vanity run [u, u + width]: at one end, drawn, when the rest
    takes a counter segment; else in the middle."""
    if width - d.sink_width >= d.vanity_counter - 1e-6:
        return r4(u if rng.random() < 0.5 else u + width - d.sink_width)
    return centred(u, width, d.sink_width)


def _wall_offsets(
    walls: Sequence[Wall],
    width: float,
    depth: float,
    allowed: BaseGeometry,
    obstacles: Sequence[BaseGeometry],
    front: float,
    floor: Polygon,
    front_obstacles: Sequence[BaseGeometry],
) -> list[tuple[Wall, float]]:
    """Every (wall, offset) where a wall-backed slot fits in `allowed`, its front on the floor."""
    return [
        (w, float(u))
        for w in walls
        for u in free_offsets(
            w,
            width,
            depth,
            allowed,
            obstacles,
            front=front,
            front_allowed=floor,
            front_obstacles=front_obstacles,
        )
    ]


def _plan_bathroom(
    walls: Sequence[Wall],
    floor: Polygon,
    rng: np.random.Generator,
    keepouts: Sequence[BaseGeometry],
    bath_region: BaseGeometry | None,
    vanity_region: BaseGeometry | None,
    dims: BathroomDims = BATHROOM,
) -> FixturePlan | None:
    """A bathtub in a corner, a toilet, a sink (often in a vanity); None if they do not fit."""
    d = dims
    bath = floor if bath_region is None else bath_region.intersection(floor)
    vanity_zone = floor if vanity_region is None else vanity_region.intersection(floor)
    n = len(walls)
    tub_opts: list[tuple[Wall, float, float]] = []
    for i, w in enumerate(walls):
        if w.length < min(d.tub_lengths) - 1e-6:
            continue
        lengths = [r4(w.length)] if w.length <= d.tub_alcove_max else list(d.tub_lengths)
        start_convex = corner_convex(walls, (i - 1) % n)
        end_convex = corner_convex(walls, i)
        for tl in lengths:
            ok = free_offsets(
                w, tl, d.tub_depth, bath, keepouts, front=d.tub_front, front_allowed=floor
            )
            for u in ok:
                at_start, at_end = (
                    u <= 1e-6 and start_convex,
                    u + tl >= w.length - 1e-6 and end_convex,
                )
                if at_start or at_end:
                    tub_opts.append((w, float(u), tl))
    if not tub_opts:
        return None
    tw, tu, tl = _pick(rng, tub_opts)
    # other fixtures keep clear of the tub as built (a little longer and deeper than its slot)
    tub_foot = footprint(tw, tu - d.tub_slack, tl + 2 * d.tub_slack, d.tub_depth + d.tub_slack)
    obstacles = list(keepouts) + [tub_foot]

    toilet_opts = _wall_offsets(
        walls, d.toilet_width, d.toilet_depth, bath, obstacles, d.toilet_front, floor, [tub_foot]
    )
    if not toilet_opts:
        return None
    beside = [o for o in toilet_opts if _beside(o, tw, tu, tl, d)]
    if beside and rng.random() < d.toilet_beside_tub:
        toilet_opts = beside
    ow, ou = _pick(rng, toilet_opts)
    toilet_foot = footprint(ow, ou, d.toilet_width, d.toilet_depth)
    obstacles.append(toilet_foot)
    fixed = [tub_foot, toilet_foot]

    vanity = sink = None
    if rng.random() < d.vanity_probability:
        for vw in sorted(d.vanity_widths, reverse=True):
            opts = _wall_offsets(
                walls, vw, d.vanity_depth, vanity_zone, obstacles, d.sink_front, floor, fixed
            )
            if opts:
                w, u = _pick(rng, opts)
                vanity = Place(w.id, u, vw)
                sink = Place(w.id, _sink_offset(rng, u, vw, d), d.sink_width, run=0)
                break
    if sink is None:
        opts = _wall_offsets(
            walls, d.sink_width, d.sink_depth, vanity_zone, obstacles, d.sink_front, floor, fixed
        )
        if not opts:
            return None
        w, u = _pick(rng, opts)
        sink = Place(w.id, u, d.sink_width)
    tub, toilet = Place(tw.id, tu, tl), Place(ow.id, ou, d.toilet_width)
    return bathroom_plan(tub, toilet, sink, vanity, sink_first=True, dims=d)


def plan_fixtures(
    room_type: str,
    walls: Sequence[Wall],
    floor: Polygon,
    rng: np.random.Generator,
    keepouts: Sequence[BaseGeometry] = (),
    zones: Sequence[BaseGeometry | None] = (None, None),
) -> FixturePlan | None:
    """Draw the fixtures a room keeps: a kitchen's or a bathroom's plan, other rooms an empty one.

    Args:
        room_type: the room's type.
        walls: the room's walls.
        floor: the floor polygon.
        rng: source of every random choice.
        keepouts: areas fixtures must not touch (door clearance zones).
        zones: the room's two zones in its spec's order, None for none (the whole floor): a
            kitchen's fixtures go in the first (`work`); a bathroom's bathtub and toilet go in the
            first (`bath`), its sink in the second (`vanity`).

    Returns:
        The plan, or None if the fixtures do not fit (the caller redraws the room or its doors).
    """
    if room_type == "Kitchen":
        return _plan_kitchen(walls, floor, rng, zones[0], keepouts)
    if room_type == "Bathroom":
        return _plan_bathroom(walls, floor, rng, keepouts, zones[0], zones[1])
    return FixturePlan()
