"""Where to write labels on a picture so that none overlaps another: a greedy placement.

Each label, in turn, takes the first free spot among candidates in rings of growing distance around its
anchor (the point it names): free means inside the picture, clear of every label already placed and of
the obstacles, and, if a spot allows it, clear of other labels' anchors and leader lines and of points to
avoid (a path drawn on the picture) too. A label that sits away from its anchor gets a leader line back
to it. A label with no free spot in the picture goes to a legend column to the right of it (x >= width),
so that every label is placed.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

Box = tuple[float, float, float, float]
"""A pixel rectangle (x0, y0, x1, y1), y down."""

ANGLES = 16
"""Directions tried per ring around an anchor."""

RINGS_PER_BATCH = 6
"""Rings whose candidates are checked in one go (most labels find a spot in the first batch)."""

LEADER_SAMPLES = np.linspace(0.1, 1.0, 8)
"""Fractions along a leader line, from anchor to label, where it is checked against other labels."""


@dataclass(frozen=True)
class LabelSpec:
    """A label to place: `text` of pixel `size` (width, height) naming the point `anchor`.

    `on_anchor`: it may be written centred on its anchor (a piece of furniture's name on the piece);
    otherwise it goes beside the anchor, leaving the point itself in sight (a small object).
    """

    key: str
    text: str
    anchor: tuple[float, float]
    size: tuple[float, float]
    on_anchor: bool = False


@dataclass(frozen=True)
class PlacedLabel:
    """Where a label went: its `box`, and the `anchor` it names."""

    key: str
    text: str
    anchor: tuple[float, float]
    box: Box

    @property
    def leader_end(self) -> tuple[float, float] | None:
        """The point of the box nearest the anchor, where a leader line ends; None if the box holds the anchor."""
        x, y = self.anchor
        x0, y0, x1, y1 = self.box
        end = (min(max(x, x0), x1), min(max(y, y0), y1))
        return None if end == (x, y) else end


def boxes_overlap(a: Box, b: Box) -> bool:
    """Whether two boxes share any area (touching edges do not count)."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def place_labels(specs: Sequence[LabelSpec], width: float, height: float, obstacles: Sequence[Box] = (),
                 avoid: np.ndarray | None = None, gap: float = 2.0) -> list[PlacedLabel]:
    """Place every label, in the order given, so that no two boxes overlap, none overlaps an obstacle, and
    each lies inside the `width` x `height` picture or else in a legend column at x >= width.

    Args:
        specs: the labels, most constrained first (they get the spots nearest their anchors).
        width: picture width in pixels.
        height: picture height in pixels.
        obstacles: boxes no label may cover (text already written).
        avoid: (N, 2) pixel points a label covers only where no other spot is free (a path drawn on the picture).
        gap: pixels between a label and its anchor, and between legend rows.

    Returns:
        One placed label per spec, in the same order.
    """
    anchors = np.array([s.anchor for s in specs], dtype=float).reshape(-1, 2)
    taken = np.array(obstacles, dtype=float).reshape(-1, 4)
    leaders = np.zeros((0, 2)) if avoid is None else np.asarray(avoid, dtype=float).reshape(-1, 2)
    placed: list[PlacedLabel] = []
    legend_y = gap
    reach = math.hypot(width, height)
    for i, spec in enumerate(specs):
        others = np.delete(anchors, i, axis=0)
        box = _first_free(spec, width, height, taken, others, leaders, gap, reach)
        if box is None:
            w, h = spec.size
            box = (width + gap, legend_y, width + gap + w, legend_y + h)
            legend_y += h + gap
        label = PlacedLabel(spec.key, spec.text, spec.anchor, box)
        placed.append(label)
        taken = np.vstack([taken, np.array(box)[None]])
        end = label.leader_end
        if end is not None:
            leaders = np.vstack([leaders, _along(np.array(spec.anchor), np.array(end)[None])[0]])
    return placed


