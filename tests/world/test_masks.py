"""ALFRED interaction-arg formats (RLE mask, bbox, point) and evaluator-style target resolution."""

from __future__ import annotations

import ast
import itertools
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from luminous_sim.world.masks import (
    FRAME_SHAPE,
    bbox_from_mask,
    interaction_args,
    mask_to_rle,
    point_from_mask,
    rank_targets,
    resolve_point,
    resolve_target,
    rle_to_mask,
)

REPO = Path(__file__).resolve().parents[2]
SHARED_ALFRED = REPO.parent / "shared" / "alfred"
MASKS_PY = REPO / "luminous_sim" / "world" / "masks.py"

# What masks.py's docstrings state, measured over ALFRED's json_2.1.0 valid_seen split (251 trajectories,
# unchanged): every one of its 1,636 interactions agrees exactly (mask re-encoding, bbox, point and the
# whole args dict); the point needs the closest-pixel fallback in 255 of them, with a tie in 23.
VALID_SEEN_INTERACTIONS = 1636
POINT_FALLBACKS = 255
POINT_FALLBACK_TIES = 23


# --------------------------------------------------------------------------------------------
# Reference ports of ALFRED's loops (gen/utils/image_util.py, game_state_base.get_point_of_obj)


def alfred_compress(seg_mask: np.ndarray) -> list[list[int]]:
    out: list[list[int]] = []
    idx, curr_run, run_len = 0, False, 0
    for row in seg_mask:
        for v in row:
            if v == 1 and not curr_run:
                curr_run = True
                out.append([idx, None])
            if v == 0 and curr_run:
                curr_run = False
                out[-1][1] = run_len
                run_len = 0
            if curr_run:
                run_len += 1
            idx += 1
    if curr_run:
        out[-1][1] = run_len
    return out


def alfred_point(seg_mask: np.ndarray) -> list[int]:
    nz_rows, nz_cols = np.nonzero(seg_mask)
    x0, y0, xmax, ymax = min(nz_cols), min(nz_rows), max(nz_cols), max(nz_rows)
    cx = int((xmax - x0) / 2 + x0)
    cy = int((ymax - y0) / 2 + y0)
    if seg_mask[cy, cx] == 0:
        c = (cx, cy)
        cx, cy = min(
            zip(nz_cols, nz_rows), key=lambda co: (co[0] - c[0]) ** 2 + (co[1] - c[1]) ** 2
        )
    return [int(cx), int(cy)]


small_masks = st.tuples(st.integers(1, 24), st.integers(1, 24)).flatmap(
    lambda s: arrays(np.bool_, s, elements=st.booleans())
)
nonempty_masks = small_masks.filter(lambda m: m.any())


# --------------------------------------------------------------------------------------------
# RLE


@settings(max_examples=300, deadline=None)
@given(small_masks)
def test_rle_round_trip(mask):
    rle = mask_to_rle(mask)
    assert np.array_equal(rle_to_mask(rle, mask.shape), mask)
    assert all(type(a) is int and type(b) is int for a, b in rle)


@settings(max_examples=200, deadline=None)
@given(small_masks)
def test_rle_matches_alfred_compress_mask(mask):
    assert mask_to_rle(mask) == alfred_compress(mask.astype(int))


@settings(max_examples=200, deadline=None)
@given(small_masks)
def test_rle_runs_are_maximal_sorted_and_positive(mask):
    rle = mask_to_rle(mask)
    for (s0, l0), (s1, _) in itertools.pairwise(rle):
        assert s0 + l0 < s1  # gap of at least one off-pixel: runs are maximal
    assert all(length > 0 for _, length in rle)
    assert sum(length for _, length in rle) == int(mask.sum())


