"""Issue 17: every `luminous` entry point refuses bad input with one line (exit 2), never a traceback."""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import trimesh

from luminous_sim.cli.main import DESCRIPTION, build_parser, main

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "cdf" / "examples"


def run(argv: list[str], capsys) -> tuple[int, str, str]:
    """main(argv) with argparse's SystemExit turned into its status."""
    try:
        code = main(argv)
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 2
    out = capsys.readouterr()
    return code, out.out, out.err


def one_line_error(err: str) -> bool:
    lines = [ln for ln in err.splitlines() if ln.strip() and not ln.startswith(("usage:", " "))]
    return len(lines) == 1 and "error:" in lines[0] and "Traceback" not in err


# item 4: negative seeds
@pytest.mark.parametrize("argv", [
    ["generate", "--out", "o", "--seed", "-1"],
    ["demo", "--seed", "-1"],
    ["rooms", "generate", "Kitchen", "--seed", "-3", "--out", "r.json"],
    ["rooms", "show", "kitchen_L", "--seed", "-1", "--out", "r.png"],
    ["speaker", "train", "--data", "d", "--out", "s.pt", "--seed", "-1"],
])
def test_negative_seed_is_refused(argv, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(argv, capsys)
    assert code == 2 and one_line_error(err) and "--seed" in err and ("-1" in err or "-3" in err)
    assert not any(tmp_path.iterdir())


# item 5: --out naming a file, a folder, an unwritable place, the wrong kind of file
def test_out_naming_a_file_or_wrong_suffix_is_refused(capsys, tmp_path):
    afile = tmp_path / "taken.txt"
    afile.write_text("x")
    for argv, needle in [
        (["generate", "--out", str(afile), "--no-physics"], "is not a folder"),
        (["demo", "--out", str(afile)], "is not a folder"),
        (["cdf", "schema", "--out", str(afile)], "is not a folder"),
        (["rooms", "show", "kitchen_L", "--out", str(tmp_path / "room.txt")], "ending in .png"),
        (["rooms", "show", "kitchen_L", "--out", str(tmp_path)], "is a folder"),
        (["rooms", "generate", "Kitchen", "--out", str(tmp_path / "room.png")], "ending in .json"),
        (["assets", "sheet", "--out", str(tmp_path / "s.jpg")], "ending in .png"),
    ]:
        code, _, err = run(argv, capsys)
        assert code == 2 and one_line_error(err) and needle in err and "--out" in err, (argv, err)
    assert afile.read_text() == "x"


@pytest.mark.parametrize("argv", [
    ["rooms", "generate", "Kitchen", "--out", "/proc/luminous/k.json"],
    ["rooms", "show", "kitchen_L", "--out", "/proc/luminous.png"],
    ["generate", "--out", "/proc/luminous", "--no-physics"],
    ["cdf", "schema", "--out", "/proc/luminous"],
])
def test_out_where_nothing_can_be_written_is_a_clear_error(argv, capsys):
    code, _, err = run(argv, capsys)
    assert code == 2 and one_line_error(err) and "/proc/luminous" in err


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes anywhere")
def test_unwritable_out_is_a_clear_error(capsys, tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        code, _, err = run(["rooms", "generate", "Kitchen", "--out", str(locked / "sub" / "k.json")], capsys)
        assert code == 2 and one_line_error(err) and "Permission denied" in err and str(locked) in err
        code, _, err = run(["rooms", "show", "kitchen_L", "--out", str(locked / "k.png")], capsys)
        assert code == 2 and one_line_error(err) and "Permission denied" in err
    finally:
        locked.chmod(0o700)


# item 6: a --room of another type than the CDF's
def test_room_of_the_wrong_type_names_its_type(capsys, tmp_path):
    code, _, err = run(["generate", "--cdf", str(EXAMPLES / "bedroom_reading_desk.yaml"), "--room", "FloorPlan12",
                        "--out", str(tmp_path / "o"), "--no-physics"], capsys)
    assert code == 2 and one_line_error(err)
    assert "FloorPlan12 is a Kitchen" in err and "Bedroom" in err and "could not be placed" not in err
    assert not (tmp_path / "o").exists()


def test_help_example_works(capsys, tmp_path):
    """The example in `generate --help` generates a valid scene."""
    gen = next(p for p in _parsers(build_parser()) if p.prog == "luminous generate")
    words = gen.epilog.split("   ")[0].split()
    assert words[:2] == ["example:", "luminous"]
    argv = [w.replace("cdf/", str(REPO / "cdf") + "/", 1) if w.startswith("cdf/") else w for w in words[2:]]
    argv = [str(tmp_path / "scene") if w == "out/scene" else w for w in argv] + ["--no-physics"]
    code, out, err = run(argv, capsys)
    assert code == 0 and "valid: True" in out, err


# item 8: counts that do nothing, unknown types
@pytest.mark.parametrize("count", ["0", "-2", "x"])
def test_count_must_be_positive(count, capsys, tmp_path):
    code, _, err = run(["generate", "--count", count, "--out", str(tmp_path / "o")], capsys)
    assert code == 2 and one_line_error(err) and "--count" in err


def test_assets_list_unknown_type_suggests(capsys):
    code, _, err = run(["assets", "list", "--type", "Mugg"], capsys)
    assert code == 2 and one_line_error(err) and "did you mean Mug" in err
    code, _, err = run(["assets", "list", "--type", "Nonsense"], capsys)
    assert code == 2 and "unknown object type 'Nonsense'" in err


# item 9: a closed pipe, a FIFO
def test_broken_pipe_is_quiet(tmp_path):
    code = "import sys; from luminous_sim.cli.main import main; sys.exit(main(['rooms', 'list', '--json']))"
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            cwd=REPO, env={**os.environ, "PYTHONPATH": str(REPO)})
    proc.stdout.read(10)
    proc.stdout.close()  # what `| head -c 10` does
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=120) == 0 and "Traceback" not in err and "BrokenPipe" not in err, err


