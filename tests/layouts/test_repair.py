"""Imported layouts go through CSSG's validation: overlaps, pieces outside the room and blocked doors are
repaired by the least movement or the layout is rejected with reasons; the object layer furnishes it."""

from __future__ import annotations

import json

import numpy as np
import pytest

from luminous_sim import layouts, tasks
from luminous_sim.layouts import import_atiss, import_front, loads, realize
from luminous_sim.scene import footprint
from tests.layouts.helpers import ATISS, FRONT, MODEL_INFO


@pytest.fixture(scope="module")
def kitchen():
    return realize(import_front(FRONT, model_info=MODEL_INFO), seed=0)


def test_the_imported_kitchen_is_repaired_and_accepted(kitchen):
    assert kitchen.ok and kitchen.problems() == []
    moved = {r.key: r for r in kitchen.given.repairs if r.action == "moved"}
    assert set(moved) == {"furniture/8", "furniture/9"}
    assert moved["furniture/8"].reason == "overlaps furniture/3" and 0 < moved["furniture/8"].distance < 1.0
    assert moved["furniture/9"].reason == "blocks door Door_0"
    report = kitchen.given.generated.report
    assert report.overlaps == [] and report.unreachable == [] and report.ok
    assert [u["category"] for u in kitchen.unmatched] == ["Pendant Lamp"]


def test_moved_pieces_keep_clear_of_the_door_and_each_other(kitchen):
    from luminous_sim.assets.catalog import default_catalog

    scene = kitchen.given.generated.scene
    catalog = default_catalog()
    zone = scene.room.door_clearance_zones()[0]
    floor = [o for o in scene.objects if o.parent is None and o.layer in ("furniture", "fixture")]
    feet = [footprint(catalog.for_object(o), o.position[0], o.position[1], o.yaw) for o in floor]
    assert all(f.intersection(zone).area < 1e-4 for f in feet)
    assert all(scene.room.polygon().buffer(1e-3).contains(f) for f in feet)


def test_the_object_layer_furnishes_it_and_a_task_is_feasible(kitchen):
    scene = kitchen.given.generated.scene
    types = {o.type for o in scene.objects}
    assert {"SinkBasin", "Faucet"} <= types  # the sink's parts, which the layout does not give
    assert any(o.layer == "object" and o.parent for o in scene.objects)
    state = tasks.state_from_scene(scene)
    feasible = tasks.feasible_task_types(scene, state)
    assert "pick_and_place_simple" in feasible and "pick_cool_then_place_in_recep" in feasible
    task = tasks.sample_task(scene, state, "pick_cool_then_place_in_recep", np.random.default_rng(0))
    assert task.params


def test_required_objects_are_added():
    layout = import_front(FRONT, model_info=MODEL_INFO)
    got = realize(layout, seed=0, defaults=False, required=("Apple", "Mug"))
    types = [o.type for o in got.given.generated.scene.objects]
    assert types.count("Apple") == 1 and types.count("Mug") == 1 and got.ok
    assert {"apple_required", "mug_required"} <= set(got.given.generated.report.required)


def test_the_same_layout_and_seed_give_the_same_scene(kitchen):
    again = realize(import_front(FRONT, model_info=MODEL_INFO), seed=0)
    assert again.given.generated.scene.to_json() == kitchen.given.generated.scene.to_json()


def test_without_repair_the_problems_are_reported():
    got = realize(import_front(FRONT, model_info=MODEL_INFO), seed=0, repair=False)
    assert not got.ok and any("overlaps" in p for p in got.problems())
    assert not [r for r in got.given.repairs if r.action == "moved"]


def test_the_imported_bedroom_is_accepted():
    got = realize(import_atiss(ATISS), seed=0)
    assert got.ok, got.problems()
    assert [r.key for r in got.given.repairs if r.action == "moved"] == ["box_5"]
    assert {m["type"] for m in got.matches} == {"Bed", "SideTable", "Dresser", "Desk", "Chair"}


def test_a_layout_that_cannot_be_repaired_is_rejected_with_reasons():
    room = {"name": "tiny", "room_type": "Bedroom", "outline": [[0, 0], [2.4, 0], [2.4, 2.4], [0, 2.4]]}
    beds = [{"id": f"bed{i}", "category": "double bed", "size": [1.6, 2.1, 0.9], "position": [1.2, 1.2, 0.45]}
            for i in range(2)]
    got = realize(loads(json.dumps({"room": room, "objects": beds})), seed=0)
    assert not got.ok
    assert any(p.startswith("bed1 (Bed): overlaps bed0") and "no free place" in p for p in got.problems())
    assert got.to_dict()["accepted"] is False


def test_pieces_outside_the_room_are_pulled_in():
    room = {"name": "r", "room_type": "LivingRoom", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]]}
    sofa = {"id": "sofa", "category": "sofa", "size": [2.0, 0.9, 0.8], "position": [3.6, 2.0, 0.4], "yaw": 1.5708}
    got = realize(loads(json.dumps({"room": room, "objects": [sofa]})), seed=0, defaults=False)
    (move,) = [r for r in got.given.repairs if r.action == "moved"]
    assert move.reason == "outside the room" and move.distance < 0.6 and got.ok
    assert layouts.MAX_SCALE >= got.matches[0]["scale"] >= layouts.MIN_SCALE
