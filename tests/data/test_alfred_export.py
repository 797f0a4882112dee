"""ALFRED json_2.1.0 export: a real solved episode's traj_data.json has the key/type structure of every
real valid_seen file, field by field; the folder layout, raw images and sidecar are ALFRED's and ours."""

from __future__ import annotations

import copy
import io
import json
from itertools import pairwise
from pathlib import Path

import pytest

from luminous_sim.data import export_alfred, fold_subgoals, scene_for_task, structure, structure_differences
from luminous_sim.episode import run_episode
from luminous_sim.scene import Scene

TASK = "pick_and_place_simple"


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    scene = scene_for_task(TASK, "Bathroom", seed=0)
    result, record = run_episode(scene, TASK, seed=0)
    assert result.success
    trial = export_alfred(tmp_path_factory.mktemp("alfred"), scene, record, seed=0, video=True)
    return scene, record, trial, json.loads((trial / "traj_data.json").read_text())


@pytest.fixture(scope="module")
def real_structures(shared_alfred):
    files = sorted((shared_alfred / "valid_seen").glob("*/*/traj_data.json"))
    if not files:
        pytest.skip(f"no traj_data.json under {shared_alfred / 'valid_seen'}")
    return [(str(f.relative_to(shared_alfred)), structure(json.loads(f.read_text()))) for f in files]


def test_structure_matches_every_real_valid_seen_file(exported, real_structures):
    *_, data = exported
    problems = structure_differences(structure(data), real_structures)
    assert not problems, "\n".join(problems[:50])
    subgoals = [h["planner_action"]["action"] for h in data["plan"]["high_pddl"]]
    assert not any(a == b == "GotoLocation" for a, b in pairwise(subgoals)), subgoals  # as in ALFRED's


def test_structure_check_names_what_differs(exported, real_structures):
    *_, data = exported
    broken = copy.deepcopy(data)
    pick = next(h for h in broken["plan"]["high_pddl"] if h["planner_action"]["action"] == "PickupObject")
    del pick["planner_action"]["forceVisible"]
    broken["scene"]["scene_num"] = str(broken["scene"]["scene_num"])
    broken["turk_annotations"]["anns"][0]["worker"] = "x"
    del broken["task_id"]
    problems = "\n".join(structure_differences(structure(broken), real_structures))
    assert "plan.high_pddl[].planner_action<PickupObject>" in problems
    assert "type at scene.scene_num: ours ['string'], ALFRED ['integer']" in problems
    assert "extra path turk_annotations.anns[].worker" in problems
    assert "missing path task_id" in problems


def test_folder_images_and_sidecar(exported):
    scene, record, trial, data = exported
    p = data["pddl_params"]
    assert trial.parent.name == f"{TASK}-{p['object_target']}-None-{p['parent_target']}-{data['scene']['scene_num']}"
    assert trial.name == data["task_id"] and data["task_id"].startswith("trial_T")
    names = sorted(f.name for f in (trial / "raw_images").iterdir())
    assert names == [im["image_name"].replace(".png", ".jpg") for im in data["images"]]
    assert len(names) == len(data["plan"]["low_actions"]) + 1  # the start frame, then one per action
    from PIL import Image

    assert Image.open(io.BytesIO((trial / "raw_images" / names[0]).read_bytes())).format == "JPEG"
    assert (trial / "video.mp4").stat().st_size > 0
    problem = (trial / "pddl_states" / "problem_0.pddl").read_text()
    assert problem.startswith("(define (problem") and "(:goal" in problem
    side = json.loads((trial / "luminous.json").read_text())
    assert side["seed"] == 0 and side["task"] == record.task.to_dict()
    assert side["goal_conditions"] == list(record.trajectory.goal_conditions)
    assert Scene.from_json(json.dumps(side["scene"])) == scene
    anns = data["turk_annotations"]["anns"]
    assert len(anns) == 3 and all(a["votes"] == [1, 1, 1] for a in anns)
    assert anns[0]["high_descs"] == record.instructions[0].high_descs
    assert all(len(a["high_descs"]) == len(data["plan"]["high_pddl"]) - 1 for a in anns)


def test_high_pddl_has_only_alfred_subgoals_and_low_actions_stay_ordered(exported):
    *_, data = exported
    high = data["plan"]["high_pddl"]
    assert [h["high_idx"] for h in high] == list(range(len(high)))
    assert {h["planner_action"]["action"] for h in high} <= {"GotoLocation", "PickupObject", "PutObject", "End"}
    idx = [a["high_idx"] for a in data["plan"]["low_actions"]]
    assert idx == sorted(idx) and set(idx) == set(range(len(high) - 1))
    k = next(i for i, h in enumerate(high) if h["planner_action"]["action"] == "PickupObject")
    pick, goto = high[k]["planner_action"], high[k - 1]  # ALFRED names the walk by where the object lies
    assert goto["discrete_action"]["args"] == [pick["coordinateReceptacleObjectId"][0].lower()]


