"""Issue 17, beyond the list: random, hostile argument vectors for every `luminous` subcommand end with exit
status 0 or 2 and never a traceback.

The fast variant replaces the few library calls that build for long (the asset library, contact sheets,
the demo, scene layouts and their pictures, mesh decomposition, the world an export or the viewer builds, the
viewer's server and its wait for Ctrl-C) with stand-ins, so what is exercised is
the command line itself: parsing, checking and error reporting. The slow variant runs `generate` for real.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from types import SimpleNamespace

import pytest
import trimesh
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.cli.main import main

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted(str(p) for p in (REPO / "cdf" / "examples").glob("*.yaml"))

NUMBERS = ["-1", "0", "1", "2", "3", "-2", "nan", "inf", "-inf", "1e308", "1e-320", "0.5", "99999999999999999999",
           "9223372036854775808", "0x10", "1_000", " 4", "", "abc", "--"]
PATHS = ["@file", "@dir", "@fifo", "@missing", "@missing/deep/x", "/proc/nope", "/etc/passwd", "../x", "out.png",
         "out.json", "out.txt", "o", "@dir/x.png", "@dir/x.json"]
TYPES = ["Mug", "Chair", "Fridge", "Nonsense", "mug", "Mugg", "", "Kitchen"]
ROOMS = ["FloorPlan1", "FloorPlan12", "FloorPlan205", "kitchen_L", "bedroom", "../x", "nowhere", "", "FloorPlan99999"]
ROOM_TYPES = ["Kitchen", "Bedroom", "LivingRoom", "Bathroom", "Garage", ""]
LAYOUTS = [str(REPO / "tests" / "layouts" / "fixtures" / n) for n in ("front_kitchen.json", "atiss_bedroom.json")]
MODEL_INFO = str(REPO / "tests" / "layouts" / "fixtures" / "front_model_info.json")
SCENES = ["@scene", "@scene/scene.json", "@nanscene", "@bigscene", "@dupscene"]
EPISODES = ["@episode", "@badepisode", "@otherepisode"]
DATA = ["@data_ok", "@data_escape", "@data_absolute", "@data_badtask", "@data_linked", "@data_fifo",
        "@data_zero", "@data_nested", "@data_missing_type", "@data_tree"]
"""Dataset folders for `eval --data` (`_eval_folders`): one intact trial, and hostile ones."""
EXIT_CODES: dict[tuple[str, ...], tuple[int, ...]] = {("eval",): (0, 1, 2)}
"""Exit statuses a subcommand may end with besides 0 and 2 (`eval`: 1 for a broken trial or a crashed build)."""

COMMANDS: dict[tuple[str, ...], dict[str, list[str] | None]] = {
    ("assets", "build"): {"--types": TYPES, "--out": PATHS, "--jobs": NUMBERS},
    ("assets", "list"): {"--json": None, "--type": TYPES},
    ("assets", "sheet"): {"--out": PATHS, "--types": TYPES, "--tile": NUMBERS, "--states-on": None},
    ("assets", "import"): {"": ["@mesh", "@meshcm", *PATHS], "--type": TYPES, "--scale": NUMBERS + ["0.01"],
                           "--up": ["y", "z", "x"], "--mass": NUMBERS, "--any-size": None},
    ("cdf", "validate"): {"": EXAMPLES + ["@bigsize", "@badyaml", *PATHS]},
    ("cdf", "schema"): {"--out": PATHS},
    ("demo",): {"--out": PATHS, "--seed": NUMBERS, "--room-types": ROOM_TYPES, "--no-episode": None},
    ("generate",): {"--cdf": EXAMPLES + ["@bigsize", "@badyaml", *PATHS], "--room-type": ROOM_TYPES,
                    "--seed": NUMBERS, "--count": NUMBERS, "--out": PATHS, "--room": ROOMS, "--baseline": None,
                    "--no-physics": None, "--method": ["cssg", "uniform", "learned", "x"], "--model": PATHS},
    ("import-layout",): {"": LAYOUTS + PATHS, "--format": ["front", "atiss", "luminous", "x"], "--out": PATHS,
                         "--seed": NUMBERS, "--room": ["Kitchen-2306", "Balcony-1720", *ROOMS],
                         "--model-info": [MODEL_INFO, *PATHS], "--room-type": ROOM_TYPES, "--require": TYPES,
                         "--no-repair": None, "--no-physics": None},
    ("export-layout",): {"": PATHS, "--out": PATHS},
    ("export",): {"": SCENES + PATHS, "--format": ["glb", "usd", "mjcf", "x", ""],
                  "--out": ["out.glb", "out.usda", "out.usdc", "out.xml", "@dir/x.glb", *PATHS], "--no-ceiling": None,
                  "--check": None},
    ("view",): {"": SCENES + PATHS, "--trajectory": EPISODES + PATHS, "--port": NUMBERS + ["65535", "8080"],
                # no host that needs DNS: a label too long is refused while encoding, 192.0.2.1 (TEST-NET-1) by bind
                "--host": ["127.0.0.1", "localhost", "a" * 64 + ".x", "192.0.2.1", "", "::1"]},
    ("train-layouts",): {"--out": PATHS + ["m.pt", "@dir/m.pt"], "--epochs": NUMBERS, "--rooms": NUMBERS,
                         "--seed": NUMBERS, "--no-augment": None, "--quiet": None},
    ("rooms", "list"): {"--json": None},
    ("rooms", "convert"): {"--layouts": PATHS, "--out": PATHS, "--scene": NUMBERS},
    ("rooms", "show"): {"": ROOMS, "--out": PATHS, "--seed": NUMBERS},
    ("rooms", "generate"): {"": ROOM_TYPES, "--shape": ["rect", "L", "two_zone", "O", ""], "--seed": NUMBERS,
                            "--name": ROOMS, "--out": PATHS},
    ("speaker", "train"): {"--data": PATHS, "--out": PATHS, "--epochs": NUMBERS, "--batch-size": NUMBERS,
                           "--lr": NUMBERS, "--seed": NUMBERS, "--held-out": NUMBERS, "--max-examples": NUMBERS,
                           "--emb-dim": NUMBERS, "--hid-dim": NUMBERS, "--eval-beam": NUMBERS, "--quiet": None},
    ("speaker", "describe"): {"--model": PATHS, "--traj": PATHS, "--beam": NUMBERS, "--json": None,
                              "--no-repeat-ngram": NUMBERS},
    ("speaker", "evaluate"): {"--model": PATHS, "--data": PATHS, "--beam": NUMBERS, "--all": None,
                              "--no-repeat-ngram": NUMBERS},
    ("eval",): {"--policy": ["oracle", "random", "oracle", "nowhere:make", "os:getcwd", "x", ""],
                "--data": DATA * 3 + PATHS, "--split": ["S+", "U+", "U+test", "S", "../x"], "--out": PATHS,
                "--episodes": NUMBERS, "--workers": ["1", "0", "-1", "257", "x"], "--seed": NUMBERS,
                "--env": ["max_steps=2", "width=0", "split=S+", "cdf=[1]", "x", "=", "max_steps=nan", "nope=1"],
                "--live": None, "--rebuild": None, "--build": PATHS, "--backend": ["local", "ray", "x"],
                "--address": ["h:1", ""]},
}
"""Each subcommand's flags ("" for positionals) with the values to draw from (None: a switch)."""