def test_fifo_cdf_is_refused_without_reading(tmp_path):
    fifo = tmp_path / "cdf.yaml"
    os.mkfifo(fifo)
    code = f"import sys; from luminous_sim.cli.main import main; sys.exit(main(['cdf', 'validate', {str(fifo)!r}]))"
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120, cwd=REPO,
                          env={**os.environ, "PYTHONPATH": str(REPO)})
    assert proc.returncode == 2
    assert "a FIFO (named pipe); expected a regular CDF file" in proc.stderr and str(fifo) in proc.stderr


# item 10: PyBullet's connect message
def test_new_client_prints_nothing(capfd):
    from luminous_sim.world.client import new_client

    capfd.readouterr()
    client = new_client()
    client.disconnect()
    out = capfd.readouterr()
    assert out.out == "" and "argv[0]" not in out.err


@pytest.mark.parametrize("module", ["camera", "asset_loader", "scene_builder", "physics_check", "world"])
def test_importing_any_world_module_first_prints_nothing(module):
    """PyBullet prints its build time when first imported: whichever world module comes first, nothing shows."""
    proc = subprocess.run([sys.executable, "-c", f"import luminous_sim.world.{module}"], capture_output=True,
                          text=True, timeout=120, cwd=REPO, env={**os.environ, "PYTHONPATH": str(REPO)})
    assert proc.returncode == 0 and proc.stdout == "" and proc.stderr == ""


