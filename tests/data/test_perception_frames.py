"""The perception dataset: frames with exact labels, deterministic per seed, resumable, never of evaluation
structures, checked against evaluation builds by scene key."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import numpy as np
import pytest

from luminous_sim.cli.main import main
from luminous_sim.data import (
    PerceptionDataError,
    build_perception,
    built_trials,
    iter_shards,
    leaks,
    perception_jobs,
    read_header,
    read_manifest,
)
from luminous_sim.data.perception_frames import EVALUATION_ONLY, EXPERT_FRAMES, EXPLORE_FRAMES
from luminous_sim.vocab import ALL_TYPES

SIZE = 64
"""Small frames: the world's build, not the rendering, is what a job costs."""


def _digests(out: Path) -> dict[str, str]:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted((out / "shards").iterdir())}


@pytest.fixture(scope="module")
def dataset(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("perception") / "p"
    report = build_perception(out, perception_jobs(seed=3, generated=2, size=SIZE))
    assert (report.made, report.kept, report.failed) == (2, 0, {}), report.summary()
    return out


def test_frames_carry_exact_depth_and_labels(dataset):
    records = read_manifest(dataset)
    assert [r["order"] for r in records] == [0, 1] and all(r["source"] == "generated" for r in records)
    assert all(r["structure"] not in EVALUATION_ONLY for r in records)
    for record, arrays in iter_shards(dataset):
        n = record["frames"]
        assert 2 <= n <= 1 + EXPLORE_FRAMES + EXPERT_FRAMES and arrays["rgb"].shape == (n, SIZE, SIZE, 3)
        assert arrays["depth"].dtype == np.uint16 and arrays["depth"].shape == (n, SIZE, SIZE)
        assert 0 < arrays["depth"].min() and arrays["depth"].max() < 20_000  # millimetres inside a room
        types, instances = arrays["types"], arrays["instances"]
        assert types.max() <= len(ALL_TYPES) and len(np.unique(types)) > 2
        assert (types[instances < 0] == 0).all()  # no body, no type
        for body in np.unique(instances[types > 0])[:20]:  # one body, one type
            assert len(np.unique(types[instances == body])) == 1
        assert int(arrays["expert"].sum()) == record["expert_frames"] >= 1
    manifest = (dataset / "manifest.jsonl").read_bytes()
    assert read_header(dataset)["manifest_sha256"] == hashlib.sha256(manifest).hexdigest()


def test_same_seed_same_shards_and_a_run_resumes_what_is_missing_or_altered(dataset, tmp_path):
    before = _digests(dataset)
    copy = tmp_path / "p"
    copy.mkdir()
    (copy / "shards").mkdir()
    for name in ("manifest.jsonl", "perception.json"):
        (copy / name).write_bytes((dataset / name).read_bytes())
    (copy / "shards" / "shard-00000.npz").write_bytes((dataset / "shards" / "shard-00000.npz").read_bytes()[:-10])
    report = build_perception(copy, perception_jobs(seed=3, generated=2, size=SIZE))
    assert (report.made, report.kept) == (2, 0)  # one torn, one missing: both rendered again
    assert _digests(copy) == before
    assert (copy / "manifest.jsonl").read_bytes() == (dataset / "manifest.jsonl").read_bytes()
    again = build_perception(copy, perception_jobs(seed=3, generated=2, size=SIZE))
    assert (again.made, again.kept) == (0, 2)
    with pytest.raises(PerceptionDataError, match="seed 3.*seed 4"):
        build_perception(copy, perception_jobs(seed=4, generated=2, size=SIZE))


def test_a_shard_altered_after_the_build_is_refused_on_read(dataset, tmp_path):
    copy = tmp_path / "p"
    copy.mkdir()
    (copy / "shards").mkdir()
    for name in ("manifest.jsonl", "perception.json", "shards/shard-00000.npz", "shards/shard-00001.npz"):
        (copy / name).write_bytes((dataset / name).read_bytes())
    shard = copy / "shards" / "shard-00001.npz"
    data = bytearray(shard.read_bytes())
    data[len(data) // 2] ^= 0xFF
    shard.write_bytes(bytes(data))
    with pytest.raises(PerceptionDataError, match="shard-00001.npz: its sha256"):
        list(iter_shards(copy))


def test_uplus_trials_are_refused_and_evaluation_frames_are_caught_by_scene_key(uplus_build, dataset, tmp_path):
    trial = built_trials(uplus_build)[0]
    refused = build_perception(tmp_path / "t", perception_jobs(seed=0, generated=0, trials=[trial], size=SIZE))
    assert refused.failed == {"EvaluationStructure": 1} and refused.made == 1  # told apart by its class
    record = json.loads((tmp_path / "t" / "manifest.jsonl").read_text())
    assert record["cause"] == "EvaluationStructure" and record["trial"] is None
    assert leaks(dataset, [uplus_build]) == []
    # U+'s entry 0 rendered as an evaluation dataset (by the CLI): the build's trial 0 is the same scene
    out = tmp_path / "eval"
    assert main(["dataset", "perception", "--split", "U+", "--count", "1", "--size", str(SIZE), "--out", str(out),
                 "--no-progress"]) == 0
    assert read_header(out)["evaluation"] == "U+"
    found = leaks(out, [uplus_build])
    assert any("an evaluation dataset" in f for f in found) and any("is an evaluation trial's" in f for f in found)
    assert any("is U+'s or U+test's" in f for f in found)
