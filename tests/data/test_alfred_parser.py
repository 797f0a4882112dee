"""The ALFRED task parser: every real valid_seen trajectory parses into a valid CDF whose task round-trips, and
hand-made trajectories show each rule (placements from first pickups, states, agent start, what is dropped)."""

from __future__ import annotations

import json

import pytest

from luminous_sim.cdf import dumps, loads
from luminous_sim.cssg import start_outside
from luminous_sim.data import AlfredParseError, parse_alfred
from luminous_sim.rooms import load_room
from luminous_sim.tasks import PddlParams, params_from_goal
from tests.data.alfred_traj import coord, goto, oid, pickup, put, traj

APPLE = oid("Apple", 1.0, 0.95, 0.5)
FRIDGE = oid("Fridge", -1.0, 0.0, 2.0)
COUNTER = ("CounterTop", 1.0, 0.9, 0.4)
MICROWAVE = oid("Microwave", 0.5, 1.2, -1.0)


def _relations(parse):
    return {(r.subject, r.relation, r.target) for r in parse.cdf.scene.relations}


def _state(parse, name):
    spec = parse.cdf.object_named(name)
    return spec.state.model_dump(exclude_none=True) if spec and spec.state else {}


@pytest.fixture(scope="module")
def valid_seen(shared_alfred):
    files = sorted((shared_alfred / "valid_seen").glob("*/*/traj_data.json"))
    if not files:
        pytest.skip(f"no traj_data.json under {shared_alfred / 'valid_seen'}")
    return files


def test_every_valid_seen_file_parses_validates_and_round_trips(valid_seen):
    assert len(valid_seen) == 251
    for f in valid_seen:
        data = json.loads(f.read_text())
        parse = parse_alfred(f)
        cdf = parse.cdf
        assert loads(dumps(cdf)) == cdf, f  # the written YAML validates and reads back the same
        assert cdf.scene.room == data["scene"]["floor_plan"] == parse.floor_plan
        assert cdf.task is not None and cdf.task.type == data["task_type"]
        params = PddlParams.from_json(data["pddl_params"])
        assert parse.params == params
        assert params_from_goal(cdf, cdf.task.goal) == params, f
        assert start_outside(cdf, load_room(parse.floor_plan)) is None
        assert {n.field for n in parse.dropped} >= {"scene.object_poses", "plan", "turk_annotations"}
        assert set(parse.keys) == {o.name for o in cdf.scene.objects}


def test_real_look_at_file(valid_seen):
    f = next(p for p in valid_seen if p.parts[-3] == "look_at_obj_in_light-AlarmClock-None-DeskLamp-323")
    parse = parse_alfred(f)
    assert _relations(parse) == {("alarm_clock", "on", "dresser")}
    assert _state(parse, "desk_lamp") == {"isToggled": False}  # scene.object_toggles
    agent = parse.cdf.task.agent
    assert agent.position == (0.25, 1.0) and agent.rotation == 90 and agent.horizon == 30
    assert parse.keys["alarm_clock"] == "AlarmClock|+02.69|+01.23|+01.40"


def test_real_sliced_and_cleaning_files(valid_seen):
    f = next(p for p in valid_seen if p.parts[-3] == "pick_cool_then_place_in_recep-AppleSliced-None-DiningTable-18")
    parse = parse_alfred(f)
    types = {o.name: o.type for o in parse.cdf.scene.objects}
    assert types["apple"] == "Apple" and "AppleSliced" not in types.values()  # a slice stands for its apple
    assert ("apple", "on", "counter_top") in _relations(parse)  # where the first slice was picked up
    assert _state(parse, "fridge") == {"isOpen": False}  # opened by the expert before anything else
    f = next(p for p in valid_seen if p.parts[-3] == "pick_clean_then_place_in_recep-Mug-None-CoffeeMachine-26")
    parse = parse_alfred(f)
    assert _state(parse, "mug") == {"isDirty": True, "isFilled": False}  # scene.dirty_and_empty
    assert any(n.field == "scene.dirty_and_empty" for n in parse.dropped)


def _simple(high, **kw):
    params = {"object_target": "Apple", "parent_target": "Fridge"}
    return traj("pick_and_place_simple", params, "FloorPlan1", high, **kw)


def test_first_pickup_gives_the_placement_later_ones_do_not():
    data = _simple([goto("countertop"), pickup(APPLE, coord(*COUNTER)), goto("microwave"), put(APPLE, MICROWAVE),
                    pickup(APPLE, coord("Microwave", 0.5, 1.2, -1.0)), goto("fridge"), put(APPLE, FRIDGE)])
    parse = parse_alfred(data)
    assert _relations(parse) == {("apple", "on", "counter_top")}
    assert [o.name for o in parse.cdf.scene.objects] == ["apple", "counter_top", "microwave", "fridge"]
    puts = [n for n in parse.kept if n.item.startswith("put ")]
    assert [n.item for n in puts] == ["put apple in microwave", "put apple in fridge"]


