"""Issue 27: every command that reads a file names a missing file, a folder, a device and a FIFO as such, and a
malformed file with the file's name, in one line (exit 2), never a traceback; FIFOs are never opened (they
would block)."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from luminous_sim.cli.main import main
from tests.cli.test_errors import one_line_error, run

FRONT = Path(__file__).resolve().parents[1] / "layouts" / "fixtures" / "front_kitchen.json"

COMMANDS = {
    "cdf validate": lambda p, o: ["cdf", "validate", p],
    "generate --cdf": lambda p, o: ["generate", "--cdf", p, "--out", o, "--no-physics"],
    "generate --house": lambda p, o: ["generate", "--house", p, "--out", o, "--no-physics"],
    "run --cdf": lambda p, o: ["run", "--cdf", p, "--out", o],
    "import-layout luminous": lambda p, o: ["import-layout", p, "--format", "luminous", "--out", o],
    "import-layout front": lambda p, o: ["import-layout", p, "--format", "front", "--out", o],
    "import-layout atiss": lambda p, o: ["import-layout", p, "--format", "atiss", "--out", o],
    "import-layout --model-info": lambda p, o: ["import-layout", str(FRONT), "--format", "front", "--model-info", p,
                                                "--out", o],
    "export-layout": lambda p, o: ["export-layout", p, "--out", o + ".json"],
}
KIND = {"missing": ("no such file", "cannot read"), "folder": ("a folder",), "device": ("a device",),
        "fifo": ("a FIFO",), "malformed": ("not JSON", "invalid JSON", "not a valid scene file (not JSON")}


@pytest.fixture()
def inputs(tmp_path: Path) -> dict[str, str]:
    os.mkfifo(tmp_path / "pipe.json")
    (tmp_path / "dir.json").mkdir()
    (tmp_path / "bad.json").write_text('{"a": [1,')
    return {"missing": str(tmp_path / "missing.json"), "folder": str(tmp_path / "dir.json"), "device": "/dev/null",
            "fifo": str(tmp_path / "pipe.json"), "malformed": str(tmp_path / "bad.json")}


@pytest.mark.parametrize("case", list(KIND))
@pytest.mark.parametrize("command", list(COMMANDS))
def test_bad_input_files_are_named_in_one_line(command: str, case: str, inputs: dict[str, str], tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    path = inputs[case]
    out = str(tmp_path / "out")
    code, _, err = run(COMMANDS[command](path, out), capsys)
    assert code == 2 and one_line_error(err), err
    assert path in err and any(k in err for k in KIND[case]), err
    assert not Path(out).exists() and not Path(out + ".json").exists()


@pytest.mark.parametrize(("content", "needle"), [
    ("[]", "not a valid scene file (expected a JSON object, got list)"),
    ("{}", "not a valid scene file (room: Field required; seed: Field required; generator: Field required (and 1 "
           "more))"),
    ('{"room": 3, "seed": "x", "generator": "g", "objects": []}', "not a valid scene file (room: "),
])
def test_export_layout_refuses_a_malformed_scene_in_one_line(content: str, needle: str, tmp_path: Path,
                                                             capsys: pytest.CaptureFixture[str]) -> None:
    scene = tmp_path / "scene.json"
    scene.write_text(content)
    code, _, err = run(["export-layout", str(scene), "--out", str(tmp_path / "l.json")], capsys)
    assert code == 2 and one_line_error(err) and f"{scene}: {needle}" in err, err
    assert not (tmp_path / "l.json").exists()


def test_export_layout_names_a_scene_the_layout_format_refuses(tmp_path: Path,
                                                               capsys: pytest.CaptureFixture[str]) -> None:
    """A scene whose object the stricter layout model refuses (here a state on a type without the ability) is
    named in one line, not a pydantic traceback."""
    assert main(["generate", "--room-type", "Kitchen", "--seed", "1", "--out", str(tmp_path / "g"),
                 "--no-physics"]) == 0
    path = tmp_path / "g" / "scene.json"
    data = json.loads(path.read_text())
    chair = next(i for i, o in enumerate(data["objects"]) if o["type"] in ("Apple", "Bread", "Egg"))
    data["objects"][chair]["states"] = {"isOpen": True}
    path.write_text(json.dumps(data))
    capsys.readouterr()
    code, _, err = run(["export-layout", str(path), "--out", str(tmp_path / "l.json")], capsys)
    assert code == 2 and one_line_error(err), err
    oid = data["objects"][chair]["id"]
    assert f"{path} (as a layout): objects[{chair}] ({oid}): states.isOpen: Apple is not openable" in err
    assert not (tmp_path / "l.json").exists()


def test_bc_checkpoints_and_demo_folders_are_named(tmp_path: Path) -> None:
    pytest.importorskip("torch")
    from luminous_sim.bc.demos import load_demos
    from luminous_sim.bc.train import load_checkpoint
    from luminous_sim.errors import LuminousError

    garbage = tmp_path / "bad.pt"
    garbage.write_text('{"a": [1,')
    for path, needle in [(tmp_path, "a folder; expected a behaviour-cloning checkpoint"),
                         (Path("/dev/null"), "a device; expected a behaviour-cloning checkpoint"),
                         (garbage, "not a behaviour-cloning checkpoint (")]:
        with pytest.raises(LuminousError) as err:
            load_checkpoint(path)
        assert str(err.value).startswith(f"{path}: {needle}") and "\n" not in str(err.value), str(err.value)
    with pytest.raises(LuminousError, match="bad.pt: not a folder; expected the demonstrations folder"):
        load_demos(garbage)


PATH_KIND = {"folder": "a folder", "device": "a device", "fifo": "a FIFO (named pipe)"}
NAMED_COMMANDS = {
    "rooms convert --layouts": (lambda p, o: ["rooms", "convert", "--layouts", p, "--out", o],
                                {"missing": "no such layouts folder", "file": "a regular file", "device": "a device",
                                 "fifo": "a FIFO (named pipe)"}),
    "assets import": (lambda p, o: ["assets", "import", p, "--type", "Mug"],
                      {"missing": "no such file", **PATH_KIND}),
    "speaker describe --model": (lambda p, o: ["speaker", "describe", "--model", p, "--traj", p],
                                 {"missing": "no such file or folder", **PATH_KIND}),
    "speaker evaluate --model": (lambda p, o: ["speaker", "evaluate", "--model", p, "--data", o],
                                 {"missing": "no such file or folder", **PATH_KIND}),
    "speaker train --data": (lambda p, o: ["speaker", "train", "--data", p, "--out", o + ".pt"],
                             {"missing": "no such file or folder", "device": "a device",
                              "fifo": "a FIFO (named pipe)"}),
}


@pytest.mark.parametrize(("command", "case"), [(c, k) for c, (_, kinds) in NAMED_COMMANDS.items() for k in kinds])
def test_paths_are_named_by_what_they_are(command: str, case: str, inputs: dict[str, str], tmp_path: Path,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 27: a folder, a device or a FIFO given where a file (or a file where a folder) is expected is named as
    such, never "not found" or "not a regular file"; FIFOs are never opened."""
    if command.startswith("speaker"):
        pytest.importorskip("torch")
    argv, kinds = NAMED_COMMANDS[command]
    paths = {**inputs, "file": inputs["malformed"]}
    path = paths[case]
    out = str(tmp_path / "out")
    code, _, err = run(argv(path, out), capsys)
    assert code == 2 and one_line_error(err), err
    assert f"{path}: {kinds[case]}" in err and "not found" not in err, err
    assert not Path(out).exists() and not Path(out + ".pt").exists()