def _first_free(spec: LabelSpec, width: float, height: float, taken: np.ndarray, others: np.ndarray,
                leaders: np.ndarray, gap: float, reach: float) -> Box | None:
    """The first candidate box that is free and clear of other anchors and leaders, else the first merely free."""
    step = max(spec.size[1] / 2, 1.0)
    rings = int(reach / step) + 1
    fallback: Box | None = None
    for start in range(0, rings, RINGS_PER_BATCH):
        cands = _candidates(spec, np.arange(start, min(start + RINGS_PER_BATCH, rings)) * step + gap,
                            with_centre=start == 0)
        free = _inside(cands, width, height) & ~_hits_boxes(cands, taken)
        clear = free & ~_covers_points(cands, others) & ~_covers_points(cands, leaders)
        if clear.any():
            k = int(np.argmax(clear & ~_leader_crosses(spec.anchor, cands, taken)))
            if not clear[k]:
                k = int(np.argmax(clear))
            return _as_box(cands[k])
        if fallback is None and free.any():
            fallback = _as_box(cands[int(np.argmax(free))])
    return fallback


def _as_box(row: np.ndarray) -> Box:
    return (float(row[0]), float(row[1]), float(row[2]), float(row[3]))


def _candidates(spec: LabelSpec, distances: np.ndarray, with_centre: bool) -> np.ndarray:
    """Boxes (N, 4) whose nearest edge is each distance from the anchor, in ANGLES directions per distance:
    sideways first (labels are wide), then up and down, then the diagonals; first of all, centred on the
    anchor, if the spec allows it."""
    w, h = spec.size
    angles = np.arange(ANGLES) * 2 * np.pi / ANGLES
    angles = angles[np.lexsort((np.sin(angles), np.cos(angles) < 0, np.round(np.abs(np.sin(angles)), 6)))]
    ux, uy = np.cos(angles), np.sin(angles)
    with np.errstate(divide="ignore"):
        to_edge = np.minimum(w / 2 / np.abs(ux), h / 2 / np.abs(uy))  # centre to edge along the direction
    reach = to_edge[None, :] + distances[:, None]
    cx = (spec.anchor[0] + ux[None, :] * reach).ravel()
    cy = (spec.anchor[1] + uy[None, :] * reach).ravel()
    if with_centre and spec.on_anchor:
        cx, cy = np.r_[spec.anchor[0], cx], np.r_[spec.anchor[1], cy]
    return np.stack([cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2], axis=1)


def _inside(cands: np.ndarray, width: float, height: float) -> np.ndarray:
    return (cands[:, 0] >= 0) & (cands[:, 1] >= 0) & (cands[:, 2] <= width) & (cands[:, 3] <= height)


def _hits_boxes(cands: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Per candidate, whether it overlaps any of `boxes`."""
    if not len(boxes):
        return np.zeros(len(cands), dtype=bool)
    c, b = cands[:, None, :], boxes[None, :, :]
    hit = (c[..., 0] < b[..., 2]) & (b[..., 0] < c[..., 2]) & (c[..., 1] < b[..., 3]) & (b[..., 1] < c[..., 3])
    return np.asarray(hit.any(axis=1))


def _covers_points(cands: np.ndarray, points: np.ndarray, pad: float = 1.0) -> np.ndarray:
    """Per candidate, whether it covers any of `points` (within `pad` pixels)."""
    if not len(points):
        return np.zeros(len(cands), dtype=bool)
    c, p = cands[:, None, :], points[None, :, :]
    inside = ((c[..., 0] - pad <= p[..., 0]) & (p[..., 0] <= c[..., 2] + pad)
              & (c[..., 1] - pad <= p[..., 1]) & (p[..., 1] <= c[..., 3] + pad))
    return np.asarray(inside.any(axis=1))


def _along(anchor: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """Points (N, S, 2) along the segments from `anchor` to each of `ends` (N, 2)."""
    return anchor[None, None, :] + (ends - anchor)[:, None, :] * LEADER_SAMPLES[None, :, None]


def _leader_crosses(anchor: tuple[float, float], cands: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """Per candidate, whether its leader line from `anchor` would run through any of `boxes`."""
    if not len(boxes):
        return np.zeros(len(cands), dtype=bool)
    a = np.array(anchor)
    ends = np.stack([np.clip(a[0], cands[:, 0], cands[:, 2]), np.clip(a[1], cands[:, 1], cands[:, 3])], axis=1)
    pts = _along(a, ends)[:, :, None, :]
    b = boxes[None, None, :, :]
    inside = ((b[..., 0] < pts[..., 0]) & (pts[..., 0] < b[..., 2])
              & (b[..., 1] < pts[..., 1]) & (pts[..., 1] < b[..., 3]))
    return np.asarray(inside.any(axis=(1, 2)))
