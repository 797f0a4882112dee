"""benchmarks/bench_oracle.py: the raw (unfiltered) draw of a slot and the before/after-filter table."""

from __future__ import annotations

import pytest

from tests.conftest import load_script


@pytest.fixture(scope="module")
def bench():
    yield from load_script("benchmarks/bench_oracle.py")


def _slot(k: int, raw: dict, success: bool | None = True) -> dict:
    return {"type": "pick_and_place_simple", "k": k, "success": success, "raw": raw}


def test_the_table_counts_every_raw_draw_before_the_filter_and_what_it_removed(bench, capsys):
    by_type = {"pick_and_place_simple": [
        _slot(0, {"sampled": True, "success": True, "removed": None}),
        _slot(1, {"sampled": True, "success": False, "removed": "no free, stable spot for its put",
                  "goal": "g", "failure": "full"}),
        _slot(2, {"sampled": True, "success": True, "removed": "no free, stable spot for its put"}),
        _slot(3, {"sampled": False, "why": "no scene"}, success=None),
    ]}
    bench.filter_table(by_type, ["pick_and_place_simple"])
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("pick_and_place_simple"))
    assert row.split()[1:] == ["2/3", "(67%)", "2", "1/1", "(100%)", "1/2", "(50%)", "3/3", "(100%)", "1"]
    assert "2  no free, stable spot for its put" in out
    assert "pick_and_place_simple k=1 g: full" in out


def test_a_raw_draw_is_the_samplers_own_and_the_filter_verdict_matches_draw_task(bench):
    import numpy as np

    from luminous_sim.data import scene_for_task
    from luminous_sim.episode import prepared_world
    from luminous_sim.planning import draw_task

    task_type = "look_at_obj_in_light"
    scene = scene_for_task(task_type, "Bedroom", 1000)
    raw = bench.raw_episode(scene, task_type, 0)
    assert raw["sampled"] and raw["goal"].startswith("(exists")
    world = prepared_world(scene, task_type)
    try:
        view = world.view()
        drawn = draw_task(scene, view, task_type, np.random.default_rng(0))
        assert bench.filter_verdict(scene, view, task_type, drawn.params) is None  # what the filter draws, it keeps
    finally:
        world.close()