def test_rle_empty_and_full():
    h, w = FRAME_SHAPE
    assert mask_to_rle(np.zeros(FRAME_SHAPE, bool)) == []
    assert mask_to_rle(np.ones(FRAME_SHAPE, bool)) == [[0, h * w]]
    assert mask_to_rle(np.ones((3, 7), np.uint8)) == [[0, 21]]
    assert not rle_to_mask([]).any()
    assert rle_to_mask([]).shape == FRAME_SHAPE
    assert rle_to_mask([[0, h * w]]).all()


def test_rle_runs_wrap_across_rows_row_major():
    m = np.zeros((4, 5), bool)
    m[0, 4] = m[1, 0] = m[1, 1] = True  # end of row 0 continues into row 1
    m[3, 2] = True
    assert mask_to_rle(m) == [[4, 3], [17, 1]]
    # a column-major (transposed) view is still read row-major
    f = np.asfortranarray(m)
    assert mask_to_rle(f) == [[4, 3], [17, 1]]
    assert mask_to_rle(m.T) == alfred_compress(m.T.astype(int))


def test_rle_nonbinary_values_count_as_on():
    assert mask_to_rle(np.array([[0, 255, 3], [0, 0, 1]])) == [[1, 2], [5, 1]]


def test_rle_to_mask_accepts_overlaps_and_rejects_bad_runs():
    m = rle_to_mask([[0, 3], [2, 2]], (2, 3))
    assert m.tolist() == [[True, True, True], [True, False, False]]
    assert rle_to_mask([(1, 1)], (1, 3)).tolist() == [[False, True, False]]
    for bad in ([[0, 7]], [[-1, 2]], [[0, -1]], [[0, 1, 2]], [[0.5, 1]], [1, 2]):
        with pytest.raises(ValueError):
            rle_to_mask(bad, (2, 3))


def test_mask_must_be_2d():
    with pytest.raises(ValueError):
        mask_to_rle(np.zeros(5, bool))
    with pytest.raises(ValueError):
        bbox_from_mask(np.zeros((2, 2, 3), bool))


# --------------------------------------------------------------------------------------------
# bbox / point / interaction_args


def test_bbox_thor_convention_and_inclusive_extent():
    m = np.zeros((10, 12), bool)
    m[2:5, 3:9] = True  # rows 2..4, cols 3..8
    assert bbox_from_mask(m, thor_convention=False) == [3, 2, 8, 4]
    assert bbox_from_mask(m) == [3, 3, 8, 5]  # THOR: y is one more than the row
    full = np.ones(FRAME_SHAPE, bool)
    assert bbox_from_mask(full) == [0, 1, 299, 300]
    with pytest.raises(ValueError):
        bbox_from_mask(np.zeros((4, 4), bool))


def test_point_centre_and_fallback():
    m = np.zeros((9, 9), bool)
    m[2:7, 1:6] = True  # cols 1..5, rows 2..6: centre (3, 4)
    assert point_from_mask(m) == [3, 4]
    m = np.zeros((9, 9), bool)
    m[1:4, 1:4] = True  # even extent cols 1..4 -> centre rounds down
    m[1:4, 4] = True
    assert point_from_mask(m) == [2, 2]
    ring = np.zeros((7, 7), bool)
    ring[0, :] = ring[-1, :] = ring[:, 0] = ring[:, -1] = True
    # centre (3, 3) is off the ring; (3, 0), (0, 3), (6, 3), (3, 6) tie at distance 3:
    # the first in row-major order, (x=3, y=0), wins as in ALFRED.
    assert point_from_mask(ring) == [3, 0]
    assert alfred_point(ring) == [3, 0]
    with pytest.raises(ValueError):
        point_from_mask(np.zeros((4, 4), bool))


@settings(max_examples=300, deadline=None)
@given(nonempty_masks)
def test_point_matches_alfred_and_lies_on_mask(mask):
    p = point_from_mask(mask)
    assert p == alfred_point(mask)
    assert mask[p[1], p[0]]
    x0, y0, x1, y1 = bbox_from_mask(mask, thor_convention=False)
    assert x0 <= p[0] <= x1 and y0 <= p[1] <= y1