@pytest.mark.slow
@pytest.mark.parametrize("task_type,room", [
    ("pick_heat_then_place_in_recep", "Kitchen"), ("pick_cool_then_place_in_recep", "Kitchen"),
    ("pick_clean_then_place_in_recep", "Kitchen"), ("look_at_obj_in_light", "Bedroom"),
])
def test_other_task_types_match_every_real_file(task_type, room, tmp_path, real_structures):
    """Heat, cool, clean and look-at bring CleanObject/HeatObject keys, the toggles that carry them,
    object_toggles and dirty_and_empty (about 3-8 s each)."""
    scene = scene_for_task(task_type, room, seed=0)
    result, record = run_episode(scene, task_type, seed=0)
    assert result.success
    data = json.loads((export_alfred(tmp_path, scene, record, seed=0) / "traj_data.json").read_text())
    problems = structure_differences(structure(data), real_structures)
    assert not problems, "\n".join(problems[:50])
    subgoals = [h["planner_action"]["action"] for h in data["plan"]["high_pddl"]]
    assert not any(a == b == "GotoLocation" for a, b in pairwise(subgoals)), subgoals  # as in ALFRED's
    assert data["scene"]["dirty_and_empty"] == (task_type == "pick_clean_then_place_in_recep")
    assert bool(data["scene"]["object_toggles"]) == (task_type == "look_at_obj_in_light")


def test_open_and_close_subgoals_fold_into_their_interactions():
    acts = ["GotoLocation", "OpenObject", "PickupObject", "CloseObject", "GotoLocation", "OpenObject", "GotoLocation",
            "PutObject"]
    assert fold_subgoals(acts) == [0, 1, 1, 1, 2, 2, 3, 4]


def test_consecutive_walks_merge_into_one_as_in_alfred_plans():
    from luminous_sim.data.alfred_export import merge_walks

    # the walk, open, walk, put above: the open joins the first walk, and the two walks are one
    assert merge_walks(["GotoLocation", "PickupObject", "GotoLocation", "GotoLocation", "PutObject"]) == [
        0, 1, 2, 2, 3]
    assert merge_walks(["GotoLocation", "GotoLocation", "GotoLocation", "CoolObject", "GotoLocation",
                        "PutObject"]) == [0, 0, 0, 1, 2, 3]
    assert merge_walks(["PickupObject", "PutObject"]) == [0, 1]


def test_extra_annotations_change_nothing_that_is_written(tmp_path: Path, exported):
    scene, record, *_ = exported
    plain, _ = run_episode(scene, TASK, seed=0, out_dir=tmp_path / "plain", record_frames=False, extra_annotations=0)
    again, rec = run_episode(scene, TASK, seed=0, out_dir=tmp_path / "rec", record_frames=False)
    assert len(rec.instructions) == 3
    assert plain.low_actions == again.low_actions == len(record.trajectory.low_actions)
    assert (tmp_path / "rec" / "instructions.txt").read_text().startswith(rec.instructions[0].task_desc + "\n")
    for name in ("trajectory.json", "instructions.txt"):
        assert (tmp_path / "plain" / name).read_bytes() == (tmp_path / "rec" / name).read_bytes()


def test_sidecar_alone_regenerates_the_same_files(tmp_path: Path, exported):
    *_, trial, _ = exported
    side = json.loads((trial / "luminous.json").read_text())
    scene = Scene.from_json(json.dumps(side["scene"]))
    _, record = run_episode(scene, side["task"]["task_type"], side["seed"])
    again = export_alfred(tmp_path, scene, record, seed=side["seed"])
    for rel in ("traj_data.json", "luminous.json", "pddl_states/problem_0.pddl", "raw_images/000000005.jpg"):
        assert (again / rel).read_bytes() == (trial / rel).read_bytes(), rel


def test_an_unsolved_episode_is_refused_with_its_first_cause():
    """After a replan the last message often only echoes the first: the refusal quotes the first cause."""
    from luminous_sim.data.alfred_export import ExportError, alfred_traj_data, first_cause
    from luminous_sim.episode import EpisodeRecord
    from luminous_sim.errors import Failure, FailureCode
    from luminous_sim.planning import Trajectory

    traj = Trajectory(init_action={})
    traj.fail(Failure(FailureCode.RECEPTACLE_FULL, "PutObject failed: Hanger|1 is full"))
    traj.fail(Failure(FailureCode.NO_PLAN, "the goal cannot be reached"))
    assert traj.failure == "the goal cannot be reached" and first_cause(traj) == "PutObject failed: Hanger|1 is full"
    record = EpisodeRecord(task=None, trajectory=traj, start_state=None, instructions=[])
    with pytest.raises(ExportError, match=r"failed: PutObject failed: Hanger\|1 is full\)"):
        alfred_traj_data(None, record, seed=0)  # type: ignore[arg-type]  # refused before the scene is read
    unmet = Trajectory(init_action={}, goal_conditions=(1, 2))
    assert first_cause(unmet) == "the goal is not met at the end: 1 of 2 goal conditions hold"
