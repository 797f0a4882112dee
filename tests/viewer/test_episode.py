"""An episode folder read back for playback: poses replayed from the actions, a frame and an instruction per
step; a folder that is not an episode is refused with its path named."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from luminous_sim.viewer import ViewerError, load_episode
from tests.viewer.conftest import ACTIONS, HIGH_DESCS, write_episode


def test_steps_replay_the_actions_from_the_start_pose(tmp_path: Path):
    ep = load_episode(write_episode(tmp_path / "ep", (1.0, 2.0)))
    assert [s.action for s in ep.steps] == ["start", *ACTIONS]
    assert [(s.pose.x, s.pose.y, s.pose.rotation, s.pose.horizon) for s in ep.steps] == [
        (1.0, 2.0, 0, 30), (1.0, 2.25, 0, 30), (1.0, 2.25, 90, 30), (1.25, 2.25, 90, 30), (1.25, 2.25, 90, 45),
        (1.5, 2.25, 90, 45)]
    assert ep.path()[-1] == (1.5, 2.25)
    assert ep.task_desc == "look at the apple" and ep.task_type == "look_at_obj_in_light" and ep.success


def test_each_step_has_its_frame_and_instruction(tmp_path: Path):
    ep = load_episode(write_episode(tmp_path / "ep", (0.0, 0.0)))
    assert [s.frame.name if s.frame else None for s in ep.steps] == [f"{k:09d}.png" for k in range(len(ACTIONS) + 1)]
    assert [s.instruction for s in ep.steps] == [HIGH_DESCS[0]] * 4 + [HIGH_DESCS[1]] * 2


def test_an_episode_without_frames_still_plays(tmp_path: Path):
    ep = load_episode(write_episode(tmp_path / "ep", (0.0, 0.0), frames=False))
    assert len(ep.steps) == len(ACTIONS) + 1 and all(s.frame is None for s in ep.steps)


def test_a_folder_without_a_trajectory_is_refused(tmp_path: Path):
    with pytest.raises(ViewerError, match=r"no trajectory\.json; expected an episode folder"):
        load_episode(tmp_path)


@pytest.mark.parametrize(("change", "message"), [
    (lambda d: d.pop("init_action"), "init_action: expected TeleportFull"),
    (lambda d: d["plan"].pop("low_actions"), "plan.low_actions: expected a list"),
    (lambda d: d["plan"]["low_actions"][2].pop("api_action"), r"plan.low_actions\[2\]: expected api_action"),
])
def test_a_malformed_trajectory_is_named(tmp_path: Path, change, message):
    folder = write_episode(tmp_path / "ep", (0.0, 0.0), frames=False)
    data = json.loads((folder / "trajectory.json").read_text())
    change(data)
    (folder / "trajectory.json").write_text(json.dumps(data))
    with pytest.raises(ViewerError, match=message):
        load_episode(folder)
    (folder / "trajectory.json").write_text("{not json")
    with pytest.raises(ViewerError, match="cannot read it as JSON"):
        load_episode(folder)
