"""benchmarks/bench_parser.py: a split's template directives labelled by their entries, and the report printed."""

from __future__ import annotations

import pytest

from tests.conftest import load_script

pytest.importorskip("torch")


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_parser.py")


def test_a_splits_directives_carry_their_entries_tasks_and_are_scored(bench, capsys):
    from luminous_sim.agents import default_parser
    from luminous_sim.benchmark import benchmark_entry

    examples = bench.split_annotations("U+", 2)
    assert [e.task for e in examples] == ["U+/0", "U+/1"]
    assert [e.task_type for e in examples] == [benchmark_entry("U+", i).task_type for i in range(2)]
    assert all(e.directive and e.params == benchmark_entry("U+", i).pddl_params for i, e in enumerate(examples))
    bench.report("U+", default_parser(), examples, False)
    out = capsys.readouterr().out
    assert "U+: 2 annotations" in out and '"task_type"' in out