def test_interaction_args_shape_and_json():
    m = np.zeros(FRAME_SHAPE, bool)
    m[100:120, 140:150] = True
    args = interaction_args(m)
    assert list(args) == ["bbox", "point", "mask"]
    assert args["bbox"] == [140, 101, 149, 120]
    assert args["point"] == [144, 109]
    assert args["mask"][0] == [100 * 300 + 140, 10]
    assert json.loads(json.dumps(args)) == args
    with pytest.raises(ValueError):
        interaction_args(np.zeros(FRAME_SHAPE, bool))


# --------------------------------------------------------------------------------------------
# resolve_target / resolve_point on synthetic segmentations


@pytest.fixture
def scene():
    """10x10 segmentation: 0 background (unmapped), 1 wall, 2 big table, 3 small apple, 4 mug."""
    seg = np.zeros((10, 10), np.int32)
    seg[0:2, :] = 1  # wall, rows 0-1, 20 px
    seg[4:10, 0:10] = 2  # table, 56 px once the apple is drawn on it
    seg[5:7, 2:4] = 3  # apple, 4 px, on the table
    seg[2:4, 6:8] = 4  # mug, 4 px
    objs = {1: "Wall|1", 2: "DiningTable|2", 3: "Apple|3", 4: "Mug|4"}
    return seg, objs


def box(r0, r1, c0, c1, shape=(10, 10)):
    m = np.zeros(shape, bool)
    m[r0:r1, c0:c1] = True
    return m


def test_resolve_target_ranks_by_iou_not_intersection(scene):
    seg, objs = scene
    pred = box(4, 8, 1, 5)  # 16 px: apple 4 of 4 (IoU 4/16), table 12 of 56 (IoU 12/60)
    ranked = rank_targets(pred, seg, objs)
    assert [r[0] for r in ranked] == ["Apple|3", "DiningTable|2"]
    assert ranked[0][1] == pytest.approx(4 / 16) and ranked[0][2] == 4
    assert ranked[1][1] == pytest.approx(12 / 60) and ranked[1][2] == 12
    assert resolve_target(pred, seg, objs) == "Apple|3"


def test_resolve_target_excludes_held_object(scene):
    seg, objs = scene
    pred = box(4, 8, 1, 5)
    assert resolve_target(pred, seg, objs, held_object_id="Apple|3") == "DiningTable|2"


def test_resolve_target_prunes_non_interactable(scene):
    seg, objs = scene
    pred = box(1, 4, 6, 8)  # 6 px: wall 2 (IoU 2/24), mug 4 (IoU 4/6)
    assert resolve_target(pred, seg, objs) == "Mug|4"
    pred = box(0, 3, 0, 10)  # 30 px: wall 20 (IoU 20/30), mug 2 (IoU 2/32)
    assert resolve_target(pred, seg, objs) == "Wall|1"
    assert (
        resolve_target(pred, seg, objs, interactable=lambda o: not o.startswith("Wall")) == "Mug|4"
    )
    assert resolve_target(pred, seg, objs, interactable=lambda o: False) is None


def test_resolve_target_no_overlap_returns_none(scene):
    seg, objs = scene
    assert resolve_target(box(2, 4, 0, 4), seg, objs) is None  # background only (unmapped id 0)
    assert resolve_target(np.zeros((10, 10), bool), seg, objs) is None
    assert rank_targets(np.zeros((10, 10), bool), seg, objs) == []
    assert resolve_target(box(5, 7, 2, 4), seg, objs, held_object_id="Apple|3") is None


