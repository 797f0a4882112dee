"""Issue 27: every count the command takes has a stated limit (luminous_sim.limits), checked before work starts,
refused in one line naming the option and the limit."""

from __future__ import annotations

from pathlib import Path

import pytest

from luminous_sim.data.minari_export import MinariExportError, export_minari
from luminous_sim.limits import (
    MAX_BUILD_JOBS,
    MAX_EVAL_EPISODES,
    MAX_GENERATE_SCENES,
    MAX_MINARI_EPISODES,
    MAX_MINARI_SEEDS,
    MAX_WORKERS,
)
from tests.cli.test_errors import one_line_error, run

NAV = "Luminous-NavToObject-64-v1"
HUGE = "9223372036854775807"


@pytest.mark.parametrize(("argv", "option", "limit"), [
    (["dataset", "minari", "--env", NAV, "--episodes", HUGE], "--episodes", MAX_MINARI_EPISODES),
    (["dataset", "minari", "--env", NAV, "--episodes", str(MAX_MINARI_EPISODES + 1)], "--episodes",
     MAX_MINARI_EPISODES),
    (["dataset", "minari", "--env", NAV, "--episodes", "1", "--max-seeds", HUGE], "--max-seeds", MAX_MINARI_SEEDS),
    (["dataset", "minari", "--env", NAV, "--episodes", "1", "--max-seeds", "0"], "--max-seeds", MAX_MINARI_SEEDS),
    (["dataset", "build", "--split", "S+", "--count", "1", "--workers", HUGE], "--workers", MAX_WORKERS),
    (["dataset", "build", "--split", "S+", "--count", HUGE], "--count", MAX_BUILD_JOBS),
    (["eval", "--policy", "random", "--split", "S+", "--episodes", "1", "--workers", str(MAX_WORKERS + 1)],
     "--workers", MAX_WORKERS),
    (["generate", "--count", HUGE], "--count", MAX_GENERATE_SCENES),
    (["bc", "collect", "--episodes", HUGE], "--episodes", MAX_EVAL_EPISODES),
    (["bc", "eval", "--policy", "random", "--split", "S+", "--episodes", HUGE], "--episodes", MAX_EVAL_EPISODES),
])
def test_counts_over_their_limit_are_refused_before_work(argv: list[str], option: str, limit: int, tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "out"
    code, _, err = run([*argv, "--out", str(out)], capsys)
    assert code == 2 and one_line_error(err), err
    assert option in err and str(limit) in err, err
    assert not out.exists()


@pytest.mark.parametrize(("kwargs", "needle"), [
    ({"episodes": 10**18}, f"episodes: expected a whole number from 1 to {MAX_MINARI_EPISODES} "
                           "(luminous_sim.limits.MAX_MINARI_EPISODES), got 1000000000000000000"),
    ({"episodes": 0}, "episodes: expected a whole number from 1"),
    ({"episodes": True}, "episodes: expected a whole number from 1"),
    ({"episodes": 1, "max_seeds": 10**18}, f"max_seeds: expected a whole number from 1 to {MAX_MINARI_SEEDS}"),
])
def test_the_library_minari_export_checks_its_bounds_first(kwargs: dict, needle: str, tmp_path: Path) -> None:
    with pytest.raises(MinariExportError) as err:
        export_minari(NAV, out=tmp_path / "m", **kwargs)
    assert str(err.value) == needle or str(err.value).startswith(needle)
    assert not (tmp_path / "m").exists()


@pytest.mark.parametrize(("argv", "option", "limit"), [
    (["speaker", "train", "--data", "d", "--out", "s.pt", "--epochs", HUGE], "--epochs", "MAX_EPOCHS"),
    (["speaker", "train", "--data", "d", "--out", "s.pt", "--batch-size", HUGE], "--batch-size", "MAX_BATCH_SIZE"),
    (["speaker", "train", "--data", "d", "--out", "s.pt", "--max-examples", HUGE], "--max-examples",
     "MAX_TRAIN_EXAMPLES"),
    (["speaker", "train", "--data", "d", "--out", "s.pt", "--max-trajectories", HUGE], "--max-trajectories",
     "MAX_TRAJECTORIES"),
    (["speaker", "describe", "--model", "s.pt", "--traj", "t.json", "--no-repeat-ngram", HUGE], "--no-repeat-ngram",
     "MAX_NGRAM"),
    (["bc", "train", "--demos", "d", "--out", "b.pt", "--epochs", HUGE], "--epochs", "MAX_EPOCHS"),
    (["bc", "train", "--demos", "d", "--out", "b.pt", "--batch-size", HUGE], "--batch-size", "MAX_BATCH_SIZE"),
    (["bc", "train", "--demos", "d", "--out", "b.pt", "--threads", HUGE], "--threads", "MAX_THREADS"),
    (["bc", "collect", "--episodes", "1", "--start", HUGE, "--out", "o"], "--start", "MAX_EPISODE_INDEX"),
    (["assets", "build", "--jobs", HUGE], "--jobs", "MAX_WORKERS"),
    (["rooms", "convert", "--layouts", "l", "--out", "o", "--scene", HUGE], "--scene", "MAX_FLOOR_PLAN"),
    (["train-layouts", "--out", "m.pt", "--epochs", HUGE], "--epochs", "MAX_EPOCHS"),
    (["train-layouts", "--out", "m.pt", "--rooms", HUGE], "--rooms", "MAX_LAYOUT_ROOMS"),
])
def test_training_and_worker_counts_are_bounded_naming_the_limit(argv: list[str], option: str, limit: str,
                                                                 tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    """Issue 27: no integer option accepts up to 2**63-1; the message names the option, the bound and the
    constant of luminous_sim.limits it comes from."""
    import luminous_sim.limits as limits

    monkeypatch.chdir(tmp_path)
    code, _, err = run(argv, capsys)
    assert code == 2 and one_line_error(err), err
    assert option in err and str(getattr(limits, limit)) in err and f"luminous_sim.limits.{limit}" in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == []


def test_no_integer_option_is_unbounded() -> None:
    """Every `type=` of an integer option of the command has an upper bound below 2**63-1 (seeds excepted)."""
    import argparse

    from luminous_sim.cli.args import seed
    from luminous_sim.cli.main import build_parser

    def walk(parser: argparse.ArgumentParser, path: str):
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    yield from walk(sub, f"{path} {name}")
            elif getattr(action.type, "__name__", "") == "whole number" and action.type is not seed:
                yield f"{path} {action.option_strings}", action.type

    options = list(walk(build_parser(), "luminous"))
    assert len(options) > 20, options
    unbounded = []
    for where, parse in options:
        try:
            parse(HUGE)
        except argparse.ArgumentTypeError:
            continue
        unbounded.append(where)
    assert not unbounded