WILD = st.text(st.characters(blacklist_categories=("Cs",), blacklist_characters="\x00"), max_size=12)
"""Anything a shell can pass (no NUL, no lone surrogates)."""


@st.composite
def argv_for(draw, command: tuple[str, ...]) -> list[str]:
    flags = COMMANDS[command]
    argv = list(command)
    for flag in draw(st.lists(st.sampled_from(sorted(flags)), max_size=6)):
        values = flags[flag]
        if values is None:
            argv.append(flag)
            continue
        value = draw(st.one_of(st.sampled_from(values), WILD) if draw(st.integers(0, 9)) == 0
                     else st.sampled_from(values))
        argv += [value] if flag == "" else [flag, value]
    if draw(st.booleans()):
        argv.append(draw(st.sampled_from(["--help", "-h", "--nonsense", "x"]) | WILD))
    return argv


def _eval_folders(root: Path, trial: Path) -> dict[str, str]:
    """Dataset folders for `eval --data`: a copy of the built `trial`, and hostile ones (a split key or task path
    that climbs out, a trial folder that is a link, special, endless and deeply nested sidecars, a task naming
    a type its scene lacks, a plain tree without splits.json)."""
    import json
    import shutil

    def folder(name: str, doc: object = None) -> Path:
        data = root / name
        shutil.copytree(trial, data / "S" / "t" / "r")
        (data / "splits.json").write_text(json.dumps(doc or {"S": [{"repeat_idx": 0, "task": "t/r"}]}))
        return data

    folder("data_ok")
    folder("data_escape", {"../../escape": [{"repeat_idx": 0, "task": "S/t/r"}]})
    folder("data_absolute", {str(root / "data_ok"): [{"repeat_idx": 0, "task": "S/t/r"}]})
    folder("data_badtask", {"S": [{"repeat_idx": 0, "task": "../../data_ok/S/t/r"}]})
    linked = folder("data_linked")
    shutil.rmtree(linked / "S" / "t" / "r")
    os.symlink(root / "data_ok" / "S" / "t" / "r", linked / "S" / "t" / "r")
    for name, make in (("data_fifo", os.mkfifo), ("data_zero", lambda p: os.symlink("/dev/zero", p)),
                       ("data_nested", lambda p: p.write_text("[" * 100_000))):
        side = folder(name) / "S" / "t" / "r" / "luminous.json"
        side.unlink()
        make(side)
    missing = folder("data_missing_type") / "S" / "t" / "r"
    for file, params in (("traj_data.json", lambda d: d["pddl_params"]),
                         ("luminous.json", lambda d: d["task"]["pddl_params"])):
        doc = json.loads((missing / file).read_text())
        params(doc)["parent_target"] = "Bathtub"
        (missing / file).write_text(json.dumps(doc))
    (folder("data_tree") / "splits.json").unlink()
    return {f"@{name}": str(root / name) for name in (d.removeprefix("@") for d in DATA)}


