"""benchmarks/bench_bc.py: which entries are held out, and the test of the clone's S+ -> U+ drop."""

from __future__ import annotations

import pytest

from tests.conftest import load_script

pytest.importorskip("scipy")


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_bc.py")


def test_held_out_s_plus_entries_skip_the_training_range(bench):
    training = range(28, 428)
    assert bench.held_out("S+", 30, training) == list(range(28)) + [428, 429]
    assert bench.held_out("S+", 5, training) == [0, 1, 2, 3, 4]
    assert bench.held_out("U+", 30, training) == list(range(30))
    assert not set(bench.held_out("S+", 300, training)) & set(training)


def test_a_clear_drop_is_significant_and_no_drop_is_not(bench):
    n = 200
    seen = [[k < 60 for k in range(n)]] * 3  # SR 0.30 on S+
    unseen = [[k < 20 for k in range(n)]] * 3  # SR 0.10 on U+
    gap = bench.gap_test({"S+": seen, "U+": unseen}, repeats=2000)
    assert gap["drop"] == pytest.approx(0.2)
    assert 0 < gap["ci95"][0] < 0.2 < gap["ci95"][1]
    assert gap["p_bootstrap"] < 0.01 and all(p < 1e-4 for p in gap["fisher_p"])
    same = bench.gap_test({"S+": unseen, "U+": unseen}, repeats=2000)
    assert same["drop"] == 0 and same["ci95"][0] < 0 < same["ci95"][1]
    assert same["p_bootstrap"] > 0.3 and all(p > 0.5 for p in same["fisher_p"])
