"""`luminous run`: a CDF's own task end to end; exit 0 when done, 1 when not, 2 on bad input (issue 14)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.cli.test_errors import EXAMPLES, one_line_error, run

EPISODE_FILES = ("trajectory.json", "video.mp4", "top_down.png", "instructions.txt")
APPLE = EXAMPLES / "kitchen_apple_fridge.yaml"


def _variant(tmp_path: Path, name: str, old: str, new: str, source: Path = APPLE) -> Path:
    text = source.read_text()
    assert old in text
    path = tmp_path / name
    path.write_text(text.replace(old, new))
    return path


def _high(out: Path) -> list[str]:
    record = json.loads((out / "trajectory.json").read_text())
    return [h["planner_action"]["action"] for h in record["plan"]["high_pddl"]]


def test_a_cdf_with_an_execution_script(tmp_path, capsys):
    out = tmp_path / "apple"
    code, stdout, err = run(["run", "--cdf", str(APPLE), "--seed", "0", "--out", str(out)], capsys)
    assert code == 0, err
    assert "task done in room FloorPlan18" in stdout and "following its execution script" in stdout
    assert "goal conditions: 2/2" in stdout and "first failure" not in stdout
    assert all((out / f).is_file() for f in EPISODE_FILES) and any((out / "frames").iterdir())
    assert _high(out) == ["GotoLocation", "PickupObject", "GotoLocation", "OpenObject", "PutObject", "CloseObject",
                          "End"]  # the script's steps, not a plan of the oracle's
    record = json.loads((out / "trajectory.json").read_text())
    assert record["success"] and record["init_action"]["rotation"] == 90  # task.agent's rotation


def test_a_cdf_without_a_script_is_planned_by_the_oracle(tmp_path, capsys):
    out = tmp_path / "remote"
    code, stdout, err = run(["run", "--cdf", str(EXAMPLES / "livingroom_painting_sofa.yaml"), "--out", str(out)],
                            capsys)
    assert code == 0, err
    assert "planned by the oracle" in stdout and "goal: (inReceptacle remote coffee_table)" in stdout
    assert all((out / f).is_file() for f in EPISODE_FILES)


def test_a_script_that_fails_exits_1_with_its_first_cause(tmp_path, capsys):
    """Nothing is held: the put fails at once, and the summary says why."""
    cdf = _variant(tmp_path, "bad_script.yaml", "execution:\n  - {action: GotoLocation, object: counter}",
                   "execution:\n  - {action: PutObject, objectId: apple, receptacleObjectId: fridge}\n"
                   "  - {action: GotoLocation, object: counter}")
    code, stdout, err = run(["run", "--cdf", str(cdf), "--out", str(tmp_path / "o")], capsys)
    assert code == 1 and not err
    assert "task NOT done" in stdout and "first failure: [" in stdout
    record = json.loads((tmp_path / "o" / "trajectory.json").read_text())
    assert not record["success"] and record["failure"] and record["failures"][0]["message"] == record["failure"]


@pytest.mark.parametrize(("name", "old", "new", "field"), [
    ("malformed.yaml", "  room: FloorPlan18", "  room: FloorPlan18\n  colour: red", "scene"),
    ("contradiction.yaml", "goal: (and (inReceptacle apple fridge) (isCool apple))",
     "goal: (and (isHot apple) (isCool apple))", "task.goal"),
    ("outside.yaml", "agent: {rotation: 90, horizon: 30}", "agent: {position: [20, 20], rotation: 90}",
     "task.agent.position"),
    ("unknown_object.yaml", "goal: (and (inReceptacle apple fridge) (isCool apple))",
     "goal: (isCool pear)", "task.goal"),
])
def test_bad_input_exits_2_naming_file_and_field(tmp_path, capsys, name, old, new, field):
    cdf = _variant(tmp_path, name, old, new)
    out = tmp_path / "o"
    code, _, err = run(["run", "--cdf", str(cdf), "--out", str(out)], capsys)
    assert code == 2 and one_line_error(err), err
    assert str(cdf) in err and field in err
    assert not out.exists()  # refused before anything was written


def test_a_cdf_without_a_task_section(tmp_path, capsys):
    cdf = EXAMPLES / "study_desk_chair.yaml"
    code, _, err = run(["run", "--cdf", str(cdf), "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err) and f"{cdf}: task: the CDF has no task section" in err


def test_a_room_of_another_type_and_a_missing_file(tmp_path, capsys):
    code, _, err = run(["run", "--cdf", str(APPLE), "--room", "FloorPlan301", "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err) and "FloorPlan301 is a Bedroom" in err and str(APPLE) in err
    code, _, err = run(["run", "--cdf", str(tmp_path / "none.yaml"), "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err) and "none.yaml" in err


def test_an_initial_state_the_scene_does_not_meet(tmp_path, capsys):
    """The apple is placed on the counter by the CDF's relations; an initial state that has it in the
    fridge cannot hold."""
    cdf = _variant(tmp_path, "initial.yaml", "initial: (not (isOpen fridge))", "initial: (inReceptacle apple fridge)")
    code, _, err = run(["run", "--cdf", str(cdf), "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err)
    assert f"{cdf}: task.initial: (inReceptacle apple fridge) does not hold" in err


def test_a_start_outside_a_procedural_room_is_refused_once_the_room_is_drawn(tmp_path, capsys):
    bedroom = EXAMPLES / "bedroom_reading_desk.yaml"
    cdf = _variant(tmp_path, "bed.yaml", "position: [1.0, 1.0]", "position: [1.0, -0.5]", source=bedroom)
    code, _, err = run(["run", "--cdf", str(cdf), "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err)
    assert f"{cdf}: task.agent.position: (1, -0.5) is outside room" in err


def test_a_cdf_size_no_asset_meets_names_the_file(tmp_path, capsys):
    cdf = _variant(tmp_path, "huge.yaml", "attributes: {colour: red, size: 1.1}", "attributes: {colour: red, size: 9}")
    code, _, err = run(["run", "--cdf", str(cdf), "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err) and str(cdf) in err