def test_coordinate_matches_the_objectid_of_the_same_object():
    cabinet, mug = oid("Cabinet", 0.3, 1.5, 2.0), oid("Mug", 0.3, 1.5, 2.1)
    low = [{"action": "OpenObject", "objectId": cabinet, "high_idx": 1},
           {"action": "PickupObject", "objectId": mug, "high_idx": 1},
           {"action": "CloseObject", "objectId": cabinet, "high_idx": 1}]
    data = traj("pick_and_place_simple", {"object_target": "Mug", "parent_target": "Fridge"}, "FloorPlan1",
                [goto("cabinet"), pickup(mug, coord("Cabinet", 0.301, 1.498, 2.004)), put(mug, FRIDGE)], low=low)
    parse = parse_alfred(data)
    assert parse.keys["cabinet"] == cabinet and "cabinet_2" not in parse.keys
    assert _relations(parse) == {("mug", "in", "cabinet")}
    assert _state(parse, "cabinet") == {"isOpen": False}


def test_dropped_items_name_their_reason():
    knife = oid("Knife", 0.2, 0.9, 0.1)
    data = traj("pick_and_place_simple", {"object_target": "Knife", "parent_target": "Drawer"}, "FloorPlan1",
                [pickup(knife, coord("CoffeeMachine", 0.2, 0.9, 0.1)), put(knife, oid("Drawer", 1, 0.5, 1))],
                start=(50.0, 50.0))
    parse = parse_alfred(data, source="hand.json")
    reasons = {n.item: n.reason for n in parse.dropped}
    assert "receptacle table does not let a CoffeeMachine hold a Knife" in reasons["knife on coffee_machine"]
    assert "outside room 'FloorPlan1'" in reasons["TeleportFull x=50 z=50 rotation=90 horizon=30"]
    assert parse.cdf.task.agent is None and not parse.cdf.scene.relations


def test_no_receptacle_and_task_requirements():
    data = traj("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Fridge", "object_sliced": True},
                "FloorPlan1", [pickup(oid("ButterKnife", 0, 0.9, 0), None),
                               pickup(oid("Apple", 1, 0.9, 1, "AppleSliced_1"), coord(*COUNTER))])
    parse = parse_alfred(data)
    types = [o.type for o in parse.cdf.scene.objects]
    assert "Knife" not in types  # the expert's ButterKnife is the slicing tool the task needs
    assert "Fridge" in types  # required by the task though no action names it
    assert any("picked up from no receptacle" in n.reason for n in parse.dropped)
    assert ("apple", "on", "counter_top") in _relations(parse)


def test_lamp_toggles_and_movable_recep_started_inside():
    lamp = oid("DeskLamp", 1, 0.8, 1)
    data = traj("look_at_obj_in_light", {"object_target": "Book", "toggle_target": "DeskLamp"}, "FloorPlan301",
                [pickup(oid("Book", 0, 0.5, 0), coord("Bed", 0, 0.4, 0)),
                 {"action": "ToggleObject", "objectId": lamp, "forceVisible": True}],
                toggles=[{"isOn": False, "objectType": "DeskLamp"}, {"isOn": True, "objectType": "FloorLamp"}])
    parse = parse_alfred(data)
    assert _state(parse, "desk_lamp") == {"isToggled": False}
    assert any(n.field == "scene.object_toggles[1]" for n in parse.dropped)
    cup, spoon = oid("Cup", 0, 0.9, 0), oid("Spoon", 0, 0.95, 0)
    data = traj("pick_and_place_with_movable_recep",
                {"object_target": "Spoon", "mrecep_target": "Cup", "parent_target": "DiningTable"}, "FloorPlan1",
                [pickup(cup, coord(*COUNTER)), put(cup, oid("DiningTable", 2, 0, 2))])
    parse = parse_alfred(data)
    assert ("spoon", "in", "cup") in _relations(parse) and spoon not in parse.keys.values()


@pytest.mark.parametrize(("mutate", "needle"), [
    (lambda d: d.pop("plan"), "missing key 'plan.high_pddl'"),
    (lambda d: d["scene"].update(floor_plan="FloorPlan999"), "scene.floor_plan"),
    (lambda d: d["scene"].update(dirty_and_empty="yes"), "scene.dirty_and_empty: expected bool"),
    (lambda d: d["pddl_params"].update(parent_target="Toaster"), "Toaster"),
    (lambda d: d.update(task_type="pick_three"), "unknown task type"),
    (lambda d: d["plan"]["high_pddl"][0]["planner_action"].update(coordinateReceptacleObjectId=[1]),
     "coordinateReceptacleObjectId"),
])
def test_bad_input_names_the_file_and_key(mutate, needle):
    data = _simple([pickup(APPLE, coord(*COUNTER)), put(APPLE, FRIDGE)])
    mutate(data)
    with pytest.raises(AlfredParseError, match="^broken.json: ") as err:
        parse_alfred(data, source="broken.json")
    assert needle in str(err.value)


def test_unreadable_file(tmp_path):
    bad = tmp_path / "traj_data.json"
    bad.write_text("{not json")
    with pytest.raises(AlfredParseError, match="not JSON"):
        parse_alfred(bad)


def test_parse_is_deterministic():
    data = _simple([pickup(APPLE, coord(*COUNTER)), put(APPLE, FRIDGE)])
    assert dumps(parse_alfred(data).cdf) == dumps(parse_alfred(json.loads(json.dumps(data))).cdf)
