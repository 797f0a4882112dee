"""Method (b): ALFRED's own task designs re-solved in scenes generated in their own floor plans."""

from __future__ import annotations

import json
from collections import defaultdict

import pytest

from luminous_sim.data import (
    DesignError,
    clear_for_put,
    design_scene,
    read_design,
    read_designs,
    scene_misfit,
    solve_design,
)
from luminous_sim.episode import prepared_world
from luminous_sim.planning import has_room, has_room_for_two

SAMPLE = {  # one design per task type, quick to solve, each exercising one of the fixed causes
    "look_at_obj_in_light": "look_at_obj_in_light-BaseballBat-None-DeskLamp-303",  # a bat fits no side table
    "pick_and_place_simple": "pick_and_place_simple-SprayBottle-None-GarbageCan-409",  # reach into a low can
    "pick_two_obj_and_place": "pick_two_obj_and_place-SoapBar-None-GarbageCan-418",
    "pick_clean_then_place_in_recep": "pick_clean_then_place_in_recep-Cloth-None-Drawer-423",  # a low drawer
    # its microwave faced the fridge beside it: nothing put in it showed to be taken out again
    "pick_heat_then_place_in_recep": "pick_heat_then_place_in_recep-Apple-None-DiningTable-26",
    "pick_cool_then_place_in_recep": "pick_cool_then_place_in_recep-Pan-None-StoveBurner-18",  # a pan on a burner
    "pick_and_place_with_movable_recep": "pick_and_place_with_movable_recep-AppleSliced-Pan-CounterTop-8",
}
"""Each failed before its fix (reach measured to a region's floor, a pan's rim limiting what goes in it, a
pan wider than its burner, a bat sent to a side table, a microwave turned away from where the agent stands)."""
FLOOR = 0.95
"""The goal per task type over all of valid_seen (seed 0: 250/251 solved; pick_two_obj_and_place-Pan-None-CounterTop-14
finds its counter full since appliances face the room)."""


def _design(root, task_dir: str):
    return read_design(next((root / "valid_seen" / task_dir).glob("*/traj_data.json")))


def test_a_design_is_read_from_a_real_traj_data_file(shared_alfred):
    d = _design(shared_alfred, "pick_and_place_simple-SprayBottle-None-GarbageCan-409")
    assert (d.task_type, d.params.object_target, d.params.parent_target) == (
        "pick_and_place_simple", "SprayBottle", "GarbageCan")
    assert (d.floor_plan, d.scene_num, d.room_type) == ("FloorPlan409", 409, "Bathroom")
    assert len(read_designs(shared_alfred / "valid_seen")) == 251


def test_a_malformed_design_names_the_file_and_field(tmp_path):
    bad = tmp_path / "traj_data.json"
    bad.write_text(json.dumps({"task_type": "pick_and_place_simple", "scene": {"floor_plan": "FloorPlan1"}}))
    with pytest.raises(DesignError, match=r"traj_data.json: missing key 'pddl_params'"):
        read_design(bad)
    bad.write_text(json.dumps({"task_type": "pick_and_place_simple", "pddl_params": {"object_target": "Apple"},
                               "scene": {"floor_plan": "FloorPlan2", "scene_num": 1},
                               "plan": {"high_pddl": [], "low_actions": []}}))
    with pytest.raises(DesignError, match="does not match scene.scene_num"):
        read_design(bad)
    good = {"task_type": "pick_and_place_simple", "pddl_params": {"object_target": "Apple"},
            "scene": {"floor_plan": "FloorPlan1", "scene_num": 1},
            "plan": {"high_pddl": [{"discrete_action": {"action": "GotoLocation"}}], "low_actions": []}}
    for anns, field in (({"anns": "text"}, r"'turk_annotations.anns': expected a list"),
                        ({"anns": [{"task_desc": "take it", "high_descs": [3]}]}, r"'turk_annotations.anns\[0\]'")):
        bad.write_text(json.dumps({**good, "turk_annotations": anns}))
        with pytest.raises(DesignError, match=field):
            read_design(bad)
    bad.write_text(json.dumps({**good, "plan": {"high_pddl": [{"discrete_action": 1}], "low_actions": []},
                               "turk_annotations": {"anns": [{"task_desc": "take it", "high_descs": []}]}}))
    with pytest.raises(DesignError, match=r"'plan.high_pddl\[0\].discrete_action.action'"):
        read_design(bad)


