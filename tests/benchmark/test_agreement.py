"""One definition of an episode: `dataset build`, `eval --data`, live `eval` and `env.reset` give the same
episode_key for the same entry, recomputed by each from what it has (the build from the generator, the
evaluation from the trial's files, the env from its restored world); negative controls show the oracle's
replay is judged, not assumed."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from luminous_sim.benchmark import benchmark_entry, read_trial
from luminous_sim.data import Manifest
from luminous_sim.env import LuminousEnv
from luminous_sim.eval import EVAL_ENV, evaluate, evaluate_data
from luminous_sim.world.masks import mask_to_rle
from tests.conftest import UPLUS_BUILT

COUNT = UPLUS_BUILT


@pytest.fixture(scope="module")
def built(uplus_build) -> Path:
    """The shared canonical build of U+'s first entries (one of each task type)."""
    return uplus_build


@pytest.fixture(scope="module")
def replayed(built):
    """The oracle's evaluation of every trial of the build (its recorded actions replayed)."""
    return evaluate_data("oracle", built, split="U+")


def _frozen_keys() -> list[str]:
    return [benchmark_entry("U+", i).episode_key for i in range(COUNT)]


def test_build_eval_and_reset_agree_on_every_key(built, replayed):
    frozen = _frozen_keys()
    records = sorted(Manifest(built / "manifest.jsonl"), key=lambda r: r["order"])
    assert [r["episode_key"] for r in records] == frozen
    assert [o.episode_key for o in replayed.outcomes] == frozen
    assert [o.index for o in replayed.outcomes] == list(range(COUNT))
    env = LuminousEnv(**{**EVAL_ENV, "verify_expert": False, "high_descs": False})  # keys need no expert
    try:
        keys = [env.reset(options={"split": "U+", "index": i})[1]["episode_key"] for i in range(COUNT)]
    finally:
        env.close()
    assert keys == frozen
    live = evaluate("random", "U+", 1, env_kwargs={"max_steps": 3})
    assert live.outcomes[0].episode_key == frozen[0]


def test_the_oracle_replays_every_built_trial_through_the_agent_interface(built, replayed):
    assert all(o.success for o in replayed.outcomes), [(o.index, o.end, o.detail) for o in replayed.outcomes]
    for o in replayed.outcomes:
        trial = read_trial(built / o.trial)
        assert o.steps == len(trial.low_actions) == o.expert_length
        assert o.instruction == trial.task.instruction


def _copy_trial(built: Path, dest: Path, k: int = 0) -> Path:
    record = sorted(Manifest(built / "manifest.jsonl"), key=lambda r: r["order"])[k]
    trial = dest / "mine" / record["trial"]
    shutil.copytree(built / "U+" / record["trial"], trial)
    return trial


def _edit(trial: Path, change) -> None:
    path = trial / "traj_data.json"
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))


def _interactions(data) -> list[int]:
    low = data["plan"]["low_actions"]
    return [k for k, a in enumerate(low) if (a["discrete_action"].get("args") or {}).get("mask")]


def test_a_trial_without_its_last_interaction_is_no_success(built, tmp_path):
    trial = _copy_trial(built, tmp_path)

    def drop_last(data):
        last = _interactions(data)[-1]
        del data["plan"]["low_actions"][last]

    _edit(trial, drop_last)
    (outcome,) = evaluate_data("oracle", tmp_path).outcomes
    assert not outcome.success and outcome.end == "stop"


def test_a_mask_moved_onto_another_object_is_no_success(built, tmp_path):
    trial = _copy_trial(built, tmp_path)
    data = json.loads((trial / "traj_data.json").read_text())
    k = _interactions(data)[0]
    target = data["plan"]["low_actions"][k]["api_action"]["objectId"]
    env = LuminousEnv(**EVAL_ENV)
    try:
        env.reset(options={"trial": str(trial)})
        for a in read_trial(trial).low_actions[:k]:
            env.step(a)
        masks = env.world.instance_masks()
        other = max((o for o in masks if o != target and masks[o].any()), key=lambda o: masks[o].sum())
        moved = mask_to_rle(masks[other])
    finally:
        env.close()

    def move(d):
        d["plan"]["low_actions"][k]["discrete_action"]["args"]["mask"] = moved

    _edit(trial, move)
    (outcome,) = evaluate_data("oracle", tmp_path).outcomes
    assert not outcome.success


def test_the_key_is_recomputed_from_the_files_not_read_from_them(built, tmp_path):
    trial = _copy_trial(built, tmp_path)
    side = trial / "luminous.json"
    doc = json.loads(side.read_text())
    obj = next(o for o in doc["scene"]["objects"] if o.get("layer") == "object")
    obj["position"][0] += 0.01
    side.write_text(json.dumps(doc))
    (outcome,) = evaluate_data("random", tmp_path, env_kwargs={"max_steps": 2}).outcomes
    assert doc["benchmark"]["episode_key"] == _frozen_keys()[0]
    assert outcome.episode_key and outcome.episode_key != _frozen_keys()[0]


def test_a_failed_build_job_counts_against_the_population(built, tmp_path):
    from luminous_sim.data.manifest import _line

    shutil.copytree(built, tmp_path / "b")
    manifest = tmp_path / "b" / "manifest.jsonl"
    lines = manifest.read_text().splitlines()
    record = {k: v for k, v in json.loads(lines[1]).items() if k != "check"}
    assert record["status"] == "built"
    record.update(status="failed", stage="oracle", cause="marked failed by the test", trial=None)
    lines[1] = _line(record).strip()
    manifest.write_text("\n".join(lines) + "\n")
    report = evaluate_data("random", tmp_path / "b", split="U+", env_kwargs={"max_steps": 2})
    assert [o.end == "unavailable" for o in report.outcomes] == [k == 1 for k in range(COUNT)]
    assert report.outcomes[1].cause == "build" and "marked failed" in report.outcomes[1].detail
    assert report.overall.entries == COUNT and report.overall.episodes == COUNT - 1