def test_attributes_of_a_cdf_object_bound_to_the_rooms_own_fixture_are_reported(tmp_path, capsys):
    """A kitchen's fridge is the room's own: a colour asked of it cannot be applied, and that is said."""
    cdf = tmp_path / "fridge.yaml"
    cdf.write_text("cdf_version: 2\nname: red_fridge\nscene:\n  room_type: Kitchen\n  objects:\n"
                   "    - {name: fridge, type: Fridge, attributes: {colour: red}}\n")
    assert main(["generate", "--cdf", str(cdf), "--seed", "0", "--out", str(tmp_path / "out"), "--no-physics"]) == 0
    assert "fridge is the room's own Fridge; its attributes colour were not applied" in capsys.readouterr().out
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["layout"]["ignored_attributes"] == {"fridge": ["colour"]}


# item 11: YAML errors name the file; lists are called lists
def test_yaml_error_names_the_file(capsys, tmp_path):
    bad = tmp_path / "broken.yaml"
    bad.write_text("cdf_version: 2\nscene: [a\n")
    code, _, err = run(["cdf", "validate", str(bad)], capsys)
    assert code == 2 and "<unicode string>" not in err and f'in "{bad}", line 2' in err


def test_a_list_is_not_called_a_tuple(capsys, tmp_path):
    bad = tmp_path / "objs.yaml"
    bad.write_text("cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects: 3\n")
    code, _, err = run(["cdf", "validate", str(bad)], capsys)
    assert code == 2 and "tuple" not in err and "scene.objects: expected a list" in err


# item 13: help texts
def _parsers(parser: argparse.ArgumentParser):
    yield parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                yield from _parsers(sub)


def test_every_option_has_help_and_the_top_level_a_description(capsys):
    parser = build_parser()
    assert parser.description == DESCRIPTION and "Entry point" not in parser.format_help()
    missing = [f"{p.prog} {a.dest}" for p in _parsers(parser) for a in p._actions
               if not isinstance(a, (argparse._HelpAction, argparse._SubParsersAction)) and not a.help]
    assert missing == []


def test_rooms_generate_says_how_its_output_is_used(capsys, tmp_path, monkeypatch):
    parser = build_parser()
    rooms_generate = next(p for p in _parsers(parser) if p.prog.endswith("rooms generate"))
    assert "LUMINOUS_ROOM_LIBRARY" in rooms_generate.format_help()
    code, out, _ = run(["rooms", "generate", "Kitchen", "--out", str(tmp_path / "lib" / "mine.json")], capsys)
    assert code == 0 and f"LUMINOUS_ROOM_LIBRARY={tmp_path / 'lib'}" in out and "--room mine" in out
    monkeypatch.setenv("LUMINOUS_ROOM_LIBRARY", str(tmp_path / "lib"))
    code, out, _ = run(["rooms", "list"], capsys)
    assert code == 0 and "mine " in out
    readme = (REPO / "README.md").read_text()
    assert any("rooms generate" in ln and "LUMINOUS_ROOM_LIBRARY" in ln for ln in readme.splitlines())


# item 1: assets import
def _mug_in_centimetres(path: Path) -> Path:
    mesh = trimesh.creation.cylinder(radius=4.0, height=9.0, sections=16)  # a 9 cm mug, written in cm
    mesh.export(path)
    return path


@pytest.mark.parametrize("flag,value", [("--mass", "nan"), ("--mass", "-5"), ("--mass", "0"), ("--mass", "inf"),
                                        ("--scale", "nan"), ("--scale", "-1"), ("--scale", "0")])
def test_import_refuses_non_positive_or_non_finite(flag, value, capsys, tmp_path, monkeypatch):
    monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(tmp_path / "user"))
    src = _mug_in_centimetres(tmp_path / "mug.stl")
    code, _, err = run(["assets", "import", str(src), "--type", "Mug", "--up", "z", flag, value], capsys)
    assert code == 2 and one_line_error(err) and flag in err
    assert not (tmp_path / "user").exists()


