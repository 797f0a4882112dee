"""Kitchen and bathroom fixture slots for converted ALFRED rooms, placed where ALFRED's objects are.

One of the two sources of the plan builder `fixture_plan`. Kitchens get CounterTop runs along walls
near cabinets, drawers, counters and the sink; the sink and fridge go where ALFRED's objects are,
the stove on a run about 1.5 m from the sink. Bathrooms get the toilet, sink (in a vanity counter
when the scene has a CounterTop) and bathtub where ALFRED's objects are, or a shower stall when the
scene has no bathtub. A fixture whose object has no position goes where it covers the fewest
reachable points (furniture stood there). There is no randomness: a layout always gives the same
plan; None means "use the procedural planner".
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon

from luminous_sim.rooms.alfred_data import AlfredLayout
from luminous_sim.rooms.fixture_plan import (
    BATHROOM,
    KITCHEN,
    Place,
    Span,
    bathroom_plan,
    centred,
    cut_run_end,
    kitchen_plan,
    layout_name,
    offsets_clear_of,
)
from luminous_sim.rooms.geometry import r4, snap_down, snap_up
from luminous_sim.rooms.placement import STEP, footprint, free_intervals, free_offsets, nearest_wall
from luminous_sim.rooms.shell import FixturePlan, Wall

COUNTER_SUPPORT = ("CounterTop", "Cabinet", "Drawer", "Sink")
COUNTER_REACH = 1.0
COUNTER_PAD = 0.35
FIXTURE_REACH = 1.5
STOVE_SINK_DISTANCE = 1.5
STOVE_SINK_GAP = 0.3
RUN_END_GAP = 0.05
"""Least counter (m) between a sink or stove and its run's end."""
FRIDGE_WIDTH = 0.8
VANITY_WIDTHS = (1.0, 0.8)


def _slot_near(
    walls: Sequence[Wall],
    floor: Polygon,
    hint: tuple[float, float] | None,
    width: float,
    depth: float,
    obstacles: Sequence[Polygon],
    front: float,
    far_from: np.ndarray,
) -> tuple[Wall, float] | None:
    """Place a wall-backed slot closest to `hint`; without one, where it covers the fewest of
    `far_from` (the reachable points) and then lies farthest from them."""
    if hint is not None:
        near = nearest_wall(walls, hint, FIXTURE_REACH)
        if near is not None:
            wall, u, _ = near
            offs = free_offsets(wall, width, depth, floor, obstacles, front=front)
            if len(offs):
                i = int(np.argmin(np.abs(offs + width / 2 - u) + offs * 1e-9))
                if abs(offs[i] + width / 2 - u) <= 1.0:
                    return wall, r4(offs[i])
    best: tuple[Wall, float] | None = None
    best_key: tuple[float, ...] | None = None
    pts = shapely.points(far_from) if len(far_from) else None
    for wi, wall in enumerate(walls):
        for u in free_offsets(wall, width, depth, floor, obstacles, front=front):
            foot = footprint(wall, float(u), width, depth)
            if hint is not None:
                cx, cy = foot.centroid.coords[0]
                key: tuple[float, ...] = (math.dist((cx, cy), hint), wi, float(u))
            elif pts is not None:
                dist = shapely.distance(foot, pts)
                key = (int(np.sum(dist < 1e-9)), -round(float(np.min(dist)), 6), wi, float(u))
            else:
                key = (0, 0.0, wi, float(u))
            if best_key is None or key < best_key:
                best, best_key = (wall, r4(float(u))), key
    return best


