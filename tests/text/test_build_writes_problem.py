"""A build writes ALFWorld's problem beside each trial by default and records so; `--no-alfworld` writes
none, and asking for the receptacles' places leaves the trajectory as it is."""

from __future__ import annotations

import json

from luminous_sim.cli.main import main


def test_every_built_trial_has_its_problem_and_ids(uplus_build):
    assert json.loads((uplus_build / "build.json").read_text())["alfworld"] is True
    trials = sorted((uplus_build / "U+").glob("*/*/traj_data.json"))
    assert trials
    for traj in trials:
        problem = (traj.parent / "initial_state.pddl").read_text()
        sidecar = json.loads((traj.parent / "luminous.json").read_text())
        ids = sidecar["alfworld"]["ids"]
        assert problem.startswith("(define (problem plan_trial_t") and "(:domain alfred)" in problem
        assert all(f"    {pddl} - " in problem for pddl in ids.values())
        scene_ids = {o["id"] for o in sidecar["scene"]["objects"]}
        assert set(ids) <= scene_ids  # our own objects (slices appear only once cut)


def test_no_alfworld_writes_no_problem_and_the_same_trajectory(uplus_build, tmp_path):
    out = tmp_path / "build"
    assert main(["dataset", "build", "--split", "U+", "--count", "1", "--no-frames", "--no-alfworld", "--no-progress",
                 "--out", str(out)]) == 0
    assert json.loads((out / "build.json").read_text())["alfworld"] is False
    (trial,) = (out / "U+").glob("*/*/traj_data.json")
    assert not (trial.parent / "initial_state.pddl").exists()
    assert "alfworld" not in json.loads((trial.parent / "luminous.json").read_text())
    same = uplus_build / "U+" / trial.relative_to(out / "U+")
    assert trial.read_bytes() == same.read_bytes()
