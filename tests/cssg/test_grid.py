"""The candidate grid: feasibility by erosion means the whole footprint is on free floor."""

from __future__ import annotations

import numpy as np
import pytest
from shapely.geometry import Polygon, box

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg.grid import HEADINGS, RES, FloorGrid
from luminous_sim.cssg.pose import footprint
from luminous_sim.cssg.scores import directional_wall_distance, heading_index


@pytest.fixture(scope="module")
def chair():
    return default_catalog().of_type("Chair")[0]


def test_wall_distance_and_normals():
    g = FloorGrid.from_polygon(Polygon([(0, 0), (4, 0), (4, 3), (0, 3)]))
    assert g.wall_dist[0, 40] == pytest.approx(RES / 2)
    assert g.wall_dist.max() == pytest.approx(1.5 - RES / 2)
    assert g.wall_normal[0, 40].tolist() == [0, 1] and g.wall_normal[30, 0].tolist() == [1, 0]
    d = directional_wall_distance(g)
    r, c = g.cell(1.0, 2.0)
    assert d[:, r, c] == pytest.approx([1.0, 3.0, 2.0, 1.0], abs=RES)


@pytest.mark.parametrize("heading", HEADINGS)
def test_feasible_cells_keep_the_footprint_on_free_floor(chair, heading):
    room = Polygon([(0, 0), (5, 0), (5, 2), (3, 2), (3, 4), (0, 4)])  # an L
    g = FloorGrid.from_polygon(room)
    obstacle = box(1.0, 1.0, 2.0, 1.6)
    g.block(obstacle)
    feas = g.feasible(chair, heading, margin=0.0)
    rows, cols = np.nonzero(feas)
    assert len(rows) > 50
    rng = np.random.default_rng(0)
    for i in rng.choice(len(rows), 200):
        fp = footprint(chair, g.xs[cols[i]], g.ys[rows[i]], heading)
        assert room.buffer(RES).contains(fp), "footprint leaves the room"
        assert fp.intersection(obstacle).area < (2 * RES) * max(fp.length, 1) , "footprint covers the obstacle"
    # and cells well clear of everything are feasible
    r, c = g.cell(4.0, 1.0)
    assert feas[r, c]


def test_heading_index_faces_the_direction():
    assert heading_index(np.array(0.0), np.array(1.0)) == 0  # +y: yaw 0
    assert heading_index(np.array(-1.0), np.array(0.0)) == 1  # -x: yaw 90 degrees
    assert heading_index(np.array(0.0), np.array(-1.0)) == 2
    assert heading_index(np.array(1.0), np.array(0.0)) == 3
