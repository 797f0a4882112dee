"""The agent's start: a plausibility bound in the schema, and inside the room where the room is known."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml

from luminous_sim.cdf import CDFValidationError, from_document
from luminous_sim.cli import main as cli
from luminous_sim.cssg import generate, start_outside
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.rooms import load_room
from tests.cdf.helpers import base

ROOM = "FloorPlan18"  # outline x -2.05..2.3, y 0..7.55 (L-shaped: x > 1.55 only for y >= 5.35)


def _doc(position: list[float], room: str | None = ROOM) -> dict:
    doc = base()
    if room is not None:
        doc["scene"]["room"] = room
    doc["task"]["agent"] = {"position": position, "rotation": 90}
    return doc


@pytest.fixture(autouse=True)
def _only_cdf_subcommand(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cli, "SUBCOMMAND_MODULES", ("luminous_sim.cli.cdf_cmd",))


@pytest.mark.parametrize(("position", "index"), [([50, 50], 0), ([0, -25.5], 1), ([-1e6, 0], 0)])
def test_schema_refuses_implausible_coordinates(position: list[float], index: int) -> None:
    with pytest.raises(CDFValidationError) as info:
        from_document(_doc(position, room=None), "kitchen.yaml")
    text = str(info.value)
    assert f"kitchen.yaml: task.agent.position[{index}]: " in text, text
    assert "outside -25..25 m" in text and "expected a start inside the room" in text, text


def test_schema_accepts_the_bound_itself() -> None:
    assert from_document(_doc([25, -25], room=None), "kitchen.yaml").task is not None


@pytest.mark.parametrize(("position", "inside"), [([0, 3], True), ([2, 6], True), ([2, 3], False), ([10, 3], False)])
def test_start_outside_follows_the_outline(position: list[float], inside: bool) -> None:
    cdf = from_document(_doc(position), "kitchen.yaml")
    problem = start_outside(cdf, load_room(ROOM))
    assert (problem is None) == inside, problem
    if problem:
        assert f"outside room '{ROOM}'" in problem and "expected a start inside its floor outline" in problem


def test_cli_refuses_a_start_outside_the_named_room(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad, good = tmp_path / "far.yaml", tmp_path / "near.yaml"
    bad.write_text(yaml.safe_dump(_doc([10, 3])))
    good.write_text(yaml.safe_dump(_doc([0, 3])))
    assert cli.main(["cdf", "validate", str(good), str(bad)]) == 2
    captured = capsys.readouterr()
    assert f"{good}: OK" in captured.out
    assert f"{bad}: task.agent.position: (10, 3) is outside room '{ROOM}'" in captured.err, captured.err


def test_generate_refuses_a_start_outside_a_named_room() -> None:
    cdf = from_document(_doc([10, 3]), "kitchen.yaml")
    with pytest.raises(InfeasibleSceneError, match=r"task.agent.position: \(10, 3\) is outside room 'FloorPlan18'"):
        generate(cdf, seed=0)


def test_generate_refuses_a_start_outside_a_given_room() -> None:
    cdf = from_document(_doc([10, 3], room=None), "kitchen.yaml")
    with pytest.raises(InfeasibleSceneError, match=r"task.agent.position: \(10, 3\) is outside room"):
        generate(cdf, seed=0, room=load_room(ROOM))