def _sandbox(root: Path, trial: Path | None = None) -> dict[str, str]:
    """Files the `@name` values stand for (with `trial`, the dataset folders of `eval --data` too)."""
    (root / "dir").mkdir()
    (root / "file").write_text("not what anything expects\n")
    os.mkfifo(root / "fifo")
    trimesh.creation.cylinder(radius=0.04, height=0.09, sections=12).export(root / "mug.stl")
    trimesh.creation.cylinder(radius=4.0, height=9.0, sections=12).export(root / "mugcm.stl")
    (root / "bigsize.yaml").write_text("cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects:\n"
                                       "    - {name: chair, type: Chair, attributes: {size: 9.9}}\n")
    (root / "badyaml.yaml").write_text("cdf_version: 2\nscene: [a\n")
    names = _scenes(root)
    return {**names, "@file": str(root / "file"), "@dir": str(root / "dir"), "@fifo": str(root / "fifo"),
            "@missing": str(root / "missing"), "@mesh": str(root / "mug.stl"), "@meshcm": str(root / "mugcm.stl"),
            "@bigsize": str(root / "bigsize.yaml"), "@badyaml": str(root / "badyaml.yaml"),
            **(_eval_folders(root, trial) if trial is not None else {})}


def _scene_doc() -> dict:
    import numpy as np

    from luminous_sim.rooms.library import shell_for

    table = {"id": "DiningTable|0", "type": "DiningTable", "asset": "DiningTable_1", "position": [1.0, 1.0, 0.0],
             "yaw": 0.0, "layer": "furniture"}
    apple = {"id": "Apple|0", "type": "Apple", "asset": "Apple_1", "position": [1.0, 1.0, 0.9], "yaw": 0.0,
             "layer": "object", "parent": "DiningTable|0"}
    return {"room": json.loads(shell_for("FloorPlan1", np.random.default_rng(0)).to_json()), "seed": 0,
            "generator": "fuzz", "objects": [table, apple]}


