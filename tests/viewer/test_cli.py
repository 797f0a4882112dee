"""`luminous view`'s refusals (one line, exit status 2, before anything is served) and `luminous demo`'s line
that opens its episode in the viewer."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import pytest

from luminous_sim.cli.main import main


def test_no_scene_folder_is_one_line(tmp_path: Path, capsys):
    assert main(["view", str(tmp_path / "nowhere"), "--port", "0"]) == 2
    err = capsys.readouterr().err
    assert "luminous view: error:" in err and "nowhere" in err and "Traceback" not in err


def test_no_episode_folder_is_one_line(scene_dir: Path, tmp_path: Path, capsys):
    assert main(["view", str(scene_dir), "--trajectory", str(tmp_path), "--port", "0"]) == 2
    assert "no trajectory.json; expected an episode folder" in capsys.readouterr().err


def test_a_bad_port_is_refused(scene_dir: Path, capsys):
    with pytest.raises(SystemExit) as exc:
        main(["view", str(scene_dir), "--port", "70000"])
    assert exc.value.code == 2 and "--port" in capsys.readouterr().err


def test_the_demo_prints_the_command_that_opens_its_episode(tmp_path: Path, monkeypatch, capsys):
    import luminous_sim.demo as demo

    monkeypatch.setattr(demo, "run_demo", lambda out, seed, types: [])
    monkeypatch.setattr(demo, "run_demo_episode", lambda out, seed: SimpleNamespace(
        goal_conditions=(1, 1), task_type="stub", success=True, low_actions=0, out_dir=out))
    assert main(["demo", "--out", str(tmp_path / "demo")]) == 0
    ep = tmp_path / "demo" / "episode"
    assert f"luminous view {ep} --trajectory {ep}" in capsys.readouterr().out
