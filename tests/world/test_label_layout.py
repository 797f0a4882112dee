"""Label placement: every label placed, none overlapping another or an obstacle, leaders when moved."""

from __future__ import annotations

import itertools

import numpy as np

from luminous_sim.world.label_layout import LabelSpec, PlacedLabel, boxes_overlap, place_labels


def _no_overlaps(placed: list[PlacedLabel]) -> None:
    for a, b in itertools.combinations(placed, 2):
        assert not boxes_overlap(a.box, b.box), (a, b)


def test_a_crowd_at_one_point_spreads_out_with_leaders():
    specs = [LabelSpec(str(i), f"thing {i}", (100.0, 100.0), (40.0, 12.0)) for i in range(30)]
    placed = place_labels(specs, 200, 200)
    assert [p.key for p in placed] == [s.key for s in specs]
    _no_overlaps(placed)
    assert all(p.box[2] <= 200 and p.box[3] <= 200 and min(p.box) >= 0 for p in placed)
    assert all(p.leader_end is not None for p in placed)  # beside or away from the point, never on it
    near = [np.hypot(*(np.array(p.leader_end) - p.anchor)) for p in placed[:2]]
    assert max(near) <= 3.0  # the first two right beside it, left and right


def test_furniture_is_written_on_itself_and_obstacles_are_kept_clear():
    obstacle = (0.0, 0.0, 60.0, 20.0)
    placed = place_labels([LabelSpec("t", "Table", (30.0, 50.0), (30.0, 12.0), on_anchor=True),
                           LabelSpec("m", "Mug", (30.0, 10.0), (20.0, 12.0))], 100, 100, obstacles=[obstacle])
    assert placed[0].box == (15.0, 44.0, 45.0, 56.0) and placed[0].leader_end is None
    assert not boxes_overlap(placed[1].box, obstacle) and placed[1].leader_end is not None


def test_labels_that_do_not_fit_go_to_a_legend_beside_the_picture():
    specs = [LabelSpec(str(i), "long label", (20.0, 20.0), (30.0, 10.0)) for i in range(12)]
    placed = place_labels(specs, 40, 40)
    _no_overlaps(placed)
    legend = [p for p in placed if p.box[0] >= 40]
    assert legend and len(legend) < len(placed)


def test_a_path_to_avoid_is_kept_clear_while_there_is_room():
    path = np.stack([np.full(50, 72.0), np.linspace(0, 100, 50)], axis=1)  # a line just right of the anchor
    placed = place_labels([LabelSpec("m", "Mug", (70.0, 50.0), (20.0, 12.0))], 100, 100, avoid=path)
    assert placed[0].box[2] < 70.0  # written on the left, the line's side left free
