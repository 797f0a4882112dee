"""The natural-room rules: each test fails when its rule (data or code) is taken out."""

from __future__ import annotations

import math

import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.cssg import empty_cdf, generate, generate_uniform
from luminous_sim.cssg.natural import alignment_checks, floor_reach, functional_checks, host_checks
from luminous_sim.cssg.requests import requests_from_cdf
from luminous_sim.cssg.tables import fallback_weight, host_weight

SEEDS = range(8)


def _checks(room_type: str, rule: str, seeds=SEEDS) -> list[bool]:
    out = []
    for seed in seeds:
        scene = generate(empty_cdf(room_type), seed=seed).scene
        out += [c.met for c in functional_checks(scene) if c.rule == rule]
    return out


def test_chairs_sit_at_a_table_and_face_it():
    met = _checks("LivingRoom", "seat at a table, facing it", range(12)) + \
        _checks("Kitchen", "seat at a table, facing it", range(12))
    assert len(met) >= 5 and all(met)


def test_a_chair_needs_a_table_to_sit_at():
    doc = cdf.loads("cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects:\n    - {name: c, type: Chair}\n")
    for seed in range(20):
        reqs = requests_from_cdf(empty_cdf("Kitchen"), "Kitchen", np.random.default_rng(seed))
        types = {r.type for r in reqs}
        assert "Chair" not in types or types & {"DiningTable", "Desk"}
    # a chair the CDF asks for is kept whatever else the room has
    assert any(r.type == "Chair" for r in requests_from_cdf(doc, "Kitchen", np.random.default_rng(0)))


def test_the_sofa_faces_the_coffee_table_or_tv():
    met = _checks("LivingRoom", "sofa facing the TV or coffee table")
    assert len(met) == len(SEEDS) and all(met)


def test_armchairs_face_the_seating_group():
    met = _checks("LivingRoom", "armchair facing the seating group", range(12))
    assert len(met) >= 4 and sum(met) >= len(met) - 1


def test_side_tables_stand_at_the_bed_head():
    met = _checks("Bedroom", "side table at the bed's head")
    assert len(met) >= 6 and all(met)
    assert ("at_head_of", "Bed") in _implicit("Bedroom", "SideTable")


def test_the_tv_stand_stands_across_from_the_sofa():
    assert ("across_from", "Sofa") in _implicit("LivingRoom", "TVStand")


def _implicit(room_type: str, subject: str) -> set[tuple[str, str]]:
    """(relation, anchor type) of the implicit rules a default `subject` gets in rooms of this type."""
    out = set()
    for seed in range(10):
        reqs = {r.name: r for r in requests_from_cdf(empty_cdf(room_type), room_type, np.random.default_rng(seed))}
        out |= {(rel.relation, reqs[rel.anchor].type) for r in reqs.values() if r.type == subject
                for rel in r.rels if not rel.explicit and rel.anchor in reqs}
    return out


def test_no_sofa_against_the_dining_table():
    met = _checks("LivingRoom", "sofa clear of the dining table", range(12))
    assert len(met) >= 3 and all(met)


def test_drawer_units_stand_against_a_wall():
    met = _checks("Kitchen", "drawer unit against a wall")
    assert met and all(met)


def test_furniture_leaves_no_dead_zone():
    """Only a piece the room must have (its bed), in a room too small to keep it from, may cut floor off."""
    for room_type in ("Bedroom", "LivingRoom"):
        for seed in SEEDS:
            scene = generate(empty_cdf(room_type), seed=seed).scene
            if floor_reach(scene).share < 0.95:
                bedless = scene.model_copy(update={"objects": tuple(o for o in scene.objects if o.type != "Bed")})
                assert floor_reach(bedless).share >= 0.95, (room_type, seed)


def test_the_l_shaped_demo_bedroom_keeps_its_second_wing():
    """demo seed 0: the bed used to cut the whole second wing off."""
    reach = floor_reach(generate(empty_cdf("Bedroom"), seed=0).scene)
    assert reach.share >= 0.95 and reach.largest_cut_off < 1.0


def test_the_measures_tell_a_random_room_from_a_natural_one():
    from luminous_sim.cssg import choose_room

    shell = choose_room(empty_cdf("LivingRoom"), np.random.default_rng(3))
    uniform = [generate_uniform(shell, seed) for seed in range(4)]
    assert any(not c.met for s in uniform for c in alignment_checks(s))
    assert min(floor_reach(s).share for s in uniform) < 0.95


def test_furniture_is_square_to_the_room():
    for seed in SEEDS:
        checks = alignment_checks(generate(empty_cdf("LivingRoom"), seed=seed).scene)
        assert checks and all(c.met for c in checks)
        assert all(abs(math.remainder(o.yaw, math.pi / 2)) < 1e-4
                   for o in generate(empty_cdf("Bedroom"), seed=seed).scene.objects if o.layer == "furniture")