@pytest.mark.parametrize("task_type", sorted(SAMPLE))
def test_one_design_per_task_type_is_solved(shared_alfred, task_type):
    result = solve_design(_design(shared_alfred, SAMPLE[task_type]), seed=0)
    assert result.success, (result.cause, result.message)
    assert result.goal_conditions[0] == result.goal_conditions[1] > 0


def test_a_design_scene_starts_with_its_goal_unmet_and_room_for_the_put(shared_alfred):
    design = _design(shared_alfred, "pick_two_obj_and_place-SoapBar-None-GarbageCan-418")
    scene = design_scene(design, seed=0)
    assert scene.room.name == "FloorPlan418"
    assert scene_misfit(scene, design) is None
    world = prepared_world(scene, design.task_type)
    try:  # the garbage can's floor is 1.5 m below the eye: reach is to the can, as in AI2-THOR
        assert has_room_for_two(world.view(), "SoapBar", "GarbageCan")
    finally:
        world.close()


def test_an_apple_slice_goes_in_a_pan_though_it_stands_over_the_rim(shared_alfred):
    design = _design(shared_alfred, "pick_and_place_with_movable_recep-AppleSliced-Pan-CounterTop-8")
    world = prepared_world(design_scene(design, seed=0), design.task_type)
    try:
        assert has_room(world.view(), "AppleSliced", "Pan")
    finally:
        world.close()


def test_clearing_for_a_put_drops_the_rooms_defaults_from_the_target_not_the_cdfs_objects(shared_alfred):
    from luminous_sim.cssg import generate
    from luminous_sim.rooms import load_room
    from luminous_sim.tasks import cdf_for_task

    design = _design(shared_alfred, "pick_two_obj_and_place-SoapBar-None-GarbageCan-418")
    doc = cdf_for_task(design.task_type, design.params, design.room_type)
    scene = generate(doc, seed=3, room=load_room(design.floor_plan)).scene
    declared = {o.name for o in doc.scene.objects}
    cans = {o.id for o in scene.objects if o.type == "GarbageCan"}
    scene = scene.model_copy(update={"objects": (*scene.objects, scene.objects[-1].model_copy(update={
        "id": "Cloth|extra", "type": "Cloth", "name": "cloth_auto9", "parent": next(iter(cans)),
        "layer": "object"}))})
    cleared = clear_for_put(scene, design.params, declared)
    assert cleared is not None and "Cloth|extra" in cleared.notes["cleared_for_task"]
    assert not [o for o in cleared.objects if o.parent in cans]
    assert {o.name for o in cleared.objects if o.name and o.name.split("#")[0] in declared} == {
        o.name for o in scene.objects if o.name and o.name.split("#")[0] in declared}


@pytest.mark.parametrize("task_dir", ["pick_heat_then_place_in_recep-Tomato-None-DiningTable-16",
                                      "pick_heat_then_place_in_recep-Cup-None-Cabinet-22"])
