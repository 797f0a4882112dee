"""The candidate grid: feasibility by erosion means the whole footprint is on free floor."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import Polygon, box

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg.grid import HEADINGS, RES, FloorGrid
from luminous_sim.cssg.scores import directional_wall_distance, heading_index
from luminous_sim.scene import footprint


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


def test_heading_index_breaks_diagonal_ties_towards_y():
    assert heading_index(np.array(1.0), np.array(1.0)) == 0
    assert heading_index(np.array(-1.0), np.array(-1.0)) == 2
    assert heading_index(np.array(0.0), np.array(0.0)) == 0


def test_directional_wall_distance_matches_a_scan():
    g = FloorGrid.from_polygon(Polygon([(0, 0), (5, 0), (5, 2), (3, 2), (3, 4), (0, 4)]))
    d = directional_wall_distance(g)
    h, w = g.room.shape
    for r, c in [(5, 5), (10, 70), (60, 20), (39, 59), (0, 0)]:
        if not g.room[r, c]:
            continue
        runs = []
        for dr, dc in ((0, -1), (0, 1), (-1, 0), (1, 0)):
            k = 0
            while 0 <= r + k * dr < h and 0 <= c + k * dc < w and g.room[r + k * dr, c + k * dc]:
                k += 1
            runs.append((k - 0.5) * RES)
        assert d[:, r, c] == pytest.approx(runs)


def test_cells_are_the_cell_centres_inside_a_polygon():
    g = FloorGrid.from_polygon(Polygon([(0, 0), (4, 0), (4, 3), (0, 3)]))
    gx, gy = g.coords()
    for poly in (box(1.02, 0.51, 1.93, 1.26), Polygon([(2, 0.2), (3.1, 0.9), (2.6, 1.7), (1.5, 1.0)]),
                 box(-0.5, 2.6, 0.4, 3.5)):
        assert np.array_equal(g._cells(poly), shapely.contains_xy(poly, gx, gy))


def test_feasibility_is_cached_until_the_free_mask_changes(chair):
    g = FloorGrid.from_polygon(Polygon([(0, 0), (4, 0), (4, 3), (0, 3)]))
    before = g.feasible(chair, HEADINGS[0])
    assert g.feasible(chair, HEADINGS[0]) is before and not before.flags.writeable
    r, c = g.cell(2.0, 1.5)
    assert before[r, c]
    g.block(box(1.8, 1.3, 2.2, 1.7))
    assert not g.feasible(chair, HEADINGS[0])[r, c]
    g.set_free(g.room.copy())
    assert np.array_equal(g.feasible(chair, HEADINGS[0]), before)


def test_away_from_wall_measures_the_pieces_own_edges_turned_the_better_way():
    """A 2 m table in a 2.6 m wide corridor room clears the long walls only lengthwise: the field prefers
    that heading, and the cost read at a yaw is the clearance of the table as it stands."""
    from luminous_sim.cssg.scores import WALL_CLEAR, cost_in_field, relation_field

    table = max(default_catalog().of_type("DiningTable"), key=lambda e: e.dims[0])
    w, d = table.dims[0], table.dims[1]
    assert w > 1.8 and d < 1.0
    g = FloorGrid.from_polygon(Polygon([(0, 0), (2.6, 0), (2.6, 6), (0, 6)]))  # long along y
    walls = directional_wall_distance(g)
    field = relation_field("away_from", g, table, None, walls, (1.3, 3.0))
    cost, head = field
    r, c = g.cell(1.3, 3.0)
    assert head is not None and head[r, c] == 1  # turned a quarter: its length along the room's
    assert cost[r, c] == pytest.approx(max(0.0, WALL_CLEAR - (1.3 - d / 2)), abs=2 * RES)
    lengthwise = cost_in_field("away_from", field, g, table, walls, 1.3, 3.0, yaw=np.pi / 2)
    across = cost_in_field("away_from", field, g, table, walls, 1.3, 3.0, yaw=0.0)
    assert lengthwise == pytest.approx(cost[r, c], abs=1e-9)
    assert across == pytest.approx(WALL_CLEAR - (1.3 - w / 2), abs=2 * RES) and across > lengthwise


def test_the_last_try_takes_the_variant_whose_best_cell_is_cheapest():
    """A dining table away from the walls of a small, empty room: the last try is not a random variant but the
    one that fits best, and `_cheapest` is the least drawable cost (a brute-force minimum)."""
    from luminous_sim.cssg.draft import SceneDraft
    from luminous_sim.cssg.furniture import (
        WRONG_HEADING_PENALTY,
        FloorContext,
        _cheapest,
        place_piece,
        score,
    )
    from luminous_sim.cssg.requests import Rel, Request
    from luminous_sim.rooms.generate import generate_shell

    shell = generate_shell("Bathroom", np.random.default_rng(1), shape="rect")  # 6.6 m2: tables differ
    draft = SceneDraft(shell, default_catalog(), np.random.default_rng(0))
    ctx = FloorContext.create(draft)
    req = Request("table", "DiningTable", "furniture", True, rels=[Rel("away_from", None, 2.0, True, True, "test")])
    variants = req.variants(draft.catalog)
    fields = {e.id: (score(ctx, req, e), np.stack([ctx.grid.feasible(e, h) for h in HEADINGS])) for e in variants}
    for (cost, head), feas in fields.values():
        k, r, c = np.nonzero(feas)
        brute = [cost[i, j] + (0.0 if head is None else WRONG_HEADING_PENALTY * (head[i, j] != h))
                 for h, i, j in zip(k, r, c, strict=True)]
        assert _cheapest((cost, head), feas) == pytest.approx(min(brute) if brute else np.inf)
    best = min(variants, key=lambda e: _cheapest(*fields[e.id]))
    assert sum(_cheapest(*f) == _cheapest(*fields[best.id]) for f in fields.values()) == 1, "one fits best"
    placed = place_piece(ctx, req, tries=1)  # the one try is the last
    assert placed is not None and placed.entry.id == best.id
