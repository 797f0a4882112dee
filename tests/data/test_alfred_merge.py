"""The merge operator: hand-made trajectories of one floor plan that disagree, and every valid_seen floor plan."""

from __future__ import annotations

import pytest

from luminous_sim.data import AlfredParseError, merge_by_floor_plan, merge_parses, parse_alfred
from luminous_sim.data.alfred_merge import is_large
from luminous_sim.data.alfred_parser import match_instance, thor_position
from tests.data.alfred_traj import coord, oid, pickup, put, traj

PLAN = "FloorPlan1"
APPLE = oid("Apple", 1.0, 0.95, 0.5)
FRIDGE = oid("Fridge", -1.0, 0.0, 2.0)
COUNTER = coord("CounterTop", 1.0, 0.9, 0.4)
PLATE = oid("Plate", 0.5, 0.9, 0.5)


def _apple_from(source, task_id, put_into=FRIDGE, plan=PLAN, **kw):
    data = traj("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Fridge"}, plan,
                [pickup(APPLE, source), put(APPLE, put_into)], task_id=task_id, **kw)
    return parse_alfred(data, source=f"{task_id}.json")


def _relations(merged):
    return {(r.subject, r.relation, r.target) for r in merged.cdf.scene.relations}


def test_most_common_placement_wins_and_the_conflict_is_reported():
    fridge_coord = coord("Fridge", -1.0, 0.0, 2.0)
    micro = oid("Microwave", 0.5, 1.2, -1.0)
    parses = [_apple_from(COUNTER, "a"), _apple_from(COUNTER, "b", put_into=micro),
              _apple_from(fridge_coord, "c", put_into=micro)]
    merged = merge_parses(parses)
    assert _relations(merged) == {("apple", "on", "counter_top")}
    (conflict,) = merged.conflicts
    assert conflict.object == "apple" and conflict.key == APPLE and conflict.about == "placement"
    assert conflict.options == (("on counter_top", 2), ("in fridge", 1))
    assert conflict.chosen == "on counter_top" and conflict.resolution.startswith("most common (2 of 3")
    # large furniture from every trajectory is kept, matched across them by instance (the fridge once)
    types = sorted(o.type for o in merged.cdf.scene.objects)
    assert types == ["Apple", "CounterTop", "Fridge", "Microwave"]
    assert merged.cdf.task is None and {n.field for n in merged.notes} >= {"task", "task.agent"}


def test_tie_goes_to_large_furniture_and_state_ties_are_left_unset():
    a = _apple_from(coord("Plate", 0.5, 0.9, 0.5), "a")
    b = _apple_from(COUNTER, "b")
    lamp = oid("DeskLamp", 1, 0.8, 1)
    book = oid("Book", 0, 0.5, 0)

    def look(task_id, on):
        data = traj("look_at_obj_in_light", {"object_target": "Book", "toggle_target": "DeskLamp"}, "FloorPlan301",
                    [pickup(book, coord("Bed", 0, 0.4, 0)), {"action": "ToggleObject", "objectId": lamp}],
                    toggles=[{"isOn": on, "objectType": "DeskLamp"}], task_id=task_id)
        return parse_alfred(data, source=task_id)

    merged = merge_parses([a, b])
    assert ("apple", "on", "counter_top") in _relations(merged) and is_large("CounterTop") and not is_large("Plate")
    (conflict,) = merged.conflicts
    assert conflict.resolution.startswith("tie; kept the one on large furniture")
    merged = merge_parses([look("x", False), look("y", True)])
    (conflict,) = merged.conflicts
    assert conflict.about == "state.isToggled" and conflict.chosen == "unset"
    lamp_spec = merged.cdf.object_named("desk_lamp")
    assert lamp_spec.state is None or lamp_spec.state.isToggled is None
    merged = merge_parses([look("x", False), look("y", True), look("z", False)])
    assert merged.cdf.object_named("desk_lamp").state.isToggled is False
    assert merged.conflicts[0].chosen == "false"


def test_furniture_union_position_matching_and_placeholders():
    cab1, cab2 = oid("Cabinet", 0.3, 1.5, 2.0), oid("Cabinet", 1.3, 1.5, 2.0)
    mug = oid("Mug", 0.3, 1.5, 2.1)

    def mug_from(cabinet_xyz, task_id, knife=False):
        high = [pickup(mug, coord("Cabinet", *cabinet_xyz)), put(mug, FRIDGE)]
        if knife:
            high.insert(0, pickup(oid("Knife", 2, 0.9, 2), COUNTER))
        data = traj("pick_and_place_simple", {"object_target": "Mug", "parent_target": "Fridge"}, PLAN, high,
                    task_id=task_id)
        return parse_alfred(data, source=task_id)

    sliced = traj("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Fridge",
                                            "object_sliced": True}, PLAN,
                  [pickup(oid("Apple", 1, 0.9, 1, "AppleSliced_1"), COUNTER)], task_id="s")
    parses = [mug_from((0.3, 1.5, 2.0), "a"), mug_from((1.3, 1.5, 2.0), "b"),
              mug_from((0.302, 1.497, 2.003), "c"), parse_alfred(sliced, source="s")]
    merged = merge_parses(parses)
    assert {merged.keys["cabinet"], merged.keys["cabinet_2"]} == {cab1, cab2} and "cabinet_3" not in merged.keys
    assert merged.conflicts[0].options == (("in cabinet", 2), ("in cabinet_2", 1))
    # the sliced task's knife is needed by type only: one Knife placeholder
    assert [o.type for o in merged.cdf.scene.objects].count("Knife") == 1
    assert any("needed by type only" in n.reason for n in merged.notes)
    # with a concrete knife in another trajectory, no placeholder is added
    merged = merge_parses([*parses, mug_from((0.3, 1.5, 2.0), "d", knife=True)])
    assert [o.type for o in merged.cdf.scene.objects].count("Knife") == 1
    assert merged.keys["knife"] == oid("Knife", 2, 0.9, 2)


def test_merge_refuses_mixed_floor_plans_and_nothing():
    with pytest.raises(AlfredParseError, match="several floor plans"):
        merge_parses([_apple_from(COUNTER, "a"), _apple_from(COUNTER, "b", plan="FloorPlan2")])
    with pytest.raises(AlfredParseError, match="no parsed trajectories"):
        merge_parses([])


def test_merge_is_order_independent():
    parses = [_apple_from(COUNTER, "a"), _apple_from(coord("Fridge", -1.0, 0.0, 2.0), "b")]
    assert merge_parses(parses).cdf == merge_parses(parses[::-1]).cdf


def test_every_valid_seen_floor_plan_merges(shared_alfred):
    files = sorted((shared_alfred / "valid_seen").glob("*/*/traj_data.json"))
    if not files:
        pytest.skip(f"no traj_data.json under {shared_alfred / 'valid_seen'}")
    parses = [parse_alfred(f) for f in files]
    merged = merge_by_floor_plan(parses)
    assert len(merged) == len({p.floor_plan for p in parses}) == 88
    for plan, m in merged.items():
        mine = [p for p in parses if p.floor_plan == plan]
        assert len(m.sources) == len(mine) and m.cdf.scene.room == plan
        kept = list(m.keys.values())
        for p in mine:  # every large piece any trajectory names is in the merged scene
            for name, key in p.keys.items():
                t = p.cdf.object_named(name).type
                if is_large(t) and thor_position(key) is not None:
                    assert match_instance(t, thor_position(key), kept) is not None, (plan, key)
