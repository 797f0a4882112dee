"""benchmarks/bench_agents.py: a played row carries the outcome, the agent's diagnosis and the truth; a failure's
first cause; Table 4's layout with intervals, the S -> S+ difference and the paper's quoted rows."""

from __future__ import annotations

import json

import pytest

from luminous_sim.benchmark import benchmark_entry
from tests.conftest import load_script

pytest.importorskip("torch")


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_agents.py")


def _row(split, index, task_type, success, seed=0, task=None, end=None, subgoal=1, seen=True):
    truth = {"task_type": task_type, "pddl_params": {"object_target": "Apple", "parent_target": "Fridge",
                                                     "mrecep_target": "", "toggle_target": "",
                                                     "object_sliced": False}}
    outcome = {"split": split, "index": index, "task_type": task_type, "floor_plan": "FloorPlan1", "layout": 0,
               "end": end or ("success" if success else "stop"), "success": success,
               "goal_conditions": [1 if success else 0, 1], "steps": 50, "expert_length": 40, "failures": 0}
    return {"job": {"split": split, "index": index, "variant": "parsed", "seed": seed},
            "outcome": outcome, "truth": truth, "seconds": 1.0,
            "diagnosis": {"task": task or truth, "subgoal": subgoal, "subgoals": 4, "action": "PutObject",
                          "target_seen": seen}}


def test_a_failures_first_cause(bench):
    wrong = {"task_type": "pick_and_place_simple", "pddl_params": {"object_target": "Apple",
                                                                  "parent_target": "CounterTop"}}
    assert bench.cause(_row("S+", 0, "pick_and_place_simple", False, task=wrong)) == "misparsed"
    assert bench.cause(_row("S+", 0, "pick_and_place_simple", False, end="max_failures")) == "limit"
    assert bench.cause(_row("S+", 0, "pick_and_place_simple", False, seen=False)) == "not_found"
    assert bench.cause(_row("S+", 0, "pick_and_place_simple", False)) == "interaction"
    assert bench.cause(_row("S+", 0, "pick_and_place_simple", False, subgoal=4)) == "plan_done"


def test_the_table_the_difference_and_the_papers_rows(bench):
    pick, heat = "pick_and_place_simple", "pick_heat_then_place_in_recep"
    results = {("S", "parsed"): [_row("S", i, t, i % 2 == 0) for i, t in enumerate([pick] * 4 + [heat] * 4)],
               ("S+", "parsed"): [_row("S+", i, t, i < 2) for i, t in enumerate([pick] * 4 + [heat] * 4)]}
    text, summary = bench.table(results, ["S", "S+"], "parsed", [0])
    assert "| Pick | 4 | 0.500" in text and summary["S"]["Average"]["sr"]["mean"] == 0.5
    assert summary["S+"]["Heat"]["sr"]["mean"] == 0.0 and summary["S+"]["Pick"]["sr"]["mean"] == 0.5
    lo, hi = summary["S"]["Average"]["sr"]["lo"], summary["S"]["Average"]["sr"]["hi"]
    assert 0.0 <= lo <= 0.5 <= hi <= 1.0
    diff_text, diff = bench.differences(results, [("S", "S+")], "parsed")
    assert diff["S->S+"]["Average"]["difference"] == pytest.approx(-0.25) and "S -> S+" in diff_text
    assert "| Pick | 0.295 | 0.131 | 0.005 | 0.429 |" in bench.paper_rows()
    assert "| Heat | 4 | 0 | 0 | 4 | 0 | 0 | 0 |" in bench.breakdown(results, "S+", "parsed")


def test_a_job_plays_its_entry_through_the_evaluations_play(bench, tmp_path):
    job = bench.Job("U+", 2, "given", 0)
    row = bench.play_job((job, str(tmp_path)))
    entry = benchmark_entry("U+", 2)
    assert row["truth"] == {"task_type": entry.task_type, "pddl_params": dict(entry.pddl_params)}
    assert row["diagnosis"]["task"] == row["truth"] and row["outcome"]["task_type"] == entry.task_type
    assert row["acts"] == row["outcome"]["steps"] + (row["outcome"]["end"] == "stop")
    assert json.loads(bench._row_path(tmp_path, job).read_text()) == row  # resumable: written as it finished
    assert bench.play_job((job, str(tmp_path))) == row


def test_s_is_built_from_an_alfred_split_where_missing_and_sampled_per_type(bench, tmp_path):
    import shutil
    from pathlib import Path

    source = sorted(Path("../shared/alfred/valid_seen").glob("look_at_obj_in_light-*/*/traj_data.json"))[0]
    split = tmp_path / "vs"
    (split / source.parent.parent.name / source.parent.name).mkdir(parents=True)
    shutil.copy(source, split / source.parent.parent.name / source.parent.name / "traj_data.json")
    bench.build_s(split, tmp_path / "S", 1)
    bench.build_s(split, tmp_path / "S", 1)  # resumes: nothing to do
    ((index, name, trial),) = bench._s_sample(tmp_path / "S", 1)
    assert (index, name) == (0, "vs") and Path(trial, "traj_data.json").is_file()


def test_an_rgb_track_job_hands_the_agent_rgb_only_and_scores_its_frames(bench, tmp_path, monkeypatch):
    from luminous_sim.agents import PerceptionSettings, train_perception
    from luminous_sim.agents.perception import PERCEPTION_VAR
    from luminous_sim.data import build_perception, perception_jobs

    build_perception(tmp_path / "p", perception_jobs(seed=5, generated=1, size=64))
    network = tmp_path / "net.pt"
    train_perception([tmp_path / "p"], PerceptionSettings(epochs=1, side=32, channels=(4, 8, 8, 8, 8),
                                                          threads=1)).save(network)
    monkeypatch.setenv(PERCEPTION_VAR, str(network))
    monkeypatch.setattr(bench, "ENV_OVERRIDES", {"max_steps": 30})
    job = bench.Job("U+", 2, "given", 0, track="rgb")
    row = bench.play_job((job, str(tmp_path)))
    assert bench._row_path(tmp_path, job).name == "U+-2-given-0-rgb.json"
    (room,) = row["perception"]
    assert room == benchmark_entry("U+", 2).room_type
    frames = row["perception"][room]["frames"]
    assert frames == (row["acts"] + bench.SCORED_EVERY - 1) // bench.SCORED_EVERY
    scores = bench.agent_frame_scores({("U+", "given"): [row]})
    assert scores["U+"][room]["frames"] == frames and 0 <= scores["U+"]["all"]["miou"] <= 1
