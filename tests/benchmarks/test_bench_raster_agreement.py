"""bench_raster_agreement compares the two rasterisers on navigation and on an oracle episode and prints totals."""

from __future__ import annotations

import re

import pytest

from tests.conftest import load_script


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_raster_agreement.py")


def test_it_counts_frames_and_differing_pixels(bench, capsys):
    bench.main(["--nav", "0:32", "--nav-steps", "6", "--ids", "Luminous-ALFRED-PickPlace-v2", "--seeds", "1",
                "--size", "32"])
    out = capsys.readouterr().out
    assert "navigation, kitchen seed 0, 32 px: 6 frames" in out
    m = re.search(r"total: (\d+) frames, (\d+) of (\d+) pixels differ", out)
    assert m and int(m.group(1)) > 6 and int(m.group(3)) == int(m.group(1)) * 32 * 32
    assert int(m.group(2)) <= int(m.group(3)) // 1000
