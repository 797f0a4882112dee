"""benchmarks/bench_alfred_parse.py --solve: a parsed CDF's own task solved, and the solved-per-type table."""

from __future__ import annotations

import pytest

from luminous_sim.data import CoverageReport, Realisation, parse_alfred
from luminous_sim.data.alfred_report import FileOutcome
from tests.conftest import load_script

TRAJ = "valid_seen/pick_and_place_simple-Newspaper-None-Sofa-224"


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_alfred_parse.py")


@pytest.fixture(scope="module")
def parse(shared_alfred):
    path = next((shared_alfred / TRAJ).rglob("traj_data.json"))
    return parse_alfred(path, source=TRAJ)


def test_the_table_counts_every_file_and_the_unsolved_causes(bench, parse, capsys):
    t = parse.task_type
    files = [
        FileOutcome("a", t, parse, realised=Realisation(True)),
        FileOutcome("b", t, parse, realised=Realisation(True)),
        FileOutcome("c", t, parse, realised=Realisation(False, "Pan on StoveBurner")),
        FileOutcome("d", t, error="no floor plan"),
        FileOutcome("e", "look_at_obj_in_light", parse, realised=Realisation(True)),
    ]
    report = CoverageReport("root", 0, files)
    solved = {"a": (True, ""), "b": (False, "[unreachable] apple_1 at 1.25 m"),
              "e": (False, "[unreachable] mug_2 at 0.5 m")}
    bench.solved_table(report, solved)
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith(t))
    assert row.split()[1:] == ["4", "3", "2", "1"]
    assert next(line for line in out.splitlines() if line.startswith("look_at")).split()[1:] == ["1", "1", "1", "0"]
    assert next(line for line in out.splitlines() if line.startswith("all")).split()[1:5] == ["5", "4", "3", "1"]
    assert "not solved: 4 (1 not parsed, 1 not realised, 2 realised but unsolved)" in out
    assert "  2  [unreachable] OBJ at N m" in out  # names and numbers folded, so causes add up


def test_a_real_parsed_cdf_is_solved_in_its_floor_plan(bench, parse):
    assert bench.solve_one((TRAJ, parse.cdf, parse.floor_plan, 0)) == (True, "")


def test_a_task_that_cannot_run_gives_its_cause_not_an_exception(bench, parse):
    ok, cause = bench.solve_one((TRAJ, parse.cdf, "FloorPlan1", 0))  # a kitchen shell for a living-room CDF
    assert not ok and cause.startswith("CDFError: ") and "room_type" in cause
