"""benchmarks/bench_perception.py: scores per room type on an evaluation dataset and the cost per frame."""

from __future__ import annotations

import json
import sys

import pytest

from luminous_sim.data import build_perception, evaluation_jobs, perception_jobs
from tests.conftest import load_script

pytest.importorskip("torch")


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_perception.py")


def test_it_scores_an_evaluation_dataset_and_times_a_frame(bench, tmp_path, monkeypatch, capsys):
    from luminous_sim.agents import PerceptionSettings, train_perception

    build_perception(tmp_path / "train", perception_jobs(seed=5, generated=1, size=64))
    network = tmp_path / "net.pt"
    train_perception([tmp_path / "train"], PerceptionSettings(epochs=1, side=32, channels=(4, 8, 8, 8, 8),
                                                               threads=1)).save(network)
    data = tmp_path / "uplus"
    build_perception(data, evaluation_jobs("U+", [0, 40], size=96))
    monkeypatch.setattr(sys, "argv", ["bench_perception.py", "--data", str(data), "--perception", str(network),
                                      "--repeats", "2", "--frames", "3"])
    assert bench.main() == 0
    report = json.loads(capsys.readouterr().out)
    assert report["data"]["evaluation"] == "U+" and report["data"]["entries"] == [0, 40]
    assert report["scores"]["all"]["frames"] > 0 and set(report["scores"]) >= {"all"}
    timing = report["ms_per_frame"]
    assert timing["size"] == 96 and timing["network_range"][0] <= timing["network_median"] <= timing["network_range"][1]


def test_the_colour_baseline_scores_what_colour_alone_tells(bench, tmp_path):
    train, data = tmp_path / "train", tmp_path / "data"
    build_perception(train, perception_jobs(seed=5, generated=1, size=64))
    build_perception(data, perception_jobs(seed=6, generated=1, size=64))
    on_itself = bench.colour_baseline(train, train)["all"]
    elsewhere = bench.colour_baseline(train, data)["all"]
    assert on_itself["pixel_accuracy"] > 0.5 and on_itself["miou"] > 0
    assert on_itself["pixel_accuracy"] >= elsewhere["pixel_accuracy"]
