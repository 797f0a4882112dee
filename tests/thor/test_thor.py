"""luminous_sim.thor: ai2thor 2.1.0's API on our World, and ALFRED's own unmodified code judging our trials.

The ALFRED tests run `tests/thor/alfred_driver.py` under `python -m luminous_sim.thor` (so `import ai2thor`
resolves through the generated shim, in spawned children too) against ALFRED's code in
../shared/alfred/code, and skip with the reason where it is absent."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from luminous_sim.thor import DATA_VAR, Controller, Event, SceneIndex, ThorSceneError, write_shim
from tests.thor import alfred_code

REPO = Path(__file__).resolve().parents[2]
DRIVER = Path(__file__).with_name("alfred_driver.py")


def _build_split(out: Path, split: str, count: int, start: int = 0) -> Path:
    from luminous_sim.data import BuildOptions, build, split_jobs

    report = build(out, split_jobs(split, count, start), options=BuildOptions(frames=False, video=False),
                   progress=False)
    assert report.built == count, report.summary()
    return out


@pytest.fixture(scope="module")
def splus1(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """S+ episode 2 (look_at_obj_in_light, a Pen under a FloorLamp: 45 actions), built without frames."""
    return _build_split(tmp_path_factory.mktemp("thor") / "splus1", "S+", 1, start=2)


@pytest.fixture(scope="module")
def trial(splus1: Path) -> dict[str, Any]:
    (path,) = sorted(splus1.glob("*/*/*/traj_data.json"))
    return json.loads(path.read_text())


@pytest.fixture()
def controller(splus1: Path, trial: dict[str, Any]):
    c = Controller(quality="MediumCloseFitShadows", data=splus1)
    c.start(player_screen_width=300, player_screen_height=300)
    c.reset(trial["scene"]["floor_plan"])
    c.step(dict(action="Initialize", gridSize=0.25, cameraY=0.75, visibility_distance=1.5, renderImage=True))
    event = c.step(dict(action="SetObjectPoses", objectPoses=trial["scene"]["object_poses"]))
    assert event.metadata["lastActionSuccess"], event.metadata["errorMessage"]
    c.step(dict(trial["scene"]["init_action"]))
    yield c
    c.stop()


def _refused(event: Event) -> None:
    assert event.metadata["lastActionSuccess"] is False
    assert isinstance(event.metadata["errorMessage"], str) and event.metadata["errorMessage"]


# ---------------------------------------------------------------------------------------------- no ALFRED code


def test_shim_makes_ai2thor_resolve_here_without_installing_it(tmp_path: Path):
    import importlib.util

    assert importlib.util.find_spec("ai2thor") is None, "a package named ai2thor is installed; the shim needs none"
    folder = write_shim(tmp_path / "shim")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(folder), str(REPO)])}
    code = "import ai2thor, ai2thor.controller as c; print(ai2thor.__version__, c.Controller.__module__)"
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["2.1.0", "luminous_sim.thor.controller"]


def test_runner_runs_a_script_as_main_with_the_shim(tmp_path: Path):
    script = tmp_path / "uses_thor.py"
    script.write_text("import sys\nfrom ai2thor.controller import Controller\n"
                      "assert __name__ == '__main__'\nprint(Controller.__module__, sys.argv[1:])\n")
    out = subprocess.run([sys.executable, "-m", "luminous_sim.thor", str(script), "a", "--b"], cwd=REPO,
                         env={**os.environ, "PYTHONPATH": str(REPO)}, capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "luminous_sim.thor.controller ['a', '--b']"


def test_event_pose_follows_ai2thor_2_1_0():
    md = {"agent": {"position": {"x": -1.25, "y": 0.9, "z": 2.5}, "rotation": {"x": 0, "y": 270.0, "z": 0},
                    "cameraHorizon": 45.0}, "objects": [], "screenWidth": 300, "screenHeight": 300}
    event = Event(md, np.zeros((300, 300, 3), np.uint8))
    assert event.pose == (-1250, 2500, 270000, 45000)
    assert event.pose_discrete == (-5, 10, 3, 45)


def test_no_dataset_folder_is_a_one_line_error(monkeypatch: pytest.MonkeyPatch):
    monkeypatch.delenv(DATA_VAR, raising=False)
    c = Controller()
    c.reset("FloorPlan8")
    with pytest.raises(ThorSceneError, match=DATA_VAR) as info:
        c.step(dict(action="SetObjectPoses", objectPoses=[]))
    assert "\n" not in str(info.value)


def test_actions_before_a_scene_are_refused_not_raised():
    c = Controller()
    c.reset("FloorPlan8")
    for act in (dict(action="MoveAhead"), dict(action="PickupObject", objectId="Apple|1|2|3"), dict(action=None)):
        _refused(c.step(act))
    assert c.step(dict(action="Initialize", gridSize=0.25)).metadata["lastActionSuccess"]
    _refused(c.step(dict(action="Initialize", gridSize=0.1)))


# ------------------------------------------------------------------------------------------ with a built trial


def test_scene_is_identified_by_floor_plan_and_object_poses(splus1: Path, trial: dict[str, Any]):
    index = SceneIndex.of(splus1)
    scene = trial["scene"]
    found = index.find(scene["floor_plan"], scene["object_poses"])
    assert found.task_type == trial["task_type"]
    assert found.scene().room.name
    moved = [dict(p, position={**p["position"], "x": p["position"]["x"] + 1.0}) for p in scene["object_poses"]]
    for floor_plan, poses, words in ((scene["floor_plan"], moved, "has these"), ("FloorPlan999", scene["object_poses"],
                                                                                 "no trial of FloorPlan999")):
        with pytest.raises(ThorSceneError, match=words) as info:
            index.find(floor_plan, poses)
        assert "\n" not in str(info.value)


def test_metadata_has_ai2thor_keys_and_segmentation_matches(controller: Controller):
    event = controller.last_event
    md = event.metadata
    for key in ("agent", "objects", "inventoryObjects", "lastAction", "lastActionSuccess", "errorMessage",
                "sceneName", "screenWidth", "screenHeight", "colors", "reachablePositions"):
        assert key in md, key
    assert set(md["agent"]) >= {"position", "rotation", "cameraHorizon"}
    fields = {"objectId", "objectType", "name", "position", "rotation", "visible", "pickupable", "receptacle",
              "openable", "toggleable", "sliceable", "dirtyable", "isOpen", "isToggled", "isSliced", "isDirty",
              "isCooked", "temperature", "parentReceptacles", "receptacleObjectIds", "axisAlignedBoundingBox",
              "distance"}
    for obj in md["objects"]:
        assert fields <= set(obj), fields - set(obj)
    assert event.frame.shape == (300, 300, 3) and event.frame.dtype == np.uint8
    assert event.depth_frame is not None and event.depth_frame.shape == (300, 300)
    seg = event.instance_segmentation_frame
    assert seg is not None and seg.shape == (300, 300, 3)
    assert event.instance_masks, "the start view shows no object"
    for oid, mask in event.instance_masks.items():
        color = event.object_id_to_color[oid]
        assert event.color_to_object_id[color] == oid
        assert np.all(seg[mask] == color)


def test_object_names_are_those_of_object_poses(controller: Controller, trial: dict[str, Any]):
    names = {o["name"] for o in controller.last_event.metadata["objects"]}
    assert {p["objectName"] for p in trial["scene"]["object_poses"]} <= names


def test_refusals_are_events_with_an_error_message(controller: Controller):
    event = controller.last_event
    far = max((o for o in event.metadata["objects"] if o["pickupable"]), key=lambda o: o["distance"])
    refusals = [
        dict(action="FlyAway"),
        dict(action="PutObject", objectId="Apple|+0.00|+0.00|+0.00", receptacleObjectId="Fridge|1|1|1",
             forceAction=True, placeStationary=True),
        dict(action="PickupObject", objectId=far["objectId"]),
        dict(action="PickupObject", objectId="NoSuchThing|+1.00|+1.00|+1.00"),
        dict(action="TeleportFull", x=0.1, y=0.9, z=0.1, rotation=0, horizon=30),
        dict(action="TeleportFull", x=event.metadata["agent"]["position"]["x"], y=0.9,
             z=event.metadata["agent"]["position"]["z"], rotation=45.0, horizon=30, tempRenderChange=True),
        dict(action="SliceObject", objectId=far["objectId"]),
        dict(action="CleanObject", objectId="NoSuchThing|+1.00|+1.00|+1.00"),
        dict(action="SetStateOfAllObjects", StateChange="CanBeUsedUpAndBroken"),
    ]
    pose = event.pose
    for act in refusals:
        refused = controller.step(act)
        _refused(refused)
        assert refused.metadata["lastAction"] == act["action"]
        assert refused.pose == pose
    ok = controller.step(dict(action="GetReachablePositions"))
    assert ok.metadata["lastActionSuccess"] and ok.metadata["reachablePositions"]
    assert all(set(p) == {"x", "y", "z"} for p in ok.metadata["reachablePositions"])


# ------------------------------------------------------------------------------------ ALFRED's own code judging


@pytest.fixture(scope="module")
def alfred(tmp_path_factory: pytest.TempPathFactory) -> Path:
    why = alfred_code.missing()
    if why:
        print(f"skipped: {why}")
        pytest.skip(why)
    return alfred_code.mirror(tmp_path_factory.mktemp("alfred") / "code")


def run_driver(data: list[Path], alfred: Path, modes: list[str], out: Path, timeout: int = 3600,
               extra: list[str] | None = None) -> list[dict[str, Any]]:
    """Run ALFRED's code on the trials of `data` under `python -m luminous_sim.thor`; one row per trial and mode."""
    cmd = [sys.executable, "-m", "luminous_sim.thor"]
    for d in data:
        cmd += ["--data", str(d)]
    cmd += [str(DRIVER), "--alfred", str(alfred), "--out", str(out), *(extra or [])]
    for m in modes:
        cmd += ["--mode", m]
    proc = subprocess.run(cmd, cwd=REPO, env={**os.environ, "PYTHONPATH": str(REPO)}, capture_output=True,
                          text=True, timeout=timeout)
    assert proc.returncode == 0, proc.stderr[-3000:]
    return [json.loads(line) for line in out.read_text().splitlines()]


