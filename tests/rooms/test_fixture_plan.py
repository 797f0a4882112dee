"""The fixture-plan builder both sources (procedural, converted) feed, and its shared placement rules."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Polygon

from luminous_sim.rooms.alfred_fixtures import plan_from_layout
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
    offset_grid,
    offsets_clear_of,
)
from luminous_sim.rooms.fixtures import plan_fixtures
from luminous_sim.rooms.shell import walls_from_outline

SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]


def test_offset_grid_keeps_the_width_inside_the_bounds():
    assert offset_grid(0.12, 1.0, 0.6).tolist() == [0.15, 0.2, 0.25, 0.3, 0.35, 0.4]
    assert offset_grid(0.0, 0.55, 0.6).size == 0
    # float noise on a grid point does not drop it
    assert offset_grid(0.1 + 1e-12, 0.7 - 1e-12, 0.6).tolist() == [0.1]


def test_offsets_clear_of_keep_the_gap_to_the_other_fixture():
    sink = Place("w0", 1.0, 0.6)
    us = offsets_clear_of(0.0, 3.0, 0.6, sink, 0.4)
    assert us and all(u + 0.6 <= 0.6 + 1e-6 or u >= 2.0 - 1e-6 for u in us)
    assert 0.0 in us and 2.0 in us and 1.95 not in us and 0.05 not in us
    assert offsets_clear_of(0.0, 3.0, 0.6, None, 0.4) == offset_grid(0.0, 3.0, 0.6).tolist()


def test_cut_run_end_takes_the_width_from_either_end():
    run = Span("w1", 0.6, 3.0)
    assert cut_run_end(run, "start", 0.8) == (0.6, Span("w1", 1.4, 3.0))
    assert cut_run_end(run, "end", 0.8) == (2.2, Span("w1", 0.6, 2.2))


def test_centred():
    assert centred(1.0, 1.0, 0.6) == 1.2


def test_layout_names():
    walls = walls_from_outline(SQUARE)
    assert layout_name(walls, ["w2"]) == "I"
    assert layout_name(walls, ["w0", "w1", "w0"]) == "L"
    assert layout_name(walls, ["w0", "w2"]) == "galley"
    assert layout_name(walls, ["w3", "w0", "w1"]) == "U"


def test_kitchen_plan_links_sink_and_stove_to_their_runs():
    runs = [Span("w0", 0.0, 2.4), Span("w1", 0.6, 2.0)]
    plan = kitchen_plan(
        "L",
        runs,
        sink=Place("w0", 0.5, 0.8, run=0),
        stove=Place("w1", 1.0, 0.6, run=1),
        fridge=Place("w2", 0.0, 0.8),
    )
    assert plan.layout == "L"
    assert [(c.id, c.wall, c.span) for c in plan.counters] == [
        ("CounterTop_0", "w0", (0.0, 2.4)),
        ("CounterTop_1", "w1", (0.6, 2.0)),
    ]
    assert all(c.depth == KITCHEN.counter_depth for c in plan.counters)
    assert [(s.id, s.type, s.counter) for s in plan.slots] == [
        ("Sink_0", "Sink", "CounterTop_0"),
        ("StoveBurner_0", "StoveBurner", "CounterTop_1"),
        ("Fridge_0", "Fridge", None),
    ]
    fridge = plan.slot("Fridge")
    assert fridge is not None
    assert (fridge.depth, fridge.height) == (KITCHEN.fridge_depth, KITCHEN.fridge_height)


@pytest.mark.parametrize("sink_first", [False, True])
def test_bathroom_plan_vanity_shower_and_slot_order(sink_first):
    plan = bathroom_plan(
        bath=Place("w0", 0.0, BATHROOM.shower_size),
        toilet=Place("w1", 1.0, BATHROOM.toilet_width),
        sink=Place("w2", 1.2, BATHROOM.sink_width, run=0),
        vanity=Place("w2", 1.0, 1.0),
        shower=True,
        sink_first=sink_first,
    )
    order = ["Sink", "Shower", "Toilet"] if sink_first else ["Shower", "Toilet", "Sink"]
    assert [s.type for s in plan.slots] == order
    (vanity,) = plan.counters
    assert (vanity.id, vanity.span, vanity.depth) == (
        "CounterTop_0",
        (1.0, 2.0),
        BATHROOM.vanity_depth,
    )
    assert plan.slot("Sink").counter == "CounterTop_0"
    shower = plan.slot("Shower")
    assert (shower.width, shower.depth, shower.height) == (0.9, 0.9, BATHROOM.shower_height)
    tub = bathroom_plan(Place("w0", 0, 1.6), Place("w1", 1, 0.75), Place("w2", 1, 0.6)).slot(
        "Bathtub"
    )
    assert tub is not None and (tub.depth, tub.height) == (BATHROOM.tub_depth, BATHROOM.tub_height)


def test_rooms_without_fixtures_get_an_empty_plan_from_either_source():
    walls, floor = walls_from_outline(SQUARE), Polygon(SQUARE)
    rng = np.random.default_rng(0)
    state = rng.bit_generator.state
    for room_type in ("LivingRoom", "Bedroom"):
        assert plan_fixtures(room_type, walls, floor, rng) == plan_from_layout(
            room_type, None, walls, floor
        )
        assert not plan_fixtures(room_type, walls, floor, rng).slots
    assert rng.bit_generator.state == state  # nothing drawn


@pytest.mark.parametrize("room_type", ["Kitchen", "Bathroom"])
def test_procedural_plans_hold_their_fixtures_in_their_own_counters(room_type):
    walls, floor = walls_from_outline(SQUARE), Polygon(SQUARE)
    plans = [plan_fixtures(room_type, walls, floor, np.random.default_rng(s)) for s in range(10)]
    assert sum(p is not None for p in plans) >= 5
    for seed, plan in enumerate(plans):
        if plan is None:
            continue
        assert plan == plan_fixtures(room_type, walls, floor, np.random.default_rng(seed))
        walls_of = {c.id: c.wall for c in plan.counters}
        for slot in plan.slots:
            if slot.counter is not None:
                run = next(c for c in plan.counters if c.id == slot.counter)
                assert slot.wall == walls_of[slot.counter]
                assert run.start - 1e-6 <= slot.offset <= slot.offset + slot.width <= run.end + 1e-6
