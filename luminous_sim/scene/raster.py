"""Operations on 2-D boolean and float grids: 4-connected labels, the exact Euclidean distance transform
with nearest-feature indices, and a box minimum filter.

They give exactly what `scipy.ndimage.label`, `distance_transform_edt` and `minimum_filter` give on the
grids the generator and the agent lattice use (the same labels in the same order, the same distances and
the same nearest feature on ties), with numpy alone. Importing `scipy.ndimage` costs a process about 28 MB
(it loads `scipy.special` and `scipy.linalg`), which a World process, that generates its scenes, cannot
spare (issue 16: at most 150 MB a World process). `tests/scene/test_raster.py` compares them with scipy.
"""

from __future__ import annotations

import numpy as np

_CHUNK = 1 << 20
"""Row-pass entries (rows x query columns x site columns) handled at once: an 8 MB temporary at most."""


def label4(mask: np.ndarray) -> tuple[np.ndarray, int]:
    """The 4-connected components of a 2-D `mask`: an int32 array numbering them 1 .. n in the raster
    order of their first cell (0 off the mask), and n; `scipy.ndimage.label` with its default structure.

    Runs of cells along each row are joined to the runs they touch in the row below (union-find over
    runs, whose count is small on the generator's grids)."""
    mask = np.asarray(mask, dtype=bool)
    if mask.ndim != 2:
        raise ValueError(f"label4 takes a 2-D mask, not {mask.ndim}-D")
    out = np.zeros(mask.shape, dtype=np.int32)
    if mask.size == 0 or not mask.any():
        return out, 0
    left = np.zeros((mask.shape[0], 1), dtype=bool)
    before, after = np.hstack([left, mask[:, :-1]]), np.hstack([mask[:, 1:], left])
    rows, starts = np.nonzero(mask & ~before)  # runs in raster order: by row, then column
    ends = np.nonzero(mask & ~after)[1] + 1
    parent = list(range(len(rows)))

    def root(k: int) -> int:
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    start_list, end_list = starts.tolist(), ends.tolist()
    first_in_row = np.searchsorted(rows, np.arange(mask.shape[0] + 1)).tolist()
    for r in range(mask.shape[0] - 1):
        a, a_stop = first_in_row[r], first_in_row[r + 1]
        b, b_stop = first_in_row[r + 1], first_in_row[r + 2]
        while a < a_stop and b < b_stop:
            if start_list[a] < end_list[b] and start_list[b] < end_list[a]:
                ra, rb = root(a), root(b)
                if ra != rb:  # the earlier run stays the root: roots are components' first runs
                    parent[max(ra, rb)] = min(ra, rb)
            if end_list[a] <= end_list[b]:
                a += 1
            else:
                b += 1
    for k in range(len(parent)):  # a parent precedes its child, so one forward pass reaches every root
        parent[k] = parent[parent[k]]
    # Roots are components' first runs: counting roots in run order numbers the components in raster order.
    root_of = np.array(parent)
    number = np.cumsum(root_of == np.arange(len(parent)), dtype=np.int32)[root_of]
    out[mask] = np.repeat(number, ends - starts)
    return out, int(number.max())


def _column_nearest(feature: np.ndarray) -> np.ndarray:
    """Per cell, the row of the nearest feature cell in its column (the upper one on a tie), -1 where the
    column has none."""
    h = feature.shape[0]
    rows = np.arange(h).reshape(-1, 1)
    above = np.maximum.accumulate(np.where(feature, rows, -1), axis=0)
    below = np.flip(np.minimum.accumulate(np.flip(np.where(feature, rows, h), axis=0), axis=0), axis=0)
    take_below = (above < 0) | ((below < h) & (below - rows < rows - above))
    nearest = np.where(take_below, below, above)
    return np.where(nearest >= h, -1, nearest)


def feature_transform(feature: np.ndarray) -> np.ndarray:
    """For every cell of a 2-D grid, the (row, col) of its nearest `feature` cell in Euclidean distance:
    an int32 array of shape (2, H, W). Ties go as in `scipy.ndimage.distance_transform_edt`'s feature
    transform (Maurer's algorithm): the lowest column, then the lowest row.

    Raises:
        ValueError: the grid is not 2-D or has no feature cell.
    """
    feature = np.asarray(feature, dtype=bool)
    if feature.ndim != 2:
        raise ValueError(f"feature_transform takes a 2-D grid, not {feature.ndim}-D")
    if not feature.any():
        raise ValueError("feature_transform: the grid has no feature cell")
    h, w = feature.shape
    nearest_row = _column_nearest(feature)
    has = nearest_row >= 0
    cols = np.arange(w)
    out = np.empty((2, h, w), dtype=np.int32)
    step = max(1, _CHUNK // (w * w))
    across = (cols[None, :] - cols[:, None]) ** 2  # (query column, site column)
    for start in range(0, h, step):
        stop = min(h, start + step)
        r = np.arange(start, stop).reshape(-1, 1)
        up = np.where(has[start:stop], (nearest_row[start:stop] - r) ** 2, np.iinfo(np.int64).max // 4)
        cost = across[None, :, :] + up[:, None, :]  # (row, query column, site column)
        site = np.argmin(cost, axis=2)  # the first minimum: the lowest column on a tie
        out[1, start:stop] = site
        out[0, start:stop] = np.take_along_axis(nearest_row[start:stop], site, axis=1)
    return out


def distance_transform(mask: np.ndarray, return_indices: bool = False
                       ) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Euclidean distance (in cells) from each cell of a 2-D `mask` to the nearest cell outside it (0 off
    the mask), as `scipy.ndimage.distance_transform_edt(mask)`; with `return_indices`, also that nearest
    cell's (row, col) per cell, as its `return_indices=True`.

    Raises:
        ValueError: the grid is not 2-D or every cell is in the mask.
    """
    mask = np.asarray(mask, dtype=bool)
    indices = feature_transform(~mask)
    h, w = mask.shape
    rows, cols = np.mgrid[0:h, 0:w]
    dr = (indices[0] - rows).astype(np.float64)
    dc = (indices[1] - cols).astype(np.float64)
    dist = np.sqrt(dr * dr + dc * dc)
    return (dist, indices) if return_indices else dist


def minimum_filter_box(grid: np.ndarray, size: tuple[int, int], cval: float) -> np.ndarray:
    """The least value of `grid` in the (rows, cols) box centred on each cell, cells beyond the edge reading
    `cval`: `scipy.ndimage.minimum_filter(grid, size=size, mode="constant", cval=cval)` for odd sizes.

    Raises:
        ValueError: a size is not a positive odd number.
    """
    grid = np.asarray(grid)
    if grid.ndim != 2 or len(size) != 2 or any(s < 1 or s % 2 == 0 for s in size):
        raise ValueError(f"minimum_filter_box takes a 2-D grid and odd positive sizes, got {size}")
    out = grid
    for axis, s in enumerate(size):
        if s == 1:
            continue
        pad = [(0, 0), (0, 0)]
        pad[axis] = (s // 2, s // 2)
        padded = np.pad(out, pad, mode="constant", constant_values=cval)
        out = np.lib.stride_tricks.sliding_window_view(padded, s, axis=axis).min(axis=-1)
    return np.array(out, dtype=grid.dtype, copy=True)
