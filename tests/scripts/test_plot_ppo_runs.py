"""scripts/plot_ppo_runs.py: the imitation rounds and PPO's moving average, read from a run's files, drawn."""

from __future__ import annotations

import json

import pytest

from tests.conftest import load_script


@pytest.fixture(scope="module")
def plot_runs():
    yield from load_script("scripts/plot_ppo_runs.py")


def _run(folder, rounds, successes):
    folder.mkdir()
    warm = [{"round": i + 1, "episodes": 10, "successes": s, "cpu_seconds": 60.0 * (i + 1)}
            for i, s in enumerate(rounds)]
    (folder / "warm_start.json").write_text(json.dumps(warm))
    lines = ["timesteps,episode_return,episode_length,success,cpu_seconds"]
    lines += [f"{10 * i},1.0,10,{s},{180 + 6 * i}" for i, s in enumerate(successes)]
    (folder / "curve.csv").write_text("\n".join(lines) + "\n")
    return folder


def test_points_come_from_the_runs_files(plot_runs, tmp_path):
    run = _run(tmp_path / "a", [10, 5, 7], [1, 0, 1, 1])
    rounds, curve = plot_runs.run_points(run, window=2)
    assert rounds == [(1.0, 1.0), (2.0, 0.5), (3.0, 0.7)]
    assert curve == [(3.1, 0.5), (3.2, 0.5), (3.3, 1.0)]


def test_the_plot_is_written_and_bad_arguments_are_named(plot_runs, tmp_path):
    run = _run(tmp_path / "a", [10], [1, 0, 1])
    out = tmp_path / "curve.png"
    assert plot_runs.main(["--run", f"seed 0={run}", "--ref", "walk=0.05", "--out", str(out)]) == 0
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(SystemExit, match="not a train_ppo.py output folder"):
        plot_runs.main(["--run", f"x={tmp_path / 'none'}", "--out", str(out)])
    with pytest.raises(SystemExit, match="the rate must be a number"):
        plot_runs.main(["--run", f"x={run}", "--ref", "walk=high", "--out", str(out)])
    with pytest.raises(SystemExit, match="expected NAME=VALUE"):
        plot_runs.main(["--run", str(run), "--out", str(out)])