def test_what_is_heated_in_a_microwave_is_seen_in_it_to_be_taken_out(shared_alfred, task_dir):
    """The microwave faces where the agent can stand (as in AI2-THOR), so the oracle takes the heated thing out
    pointing at its own mask, fully visible (`min_visible_pixels`), not at the few pixels an open container in
    view allows. Turned at random, these microwaves faced the wall and the cabinet beside them: nothing put in
    them showed from any pose."""
    import math

    from luminous_sim.data.alfred_designs import design_task
    from luminous_sim.planning import Oracle
    from luminous_sim.world.masks import rle_to_mask

    design = _design(shared_alfred, task_dir)
    scene = design_scene(design, seed=0)
    by_id = {o.id: o for o in scene.objects}
    microwave = next(o for o in scene.objects if o.type == "Microwave")
    turn = (microwave.yaw - by_id[microwave.parent].yaw) / (math.pi / 2)
    assert by_id[microwave.parent].type == "CounterTop" and round(turn) % 4 == 0  # facing the counter's front
    world = prepared_world(scene, design.task_type)
    try:
        traj = Oracle(world, record_frames=False).run(design_task(design, scene.seed).goal)
        assert traj.success, traj.failures
        actions = [a["api_action"]["action"] for a in traj.low_actions]
        heated = traj.low_actions[actions.index("PickupObject", actions.index("ToggleObjectOff"))]
        assert heated["api_action"]["objectId"] == next(o.id for o in scene.objects if o.name == "target")
        pixels = int(rle_to_mask(heated["discrete_action"]["args"]["mask"]).sum())
        assert pixels >= world.config.min_visible_pixels
    finally:
        world.close()


@pytest.mark.slow
def test_every_valid_seen_design_is_solved_at_the_measured_floor(shared_alfred):
    by_type: dict[str, list[bool]] = defaultdict(list)
    for design in read_designs(shared_alfred / "valid_seen"):
        by_type[design.task_type].append(solve_design(design, seed=0).success)
    rates = {t: sum(ok) / len(ok) for t, ok in by_type.items()}
    assert len(rates) == 7
    assert all(r >= FLOOR for r in rates.values()), rates


def test_a_plunger_goes_in_a_cabinet_whose_shelf_is_tall_enough(shared_alfred):
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.scene import can_hold

    design = _design(shared_alfred, "pick_and_place_simple-Plunger-None-Cabinet-406")
    scene = design_scene(design, seed=0)
    cat = default_catalog()
    cabinet = next(o for o in scene.objects if o.name == "receptacle")
    plunger = next(o for o in scene.objects if o.name == "target")
    assert can_hold(cat.for_object(cabinet), cat.for_object(plunger))


def test_a_roll_of_toilet_paper_is_hung_on_its_hanger_and_stays_there(shared_alfred):
    """A put on a hanger hangs the roll on it, held there (it was refused: the roll is wider than the spindle)."""
    import numpy as np

    from luminous_sim.data.alfred_designs import design_task
    from luminous_sim.planning import Oracle

    design = _design(shared_alfred, "pick_and_place_simple-ToiletPaper-None-ToiletPaperHanger-406")
    scene = design_scene(design, seed=0)
    roll = next(o.id for o in scene.objects if o.name == "target")
    hanger = next(o.id for o in scene.objects if o.name == "receptacle")
    world = prepared_world(scene, design.task_type)
    try:
        traj = Oracle(world, record_frames=False).run(design_task(design).goal)
        assert traj.success, traj.failures
        view = world.view()
        assert view.state.objects[roll].parent == hanger
        before = view.pose(roll)[0]
        for _ in range(240):
            world.client.stepSimulation()
        assert np.allclose(view.pose(roll)[0], before, atol=1e-3)
    finally:
        world.close()


def test_a_start_surface_the_floor_plan_has_no_room_for_is_avoided(shared_alfred):
    """FloorPlan25's U-shaped kitchen has no room for a dining table: the tomato starts elsewhere."""
    design = _design(shared_alfred, "pick_clean_then_place_in_recep-Tomato-None-CounterTop-25")
    scene = design_scene(design, seed=0)
    tomato = next(o for o in scene.objects if o.name == "target")
    assert scene.object(tomato.parent).type not in ("DiningTable", "CounterTop")


