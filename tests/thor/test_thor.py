"""luminous_sim.thor: ai2thor 2.1.0's API on our World, and ALFRED's own unmodified code judging our trials.

The ALFRED tests run `tests/thor/alfred_driver.py` under `python -m luminous_sim.thor` (so `import ai2thor`
resolves through the generated shim, in spawned children too) against ALFRED's code in
../shared/alfred/code, and skip with the reason where it is absent."""

from __future__ import annotations

import json
import os
import shutil
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


# ------------------------------------------------------------------------------ hostile input (each refused)


@pytest.mark.parametrize("size", [0, -1, 15, 1025, 10**6, 1.5, True, "300", None])
def test_start_refuses_a_bad_frame_size_with_a_scene_error(size: Any):
    for kw in ({"player_screen_width": size}, {"player_screen_height": size}):
        with pytest.raises(ThorSceneError, match=r"16\.\.1024") as info:
            Controller().start(**kw)
        assert "\n" not in str(info.value)


@pytest.mark.parametrize("make", [
    lambda: Controller(quality="Bogus"), lambda: Controller(quality=5), lambda: Controller(data=5),
    lambda: Controller().start(x_display=5), lambda: Controller().start(port="x"),
    lambda: Controller().start(start_unity="no"), lambda: Controller().reset(None), lambda: Controller().reset(8),
    lambda: Controller().reset("Garbage"), lambda: Controller().reset("FloorPlan1", seed=3),
], ids=["quality", "quality-type", "data", "x_display", "port", "start_unity", "reset-None", "reset-int",
        "reset-name", "reset-kwargs"])
def test_constructor_start_and_reset_refuse_bad_arguments_with_a_scene_error(make: Any):
    with pytest.raises(ThorSceneError):
        make()


def test_reset_takes_ai2thors_physics_suffix():
    c = Controller()
    assert c.reset("FloorPlan12_physics").metadata["lastActionSuccess"]
    assert c.scene_name == "FloorPlan12"


BAD_INITIALIZE = [
    ("gridSize", "0.25"), ("gridSize", float("nan")), ("cameraY", 1.0), ("cameraY", float("nan")),
    ("fieldOfView", 90), ("fieldOfView", 0), ("visibility_distance", float("nan")), ("visibility_distance", -1),
    ("visibility_distance", 0), ("visibility_distance", float("inf")), ("visibility_distance", 100),
    ("visibility_distance", "1.5"), ("visibility_distance", True), ("visibilityDistance", float("nan")),
    ("visibilityDistance", -1.0), ("visibilityDistance", float("inf")), ("renderDepthImage", "yes"),
    ("renderObjectImage", 1), ("renderImage", None), ("makeAgentsVisible", "no"), ("sequenceId", -1),
    ("agentId", 1), ("bogusKey", 1),
]


@pytest.mark.parametrize(("key", "value"), BAD_INITIALIZE, ids=[f"{k}={v!r}" for k, v in BAD_INITIALIZE])
def test_initialize_refuses_a_bad_value_with_a_failed_event(key: str, value: Any):
    c = Controller()
    c.reset("FloorPlan8")
    event = c.step({"action": "Initialize", "gridSize": 0.25, key: value})
    _refused(event)
    assert key in event.metadata["errorMessage"]
    assert c._visibility == 1.5  # a refused Initialize takes none of its values


def test_initialize_takes_alfreds_values_and_a_visibility_in_range():
    c = Controller()
    c.reset("FloorPlan8")
    ok = c.step(dict(action="Initialize", gridSize=0.25, cameraY=0.75, fieldOfView=60, renderImage=True,
                     renderDepthImage=True, renderClassImage=True, renderObjectImage=True, visibility_distance=1.5,
                     makeAgentsVisible=False))
    assert ok.metadata["lastActionSuccess"], ok.metadata["errorMessage"]
    assert c.step(dict(action="Initialize", visibilityDistance=1.0)).metadata["lastActionSuccess"]
    assert c._visibility == 1.0
    _refused(c.step(dict(action="Initialize", visibility_distance=1.0, visibilityDistance=1.5)))


def test_initialize_visibility_reaches_a_loaded_world(controller: Controller):
    assert controller.world.config.visibility_distance == 1.5
    near = [o for o in controller.last_event.metadata["objects"] if o["pickupable"] and 0.6 < o["distance"] <= 1.5]
    assert controller.step(dict(action="Initialize", visibility_distance=0.5)).metadata["lastActionSuccess"]
    assert controller.world.config.visibility_distance == 0.5
    for o in near:
        refused = controller.step(dict(action="PickupObject", objectId=o["objectId"]))
        _refused(refused)
    controller.step(dict(action="Initialize", visibility_distance=1.5))
    assert controller.world.config.visibility_distance == 1.5


