"""The fixture-plan builder: places chosen along walls become a kitchen's or bathroom's FixturePlan.

Two sources propose the places: `fixtures` (procedural rooms: drawn from the free wall stretches
with the rng) and `alfred_fixtures` (converted AI2-THOR rooms: where ALFRED's objects are). A source
decides *where* each fixture goes (a wall, an offset, a width); this module decides *what* stands
there (ids, types, depths and heights from `KITCHEN` and `BATHROOM`, which counter run holds a sink
or stove, the layout's name) and holds the placement rules both sources follow: offsets on a 5 cm
grid, a stove kept clear of the sink, a fridge cut from a counter run's free end, a sink centred in
its vanity.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from luminous_sim.rooms.geometry import r4
from luminous_sim.rooms.placement import STEP, corner_convex
from luminous_sim.rooms.shell import CounterRun, FixturePlan, FixtureSlot, SlotType, Wall


@dataclass(frozen=True)
class KitchenDims:
    """Kitchen fixture sizes, metres."""

    counter_depth: float = 0.6
    counter_height: float = 0.9
    aisle: float = 1.0
    sink_widths: tuple[float, ...] = (0.6, 0.8, 0.9)
    stove_widths: tuple[float, ...] = (0.6, 0.75)
    fridge_widths: tuple[float, ...] = (0.75, 0.8, 0.9)
    fridge_depth: float = 0.7
    fridge_height: float = 1.8
    fridge_front: float = 0.9
    end_gap: float = 0.1
    stove_side: float = 0.3
    sink_stove_gap: float = 0.4
    min_run: float = 1.2


@dataclass(frozen=True)
class BathroomDims:
    """Bathroom fixture sizes, metres."""

    tub_lengths: tuple[float, ...] = (1.5, 1.6, 1.7)
    tub_alcove_max: float = 1.85
    tub_depth: float = 0.75
    tub_height: float = 0.55
    tub_front: float = 0.6
    tub_slack: float = 0.05
    """How far (m) a bathtub may stick out of its slot: our tubs are a few cm longer and deeper."""
    toilet_width: float = 0.75
    toilet_depth: float = 0.7
    toilet_height: float = 0.8
    toilet_front: float = 0.55
    toilet_beside_tub: float = 0.75
    """Probability that the toilet stands right beside the bathtub, on its wall, given room."""
    beside_gap: float = 0.1
    """Most floor (m) left between a toilet and the bathtub it stands beside."""
    sink_width: float = 0.6
    sink_depth: float = 0.5
    vanity_widths: tuple[float, ...] = (0.8, 1.0, 1.2, 1.35)
    vanity_counter: float = 0.7
    """Least vanity length (m) beside the sink for a counter segment: a vanity this much wider
    than the sink has its sink at one end and a counter top along the rest."""
    vanity_depth: float = 0.55
    vanity_height: float = 0.85
    vanity_probability: float = 0.7
    sink_front: float = 0.6
    shower_size: float = 0.9
    """Side (m) of a square shower stall (converted bathrooms without a bathtub)."""
    shower_height: float = 2.0
    shower_front: float = 0.5


KITCHEN = KitchenDims()
BATHROOM = BathroomDims()


@dataclass(frozen=True)
class Span:
    """A counter run's stretch [start, end] along a wall."""

    wall: str
    start: float
    end: float


@dataclass(frozen=True)
class Place:
    """Where a fixture goes: `width` along `wall` from `offset`; `run` indexes its counter run."""

    wall: str
    offset: float
    width: float
    run: int | None = None


def offset_grid(a: float, b: float, width: float) -> np.ndarray:
    """Offsets u on the STEP grid with [u, u + width] inside [a, b] (tolerant of float noise)."""
    lo, hi = np.ceil(a / STEP - 1e-9), np.floor((b - width) / STEP + 1e-9)
    return np.round(np.arange(lo, hi + 1) * STEP, 4) if hi >= lo else np.zeros(0)


def offsets_clear_of(
    a: float, b: float, width: float, other: Place | None, gap: float
) -> list[float]:
    """`offset_grid(a, b, width)` less the offsets within `gap` of `other` (a sink), if given."""
    out = []
    for u in offset_grid(a, b, width):
        if other is None or (
            u + width <= other.offset - gap + 1e-6 or u >= other.offset + other.width + gap - 1e-6
        ):
            out.append(float(u))
    return out


