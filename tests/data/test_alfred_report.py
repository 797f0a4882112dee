"""`luminous alfred parse DIR [--merge] --out OUT`: CDFs per trajectory and floor plan, report.json/.md, coverage
and realisation by CSSG (a small sample here; the whole of valid_seen in the slow test and the benchmark)."""

from __future__ import annotations

import json
import shutil

import pytest

from luminous_sim.cdf import dumps, loads
from luminous_sim.cli.main import main
from luminous_sim.data import parse_alfred, parse_directory
from luminous_sim.data.alfred_report import cdf_file_name, failure_cause
from tests.data.alfred_traj import coord, oid, pickup, put, traj

SAMPLE = (
    "look_at_obj_in_light-AlarmClock-None-DeskLamp-323",
    "pick_two_obj_and_place-Glassbottle-None-Shelf-1",
    "pick_cool_then_place_in_recep-AppleSliced-None-DiningTable-18",
)


def _hand_made(root):
    apple = oid("Apple", 1.0, 0.95, 0.5)
    for i, source in enumerate((coord("CounterTop", 1.0, 0.9, 0.4), coord("Fridge", -1.0, 0.0, 2.0))):
        data = traj("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Microwave"}, "FloorPlan1",
                    [pickup(apple, source), put(apple, oid("Microwave", 0.5, 1.2, -1.0))], task_id=f"trial_{i}")
        path = root / "pick_and_place_simple-Apple-None-Microwave-1" / f"trial_{i}" / "traj_data.json"
        path.parent.mkdir(parents=True)
        path.write_text(json.dumps(data))
    broken = root / "broken" / "trial_x" / "traj_data.json"
    broken.parent.mkdir(parents=True)
    broken.write_text(json.dumps({"task_type": "pick_and_place_simple"}))


def test_cli_writes_cdfs_merged_cdfs_and_reports(tmp_path, capsys):
    src, out = tmp_path / "alfred", tmp_path / "out"
    _hand_made(src)
    assert main(["alfred", "parse", str(src), "--merge", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "parsed: 2/3" in printed and "merged: 1 floor plans, 1 conflicts resolved" in printed
    report = json.loads((out / "report.json").read_text())
    assert (report["total"], report["parsed"]) == (3, 2)
    realised = sum(1 for f in report["files"] if f["realised"] and f["realised"]["ok"])
    assert report["realised"] == realised
    assert f"realised (CSSG, own floor plan's shell, seed 0): {realised}/3" in printed
    broken = next(f for f in report["files"] if f["file"].startswith("broken"))
    assert not broken["parsed"] and "missing key 'pddl_params'" in broken["error"]
    (merged,) = report["merged"]
    assert merged["floor_plan"] == "FloorPlan1" and merged["conflicts"][0]["about"] == "placement"
    written = sorted(p.relative_to(out).as_posix() for p in out.rglob("*.yaml"))
    assert written == ["cdf/pick_and_place_simple-Apple-None-Microwave-1.trial_0.yaml",
                       "cdf/pick_and_place_simple-Apple-None-Microwave-1.trial_1.yaml", "merged/FloorPlan1.yaml"]
    md = (out / "report.md").read_text()
    assert "## broken/trial_x/traj_data.json" in md and "Dropped:" in md and "## merged FloorPlan1" in md
    # the files the parser writes pass the project's CDF validation command
    assert main(["cdf", "validate", *(str(out / p) for p in written)]) == 0


def test_cli_exits_1_when_no_trajectory_parsed(tmp_path, capsys):
    """Issue 27: a parse in which every trajectory fails is not a success (exit 1, one line on stderr naming the
    folder and the first error); the reports are still written. One that parses is exit 0 (above)."""
    src, out = tmp_path / "alfred", tmp_path / "out"
    for name in ("a", "b"):
        path = src / name / "trial_x" / "traj_data.json"
        path.parent.mkdir(parents=True)
        path.write_text(json.dumps({"task_type": "pick_and_place_simple"}))
    assert main(["alfred", "parse", str(src), "--out", str(out)]) == 1
    captured = capsys.readouterr()
    assert "parsed: 0/2" in captured.out
    (line,) = captured.err.strip().splitlines()
    assert f"none of the 2 trajectories under {src} parsed" in line and "missing key" in line, line
    assert json.loads((out / "report.json").read_text())["parsed"] == 0


def test_cli_help_states_the_exit_status(capsys):
    with pytest.raises(SystemExit):
        main(["alfred", "parse", "--help"])
    assert "1 when none did" in " ".join(capsys.readouterr().out.split())


def test_cli_refuses_a_folder_without_trajectories(tmp_path, capsys):
    assert main(["alfred", "parse", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    assert "no traj_data.json found" in capsys.readouterr().err


def test_real_sample_parses_and_is_realised_in_its_own_floor_plan(shared_alfred, tmp_path):
    root = tmp_path / "valid_seen"
    for name in SAMPLE:
        src = shared_alfred / "valid_seen" / name
        if not src.exists():
            pytest.skip(f"{src} not found")
        shutil.copytree(src, root / name)
    report = parse_directory(root, merge=True, seed=0)
    assert report.parsed == len(report.files) == len(SAMPLE)
    assert report.realised == len(SAMPLE), [f.realised for f in report.files]
    assert set(report.merged) == {"FloorPlan323", "FloorPlan1", "FloorPlan18"}


def test_failure_cause_names_types_not_instances():
    data = traj("pick_and_place_simple", {"object_target": "Apple", "parent_target": "Fridge"}, "FloorPlan1",
                [pickup(oid("Apple", 1, 1, 1), coord("CounterTop", 1, 0.9, 1)), put(oid("Apple", 1, 1, 1),
                                                                                    oid("Fridge", 2, 0, 2))])
    cdf = parse_alfred(data).cdf
    message = ("CDF x: no valid layout in 20 samples: apple on counter_top (cdf:scene.relations[0]) (20/20); "
               "fridge could not be placed (3/20)")
    assert failure_cause(message, cdf) == "Apple on CounterTop"
    outside = "task.agent.position: (9, 9) is outside"
    assert failure_cause(f"CDF x: {outside}", cdf) == outside
    assert cdf_file_name("a-b-1/trial_T1/traj_data.json") == "a-b-1.trial_T1.yaml"


@pytest.mark.slow
def test_whole_valid_seen_report_is_consistent(shared_alfred, tmp_path):
    report = parse_directory(shared_alfred / "valid_seen", merge=True, seed=0)
    assert report.parsed == len(report.files) == 251
    failed = [f for f in report.files if not f.realised.ok]
    assert all(f.realised.cause for f in failed) and sum(report.causes().values()) == len(failed)
    rows = report.by_task_type()
    assert sum(r["realised"] for r in rows.values()) == report.realised
    for m in report.merged.values():
        assert loads(dumps(m.cdf)) == m.cdf
    assert len(report.merged_realised) == len(report.merged) == 88
