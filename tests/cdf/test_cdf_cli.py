"""`luminous cdf validate|schema`, called through `luminous_sim.cli.main.main`."""

from __future__ import annotations

from pathlib import Path

import pytest

from luminous_sim.cdf import schema_text
from luminous_sim.cli import main as cli
from tests.cdf.helpers import EXAMPLES


@pytest.fixture(autouse=True)
def _only_cdf_subcommand(monkeypatch: pytest.MonkeyPatch) -> None:
    # Keep these tests independent of other subcommands' imports.
    monkeypatch.setattr(cli, "SUBCOMMAND_MODULES", ("luminous_sim.cli.cdf_cmd",))


def test_cdf_subcommand_is_registered() -> None:
    import importlib

    assert "luminous_sim.cli.cdf_cmd" in importlib.reload(cli).SUBCOMMAND_MODULES


def test_validate_examples_exits_zero(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["cdf", "validate", *map(str, EXAMPLES)]) == 0
    out = capsys.readouterr().out
    for path in EXAMPLES:
        assert f"{path}: OK" in out
    assert "upgraded from v1" in out
    assert "placement order:" in out


def test_validate_error_exits_two_with_the_message(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "kitchen.yaml"
    bad.write_text(
        "cdf_version: 2\nscene:\n  room_type: Kitchen\n  objects: [{name: apple, type: Apple}]\n"
        "  relations:\n    - {subject: apple, relation: near, target: tabel}\n"
    )
    assert cli.main(["cdf", "validate", str(EXAMPLES[0]), str(bad)]) == 2
    captured = capsys.readouterr()
    assert f"{EXAMPLES[0]}: OK" in captured.out
    assert captured.err.startswith(
        f"luminous cdf: error: {bad}: scene.relations[0].target: unknown name 'tabel'"
    )


def test_validate_missing_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["cdf", "validate", str(tmp_path / "nope.yaml")]) == 2
    assert "cannot read the file" in capsys.readouterr().err


def test_schema_writes_the_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["cdf", "schema", "--out", str(tmp_path / "s")]) == 0
    written = Path(capsys.readouterr().out.strip())
    assert written.read_text() == schema_text()


def test_schema_to_an_unwritable_place(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    assert cli.main(["cdf", "schema", "--out", str(blocker / "sub")]) == 2
    assert "cannot write the schema" in capsys.readouterr().err


def test_usage_errors_exit_two() -> None:
    with pytest.raises(SystemExit) as info:
        cli.main(["cdf", "validate"])
    assert info.value.code == 2