REACH_ACTIONS = {"PickupObject": "pickupable", "OpenObject": "openable", "CloseObject": "openable",
                 "ToggleObjectOn": "toggleable", "ToggleObjectOff": "toggleable", "CleanObject": "objectId"}


@pytest.mark.parametrize("force", [{}, {"forceAction": True}, {"forceVisible": True}], ids=["plain", "forceAction",
                                                                                            "forceVisible"])
def test_every_interaction_keeps_alfreds_reach_rule(controller: Controller, trial: dict[str, Any],
                                                    force: dict[str, bool]):
    objects = controller.last_event.metadata["objects"]
    for name, flag in REACH_ACTIONS.items():
        far = max((o for o in objects if o.get(flag)), key=lambda o: o["distance"])
        assert far["distance"] > 1.5
        refused = controller.step(dict(action=name, objectId=far["objectId"], **force))
        _refused(refused)
        assert "too far away" in refused.metadata["errorMessage"], (name, refused.metadata["errorMessage"])
    for step in trial["plan"]["low_actions"]:  # hold the trial's object, then put it somewhere far
        assert controller.step(dict(step["api_action"])).metadata["lastActionSuccess"]
        if step["api_action"]["action"] == "PickupObject":
            break
    held = controller.last_event.metadata["inventoryObjects"][0]["objectId"]
    far = max((o for o in controller.last_event.metadata["objects"] if o["receptacle"]), key=lambda o: o["distance"])
    refused = controller.step(dict(action="PutObject", objectId=held, receptacleObjectId=far["objectId"],
                                   placeStationary=True, **force))
    assert "too far away" in refused.metadata["errorMessage"], refused.metadata["errorMessage"]


@pytest.fixture(scope="module")
def clean_trial(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, Any]]:
    """S+ episode 10 (pick_clean_then_place_in_recep: a Mug washed in the sink), built without frames."""
    data = _build_split(tmp_path_factory.mktemp("thor") / "clean", "S+", 1, start=10)
    (path,) = sorted(data.glob("*/*/*/traj_data.json"))
    return data, json.loads(path.read_text())


def test_clean_object_keeps_alfreds_reach_rule(clean_trial: tuple[Path, dict[str, Any]]):
    data, traj = clean_trial
    scene = traj["scene"]
    c = Controller(data=data)
    c.start(player_screen_width=300, player_screen_height=300)
    c.reset(scene["floor_plan"])
    c.step(dict(action="Initialize", gridSize=0.25, cameraY=0.75, visibility_distance=1.5))
    c.step(dict(action="SetStateOfAllObjects", StateChange="CanBeDirty", forceAction=True))
    assert c.step(dict(action="SetObjectPoses", objectPoses=scene["object_poses"])).metadata["lastActionSuccess"]
    c.step(dict(scene["init_action"]))
    dirty = [o for o in c.last_event.metadata["objects"] if o["dirtyable"] and o["isDirty"]]
    far = max(dirty, key=lambda o: o["distance"])
    hidden = [o for o in dirty if not o["visible"] and o["distance"] <= 1.5]
    assert far["distance"] > 1.5 and hidden
    for force in ({}, {"forceAction": True}, {"forceVisible": True}):
        refused = c.step(dict(action="CleanObject", objectId=far["objectId"], **force))
        assert "too far away" in refused.metadata["errorMessage"], refused.metadata["errorMessage"]
        refused = c.step(dict(action="CleanObject", objectId=hidden[0]["objectId"], **force))
        assert "not visible" in refused.metadata["errorMessage"], refused.metadata["errorMessage"]
    assert c.step(dict(action="CleanObject", objectId="Mug|x", forceVisible="yes")).metadata["lastActionSuccess"] \
        is False
    put = None
    for step in traj["plan"]["low_actions"]:  # ALFRED's own use: the object put in the sink, in view
        act = step["api_action"]
        assert c.step(dict(act)).metadata["lastActionSuccess"]
        put = act["objectId"] if act["action"] == "PutObject" else put
        if act["action"] == "ToggleObjectOn":
            break
    basin = [o for o in c.last_event.metadata["objects"] if o["objectType"] == "SinkBasin" and put in
             o["receptacleObjectIds"]]
    assert basin and c.last_event.get_object(put)["visible"]
    ok = c.step(dict(action="CleanObject", objectId=put))
    assert ok.metadata["lastActionSuccess"], ok.metadata["errorMessage"]
    c.stop()


