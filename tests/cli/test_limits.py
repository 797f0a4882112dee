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