def test_resolve_target_tie_breaks_deterministically():
    seg = np.zeros((4, 8), np.int64)
    seg[:, 0:4] = 7
    seg[:, 4:8] = 5
    objs = {7: "B|7", 5: "A|5"}
    pred = box(0, 4, 2, 6, (4, 8))  # 8 px in each, same IoU and intersection
    assert [r[0] for r in rank_targets(pred, seg, objs)] == ["A|5", "B|7"]
    # equal IoU, larger intersection first: Z (1 px, fully covered) vs W (8 px, 2 covered)
    seg3 = np.zeros((1, 16), np.int64)
    seg3[0, 0:1] = 1
    seg3[0, 8:16] = 2
    pred3 = np.zeros((1, 16), bool)
    pred3[0, 0:4] = True  # Z plus 3 px of background
    pred3[0, 8:10] = True  # pred = 6 px; IoU Z = 1/6, IoU W = 2/12
    ranked = rank_targets(pred3, seg3, {1: "Z|1", 2: "W|2"})
    assert ranked[0][1] == pytest.approx(ranked[1][1])
    assert [r[0] for r in ranked] == ["W|2", "Z|1"]


def test_resolve_target_shape_mismatch_raises(scene):
    seg, objs = scene
    with pytest.raises(ValueError):
        resolve_target(np.ones((5, 5), bool), seg, objs)
    with pytest.raises(ValueError):
        resolve_target(np.ones((10, 10), bool), seg.astype(float), objs)


@settings(max_examples=100, deadline=None)
@given(
    arrays(np.int8, (8, 8), elements=st.integers(0, 4)),
    arrays(np.bool_, (8, 8), elements=st.booleans()),
)
def test_resolve_target_is_argmax_iou(seg, pred):
    objs = {1: "A|1", 2: "B|2", 3: "C|3", 4: "D|4"}
    got = resolve_target(pred, seg, objs, held_object_id="C|3")
    scores = []
    for inst, obj in objs.items():
        inst_mask = seg == inst
        inter = int((inst_mask & pred).sum())
        if inter == 0 or obj == "C|3":
            continue
        scores.append((-inter / int((inst_mask | pred).sum()), -inter, obj))
    assert got == (min(scores)[2] if scores else None)


def test_resolve_point(scene):
    seg, objs = scene
    assert resolve_point((2, 5), seg, objs) == "Apple|3"
    assert resolve_point([0, 9], seg, objs) == "DiningTable|2"
    assert resolve_point((5, 2), seg, objs) is None  # background
    assert resolve_point((10, 0), seg, objs) is None  # outside the frame
    assert resolve_point((-1, 0), seg, objs) is None
    assert resolve_point((0, 0), seg, objs, interactable=lambda o: o != "Wall|1") is None
    # on the held apple: the nearest pixel of another eligible object is the table below/left
    assert resolve_point((2, 5), seg, objs, held_object_id="Apple|3") == "DiningTable|2"
    # held mug at (6, 2): background around it; wall at distance 1 (row 1) is nearest
    assert resolve_point((6, 2), seg, objs, held_object_id="Mug|4") == "Wall|1"
    assert (
        resolve_point(
            (6, 2), seg, objs, held_object_id="Mug|4", interactable=lambda o: o != "Wall|1"
        )
        == "DiningTable|2"
    )
    assert resolve_point((6, 2), seg, objs, held_object_id="Mug|4", radius=0) is None
    with pytest.raises(ValueError):
        resolve_point((1.5, 2), seg, objs)
    with pytest.raises(ValueError):
        resolve_point((1, 2, 3), seg, objs)


def test_resolve_point_radius_limits_search():
    seg = np.zeros((20, 20), np.int32)
    seg[:, :] = 1  # held object everywhere...
    seg[10, 17] = 2  # ...except one pixel of a target 7 px to the right of (10, 10)
    objs = {1: "Held|1", 2: "Target|2"}
    assert resolve_point((10, 10), seg, objs, held_object_id="Held|1") is None
    assert resolve_point((10, 10), seg, objs, held_object_id="Held|1", radius=7) == "Target|2"
    assert resolve_point((12, 10), seg, objs, held_object_id="Held|1") == "Target|2"


# --------------------------------------------------------------------------------------------
# purity: no pybullet in this module