def cut_run_end(span: Span, end: str, width: float) -> tuple[float, Span]:
    """A fixture `width` wide at the `end` ("start" or "end") of a counter run: its offset, and the
    run that is left."""
    if end == "start":
        return span.start, Span(span.wall, r4(span.start + width), span.end)
    offset = r4(span.end - width)
    return offset, Span(span.wall, span.start, offset)


def centred(offset: float, width: float, inner: float) -> float:
    """Offset of something `inner` wide centred in [offset, offset + width]."""
    return r4(offset + (width - inner) / 2)


def layout_name(walls: Sequence[Wall], run_walls: Sequence[str]) -> str:
    """The layout that counter runs on these walls form: I, L, U, galley (facing) or other."""
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
        convex = all(corner_convex(walls, i) for i in idx if (i + 1) % n in idx)
        return "U" if chain and convex else "other"
    return "other"


def _counter_id(i: int) -> str:
    return f"CounterTop_{i}"


def _slot(kind: SlotType, place: Place, depth: float, height: float) -> FixtureSlot:
    """The slot `<kind>_0` at `place`, held by counter run `place.run` if given."""
    return FixtureSlot(
        id=f"{kind}_0",
        type=kind,
        wall=place.wall,
        offset=place.offset,
        width=place.width,
        depth=depth,
        height=height,
        counter=None if place.run is None else _counter_id(place.run),
    )


def kitchen_plan(
    layout: str,
    runs: Sequence[Span],
    sink: Place,
    stove: Place,
    fridge: Place,
    dims: KitchenDims = KITCHEN,
) -> FixturePlan:
    """The kitchen plan: counter runs `CounterTop_<i>`, a sink and a stove in runs, a fridge.

    Args:
        layout: the layout's name (`layout_name`, or the procedural layout drawn).
        runs: the counter runs, in id order.
        sink: the sink's place; its `run` indexes `runs`.
        stove: the stove's place; its `run` indexes `runs`.
        fridge: the fridge's place (free-standing).
        dims: fixture sizes.
    """
    d = dims
    counters = tuple(
        CounterRun(
            id=_counter_id(i),
            wall=r.wall,
            start=r.start,
            end=r.end,
            depth=d.counter_depth,
            height=d.counter_height,
        )
        for i, r in enumerate(runs)
    )
    slots = (
        _slot("Sink", sink, d.counter_depth, d.counter_height),
        _slot("StoveBurner", stove, d.counter_depth, d.counter_height),
        _slot("Fridge", fridge, d.fridge_depth, d.fridge_height),
    )
    return FixturePlan(layout=layout, counters=counters, slots=slots)  # type: ignore[arg-type]


def bathroom_plan(
    bath: Place,
    toilet: Place,
    sink: Place,
    vanity: Place | None = None,
    shower: bool = False,
    sink_first: bool = False,
    dims: BathroomDims = BATHROOM,
) -> FixturePlan:
    """The bathroom plan: a bathtub (or shower stall), a toilet, a sink (in a vanity, if any).

    Args:
        bath: the bathtub's place (or the stall's, with `shower`).
        toilet: the toilet's place.
        sink: the sink's place; `run=0` when it stands in `vanity`.
        vanity: the vanity counter `CounterTop_0`, or None for a free-standing sink.
        shower: a square shower stall instead of a bathtub.
        sink_first: list the sink slot first (the procedural rooms' order; converted rooms list it
            last, and both orders are kept so that the committed rooms stay byte-for-byte).
        dims: fixture sizes.
    """
    d = dims
    counters: tuple[CounterRun, ...] = ()
    if vanity is not None:
        counters = (
            CounterRun(
                id=_counter_id(0),
                wall=vanity.wall,
                start=vanity.offset,
                end=r4(vanity.offset + vanity.width),
                depth=d.vanity_depth,
                height=d.vanity_height,
            ),
        )
    if shower:
        bath_slot = _slot("Shower", bath, d.shower_size, d.shower_height)
    else:
        bath_slot = _slot("Bathtub", bath, d.tub_depth, d.tub_height)
    toilet_slot = _slot("Toilet", toilet, d.toilet_depth, d.toilet_height)
    sink_slot = _slot("Sink", sink, d.sink_depth, d.vanity_height)
    slots = (
        (sink_slot, bath_slot, toilet_slot) if sink_first else (bath_slot, toilet_slot, sink_slot)
    )
    return FixturePlan(layout="none", counters=counters, slots=slots)
