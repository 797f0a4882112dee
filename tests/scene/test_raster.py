"""`luminous_sim.scene.raster` gives exactly what scipy.ndimage gives (labels and their order, distances,
the nearest feature on ties, box minima), so scenes stay byte-identical without loading scipy."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from luminous_sim.scene import distance_transform, feature_transform, label4, minimum_filter_box


def _masks(count: int, seed: int = 0):
    """Random masks: salt-and-pepper ones (many ties) and blobby ones (long components, walls)."""
    rng = np.random.default_rng(seed)
    for k in range(count):
        h, w = (int(v) for v in rng.integers(1, 48, 2))
        if k % 3 == 0:
            yield ndimage.binary_dilation(rng.random((h, w)) < 0.05, iterations=int(rng.integers(1, 4)))
        else:
            yield rng.random((h, w)) < rng.random()


def test_labels_match_scipy_in_value_and_order():
    for mask in _masks(600):
        expected, n = ndimage.label(mask)
        got, m = label4(mask)
        assert m == n
        np.testing.assert_array_equal(got, expected)


def test_a_spiral_needs_many_passes_and_still_matches():
    spiral = np.zeros((41, 41), dtype=bool)
    for k in range(0, 20, 2):  # rings joined at their corner: one long winding path
        spiral[k, k:41 - k] = spiral[k:41 - k, 40 - k] = spiral[40 - k, k:41 - k] = True
        spiral[k + 2:41 - k, k] = True
    expected, n = ndimage.label(spiral)
    labels, m = label4(spiral)
    assert m == n
    np.testing.assert_array_equal(labels, expected)


def test_distances_and_nearest_features_match_scipy_ties_included():
    for mask in _masks(600, seed=1):
        if mask.all():
            continue
        dist, idx = ndimage.distance_transform_edt(mask, return_indices=True)
        got_dist, got_idx = distance_transform(mask, return_indices=True)
        assert got_dist.dtype == dist.dtype and got_idx.dtype == idx.dtype
        np.testing.assert_array_equal(got_dist, dist)
        np.testing.assert_array_equal(got_idx, idx)
        np.testing.assert_array_equal(distance_transform(mask), dist)


def test_box_minimum_matches_scipy():
    rng = np.random.default_rng(2)
    for mask in _masks(300, seed=2):
        grid = rng.random(mask.shape)
        size = (2 * int(rng.integers(0, 6)) + 1, 2 * int(rng.integers(0, 6)) + 1)
        expected = ndimage.minimum_filter(grid, size=size, mode="constant", cval=-0.05)
        np.testing.assert_array_equal(minimum_filter_box(grid, size, cval=-0.05), expected)


def test_bad_input_is_refused_by_name():
    with pytest.raises(ValueError, match="no feature cell"):
        feature_transform(np.zeros((3, 3), dtype=bool))
    with pytest.raises(ValueError, match="2-D"):
        label4(np.zeros((2, 2, 2), dtype=bool))
    with pytest.raises(ValueError, match="odd"):
        minimum_filter_box(np.zeros((3, 3)), (2, 3), cval=0.0)
    assert label4(np.zeros((0, 4), dtype=bool))[1] == 0