def test_masks_does_not_import_pybullet():
    tree = ast.parse(MASKS_PY.read_text())
    mods = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            mods |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            mods.add(node.module.split(".")[0])
    assert mods <= {"__future__", "collections", "typing", "numpy"}, mods
    code = "import sys, luminous_sim.world.masks; sys.exit('pybullet' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], check=False, cwd=REPO).returncode == 0


# --------------------------------------------------------------------------------------------
# against ALFRED's real valid_seen trajectories


@pytest.fixture(scope="module")
def real_interactions() -> list[tuple[str, int, dict]]:
    """(trajectory path, low_idx, discrete_action.args) of every interaction in valid_seen."""
    root = SHARED_ALFRED / "valid_seen"
    if not root.is_dir():
        reason = (f"ALFRED's valid_seen split (<task dir>/<trial>/traj_data.json) not found at {root}: "
                  "the checks of masks.py against ALFRED's stored masks, boxes and points are skipped")
        print(reason)
        pytest.skip(reason)
    out = []
    for path in sorted(root.glob("*/*/traj_data.json")):
        data = json.loads(path.read_text())
        for i, low in enumerate(data["plan"]["low_actions"]):
            args = low["discrete_action"]["args"]
            if args:
                out.append((str(path.relative_to(root)), i, args))
    assert len(out) == VALID_SEEN_INTERACTIONS, f"{len(out)} interactions under {root}, not valid_seen's"
    return out


def test_real_rle_reencodes_exactly(real_interactions):
    bad = []
    for where, i, args in real_interactions:
        m = rle_to_mask(args["mask"])
        assert m.any(), (where, i)
        if mask_to_rle(m) != args["mask"]:
            bad.append((where, i))
    assert not bad, f"{len(bad)} of {len(real_interactions)} masks re-encode differently: {bad[:5]}"


def test_real_bbox_agreement(real_interactions):
    agree = sum(
        bbox_from_mask(rle_to_mask(a["mask"])) == a["bbox"] for _, _, a in real_interactions
    )
    assert agree == len(real_interactions), f"bbox agreement: {agree}/{len(real_interactions)}"
    plain = sum(
        bbox_from_mask(rle_to_mask(a["mask"]), thor_convention=False) == a["bbox"] for _, _, a in real_interactions
    )
    assert plain == 0, f"the plain inclusive extent matches {plain} stored boxes"


def test_real_point_agreement(real_interactions):
    agree = sum(
        point_from_mask(rle_to_mask(a["mask"])) == a["point"] for _, _, a in real_interactions
    )
    assert agree == len(real_interactions), f"point agreement: {agree}/{len(real_interactions)}"
    fallbacks = ties = 0
    for _, _, a in real_interactions:
        m = rle_to_mask(a["mask"])
        rows, cols = np.nonzero(m)
        cx = int(cols.min() + (cols.max() - cols.min()) // 2)
        cy = int(rows.min() + (rows.max() - rows.min()) // 2)
        if not m[cy, cx]:  # the box centre is off the mask: the closest on-pixel is used
            fallbacks += 1
            dist = (cols - cx) ** 2 + (rows - cy) ** 2
            ties += int(np.sum(dist == dist.min()) > 1)
    assert (fallbacks, ties) == (POINT_FALLBACKS, POINT_FALLBACK_TIES)


def test_real_interaction_args_reproduce_stored_args(real_interactions):
    """interaction_args on the decoded mask gives back the stored args (every one), and the stored mask
    resolves to a single object when used as a prediction on its own segmentation (every 7th checked)."""
    different = [(where, i) for where, i, a in real_interactions if interaction_args(rle_to_mask(a["mask"])) != a]
    assert not different, f"{len(different)} of {len(real_interactions)} args differ: {different[:5]}"
    for _, _, a in real_interactions[::7]:
        m = rle_to_mask(a["mask"])
        seg = m.astype(np.int32)  # 1 = target, 0 = everything else (unmapped)
        assert resolve_target(m, seg, {1: "Target"}) == "Target"
        assert resolve_point(a["point"], seg, {1: "Target"}) == "Target"
