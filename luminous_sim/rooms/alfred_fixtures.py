"""Kitchen and bathroom fixture plans for converted ALFRED rooms, placed where ALFRED's objects are.

Kitchens get CounterTop runs along walls near cabinets, drawers, counters and the sink; the sink
and fridge go where ALFRED's objects are, the stove on a run about 1.5 m from the sink. Bathrooms
get the toilet, sink (in a vanity counter when the scene has a CounterTop) and bathtub where
ALFRED's objects are, or a shower stall when the scene has no bathtub. A fixture whose object has
no position goes where it covers the fewest reachable points (furniture stood there). There is no
randomness: a layout always gives the same plan; None means "use the procedural planner".
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import shapely
from shapely.geometry import Polygon

from luminous_sim.rooms.alfred_data import AlfredLayout
from luminous_sim.rooms.fixtures import BATHROOM, KITCHEN, corner_convex
from luminous_sim.rooms.geometry import r4, snap_down, snap_up
from luminous_sim.rooms.placement import STEP, footprint, free_intervals, free_offsets, nearest_wall
from luminous_sim.rooms.shell import CounterRun, FixturePlan, FixtureSlot, Wall

COUNTER_SUPPORT = ("CounterTop", "Cabinet", "Drawer", "Sink")
COUNTER_REACH = 1.0
COUNTER_PAD = 0.35
FIXTURE_REACH = 1.5
STOVE_SINK_DISTANCE = 1.5
SHOWER_SIZE = 0.9


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
    best, best_key = None, None
    pts = shapely.points(far_from) if len(far_from) else None
    for wi, wall in enumerate(walls):
        for u in free_offsets(wall, width, depth, floor, obstacles, front=front):
            foot = footprint(wall, float(u), width, depth)
            if hint is not None:
                cx, cy = foot.centroid.coords[0]
                key = (math.dist((cx, cy), hint), wi, float(u))
            elif pts is not None:
                dist = shapely.distance(foot, pts)
                key = (int(np.sum(dist < 1e-9)), -round(float(np.min(dist)), 6), wi, float(u))
            else:
                key = (0, 0.0, wi, float(u))
            if best_key is None or key < best_key:
                best, best_key = (wall, r4(float(u))), key
    return best


def _layout_name(walls: Sequence[Wall], run_walls: list[str]) -> str:
    ids = sorted(set(run_walls), key=lambda w: int(w[1:]))
    n = len(walls)
    idx = [int(w[1:]) for w in ids]
    if len(idx) == 1:
        return "I"
    if len(idx) == 2:
        a, b = idx
        wa, wb = walls[a], walls[b]
        dot = wa.direction[0] * wb.direction[0] + wa.direction[1] * wb.direction[1]
        if (b - a) % n in (1, n - 1) and abs(dot) < 1e-6:
            return "L"
        return "galley" if abs(dot) > 0.999 else "other"
    if len(idx) == 3:
        chain = any({i % n, (i + 1) % n, (i + 2) % n} == set(idx) for i in idx)
        return (
            "U"
            if chain and all(corner_convex(walls, i) for i in idx if (i + 1) % n in idx)
            else "other"
        )
    return "other"


def kitchen_plan_from_layout(
    layout: AlfredLayout, walls: Sequence[Wall], floor: Polygon
) -> FixturePlan | None:
    """Counter runs, sink, stove and fridge for a converted kitchen.

    Args:
        layout: the scene's ALFRED data (receptacle positions give the hints).
        walls: the converted room's walls.
        floor: its floor polygon.

    Returns:
        The plan, or None when the hints give no counter run or no room for the appliances.
    """
    d = KITCHEN
    fridge_hint = next(iter(layout.positions("Fridge")), None)
    fw = 0.8
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
    runs: list[CounterRun] = []
    for wid in order:
        wall = by_id[wid]
        a = max(0.0, min(support[wid]) - COUNTER_PAD)
        b = min(wall.length, max(support[wid]) + COUNTER_PAD)
        free = free_intervals(wall, d.counter_depth, floor, obstacles, front=0.6)
        for fa, fb in free:
            lo, hi = max(a, fa), min(b, fb)
            lo, hi = snap_up(lo, STEP), snap_down(hi, STEP)
            if hi - lo >= 0.6 - 1e-6:
                run = CounterRun(
                    id=f"CounterTop_{len(runs)}",
                    wall=wid,
                    start=lo,
                    end=hi,
                    depth=d.counter_depth,
                    height=d.counter_height,
                )
                runs.append(run)
                obstacles.append(footprint(wall, lo, hi - lo, d.counter_depth))
    if not runs:
        return None

    # The sink goes in the run nearest to ALFRED's sink.
    sink_hint = next(iter(layout.positions("Sink")), None)
    sink = None
    run_order = sorted(range(len(runs)), key=lambda i: (-(runs[i].end - runs[i].start), i))
    if sink_hint is not None:

        def run_dist(i: int) -> float:
            r = runs[i]
            return float(
                footprint(by_id[r.wall], r.start, r.end - r.start, r.depth).distance(
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
        u = r4(min(max(round(target / STEP) * STEP, r.start + 0.05), r.end - 0.05 - w))
        sink = FixtureSlot(
            id="Sink_0",
            type="Sink",
            wall=r.wall,
            offset=u,
            width=r4(w),
            depth=d.counter_depth,
            height=d.counter_height,
            counter=r.id,
        )
        break
    if sink is None:
        return None

    # The stove: on a run, clear of the sink, about STOVE_SINK_DISTANCE from it.
    sink_c = shapely.Point(
        footprint(by_id[sink.wall], sink.offset, sink.width, sink.depth).centroid
    )
    best, best_key = None, None
    for sw in d.stove_widths[::-1]:
        for i, r in enumerate(runs):
            wall = by_id[r.wall]
            lo, hi = r.start + 0.05, r.end - 0.05 - sw
            for u in np.round(
                np.arange(math.ceil(lo / STEP - 1e-9), math.floor(hi / STEP + 1e-9) + 1) * STEP, 4
            ):
                if (
                    r.wall == sink.wall
                    and u < sink.offset + sink.width + 0.3 - 1e-6
                    and u + sw > sink.offset - 0.3 + 1e-6
                ):
                    continue
                c = footprint(wall, float(u), sw, d.counter_depth).centroid
                key = (round(abs(c.distance(sink_c) - STOVE_SINK_DISTANCE), 6), i, float(u))
                if best_key is None or key < best_key:
                    best, best_key = (r, float(u), sw), key
        if best is not None:
            break
    if best is None:
        return None
    r, u, sw = best
    stove = FixtureSlot(
        id="StoveBurner_0",
        type="StoveBurner",
        wall=r.wall,
        offset=r4(u),
        width=sw,
        depth=d.counter_depth,
        height=d.counter_height,
        counter=r.id,
    )

    if fridge is None:
        # No position: the fridge takes a free end of the longest run.
        for i in sorted(range(len(runs)), key=lambda i: (-(runs[i].end - runs[i].start), i)):
            rr = runs[i]
            wall = by_id[rr.wall]
            for u_f, new_span in (
                (rr.end - fw, (rr.start, rr.end - fw)),
                (rr.start, (rr.start + fw, rr.end)),
            ):
                inside = all(
                    not (
                        s.counter == rr.id
                        and (
                            s.offset < new_span[0] - 1e-6 or s.offset + s.width > new_span[1] + 1e-6
                        )
                    )
                    for s in (sink, stove)
                )
                offs = free_offsets(wall, fw, d.fridge_depth, floor, [], front=d.fridge_front)
                if inside and np.any(np.isclose(offs, u_f)):
                    fridge = (wall, r4(u_f))
                    runs[i] = rr.model_copy(
                        update={"start": r4(new_span[0]), "end": r4(new_span[1])}
                    )
                    break
            if fridge is not None:
                break
        if fridge is None:
            return None
    fridge_slot = FixtureSlot(
        id="Fridge_0",
        type="Fridge",
        wall=fridge[0].id,
        offset=fridge[1],
        width=fw,
        depth=d.fridge_depth,
        height=d.fridge_height,
    )
    return FixturePlan(
        layout=_layout_name(walls, [r.wall for r in runs]),
        counters=tuple(runs),
        slots=(sink, stove, fridge_slot),
    )


def bathroom_plan_from_layout(
    layout: AlfredLayout, walls: Sequence[Wall], floor: Polygon
) -> FixturePlan | None:
    """Bathtub (or shower stall), toilet and sink (with a vanity counter) for a converted bathroom.

    Args:
        layout: the scene's ALFRED data (receptacle positions give the hints).
        walls: the converted room's walls.
        floor: its floor polygon.

    Returns:
        The plan, or None when a fixture does not fit.
    """
    d = BATHROOM
    pts = layout.points
    slots: list[FixtureSlot] = []
    obstacles: list[Polygon] = []
    if "Bathtub" in layout.objects or layout.positions("Bathtub"):
        hint = next(iter(layout.positions("Bathtub")), None)
        length = 1.6
        if hint is not None:
            near = nearest_wall(walls, hint, FIXTURE_REACH)
            if near is not None and min(d.tub_lengths) <= near[0].length <= d.tub_alcove_max:
                length = r4(near[0].length)
        placed = _slot_near(walls, floor, hint, length, d.tub_depth, obstacles, d.tub_front, pts)
        if placed is None:
            return None
        slots.append(
            FixtureSlot(
                id="Bathtub_0",
                type="Bathtub",
                wall=placed[0].id,
                offset=placed[1],
                width=length,
                depth=d.tub_depth,
                height=d.tub_height,
            )
        )
    else:
        placed = _slot_near(walls, floor, None, SHOWER_SIZE, SHOWER_SIZE, obstacles, 0.5, pts)
        if placed is None:
            return None
        slots.append(
            FixtureSlot(
                id="Shower_0",
                type="Shower",
                wall=placed[0].id,
                offset=placed[1],
                width=SHOWER_SIZE,
                depth=SHOWER_SIZE,
                height=2.0,
            )
        )
    obstacles.append(footprint(placed[0], placed[1], slots[0].width, slots[0].depth))

    placed = _slot_near(
        walls,
        floor,
        next(iter(layout.positions("Toilet")), None),
        d.toilet_width,
        d.toilet_depth,
        obstacles,
        d.toilet_front,
        pts,
    )
    if placed is None:
        return None
    slots.append(
        FixtureSlot(
            id="Toilet_0",
            type="Toilet",
            wall=placed[0].id,
            offset=placed[1],
            width=d.toilet_width,
            depth=d.toilet_depth,
            height=d.toilet_height,
        )
    )
    obstacles.append(footprint(placed[0], placed[1], d.toilet_width, d.toilet_depth))

    sink_hint = next(iter(layout.positions("Sink")), None)
    counters: tuple[CounterRun, ...] = ()
    if "CounterTop" in layout.objects:
        for vw in (1.0, 0.8):
            placed = _slot_near(
                walls, floor, sink_hint, vw, d.vanity_depth, obstacles, d.sink_front, pts
            )
            if placed is not None:
                wall, u = placed
                counters = (
                    CounterRun(
                        id="CounterTop_0",
                        wall=wall.id,
                        start=u,
                        end=r4(u + vw),
                        depth=d.vanity_depth,
                        height=d.vanity_height,
                    ),
                )
                slots.append(
                    FixtureSlot(
                        id="Sink_0",
                        type="Sink",
                        wall=wall.id,
                        offset=r4(u + (vw - d.sink_width) / 2),
                        width=d.sink_width,
                        depth=d.sink_depth,
                        height=d.vanity_height,
                        counter="CounterTop_0",
                    )
                )
                break
    if not counters:
        placed = _slot_near(
            walls, floor, sink_hint, d.sink_width, d.sink_depth, obstacles, d.sink_front, pts
        )
        if placed is None:
            return None
        slots.append(
            FixtureSlot(
                id="Sink_0",
                type="Sink",
                wall=placed[0].id,
                offset=placed[1],
                width=d.sink_width,
                depth=d.sink_depth,
                height=d.vanity_height,
            )
        )
    return FixturePlan(layout="none", counters=counters, slots=tuple(slots))