def _kitchen_plan(
    layout: AlfredLayout, walls: Sequence[Wall], floor: Polygon
) -> FixturePlan | None:
    """Counter runs, sink, stove and fridge; None when the hints give no counter run or no room
    for the appliances."""
    d = KITCHEN
    fridge_hint = next(iter(layout.positions("Fridge")), None)
    fw = FRIDGE_WIDTH
    fridge = (
        _slot_near(walls, floor, fridge_hint, fw, d.fridge_depth, [], d.fridge_front, layout.points)
        if fridge_hint is not None
        else None
    )
    obstacles = [footprint(fridge[0], fridge[1], fw, d.fridge_depth)] if fridge else []

    support: dict[str, list[float]] = {}
    for t, x, y, _ in layout.receptacles:
        if t in COUNTER_SUPPORT:
            near = nearest_wall(walls, (x, y), COUNTER_REACH)
            if near is not None:
                support.setdefault(near[0].id, []).append(near[1])
    by_id = {w.id: w for w in walls}
    order = sorted(support, key=lambda w: (-len(support[w]), int(w[1:])))
    runs: list[Span] = []
    for wid in order:
        wall = by_id[wid]
        a = max(0.0, min(support[wid]) - COUNTER_PAD)
        b = min(wall.length, max(support[wid]) + COUNTER_PAD)
        free = free_intervals(wall, d.counter_depth, floor, obstacles, front=0.6)
        for fa, fb in free:
            lo, hi = max(a, fa), min(b, fb)
            lo, hi = snap_up(lo, STEP), snap_down(hi, STEP)
            if hi - lo >= 0.6 - 1e-6:
                runs.append(Span(wid, lo, hi))
                obstacles.append(footprint(wall, lo, hi - lo, d.counter_depth))
    if not runs:
        return None

    # The sink goes in the run nearest to ALFRED's sink.
    sink_hint = next(iter(layout.positions("Sink")), None)
    sink = None
    longest_first = sorted(range(len(runs)), key=lambda i: (-(runs[i].end - runs[i].start), i))
    run_order = longest_first
    if sink_hint is not None:

        def run_dist(i: int) -> float:
            r = runs[i]
            return float(
                footprint(by_id[r.wall], r.start, r.end - r.start, d.counter_depth).distance(
                    shapely.Point(sink_hint)
                )
            )

        run_order = sorted(range(len(runs)), key=lambda i: (round(run_dist(i), 6), i))
    for i in run_order:
        r = runs[i]
        w = min(0.8, r4(r.end - r.start - 0.1))
        if w < 0.5:
            continue
        wall = by_id[r.wall]
        target = (
            wall.local([sink_hint])[0][0] - w / 2
            if sink_hint is not None
            else (r.start + r.end - w) / 2
        )
        u = r4(
            min(max(round(target / STEP) * STEP, r.start + RUN_END_GAP), r.end - RUN_END_GAP - w)
        )
        sink = Place(r.wall, u, r4(w), run=i)
        break
    if sink is None:
        return None

    # The stove: on a run, clear of the sink, about STOVE_SINK_DISTANCE from it.
    sink_c = shapely.Point(
        footprint(by_id[sink.wall], sink.offset, sink.width, d.counter_depth).centroid
    )
    best, best_key = None, None
    for sw in d.stove_widths[::-1]:
        for i, r in enumerate(runs):
            wall = by_id[r.wall]
            same_wall = sink if r.wall == sink.wall else None
            lo, hi = r.start + RUN_END_GAP, r.end - RUN_END_GAP
            for u in offsets_clear_of(lo, hi, sw, same_wall, STOVE_SINK_GAP):
                c = footprint(wall, u, sw, d.counter_depth).centroid
                key = (round(abs(c.distance(sink_c) - STOVE_SINK_DISTANCE), 6), i, u)
                if best_key is None or key < best_key:
                    best, best_key = Place(r.wall, r4(u), sw, run=i), key
        if best is not None:
            break
    if best is None:
        return None
    stove = best

    if fridge is None:
        # No position: the fridge takes a free end of the longest run.
        for i in longest_first:
            wall = by_id[runs[i].wall]
            for end in ("end", "start"):
                u_f, rest = cut_run_end(runs[i], end, fw)
                inside = all(
                    s.run != i
                    or (s.offset >= rest.start - 1e-6 and s.offset + s.width <= rest.end + 1e-6)
                    for s in (sink, stove)
                )
                offs = free_offsets(wall, fw, d.fridge_depth, floor, [], front=d.fridge_front)
                if inside and np.any(np.isclose(offs, u_f)):
                    fridge = (wall, u_f)
                    runs[i] = rest
                    break
            if fridge is not None:
                break
        if fridge is None:
            return None
    name = layout_name(walls, [r.wall for r in runs])
    return kitchen_plan(name, runs, sink, stove, Place(fridge[0].id, fridge[1], fw), d)