def test_a_layout_whose_target_no_pose_sees_is_not_a_design_scene(shared_alfred):
    """FloorPlan13, first layout: a sight line grazes the potato past the coffee machine in front of it, but
    no pose the oracle would walk to shows it in the picture (the oracle failed there)."""
    from luminous_sim.cssg import generate
    from luminous_sim.data.alfred_designs import _layout_seeds
    from luminous_sim.rooms import load_room
    from luminous_sim.tasks import cdf_for_task

    design = _design(shared_alfred, "pick_cool_then_place_in_recep-PotatoSliced-None-SinkBasin-13")
    doc = cdf_for_task(design.task_type, design.params, design.room_type)
    scene = generate(doc, seed=next(_layout_seeds(0, 1)), room=load_room(design.floor_plan)).scene
    why = scene_misfit(scene, design)
    assert why is not None and why[0] == "no_pose" and "Potato" in why[1]


def test_a_pan_put_in_a_fridge_lands_where_it_can_be_taken_out_again(shared_alfred):
    """The fridge's upper shelves are taken: the pan once went on its floor shelf, out of reach and view."""
    result = solve_design(_design(shared_alfred, "pick_cool_then_place_in_recep-Pan-None-StoveBurner-23"), seed=0)
    assert result.success, (result.cause, result.message)


@pytest.mark.slow
@pytest.mark.parametrize("task_dir", [
    "pick_and_place_with_movable_recep-Ladle-Plate-CounterTop-4",  # room kept on full counters
    "pick_heat_then_place_in_recep-Mug-None-SideTable-21",  # the microwave off FloorPlan21's full counters
    "pick_two_obj_and_place-Box-None-CoffeeTable-213",  # two boxes need a table with a row for both
    "pick_two_obj_and_place-SprayBottle-None-GarbageCan-419",  # a can wide enough for two bottles
    "pick_cool_then_place_in_recep-PotatoSliced-None-SinkBasin-13",
    "pick_two_obj_and_place-Pan-None-CounterTop-14",  # the first pan put against an edge, the second beside it
])
def test_designs_that_failed_before_are_solved(shared_alfred, task_dir):
    result = solve_design(_design(shared_alfred, task_dir), seed=0)
    assert result.success, (result.cause, result.message)


def _traj_cases(valid: dict) -> dict[str, tuple[object, str]]:
    """Damaged copies of a real traj_data.json and the message each must give (issue 27)."""
    no_plan = json.loads(json.dumps(valid))
    del no_plan["plan"]
    nan_pose = json.loads(json.dumps(valid))
    nan_pose["scene"]["object_poses"][0]["position"]["x"] = float("nan")
    return {"list": ([valid], "expected a JSON object at the top, got list"),
            "no plan": (no_plan, "missing key 'plan.high_pddl'"),
            "NaN pose": (nan_pose, r"scene.object_poses\[0\].position.x: expected a finite number, got NaN")}


def test_the_design_reader_refuses_what_alfred_parse_refuses(shared_alfred, tmp_path):
    """One reader for `luminous alfred parse` and `dataset build --from-alfred`: a JSON list, a missing plan,
    a NaN pose, a folder or a device are refused by both, naming the file and the key."""
    from luminous_sim.data.alfred_parser import AlfredParseError, parse_alfred

    valid = json.loads(next((shared_alfred / "valid_seen" / "pick_and_place_simple-SprayBottle-None-GarbageCan-409")
                             .glob("*/traj_data.json")).read_text())
    for name, (data, message) in _traj_cases(valid).items():
        path = tmp_path / name.replace(" ", "_") / "traj_data.json"
        path.parent.mkdir()
        path.write_text(json.dumps(data))
        with pytest.raises(DesignError, match=f"traj_data.json: {message}"):
            read_design(path)
        with pytest.raises(AlfredParseError, match=f"traj_data.json: {message}"):
            parse_alfred(path)
    folder = tmp_path / "folder" / "traj_data.json"
    folder.mkdir(parents=True)
    with pytest.raises(DesignError, match="traj_data.json: a folder; expected a traj_data.json file"):
        read_design(folder)
    with pytest.raises(DesignError, match="/dev/null: a device; expected a traj_data.json file"):
        read_design("/dev/null")