def test_set_up_and_common_keys_are_checked_not_taken(controller: Controller):
    pose = controller.last_event.pose
    huge = [{"objectName": "A", "position": {"x": 10**400, "y": 0, "z": 0}}]
    for act in (dict(action="SetObjectPoses", objectPoses=huge), dict(action="SetObjectPoses", objectPoses=5),
                dict(action="SetObjectPoses", objectPoses=[5]),
                dict(action="SetObjectToggles", objectToggles=[{"objectType": "FloorLamp", "isOn": "false"}]),
                dict(action="SetObjectToggles", objectToggles=5),
                dict(action="SetStateOfAllObjects", StateChange=["x"]),
                dict(action="SetStateOfAllObjects", StateChange="CanBeDirty", forceAction="yes"),
                dict(action="GetReachablePositions", gridSize=0.1), dict(action="MoveAhead", renderImage="yes"),
                dict(action="RotateLeft", agentId=3), dict(action="CleanObject", objectId=["x"])):
        refused = controller.step(act)
        _refused(refused)
        assert refused.pose == pose


# ------------------------------------------------------------------ the scene index's files (each refused)


def _trial_copy(splus1: Path, root: Path) -> tuple[Path, Path]:
    """A copy of the built trial under `root/S+/task/trial`, and a folder beside `root` with another copy."""
    (src,) = sorted(splus1.glob("*/*/*/traj_data.json"))
    trial, outside = root / "S+" / "task" / "trial", root.parent / "outside"
    for folder in (trial, outside):
        folder.mkdir(parents=True)
        for name in ("traj_data.json", "luminous.json"):
            shutil.copy(src.parent / name, folder / name)
    return trial, outside


def _fault(case: str, trial: Path, outside: Path) -> str:
    """Make the fault `case` in `trial`; the words its refusal says."""
    traj, sidecar = trial / "traj_data.json", trial / "luminous.json"
    if case in ("fifo", "sidecar-fifo"):
        target = traj if case == "fifo" else sidecar
        target.unlink()
        os.mkfifo(target)
        return "FIFO"
    if case in ("dev-zero", "link-outside", "sidecar-link-outside"):
        target = sidecar if case.startswith("sidecar") else traj
        target.unlink()
        os.symlink("/dev/zero" if case == "dev-zero" else outside / target.name, target)
        return "symbolic link"
    if case == "oversized":
        traj.write_text('{"pad": "' + "x" * 2000 + '"}')
        return "MAX_INPUT_BYTES"
    if case == "deep":
        traj.write_text("[" * 100_000 + "]" * 100_000)
        return "nested too deeply"
    if case == "folder-link":
        shutil.rmtree(trial)
        os.symlink(outside, trial)
        return "not walked"
    if case == "not-a-trial":
        traj.write_text(json.dumps({"scene": {"floor_plan": 8, "object_poses": [1]}}))
        return "not a trial"
    raise AssertionError(case)


FAULTS = ["fifo", "sidecar-fifo", "dev-zero", "link-outside", "sidecar-link-outside", "oversized", "deep",
          "folder-link", "not-a-trial"]


@pytest.mark.timeout(120)
@pytest.mark.parametrize("case", FAULTS)
def test_scene_index_refuses_special_linked_oversized_and_malformed_files(case: str, splus1: Path, tmp_path: Path,
                                                                         trial: dict[str, Any],
                                                                         monkeypatch: pytest.MonkeyPatch):
    import luminous_sim.thor.scenes as scenes

    if case == "oversized":
        monkeypatch.setattr(scenes, "MAX_INPUT_BYTES", 1000)  # the limit is named in the refusal
    root = tmp_path / "data"
    words = _fault(case, *_trial_copy(splus1, root))
    index = SceneIndex([root])
    assert index.size() == 0
    assert len(index.refused) == 1 and words in index.refused[0], index.refused
    with pytest.raises(ThorSceneError, match=words) as info:
        index.find(trial["scene"]["floor_plan"], trial["scene"]["object_poses"])
    assert "\n" not in str(info.value)


def test_scene_index_reads_a_trial_within_the_limit(splus1: Path, tmp_path: Path, trial: dict[str, Any]):
    root = tmp_path / "data"
    _trial_copy(splus1, root)
    index = SceneIndex([root])
    assert index.size() == 1 and not index.refused
    assert index.find(trial["scene"]["floor_plan"], trial["scene"]["object_poses"]).scene().room.name