def _scenes(root: Path) -> dict[str, str]:
    """Scene folders (one good, three hostile) and episode folders (one of the good scene, one malformed, one
    of another scene) for `export` and `view`."""
    from luminous_sim.scene import Scene

    doc = _scene_doc()
    hostile = {"nanscene": lambda d: d["objects"][1].update(position=[float("nan"), 0, 0]),
               "bigscene": lambda d: d["objects"][1].update(yaw=1e308),
               "dupscene": lambda d: d["objects"][1].update(id="DiningTable|0")}
    out = {}
    for name, change in [("scene", None), *hostile.items()]:
        data = json.loads(json.dumps(doc))
        if change is not None:
            change(data)
        (root / name).mkdir()
        (root / name / "scene.json").write_text(json.dumps(data))
        out[f"@{name}"] = str(root / name)
    key = Scene.model_validate(doc).content_key()
    low = [{"api_action": {"action": "MoveAhead"}, "high_idx": 0}]
    record = {"init_action": {"x": 1.0, "z": 1.0, "rotation": 0, "horizon": 30}, "plan": {"low_actions": low},
              "scene_key": key, "high_descs": ["walk"]}
    for name, update in [("episode", {}), ("badepisode", {"init_action": {"x": 1, "z": 1, "rotation": float("inf"),
                                                                          "horizon": 30}}),
                         ("otherepisode", {"scene_key": "0" * 20})]:
        (root / name).mkdir()
        (root / name / "trajectory.json").write_text(json.dumps({**record, **update}))
        out[f"@{name}"] = str(root / name)
    return out


def _stub_heavy_work(monkeypatch) -> None:
    import luminous_sim.assets.build as build
    import luminous_sim.assets.importer as importer
    import luminous_sim.cli.generate_cmd as generate_cmd
    import luminous_sim.cssg as cssg
    import luminous_sim.demo as demo
    import luminous_sim.layouts as layouts
    import luminous_sim.scene_outputs as scene_outputs
    import luminous_sim.world.asset_sheet as asset_sheet

    scene = SimpleNamespace(objects=[], room=SimpleNamespace(name="stub"))
    monkeypatch.setattr(build, "build_library", lambda **kw: SimpleNamespace(
        assets=0, seconds=0.0, decompositions_computed=0, decompositions_in_cache=0, catalog="stub"))
    monkeypatch.setattr(asset_sheet, "render_sheet", lambda entries, out, **kw: out)
    monkeypatch.setattr(demo, "run_demo", lambda out, seed, types: [])
    monkeypatch.setattr(demo, "run_demo_episode", lambda out, seed: SimpleNamespace(
        goal_conditions=(1, 1), task_type="stub", success=True, low_actions=0, out_dir=out))
    monkeypatch.setattr(cssg, "generate", lambda doc, seed=0, room=None: SimpleNamespace(scene=scene))
    monkeypatch.setattr(cssg, "sample_uniform", lambda doc, room, rng, cat: (
        SimpleNamespace(to_scene=lambda *a, **k: scene), None))
    monkeypatch.setattr(cssg, "choose_room", lambda doc, rng, catalog=None: None)
    monkeypatch.setattr(generate_cmd, "_learned", lambda doc, shell, seed, model: SimpleNamespace(scene=scene))
    monkeypatch.setattr(layouts, "train_layouts", lambda out, **kw: SimpleNamespace(
        path=out, layouts=0, examples=0, losses=[0.0], seconds=0.0))
    monkeypatch.setattr(scene_outputs, "write_scene_outputs", lambda g, out, physics=True: {"layout": {"ok": True},
                                                                                      "satisfies_cdf": True,
                                                                                      "unplaced_named_by_cdf": [],
                                                                                      "unplaced_others": []})
    import luminous_sim.cli.view_cmd as view_cmd
    import luminous_sim.export as export
    import luminous_sim.viewer.app as viewer_app

    def fake_export(source, fmt, out, ceiling=True):  # the checks, not the PyBullet build and the writing
        export.check_format(fmt, Path(out))
        export.load_scene(Path(source))
        return export.ExportResult(Path(out), fmt, 0, 0, 0.0)

    monkeypatch.setattr(export, "export", fake_export)
    monkeypatch.setattr(viewer_app, "posed_of", lambda scene: None)
    monkeypatch.setattr(viewer_app, "Viewer", lambda scene, posed, episode, host, port: SimpleNamespace(
        scene=scene, url=f"http://{host}:{port}/", close=lambda: None))
    monkeypatch.setattr(view_cmd, "wait_for_interrupt", lambda: None)
    monkeypatch.setattr(importer, "write_asset", lambda spec, out, cache: {"dims": [0.1, 0.1, 0.1],
                                                                          "collision_hulls": 1, "id": spec.asset_id,
                                                                          "type": spec.type,
                                                                          "variant": spec.variant})


