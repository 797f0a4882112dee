"""Small objects on the hosts ALFRED's scenes use for them, and on the floor where ALFRED puts them: each test
fails when its rule (data or code) is taken out."""

from __future__ import annotations

import importlib.util
import json
from types import SimpleNamespace

import numpy as np
import pytest

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.cssg.natural import floor_object_checks, host_checks
from luminous_sim.cssg.objects import _draw_spot
from luminous_sim.cssg.tables import fallback_weight, floor_relations, floor_share, host_weight, object_hosts
from luminous_sim.scene import blocks_agent
from tests.conftest import REPO

ROOM_HAS_ONE = "on ALFRED's host (room has one)"


def _spot(host_id: str, host_type: str) -> SimpleNamespace:
    return SimpleNamespace(host=SimpleNamespace(id=host_id, type=host_type))


def test_hosts_follow_alfreds_counts_with_no_flat_prior():
    assert host_weight("Knife", "CounterTop") == object_hosts()["Knife"]["CounterTop"] > 0
    assert host_weight("Knife", "Drawer") == 0  # allowed by the compatibility table, never used by ALFRED
    spots = [_spot("CounterTop|1", "CounterTop"), _spot("Drawer|1", "Drawer"), _spot("Drawer|2", "Drawer"),
             _spot("Cabinet|1", "Cabinet")]
    rng = np.random.default_rng(0)
    picks = {_draw_spot(spots, "Knife", True, rng) for _ in range(200)}
    assert picks == {0}


def test_host_weight_is_shared_among_a_types_spots_not_per_instance():
    # ALFRED: Ladle on DiningTable 6, on CounterTop 3; four counter segments must not outweigh the table
    spots = [_spot(f"CounterTop|{i}", "CounterTop") for i in range(4)] + [_spot("DiningTable|1", "DiningTable")]
    rng = np.random.default_rng(1)
    on_table = np.mean([_draw_spot(spots, "Ladle", True, rng) == 4 for _ in range(2000)])
    want = object_hosts()["Ladle"]["DiningTable"] / sum(object_hosts()["Ladle"][t] for t in ("DiningTable",
                                                                                             "CounterTop"))
    assert abs(on_table - want) < 0.05


def test_backs_off_to_overall_receptacle_frequencies_where_no_alfred_host_is_there():
    # ALFRED puts cell phones only on dressers; in a room without one, the usual hosts of anything weigh in
    spots = [_spot("Desk|1", "Desk"), _spot("Safe|1", "Safe")]
    assert host_weight("CellPhone", "Desk") == host_weight("CellPhone", "Safe") == 0
    assert fallback_weight("CellPhone", "Desk") > fallback_weight("CellPhone", "Safe") > 0
    rng = np.random.default_rng(2)
    assert np.mean([_draw_spot(spots, "CellPhone", True, rng) == 0 for _ in range(500)]) > 0.6
    assert _draw_spot(spots, "CellPhone", False, np.random.default_rng(3)) in (0, 1)


@pytest.mark.parametrize("room_type", ["Kitchen", "LivingRoom", "Bedroom", "Bathroom"])
def test_small_objects_go_where_alfred_puts_them_when_the_room_has_such_a_host(room_type):
    met = [c.met for seed in range(6) for c in host_checks(generate(empty_cdf(room_type), seed=seed).scene)
           if c.rule == ROOM_HAS_ONE]
    assert len(met) >= 10 and sum(met) >= 0.9 * len(met)


def test_hand_towels_hang_on_their_holder():
    on_holder = total = 0
    for seed in range(6):
        scene = generate(empty_cdf("Bathroom"), seed=seed).scene
        by_id = {o.id: o for o in scene.objects}
        for o in scene.objects:
            if o.type == "HandTowel" and o.parent:
                total += 1
                on_holder += by_id[o.parent].type == "HandTowelHolder"
    assert total >= 3 and on_holder == total


def test_floor_types_and_shares_come_from_alfred():
    assert floor_relations("BasketBall") and floor_relations("Plunger") and not floor_relations("Apple")
    assert floor_share("Plunger") == 1.0 and 0.5 < floor_share("BasketBall") < 1.0
    assert not floor_relations("BaseballBat")  # lying flat it is out of the agent's reach


def test_plungers_and_scrub_brushes_stand_on_the_floor_against_a_wall():
    catalog = default_catalog()
    found = set()
    for seed in range(3):
        scene = generate(empty_cdf("Bathroom"), seed=seed).scene
        loose = [o for o in scene.objects if o.layer == "object" and o.parent is None]
        found |= {o.type for o in loose}
        assert all(not o.fixed and abs(o.position[2] + catalog.for_object(o).bbox_min[2]) < 1e-3 for o in loose)
        assert all(blocks_agent(o, catalog.for_object(o)) for o in loose)  # the agent walks around them
        checks = floor_object_checks(scene, catalog)
        assert len(checks) == len(loose) and all(c.met for c in checks)
    assert {"Plunger", "ScrubBrush"} <= found


def test_a_basketball_on_the_floor_is_in_a_corner_or_against_a_wall():
    met = []
    for seed in range(8):
        scene = generate(empty_cdf("Bedroom"), seed=seed).scene
        met += [c.met for c in floor_object_checks(scene) if c.subject.startswith("BasketBall")]
    assert len(met) >= 2 and all(met)


def test_shipped_host_counts_are_what_the_script_makes(shared_alfred, tmp_path):
    spec = importlib.util.spec_from_file_location("alfred_host_counts", REPO / "scripts" / "alfred_host_counts.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    pairs, loose, n = mod.count(shared_alfred / "valid_seen")
    assert n == 251 and pairs[("Knife", "CounterTop")] == object_hosts()["Knife"]["CounterTop"]
    assert ("Pan", "Pan") not in pairs  # the receptacle the planner records, not where the agent walked to
    shipped = json.loads((REPO / "luminous_sim" / "cssg" / "data" / "object_hosts.json").read_text())
    assert sum(pairs.values()) == sum(sum(v.values()) for v in shipped["hosts"].values())
    assert loose["BaseballBat"] == shipped["floor"]["BaseballBat"]["picked_up_from_floor"] >= 1