def test_import_library_refuses_nan_mass(tmp_path, monkeypatch):
    from luminous_sim.assets.importer import import_mesh
    from luminous_sim.errors import AssetError

    monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(tmp_path / "user"))
    src = _mug_in_centimetres(tmp_path / "mug.stl")
    for mass in (float("nan"), -5.0, 0.0, float("inf")):
        with pytest.raises(AssetError, match="--mass"):
            import_mesh(src, "Mug", scale=0.01, up="z", mass=mass)
    assert not (tmp_path / "user").exists()


def test_import_refuses_an_implausible_size_and_suggests_the_scale(capsys, tmp_path, monkeypatch):
    monkeypatch.setenv("LUMINOUS_USER_ASSETS", str(tmp_path / "user"))
    src = _mug_in_centimetres(tmp_path / "mug.stl")
    code, _, err = run(["assets", "import", str(src), "--type", "Mug", "--up", "z"], capsys)
    assert code == 2 and one_line_error(err)
    assert "a Mug 9 m across is implausible" in err and "--scale 0.01 (a model in centimetres)" in err
    assert "--any-size" in err and not (tmp_path / "user").exists()
    tiny = trimesh.creation.box((0.01, 0.01, 0.01))
    tiny.export(tmp_path / "sofa.stl")
    code, _, err = run(["assets", "import", str(tmp_path / "sofa.stl"), "--type", "Sofa", "--up", "z"], capsys)
    assert code == 2 and "implausible" in err and "--scale" in err


def test_import_any_size_accepts_it(tmp_path, monkeypatch):
    from luminous_sim.assets.importer import check_size

    check_size(Path("mug.stl"), "Mug", 9.0, 1.0, any_size=True)  # no error
    check_size(Path("mug.stl"), "Mug", 0.1, 1.0, any_size=False)


# item 7: sizes that used to be clamped silently
@pytest.mark.parametrize("obj,needle", [
    ("{name: chair, type: Chair, attributes: {size: 9.9}}", "9.9x or more"),
    ("{name: fridge, type: Fridge, attributes: {size: {width: 9.9, depth: 9.9, height: 9.9}}}", "or more"),
    ("{name: mug, type: Mug, attributes: {size: 1.0e-7}}", "or less"),
])
def test_out_of_range_size_is_refused(obj, needle, capsys, tmp_path):
    cdf = tmp_path / "big.yaml"
    cdf.write_text(f"cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects:\n    - {obj}\n")
    for argv in (["cdf", "validate", str(cdf)], ["generate", "--cdf", str(cdf), "--out", str(tmp_path / "o"),
                                                 "--no-physics"],
                 ["generate", "--cdf", str(cdf), "--out", str(tmp_path / "o"), "--no-physics", "--baseline"]):
        code, _, err = run(argv, capsys)
        assert code == 2 and one_line_error(err) and str(cdf) in err and "scene.objects[0]" in err, err
        assert needle in err and "0.3x to 3x" in err
    assert not (tmp_path / "o").exists()


def test_generate_library_refuses_out_of_range_size():
    from luminous_sim import cdf
    from luminous_sim.cssg.pipeline import generate
    from luminous_sim.errors import CDFError

    doc = cdf.loads("cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects:\n"
                    "    - {name: chair, type: Chair, attributes: {size: 4.0}}\n")
    with pytest.raises(CDFError, match=r"scene.objects\[0\] \(chair\): attributes.size 4"):
        generate(doc, seed=0)


def test_in_range_size_keeps_only_variants_it_fits():
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg.attributes import SCALE_RANGE, candidates, scale_for

    chairs = default_catalog().of_type("Chair")
    tallest = max(e.dims[2] for e in chairs)
    size = {"width": 0.45, "depth": 0.47, "height": float(np.round(tallest * 0.2, 3))}
    picked = candidates(chairs, {"size": size})
    for e in picked:
        assert SCALE_RANGE[0] <= e.scale <= SCALE_RANGE[1]
    assert all(SCALE_RANGE[0] <= scale_for(e, size) for e in chairs if e.id in {p.id for p in picked})