def _stub_eval(monkeypatch, data: Path) -> None:
    """`eval` without playing: an episode is a stand-in outcome (every file is still read and checked), the
    canonical build is the intact folder, and no Ray cluster is started."""
    import contextlib

    import luminous_sim.cli.eval_cmd as eval_cmd
    import luminous_sim.data as data_module
    import luminous_sim.eval.evaluator as evaluator
    from luminous_sim.eval import EpisodeOutcome

    def play(env, agent, split, index, seed=0, *, trial="", trial_rel="", **_more):
        return EpisodeOutcome(split, index, "pick_and_place_simple", "FloorPlan1", 0, end="stop",
                              goal_conditions=(0, 1), steps=1, expert_length=1, trial=trial_rel)

    monkeypatch.setattr(evaluator, "play", play)
    monkeypatch.setattr(evaluator, "LuminousEnv", lambda **kw: SimpleNamespace(close=lambda: None))
    monkeypatch.setattr(evaluator, "make_agent", lambda *args, **kwargs: None)
    monkeypatch.setattr(eval_cmd, "_canonical_build", lambda args, backend: data)
    monkeypatch.setattr(data_module, "make_backend", lambda *a, **k: contextlib.nullcontext(None))


def run_one(argv: list[str], capsys, monkeypatch, trial: Path | None = None, codes: tuple[int, ...] = (0, 2)) -> int:
    """Run `luminous argv` in a fresh folder; the exit status, failing on any traceback."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        names = _sandbox(root, trial)
        if trial is not None:
            _stub_eval(monkeypatch, root / "data_ok")
        argv = [names.get(a.split("/")[0], a.split("/")[0]) + a[len(a.split("/")[0]):] if a.startswith("@") else a
                for a in argv]
        monkeypatch.chdir(root)
        monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(root / "user_assets"))
        monkeypatch.setenv("LUMINOUS_ROOM_LIBRARY", str(root / "rooms"))
        try:
            code = main(argv)
        except SystemExit as exc:
            code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 2)
        finally:
            os.chdir(REPO)  # not left inside a folder about to be removed
        err = capsys.readouterr().err
    assert code in codes, (argv, code, err)
    assert "Traceback" not in err, (argv, err)
    return code


TRIED: dict[tuple[str, ...], list[int]] = {}


def _built_trial(request) -> Path:
    """A trial folder of the shared U+ build (`uplus_build`), for `eval --data`."""
    import json

    build = request.getfixturevalue("uplus_build")
    return build / "U+" / json.loads((build / "splits.json").read_text())["U+"][0]["task"]


@pytest.mark.parametrize("command", sorted(COMMANDS), ids=" ".join)
def test_random_arguments_exit_0_or_2(command, capsys, monkeypatch, request):
    trial = _built_trial(request) if command == ("eval",) else None  # built before the stand-ins go in
    _stub_heavy_work(monkeypatch)
    codes = EXIT_CODES.get(command, (0, 2))

    @settings(max_examples=int(os.environ.get('LUMINOUS_FUZZ_EXAMPLES', 40)), deadline=None, database=None,
              suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
    @given(argv_for(command))
    def check(argv):
        TRIED.setdefault(command, []).append(run_one(argv, capsys, monkeypatch, trial, codes))

    check()
    codes = TRIED.get(command, [])
    print(f"\n{' '.join(command)}: {len(codes)} argument vectors, {codes.count(0)} exit 0, {codes.count(2)} exit 2")


@pytest.mark.slow
@settings(max_examples=25, deadline=None, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(argv=argv_for(("generate",)))
def test_random_generate_for_real(argv, capsys, monkeypatch):
    counts = [i for i, a in enumerate(argv) if a == "--count"]
    for i in counts:  # a real layout takes seconds: keep the count small
        if i + 1 < len(argv) and argv[i + 1].lstrip("-").isdigit() and int(argv[i + 1]) > 2:
            argv[i + 1] = "2"
    run_one(argv + ["--no-physics"], capsys, monkeypatch)