def test_no_sports_gear_on_a_bed():
    assert host_weight("BasketBall", "Bed") == 0 and fallback_weight("BasketBall", "Bed") == 0
    assert fallback_weight("BasketBall", "SideTable") > 0
    assert host_weight("Knife", "CounterTop") > host_weight("Knife", "Drawer")  # ALFRED's counts
    checks, gear = [], []
    for seed in range(20):
        scene = generate(empty_cdf("Bedroom"), seed=seed).scene
        checks += [c.met for c in host_checks(scene) if c.rule == "not on a host ruled out"]
        by_id = {o.id: o for o in scene.objects}
        gear += [o.parent is None or by_id[o.parent].type != "Bed" for o in scene.objects
                 if o.type in ("BaseballBat", "BasketBall", "TennisRacket")]
    assert checks and all(checks)
    assert len(gear) >= 3 and all(gear)  # on the floor (basketballs) or on a host other than the bed


@pytest.mark.slow
@pytest.mark.parametrize("room_type", ["Kitchen", "LivingRoom", "Bedroom", "Bathroom"])
def test_natural_rules_over_many_seeds(room_type):
    met = total = free = reached = open_rooms = 0
    for seed in range(40):
        scene = generate(empty_cdf(room_type), seed=seed).scene
        checks = functional_checks(scene) + alignment_checks(scene)
        met += sum(c.met for c in checks)
        total += len(checks)
        reach = floor_reach(scene)
        free, reached = free + reach.free, reached + reach.reached
        open_rooms += reach.share >= 0.95
    assert met >= 0.95 * total
    # the goal, pooled as bench_cssg.py reports it; a room's essential piece (bed, sofa) may cut
    # off more where nowhere is clear, so a few rooms fall short (bedroom seed 39: 0.82)
    assert reached >= 0.95 * free
    assert open_rooms >= 0.9 * 40


def _field(relation: str, subject_type: str, anchor_type: str):
    """The relation's cost and heading fields in a 6 x 6 m room, the anchor at its centre facing +y."""
    from shapely.geometry import box

    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg.grid import FloorGrid
    from luminous_sim.cssg.scores import Placed2D, directional_wall_distance, relation_field

    catalog = default_catalog()
    grid = FloorGrid.from_polygon(box(0, 0, 6, 6))
    subject, anchor_entry = catalog.of_type(subject_type)[0], catalog.of_type(anchor_type)[0]
    anchor = Placed2D(anchor_type, 3.0, 3.0, 0.0, anchor_entry)
    cost, heading = relation_field(relation, grid, subject, anchor, directional_wall_distance(grid), (3.0, 3.0))
    return grid, anchor, cost, heading


def test_at_head_of_is_beside_the_head_end_only():
    grid, bed, cost, _ = _field("at_head_of", "SideTable", "Bed")
    hw, hd = bed.half()
    side = bed.x + hw + 0.35
    head, foot = grid.cell(side, bed.center()[1] - hd + 0.25), grid.cell(side, bed.center()[1] + hd - 0.25)
    assert cost[head] < 0.2 < cost[foot]


def test_across_from_is_in_front_of_the_anchor_and_faces_it():
    grid, sofa, cost, heading = _field("across_from", "TVStand", "Sofa")
    front = grid.cell(sofa.x, sofa.y + sofa.half()[1] + 2.0)
    beside = grid.cell(sofa.x + sofa.half()[0] + 1.5, sofa.y)
    behind = grid.cell(sofa.x, sofa.y - sofa.half()[1] - 1.5)
    assert cost[front] < 0.2 < min(cost[beside], cost[behind])
    assert heading[front] == 2  # turned towards -y, to the sofa


def test_face_turns_square_to_the_side_it_stands_at():
    grid, table, cost, heading = _field("face", "Chair", "DiningTable")
    hw, hd = table.half()
    c = table.center()
    # at the long side near its end: turned to the long side (-y), not towards the table's centre (-x)
    at_side = grid.cell(c[0] + hw - 0.3, c[1] + hd + 0.3)
    assert cost[at_side] < 0.15 and heading[at_side] == 2
    off_corner = grid.cell(c[0] + hw + 0.3, c[1] + hd + 0.3)
    assert cost[off_corner] > 0.15


def test_a_small_l_shaped_bedroom_still_gets_its_bed():
    """Bedroom seed 1: no place for the bed keeps all the floor connected; it goes where it cuts off least."""
    scene = generate(empty_cdf("Bedroom"), seed=1).scene
    assert scene.room.shape == "L" and any(o.type == "Bed" for o in scene.objects)
