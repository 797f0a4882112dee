"""Behaviour cloning on the `alfred` family (the frozen split's own episodes, Table 4's setting): demonstrations
of the split's entries, a checkpoint that records the env it was trained in, and the clone evaluated by
`luminous bc eval --family alfred` on the split's entries with ALFRED's limits."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("torch")

from luminous_sim.bc import (  # after the skip: these need torch
    ALFRED_ENV,
    CHECKPOINT_VAR,
    FAMILIES,
    collect_demos,
    demos_env,
    load_checkpoint,
    load_demos,
    train_bc,
)
from luminous_sim.benchmark import benchmark_entry
from luminous_sim.cli.main import main
from luminous_sim.errors import LuminousError
from luminous_sim.eval import evaluate
from luminous_sim.vocab import ALFRED_TASK_TYPES

ENTRY = 203  # S+ pick_and_place_simple: a 24-step demonstration


@pytest.fixture(scope="module")
def demos(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("alfred-demos")
    summary = collect_demos(folder, "S+", [ENTRY], family="alfred")
    assert summary["recorded"] == 1, summary
    return folder


def test_a_demo_is_the_split_entry_itself(demos):
    (demo,) = load_demos(demos)
    entry = benchmark_entry("S+", ENTRY)
    assert demo.success and demo.index == ENTRY and entry.task_type == "pick_and_place_simple"
    assert demo.labelled == len(demo.actions) > 0
    assert demo.rgb.shape[1:] == (ALFRED_ENV["height"], ALFRED_ENV["width"], 3)
    env = demos_env(demos)
    assert set(env["task_types"]) == set(ALFRED_TASK_TYPES)
    assert env["max_steps"] == FAMILIES["alfred"]["max_steps"] == 1000
    assert env["object_slots"] == ALFRED_ENV["object_slots"]


def test_a_pickup_folder_refuses_alfred_demos(demos, tmp_path):
    collect_demos(tmp_path, "S+", [], family="pickup")
    with pytest.raises(LuminousError, match="another env"):
        collect_demos(tmp_path, "S+", [ENTRY], family="alfred")
    with pytest.raises(LuminousError, match="unknown behaviour-cloning family 'both'"):
        collect_demos(tmp_path / "x", "S+", [ENTRY], family="both")


def test_the_checkpoint_records_the_env_of_its_demos_and_the_clone_plays_alfred_entries(demos, tmp_path,
                                                                                         monkeypatch):
    path = tmp_path / "bc.pt"
    train_bc(demos, path, epochs=2, batch_size=8, seed=0)
    _, meta = load_checkpoint(path)
    assert meta["env"] == demos_env(demos)
    monkeypatch.setenv(CHECKPOINT_VAR, str(path))
    (episode,) = evaluate("luminous_sim.bc:bc_agent", "U+", [3], env_kwargs={**ALFRED_ENV, "max_steps": 12},
                          track="privileged").outcomes
    assert episode.task_type == benchmark_entry("U+", 3).task_type
    assert episode.episode_key == benchmark_entry("U+", 3).episode_key
    assert episode.end in {"success", "stop", "max_failures", "max_steps"} and episode.steps > 0


def test_bc_eval_plays_the_split_entries_with_alfreds_limits(tmp_path, capsys):
    out = tmp_path / "eval.json"
    code = main(["bc", "eval", "--family", "alfred", "--policy", "random", "--split", "U+", "--start", "3",
                 "--episodes", "1", "--out", str(out)])
    assert code == 0, capsys.readouterr().err
    report = json.loads(out.read_text())
    (episode,) = report["episodes"]
    assert episode["episode_key"] == benchmark_entry("U+", 3).episode_key
    assert episode["end"] in {"stop", "max_failures"} and episode["failures"] <= 10 and episode["steps"] < 1000


def test_a_missing_collection_record_is_named(tmp_path):
    with pytest.raises(LuminousError, match="collection.json"):
        demos_env(tmp_path)
