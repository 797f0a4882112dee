"""Hostile input to `luminous view`: a busy port 65535 or a host it cannot listen on is said in one line (exit 2)
before any server thread starts (it used to print a thread traceback and hang); an episode from another scene
is refused (the scene's content key); every trajectory field is checked (an infinite rotation, a bad
`high_idx`, a non-list `low_actions`, non-string `high_descs`, a frame name outside frames/ ...)."""

from __future__ import annotations

import json
import math
import os
import socket
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from luminous_sim.cli.main import main
from luminous_sim.limits import MAX_EPISODE_ACTIONS
from luminous_sim.scene import Scene
from luminous_sim.viewer import ViewerError, load_episode
from luminous_sim.viewer.app import free_port
from tests.viewer.conftest import write_episode

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture()
def busy_65535():
    s = socket.socket()
    try:
        s.bind(("127.0.0.1", 65535))
    except OSError:
        s.close()
        pytest.skip("port 65535 is taken here already")
    s.listen()
    yield s
    s.close()


def test_a_busy_last_port_is_one_line_and_no_hang(scene_dir: Path, busy_65535) -> None:
    proc = subprocess.run([sys.executable, "-m", "luminous_sim.cli.main", "view", str(scene_dir), "--port", "65535"],
                          cwd=REPO, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr, proc.stderr
    assert "--port 65535: ports 65535..65535 on 127.0.0.1 are all in use" in proc.stderr


def test_free_port_takes_the_next_free_one(busy_65535) -> None:
    assert free_port("127.0.0.1", 65534) in (65534,)
    assert free_port("127.0.0.1", 0) == 0
    with pytest.raises(ViewerError, match="all in use"):
        free_port("127.0.0.1", 65535)


@pytest.mark.parametrize("host", ["a" * 64 + ".x", "192.0.2.1"])  # neither asks DNS: a label too long (refused
# while encoding), an address of no interface here (TEST-NET-1: binding fails on this machine, nothing is sent)
def test_a_host_it_cannot_listen_on_is_one_line(scene_dir: Path, host: str, capsys) -> None:
    assert main(["view", str(scene_dir), "--host", host, "--port", "0"]) == 2
    err = capsys.readouterr().err
    assert f"--host {host}: cannot listen there" in err and err.count("\n") == 1, err


def _episode(tmp_path: Path, kitchen: Scene, change: Callable[[dict[str, Any]], Any] | None = None,
             frames: bool = False) -> Path:
    folder = write_episode(tmp_path / "ep", (0.0, 0.0), frames=frames, scene=kitchen)
    if change is not None:
        data = json.loads((folder / "trajectory.json").read_text())
        change(data)
        (folder / "trajectory.json").write_text(json.dumps(data))
    return folder


def test_an_episode_of_this_scene_is_played(tmp_path: Path, kitchen: Scene) -> None:
    assert len(load_episode(_episode(tmp_path, kitchen), kitchen).steps) == 6


@pytest.mark.parametrize(("change", "message"), [
    (lambda d: d.update(scene_key="0" * 20), "scene_key '0000.*' is not the scene's"),
    (lambda d: d.update(scene_key=5), "scene_key 5 is not the scene's"),
    (lambda d: (d.pop("scene_key"), d.update(scene="FloorPlan999")), "scene 'FloorPlan999' is not the scene's room"),
    (lambda d: (d.pop("scene_key"), d.pop("scene")), "records no scene"),
])
def test_an_episode_of_another_scene_is_refused(tmp_path: Path, kitchen: Scene, change, message: str) -> None:
    with pytest.raises(ViewerError, match=message):
        load_episode(_episode(tmp_path, kitchen, change), kitchen)


def test_an_old_episode_that_names_the_scene_s_room_is_played(tmp_path: Path, kitchen: Scene) -> None:
    folder = _episode(tmp_path, kitchen, lambda d: d.pop("scene_key"))
    assert len(load_episode(folder, kitchen).steps) == 6


def test_view_refuses_an_episode_of_another_scene_in_one_line(scene_dir: Path, kitchen: Scene, tmp_path: Path,
                                                               capsys) -> None:
    folder = _episode(tmp_path, kitchen, lambda d: d.update(scene_key="f" * 20))
    assert main(["view", str(scene_dir), "--trajectory", str(folder), "--port", "0"]) == 2
    err = capsys.readouterr().err
    assert "is not the scene's" in err and err.count("\n") == 1, err


def _low(d: dict[str, Any]) -> list[dict[str, Any]]:
    return d["plan"]["low_actions"]


BAD_FIELDS: list[tuple[str, Callable[[dict[str, Any]], Any], str]] = [
    ("infinite rotation", lambda d: d["init_action"].update(rotation=math.inf), "init_action.rotation: expected 0, 90"),
    ("rotation 45", lambda d: d["init_action"].update(rotation=45), "init_action.rotation"),
    ("rotation text", lambda d: d["init_action"].update(rotation="90"), "init_action.rotation"),
    ("horizon 90", lambda d: d["init_action"].update(horizon=90), "init_action.horizon: expected a whole number"),
    ("nan x", lambda d: d["init_action"].update(x=math.nan), "init_action.x: expected a finite number"),
    ("1e308 z", lambda d: d["init_action"].update(z=1e308), "init_action.z: expected a finite number"),
    ("high_idx text", lambda d: _low(d)[1].update(high_idx="x"), r"low_actions\[1\].high_idx: expected a whole"),
    ("high_idx -1", lambda d: _low(d)[1].update(high_idx=-1), r"low_actions\[1\].high_idx"),
    ("high_idx 99", lambda d: _low(d)[1].update(high_idx=99), r"low_actions\[1\].high_idx: expected .* in 0..1"),
    ("high_idx inf", lambda d: _low(d)[0].update(high_idx=math.inf), r"low_actions\[0\].high_idx"),
    ("high_idx true", lambda d: _low(d)[0].update(high_idx=True), r"low_actions\[0\].high_idx"),
    ("low_actions dict", lambda d: d["plan"].update(low_actions={"a": 1}), "plan.low_actions: expected a list"),
    ("low_actions of text", lambda d: d["plan"].update(low_actions=["MoveAhead"]), r"low_actions\[0\]: expected"),
    ("action a number", lambda d: _low(d)[0]["api_action"].update(action=3), r"low_actions\[0\]: expected"),
    ("too many actions", lambda d: d["plan"].update(low_actions=[_low(d)[0]] * (MAX_EPISODE_ACTIONS + 1)),
     "plan.low_actions: 10001 actions"),
    ("high_descs numbers", lambda d: d.update(high_descs=[1, 2]), "high_descs: expected a list of"),
    ("high_descs text", lambda d: d.update(high_descs="walk"), "high_descs: expected a list of"),
    ("high_pddl text", lambda d: d["plan"].update(high_pddl="x"), "plan.high_pddl: expected a list"),
    ("success text", lambda d: d.update(success="false"), "success: expected true or false"),
    ("task_desc number", lambda d: d.update(task_desc=5), "task_desc: expected a text"),
    ("task a list", lambda d: d.update(task=[1]), "task: expected an object"),
    ("image outside", lambda d: d["images"][0].update(image_name="../../trajectory.json"),
     r"images\[0\].image_name: expected a file name in frames/"),
    ("image absolute", lambda d: d["images"][1].update(image_name="/etc/passwd"), r"images\[1\].image_name"),
    ("images dict", lambda d: d.update(images={"a": 1}), "images: expected a list"),
]


@pytest.mark.parametrize(("change", "message"), [c[1:] for c in BAD_FIELDS], ids=[c[0] for c in BAD_FIELDS])
def test_every_malformed_trajectory_field_is_named(tmp_path: Path, kitchen: Scene, change, message: str) -> None:
    folder = _episode(tmp_path, kitchen, change)
    with pytest.raises(ViewerError, match=message) as err:
        load_episode(folder, kitchen)
    assert str(err.value).startswith(str(folder / "trajectory.json")) and "\n" not in str(err.value)


def test_a_frame_that_is_not_an_image_or_a_link_is_refused(tmp_path: Path, kitchen: Scene) -> None:
    folder = _episode(tmp_path, kitchen, frames=True)
    frame = folder / "frames" / f"{2:09d}.png"
    frame.write_bytes(b"not a png")
    with pytest.raises(ViewerError, match=f"{frame.name}: not an image"):
        load_episode(folder, kitchen)
    frame.unlink()
    frame.symlink_to("/etc/passwd")
    with pytest.raises(ViewerError, match=f"{frame.name}: a symbolic link; expected a frame image"):
        load_episode(folder, kitchen)
    frame.unlink()
    os.mkfifo(frame)
    with pytest.raises(ViewerError, match=r"a FIFO \(named pipe\); expected a frame image"):
        load_episode(folder, kitchen)


def test_a_fifo_trajectory_is_refused_without_blocking(tmp_path: Path) -> None:
    (tmp_path / "ep").mkdir()
    os.mkfifo(tmp_path / "ep" / "trajectory.json")
    with pytest.raises(ViewerError, match=r"a FIFO \(named pipe\); expected an episode's trajectory.json"):
        load_episode(tmp_path / "ep")