def test_a_trajectory_fifo_is_named_without_being_opened(inputs: dict[str, str]) -> None:
    from luminous_sim.errors import LuminousError
    from luminous_sim.language.speaker.records import load_trajectory

    with pytest.raises(LuminousError, match=r"pipe.json: a FIFO \(named pipe\); expected a trajectory file"):
        load_trajectory(inputs["fifo"])


def test_a_foreign_speaker_checkpoint_is_named_without_torchs_weights_only_note(tmp_path: Path) -> None:
    torch = pytest.importorskip("torch")
    import argparse

    from luminous_sim.errors import LuminousError
    from luminous_sim.language.speaker.checkpoint import load_checkpoint

    path = tmp_path / "foreign.pt"
    torch.save({"a": argparse.Namespace(x=1)}, path)
    with pytest.raises(LuminousError) as err:
        load_checkpoint(path)
    text = str(err.value)
    assert text.startswith(f"{path}: not a readable speaker checkpoint (") and "argparse.Namespace" in text, text
    assert "weights_only" not in text and "trust" not in text and "\n" not in text and "\x1b" not in text, text


def test_checkpoints_over_the_limit_are_refused_before_loading(tmp_path):
    """A speaker or behaviour-cloning checkpoint larger than `limits.MAX_CHECKPOINT_BYTES` is named with its size and
    the limit, before torch reads a byte (a sparse file: nothing is written)."""
    from luminous_sim.errors import LuminousError
    from luminous_sim.language.speaker.errors import SpeakerError, check_checkpoint_path
    from luminous_sim.limits import MAX_CHECKPOINT_BYTES

    big = tmp_path / "big.pt"
    with big.open("wb") as f:
        f.truncate(MAX_CHECKPOINT_BYTES + 1)
    with pytest.raises(SpeakerError, match=r"big\.pt: .* bytes; .*MAX_CHECKPOINT_BYTES"):
        check_checkpoint_path(big)
    pytest.importorskip("torch", reason="the behaviour-cloning checkpoint reader needs torch")
    from luminous_sim.bc.train import load_checkpoint

    with pytest.raises(LuminousError, match=r"big\.pt: .* bytes; .*MAX_CHECKPOINT_BYTES"):
        load_checkpoint(big)


