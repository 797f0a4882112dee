"""bench_world's size-ratio figure runs and prints every row it promises."""

from __future__ import annotations

import re

import pytest

from tests.conftest import load_script


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_world.py")


def test_size_ratio_prints_both_sizes_and_the_culling_ablation(bench, capsys):
    bench.main(["--size-ratio", "64,32", "--steps", "8", "--repeats", "1"])
    out = capsys.readouterr().out
    for row in ("64x64:", "32x32:", "32x32, culled links shown after each frame:", "64/32 CPU time per step",
                "32 px, shown after each frame / kept hidden", "32x32, compiled rasteriser:",
                "64x64, compiled rasteriser:", "32 px, compiled rasteriser / TinyRenderer",
                "64 px, compiled rasteriser / TinyRenderer", "64/32 CPU time per step with the compiled"):
        assert row in out, row
    ms = [float(x) for x in re.findall(r": ([0-9.]+) \(", out)]
    assert len(ms) >= 4 and all(x > 0 for x in ms)