def test_alfred_evaluation_loop_judges_our_trial_and_the_negative_controls(splus1: Path, alfred: Path,
                                                                           tmp_path: Path):
    rows = run_driver([splus1], alfred, ["spawn", "eval", "negatives"], tmp_path / "rows.jsonl",
                      extra=["--negatives-type", "look_at_obj_in_light"])
    crashes = [r for r in rows if "crash" in r]
    assert not crashes, crashes
    by_mode = {r["mode"]: r for r in rows}
    assert by_mode["spawn"]["child_module"] == "luminous_sim.thor.controller"
    ev = by_mode["eval"]
    assert ev["satisfied"], ev
    assert ev["alfred_gc"] == ev["our_gc"] and ev["alfred_gc"][0] == ev["alfred_gc"][1]
    assert ev["entry"]["success_spl"] == 1.0 and ev["entry"]["path_len_weight"] == ev["steps"]
    neg = by_mode["negatives"]
    assert not neg["failures"], neg["failures"]
    assert not neg["cut"]["satisfied"], neg["cut"]
    assert not neg["moved"]["satisfied"], neg["moved"]
    assert neg["moved"]["hit"] != neg["moved"]["target"], neg["moved"]


def summarize(rows: list[dict[str, Any]], built: Counter[str]) -> tuple[str, list[dict[str, Any]]]:
    """Per task type: trials ALFRED's code judged successful / built, per mode; and every failing row."""
    lines, bad = [], []
    for mode in sorted({r["mode"] for r in rows}):
        ok = Counter(r["task_type"] for r in rows if r["mode"] == mode and r.get("satisfied")
                     and not r.get("failures") and r.get("alfred_gc") == r.get("our_gc"))
        for t in sorted(built):
            lines.append(f"{mode:6s} {t:34s} {ok[t]:3d} / {built[t]:3d}")
        lines.append(f"{mode:6s} {'all':34s} {sum(ok.values()):3d} / {sum(built.values()):3d}")
        bad += [r for r in rows if r["mode"] == mode and not (r.get("satisfied") and not r.get("failures")
                                                              and r.get("alfred_gc") == r.get("our_gc"))]
    return "\n".join(lines), bad