JSON_CASES = {
    "fifo": (lambda p: os.mkfifo(p), "a FIFO (named pipe)"),
    "link to /dev/zero": (lambda p: os.symlink("/dev/zero", p), "a symbolic link"),
    "link to a good file": (lambda p: (p.with_name("good.json").write_text("{}"), os.symlink(p.with_name("good.json"),
                                                                                              p)), "a symbolic link"),
    "folder": (lambda p: p.mkdir(), "a folder"),
    "missing": (lambda p: None, "no such file or folder"),
    "over the limit": (lambda p: os.truncate(p.write_bytes(b"") or p, 1001), "over 1000 bytes"),
    "nested": (lambda p: p.write_text("[" * 100_000 + "]" * 100_000), "not JSON (nested too deeply for the parser)"),
    "NaN": (lambda p: p.write_text('{"x": NaN}'), "not JSON (NaN is not a JSON number)"),
    "Infinity": (lambda p: p.write_text("[-Infinity]"), "not JSON (-Infinity is not a JSON number)"),
    "not UTF-8": (lambda p: p.write_bytes(b'"\xff"'), "not JSON ("),
    "truncated": (lambda p: p.write_text('{"a": [1,'), "not JSON ("),
}


@pytest.mark.parametrize("case", list(JSON_CASES))
def test_read_json_file_refuses_before_reading_and_names_the_limit(case: str, tmp_path: Path) -> None:
    """`errors.read_json_file`, which every reader of a user's JSON file goes through: what the path is is checked
    before it is opened (a FIFO would block, /dev/zero is endless), at most limit + 1 bytes are read, the size
    message names the limit, and nesting too deep for the parser is a message, not a RecursionError."""
    from luminous_sim.errors import LuminousError, read_json_file

    class Mine(LuminousError):
        """The caller's own error class, which the refusal must be raised as."""

    make, says = JSON_CASES[case]
    path = tmp_path / "x.json"
    make(path)
    with pytest.raises(Mine) as err:
        read_json_file(path, 1000 if case == "over the limit" else 1 << 20, "a test file (luminous_sim.limits.X)",
                       Mine)
    text = str(err.value)
    assert text.startswith(f"{path}: {says}") and text.endswith("expected a test file (luminous_sim.limits.X)"), text
    assert "\n" not in text


def test_read_json_file_reads_a_small_regular_file(tmp_path: Path) -> None:
    from luminous_sim.errors import read_json_file

    path = tmp_path / "x.json"
    path.write_text('{"a": [1, 2.5, "b", null, true]}')
    assert read_json_file(path, path.stat().st_size, "x") == {"a": [1, 2.5, "b", None, True]}


def test_read_json_file_refuses_a_device_without_reading_it() -> None:
    from luminous_sim.errors import LuminousError, read_json_file

    with pytest.raises(LuminousError, match=r"^/dev/zero: a device; expected x$"):
        read_json_file("/dev/zero", 1 << 20, "x")
