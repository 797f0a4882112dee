"""`luminous rooms ...`: exit codes and outputs."""

from __future__ import annotations

import json

import pytest

import luminous_sim.cli.main as cli_main
from luminous_sim.rooms.library import SHIPPED_DIR
from luminous_sim.rooms.shell import load_shell


@pytest.fixture
def run(monkeypatch, capsys):
    """The real `main` with only `rooms` registered (other subcommands may be work in progress)."""
    monkeypatch.setattr(cli_main, "SUBCOMMAND_MODULES", ("luminous_sim.cli.rooms_cmd",))

    def _run(*argv: str) -> tuple[int, str, str]:
        code = cli_main.main(list(argv))
        out = capsys.readouterr()
        return code, out.out, out.err

    return _run


def test_registered_in_main():
    assert "luminous_sim.cli.rooms_cmd" in cli_main.SUBCOMMAND_MODULES


def test_list(run):
    code, out, _ = run("rooms", "list")
    assert code == 0 and "FloorPlan1 " in out and "kitchen_L" in out
    code, out, _ = run("rooms", "list", "--json")
    rows = json.loads(out)
    assert code == 0 and len([r for r in rows if r["kind"] == "file"]) >= 120
    assert {r["name"] for r in rows} >= {"FloorPlan424", "bathroom_two_zone"}


def test_show_writes_png(run, tmp_path):
    for name in ("kitchen_L", "FloorPlan2"):
        out = tmp_path / f"{name}.png"
        code, text, _ = run("rooms", "show", name, "--out", str(out), "--seed", "4")
        assert code == 0 and out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and str(out) in text


@pytest.mark.parametrize("name", ["../x", "/etc/passwd", "a/b", "nowhere"])
def test_show_bad_name_exits_2(run, tmp_path, name):
    code, _, err = run("rooms", "show", name, "--out", str(tmp_path / "x.png"))
    assert code == 2 and "luminous rooms: error:" in err and not (tmp_path / "x.png").exists()


def test_generate(run, tmp_path):
    out = tmp_path / "k.json"
    code, _, _ = run(
        "rooms", "generate", "Kitchen", "--shape", "two_zone", "--seed", "7", "--out", str(out)
    )
    assert code == 0 and load_shell(out).shape == "two_zone"


def test_convert_missing_folder_exits_2(run, tmp_path):
    code, _, err = run(
        "rooms", "convert", "--layouts", str(tmp_path / "nope"), "--out", str(tmp_path / "o")
    )
    assert code == 2 and "no such layouts folder" in err


def test_convert_one_scene(run, shared_alfred, tmp_path):
    code, out, _ = run(
        "rooms",
        "convert",
        "--layouts",
        str(shared_alfred / "layouts"),
        "--out",
        str(tmp_path),
        "--scene",
        "425",
    )
    assert code == 0 and "wrote 1 rooms" in out
    assert (tmp_path / "FloorPlan425.json").read_text() == (
        SHIPPED_DIR / "alfred" / "FloorPlan425.json"
    ).read_text()


def test_usage_error_exits_2(run):
    with pytest.raises(SystemExit) as exc:
        run("rooms", "show")
    assert exc.value.code == 2
