"""bench_env's id specs: ID, ID@SIZE and ID@SIZE/RASTERISER name the env options each figure is measured with."""

from __future__ import annotations

import pytest

from tests.conftest import load_script


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_env.py")


def test_id_specs_set_size_and_rasteriser(bench):
    import luminous_sim.env  # noqa: F401  (registers the ids)

    assert bench._options("Luminous-ObjectNav-64-v2") == ("Luminous-ObjectNav-64-v2", {})
    env_id, options = bench._options("Luminous-ObjectNav-64-v2@300/tinyrenderer")
    assert (env_id, options) == ("Luminous-ObjectNav-64-v2", {"width": 300, "height": 300,
                                                              "rasteriser": "tinyrenderer"})
    assert bench._size(env_id, options) == "300x300, tinyrenderer"
    assert bench._size(*bench._options("Luminous-ObjectNav-64-v2")) == "64x64, compiled"
