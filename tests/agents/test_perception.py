"""The rgb track's perception: the network trained from a perception dataset (the same bytes for a seed, the
data's digest and the command recorded, evaluation and unfinished datasets refused, depth and types that
improve on the training frames), its checkpoint read back or refused, its scores, and the instance tracker
giving an object one id from frame to frame."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("torch")

from luminous_sim.agents import (
    TASK_NAMED,
    InstanceTracker,
    Intrinsics,
    OwnPose,
    Perception,
    PerceptionError,
    PerceptionScores,
    PerceptionSettings,
    default_perception,
    train_perception,
)
from luminous_sim.agents.instances import MIN_PIXELS
from luminous_sim.agents.perception_net import CLASSES
from luminous_sim.agents.perception_training import read_frames, score
from luminous_sim.data import build_perception, evaluation_jobs, perception_jobs, read_manifest

TINY = PerceptionSettings(seed=1, epochs=2, batch=8, side=32, channels=(4, 8, 8, 8, 8), threads=1)


@pytest.fixture(scope="module")
def data(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("perception") / "train"
    build_perception(out, perception_jobs(seed=5, generated=2, size=64))
    return out


def test_training_gives_the_same_bytes_for_a_seed_and_records_its_data(data, tmp_path):
    first, again = train_perception([data], TINY, command="c"), train_perception([data], TINY, command="c")
    first.save(tmp_path / "a.pt")
    again.save(tmp_path / "b.pt")
    assert (tmp_path / "a.pt").read_bytes() == (tmp_path / "b.pt").read_bytes()
    other = train_perception([data], PerceptionSettings(**{**TINY.to_dict(), "seed": 2,
                                                           "channels": TINY.channels}), command="c")
    other.save(tmp_path / "c.pt")
    assert (tmp_path / "c.pt").read_bytes() != (tmp_path / "a.pt").read_bytes()
    record = Perception.load(tmp_path / "a.pt").record
    digest = hashlib.sha256((data / "manifest.jsonl").read_bytes()).hexdigest()
    assert record["data"][0]["manifest_sha256"] == digest and record["command"] == "c"
    assert record["settings"]["seed"] == 1 and len(record["epochs"]) == 2


def test_it_learns_depth_and_types_on_its_training_frames(data):
    train, _, _ = read_frames([data], 32)
    settings = PerceptionSettings(seed=0, epochs=24, batch=8, side=32, channels=(8, 16, 16, 16, 16), threads=1,
                                  lr=5e-3, depth_weight=5.0)
    untrained = train_perception([data], PerceptionSettings(**{**settings.to_dict(), "epochs": 0,
                                                              "channels": settings.channels}))
    trained = train_perception([data], settings)
    before, after = score(untrained.net, train)["all"], score(trained.net, train)["all"]
    assert after["depth_abs_rel"] < 0.5 * before["depth_abs_rel"], (before, after)
    # untrained, the head's bias gives every pixel the commonest type: the share right is the floor's and walls'
    assert after["pixel_accuracy"] > before["pixel_accuracy"] + 0.05, (before, after)
    assert after["miou"] > before["miou"] + 0.02, (before, after)  # at 32 px most objects are a pixel or two


def test_checkpoints_read_back_and_bad_ones_are_refused(data, tmp_path):
    perception = train_perception([data], TINY)
    perception.save(tmp_path / "p.pt")
    loaded = Perception.load(tmp_path / "p.pt")
    rgb = np.random.default_rng(0).integers(0, 255, (50, 70, 3), dtype=np.uint8)
    types, depth = loaded.predict(rgb)
    assert types.shape == depth.shape == (50, 70) and 0 <= types.min() and types.max() < CLASSES
    assert np.array_equal(types, perception.predict(rgb)[0]) and (depth > 0).all()
    with pytest.raises(PerceptionError, match="shape"):
        loaded.predict(rgb[..., 0])
    with pytest.raises(PerceptionError, match="no such perception checkpoint"):
        Perception.load(tmp_path / "none.pt")
    (tmp_path / "bad.pt").write_bytes(b"not a checkpoint")
    with pytest.raises(PerceptionError, match="not a readable perception checkpoint"):
        Perception.load(tmp_path / "bad.pt")


def test_evaluation_and_unfinished_datasets_never_feed_training(data, tmp_path):
    evaluation = tmp_path / "eval"
    build_perception(evaluation, evaluation_jobs("U+", [0], size=64))
    with pytest.raises(PerceptionError, match="an evaluation dataset .*U\\+"):
        train_perception([data, evaluation], TINY)
    header = json.loads((data / "perception.json").read_text())
    unfinished = tmp_path / "unfinished"
    unfinished.mkdir()
    (unfinished / "manifest.jsonl").write_bytes((data / "manifest.jsonl").read_bytes())
    (unfinished / "perception.json").write_text(json.dumps({**header, "complete": False}))
    with pytest.raises(PerceptionError, match="unfinished perception dataset"):
        train_perception([unfinished], TINY)


def test_scores_count_intersections_and_unions_over_frames():
    t = TASK_NAMED[0]
    truth = np.zeros((2, 4, 4), np.int64)
    truth[0, :2] = t  # 8 pixels of t in frame 0, none in frame 1
    predicted = np.zeros_like(truth)
    predicted[0, :1] = t  # 4 right
    predicted[1, :1] = t  # 4 wrong
    scores = PerceptionScores()
    scores.add("Kitchen", predicted, truth, np.full((2, 4, 4), 1.1), np.ones((2, 4, 4)))
    summary = scores.summary()
    assert summary["Kitchen"] == {"frames": 2, "types": 1, "miou": round(4 / 12, 4), "pixel_accuracy": 0.75,
                                  "depth_abs_rel": 0.1}
    assert summary["all"]["miou"] == summary["Kitchen"]["miou"]
    merged = PerceptionScores()
    merged.add_counts(json.loads(json.dumps(scores.to_counts())))
    merged.add_counts(scores.to_counts())
    assert merged.summary()["Kitchen"] == {**summary["Kitchen"], "frames": 4}


def test_the_tracker_keeps_one_id_per_object_from_frame_to_frame():
    """Fed the simulator's own types and depth along a walk (its pose kept from its own moves), the tracker's ids
    map onto the true instances one to one: each true object keeps the id it was first given."""
    from luminous_sim.env import LuminousEnv

    env = LuminousEnv(width=120, height=120, depth=True, segmentation=True, instance_types=True, verify_expert=False)
    try:
        obs, _ = env.reset(seed=11)
        tracker, pose = InstanceTracker(Intrinsics(120, 120)), OwnPose()
        first_id: dict[int, int] = {}
        agree = total = 0
        for name in ["RotateRight"] * 4 + ["MoveAhead", "RotateLeft", "LookDown", "RotateLeft", "MoveAhead"] * 3:
            ids = tracker.update(obs["instance_types"], obs["depth"][..., 0], pose)
            truth = obs["segmentation"]
            for body in np.unique(truth[obs["instance_types"] > 0]):
                pixels = truth == body
                if pixels.sum() < 4 * MIN_PIXELS:
                    continue
                given = ids[pixels][ids[pixels] >= 0]
                mine = int(np.bincount(given).argmax()) if len(given) else -1
                first_id.setdefault(int(body), mine)
                agree += first_id[int(body)] == mine
                total += 1
            obs, _, _, _, info = env.step(env.actions.index(name))
            if not info.get("failure_code"):
                pose = pose.after(name)
        assert total > 30 and agree / total > 0.9, (agree, total)
        assert len(set(first_id.values())) >= 0.9 * len(first_id)  # distinct objects, distinct ids
    finally:
        env.close()


def test_the_cli_trains_and_scores_and_modular_rgb_plays_with_the_network_named(data, tmp_path, capsys,
                                                                               monkeypatch):
    """`luminous agents train-perception` writes a checkpoint recording its data and command; `score-perception`
    scores every frame; `luminous eval --policy luminous_sim.agents:modular_rgb` (ALFRED's rules: rgb only)
    plays an entry in the sandbox's child process with the network `LUMINOUS_PERCEPTION` names (`modular` itself
    is refused there: tests/agents/test_modular.py); with none named and none shipped, the error says how."""
    from luminous_sim.agents.perception import PERCEPTION_FILE, PERCEPTION_VAR
    from luminous_sim.cli.main import main
    from luminous_sim.eval import evaluate

    out = tmp_path / "cli.pt"
    assert main(["agents", "train-perception", "--data", str(data), "--out", str(out), "--epochs", "1",
                 "--side", "32", "--threads", "1", "--max-frames", "16", "--quiet"]) == 0
    record = json.loads(capsys.readouterr().out)
    assert record["frames"]["train"] <= 16 and record["command"].startswith("luminous agents train-perception")
    assert record["data"][0]["manifest_sha256"] == hashlib.sha256((data / "manifest.jsonl").read_bytes()).hexdigest()
    assert main(["agents", "score-perception", "--data", str(data), "--perception", str(out)]) == 0
    assert json.loads(capsys.readouterr().out)["all"]["frames"] == sum(r["frames"] for r in read_manifest(data))
    monkeypatch.setenv(PERCEPTION_VAR, str(out))
    assert default_perception().side == 32
    (outcome,) = evaluate("luminous_sim.agents:modular_rgb", "U+", [2], env_kwargs={"max_steps": 25}).outcomes
    assert outcome.drawn and outcome.steps > 0
    monkeypatch.delenv(PERCEPTION_VAR)
    if not PERCEPTION_FILE.is_file():
        with pytest.raises(PerceptionError, match="train-perception"):
            default_perception()