def _bathroom_plan(
    layout: AlfredLayout, walls: Sequence[Wall], floor: Polygon
) -> FixturePlan | None:
    """Bathtub (or shower stall), toilet and sink (with a vanity counter); None when one of them
    does not fit."""
    d = BATHROOM
    pts = layout.points
    obstacles: list[Polygon] = []
    shower = not ("Bathtub" in layout.objects or layout.positions("Bathtub"))
    if shower:
        width = depth = d.shower_size
        placed = _slot_near(walls, floor, None, width, depth, obstacles, d.shower_front, pts)
    else:
        hint = next(iter(layout.positions("Bathtub")), None)
        width, depth = 1.6, d.tub_depth
        if hint is not None:
            near = nearest_wall(walls, hint, FIXTURE_REACH)
            if near is not None and min(d.tub_lengths) <= near[0].length <= d.tub_alcove_max:
                width = r4(near[0].length)
        placed = _slot_near(walls, floor, hint, width, depth, obstacles, d.tub_front, pts)
    if placed is None:
        return None
    bath = Place(placed[0].id, placed[1], width)
    obstacles.append(footprint(placed[0], placed[1], width, depth))

    toilet_hint = next(iter(layout.positions("Toilet")), None)
    placed = _slot_near(
        walls, floor, toilet_hint, d.toilet_width, d.toilet_depth, obstacles, d.toilet_front, pts
    )
    if placed is None:
        return None
    toilet = Place(placed[0].id, placed[1], d.toilet_width)
    obstacles.append(footprint(placed[0], placed[1], d.toilet_width, d.toilet_depth))

    sink_hint = next(iter(layout.positions("Sink")), None)
    vanity = sink = None
    if "CounterTop" in layout.objects:
        for vw in VANITY_WIDTHS:
            placed = _slot_near(
                walls, floor, sink_hint, vw, d.vanity_depth, obstacles, d.sink_front, pts
            )
            if placed is not None:
                wall, u = placed
                vanity = Place(wall.id, u, vw)
                sink = Place(wall.id, centred(u, vw, d.sink_width), d.sink_width, run=0)
                break
    if sink is None:
        placed = _slot_near(
            walls, floor, sink_hint, d.sink_width, d.sink_depth, obstacles, d.sink_front, pts
        )
        if placed is None:
            return None
        sink = Place(placed[0].id, placed[1], d.sink_width)
    return bathroom_plan(bath, toilet, sink, vanity, shower=shower, dims=d)


def plan_from_layout(
    room_type: str, layout: AlfredLayout, walls: Sequence[Wall], floor: Polygon
) -> FixturePlan | None:
    """The fixtures of a converted room, where ALFRED's objects are: a kitchen's or a bathroom's
    plan, other rooms an empty one.

    Args:
        room_type: the room's type.
        layout: the scene's ALFRED data (receptacle positions give the hints).
        walls: the converted room's walls.
        floor: its floor polygon.

    Returns:
        The plan, or None when the hints give none (the procedural planner then draws one).
    """
    if room_type == "Kitchen":
        return _kitchen_plan(layout, walls, floor)
    if room_type == "Bathroom":
        return _bathroom_plan(layout, walls, floor)
    return FixturePlan()
