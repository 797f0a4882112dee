"""Stools at a counter: bar-stool Chair variants, drawn only for a chair at a kitchen counter, standing at the
counter's front and facing it. Each test fails when its rule (data or code) is taken out."""

from __future__ import annotations

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.cssg.natural import functional_checks
from luminous_sim.cssg.requests import Request, rule_tags

STOOL = "stool at a counter, facing it"


def _stools(scene) -> list:
    catalog = default_catalog()
    return [o for o in scene.objects if o.type == "Chair" and set(catalog.for_object(o).tags) & rule_tags()]


def test_bar_stools_are_counter_height_chair_variants():
    catalog = default_catalog()
    stools = [e for e in catalog.of_type("Chair") if "bar_stool" in e.tags]
    assert len(stools) == 3 and rule_tags() == {"bar_stool"}
    for e in stools:
        seat = next(r for r in e.regions if r["name"] == "seat")
        assert 0.6 <= seat["center"][2] <= 0.7 and e.dims[2] >= 0.6  # for a 0.9 m counter


def test_a_chair_draws_a_bar_stool_only_when_a_rule_asks_for_one():
    catalog = default_catalog()
    plain = Request("chair", "Chair", "furniture", False).variants(catalog)
    at_counter = Request("chair", "Chair", "furniture", False, tag="bar_stool").variants(catalog)
    assert plain and not any("bar_stool" in e.tags for e in plain)
    assert at_counter and all("bar_stool" in e.tags for e in at_counter)
    named = Request("chair", "Chair", "furniture", True, asset="Chair_06").variants(catalog)
    assert [e.id for e in named] == ["Chair_06"]  # a CDF naming the asset gets it


def test_stools_stand_at_the_counter_front_in_kitchens_without_a_table():
    met, with_table = [], 0
    for seed in range(24):
        scene = generate(empty_cdf("Kitchen"), seed=seed).scene
        stools = _stools(scene)
        if any(o.type in ("DiningTable", "Desk") for o in scene.objects):
            with_table += 1
            assert not stools  # chairs at the dining table are ordinary chairs
        met += [c.met for c in functional_checks(scene) if c.rule == STOOL]
        assert len(met) >= len(stools)
    assert with_table >= 3 and len(met) >= 3 and all(met)


def test_no_bar_stools_outside_kitchens():
    for room_type in ("LivingRoom", "Bedroom"):
        for seed in range(6):
            assert not _stools(generate(empty_cdf(room_type), seed=seed).scene)


def test_a_stool_leaves_the_rest_of_the_floor_to_the_furniture_after_it():
    import numpy as np

    from luminous_sim.cssg.draft import SceneDraft
    from luminous_sim.cssg.furniture import FloorContext
    from luminous_sim.cssg.pipeline import choose_room
    from luminous_sim.cssg.structure import place_fixtures

    for seed in range(12):
        rng = np.random.default_rng(seed)
        shell = choose_room(empty_cdf("Kitchen"), rng)
        draft = SceneDraft(shell, default_catalog(), rng)
        place_fixtures(draft)
        ctx = FloorContext.create(draft)
        if not ctx.seat_zone.any():
            continue
        free = ctx.grid.free.copy()
        with ctx.seat_zone_open(Request("stool", "Chair", "furniture", False, tag="bar_stool")):
            assert not (ctx.grid.free & ~ctx.seat_zone).any()  # only the counters' work zone is open
        assert (ctx.grid.free == free).all()
        return
    raise AssertionError("no kitchen with a seat zone in 12 seeds")
