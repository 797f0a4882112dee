"""The agent's reachable grid: the largest 4-connected set of free 0.25 m points, as a graph
search finds it (ties: the set holding the earliest point)."""

from __future__ import annotations

from pathlib import Path

import networkx as nx
import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.cssg import generate
from luminous_sim.scene.agent_grid import STEP, largest_component, scene_reachable_grid

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples"


def _reference(pts: np.ndarray) -> np.ndarray:
    g = nx.Graph()
    keys = {(round(x / STEP), round(y / STEP)): i for i, (x, y) in enumerate(pts)}
    g.add_nodes_from(range(len(pts)))
    for (i, j), n in keys.items():
        for di, dj in ((1, 0), (0, 1)):
            m = keys.get((i + di, j + dj))
            if m is not None:
                g.add_edge(n, m)
    mask = np.zeros(len(pts), dtype=bool)
    mask[sorted(max(nx.connected_components(g), key=len))] = True
    return mask


@pytest.mark.parametrize("seed", range(6))
def test_largest_component_matches_a_graph_search(seed):
    rng = np.random.default_rng(seed)
    xs, ys = np.meshgrid(np.arange(-4, 12) * STEP, np.arange(3, 15) * STEP, indexing="ij")
    pts = np.stack([xs.ravel(), ys.ravel()], axis=1)
    pts = pts[rng.random(len(pts)) < 0.55]
    assert np.array_equal(largest_component(pts), _reference(pts))


def test_equal_components_keep_the_one_with_the_earliest_point():
    pts = np.array([[2.0, 0.0], [2.25, 0.0], [0.0, 0.0], [0.0, 0.25]])
    assert largest_component(pts).tolist() == [True, True, False, False]
    assert np.array_equal(largest_component(pts), _reference(pts))


@pytest.mark.parametrize("example", ["kitchen_coffee_mug.yaml", "bedroom_reading_desk.yaml"])
def test_a_finished_scene_has_the_grid_its_generator_validated(example):
    """The simulator's reachable grid (from the scene alone) is the one the generator's report counted."""
    g = generate(cdf.load(EXAMPLES / example), seed=1)
    grid = scene_reachable_grid(g.scene)
    assert len(grid) == g.report.reachable_points > 0
    assert np.allclose(np.round(grid / STEP), grid / STEP)