def _sweep(data: Path, alfred: Path, out: Path) -> None:
    built = Counter(p.parent.parent.name.split("-")[0] for p in data.glob("*/*/*/traj_data.json"))
    rows = run_driver([data], alfred, ["eval", "api"], out)
    table, bad = summarize(rows, built)
    print(table)
    for r in bad:
        print("FAILED:", json.dumps({k: r.get(k) for k in ("mode", "trial", "crash", "satisfied", "alfred_gc", "our_gc",
                                                            "failures")}))
    for mode in ("eval", "api"):
        n = sum(1 for r in rows if r["mode"] == mode)
        assert n == sum(built.values())
        assert sum(1 for r in bad if r["mode"] == mode) <= 0.02 * n, table


@pytest.mark.slow
def test_alfred_judges_an_splus_sample(alfred: Path, tmp_path: Path):
    count = int(os.environ.get("LUMINOUS_THOR_SWEEP", "14"))
    _sweep(_build_split(tmp_path / "splus", "S+", count), alfred, tmp_path / "rows.jsonl")


@pytest.mark.slow
def test_alfred_judges_a_from_alfred_sample(alfred: Path, tmp_path: Path):
    from luminous_sim.data import BuildOptions, build_from_alfred

    per_type = int(os.environ.get("LUMINOUS_THOR_SWEEP_PER_TYPE", "2"))
    source = alfred_code.ALFRED / "valid_seen"
    chosen: dict[str, list[Path]] = {}
    for task in sorted(p for p in source.iterdir() if p.is_dir()):
        chosen.setdefault(task.name.split("-")[0], []).append(task)
    split = tmp_path / "valid_seen"
    split.mkdir()
    for tasks in chosen.values():
        for task in tasks[:per_type]:
            os.symlink(task, split / task.name)
    report = build_from_alfred(tmp_path / "built", split, options=BuildOptions(frames=False, video=False),
                               progress=False)
    print(report.summary())
    assert report.built >= 1
    _sweep(tmp_path / "built", alfred, tmp_path / "rows.jsonl")
