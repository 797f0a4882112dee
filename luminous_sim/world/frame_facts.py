"""What one rendered frame shows, each fact computed only when asked and at most once per frame.

A World keeps one `FrameFacts` for its current view and drops it when the view may have changed (a
successful action, the agent or objects moved outside `World.step`); the next question renders anew.
The arrays and dicts handed out are shared by every caller within the frame: arrays are read-only,
and the World hands out copies of the dicts.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from luminous_sim.world.camera import Frame
from luminous_sim.world.masks import bbox_from_mask


def body_ids(seg: np.ndarray) -> np.ndarray:
    """Per-pixel body ids (-1 for background), from PyBullet's object+link segmentation."""
    return np.where(seg >= 0, seg & ((1 << 24) - 1), -1)


def body_counts(bodies: np.ndarray) -> dict[int, int]:
    """Pixels of each body id that shows in `bodies` (background, -1, left out), in increasing id order."""
    counts = np.bincount(bodies.ravel() + 1)[1:]
    shown = np.flatnonzero(counts)
    return dict(zip(shown.tolist(), counts[shown].tolist(), strict=True))


def object_masks(bodies: np.ndarray, names: dict[int, str], shown: Iterable[int] | None = None
                 ) -> dict[str, np.ndarray]:
    """Boolean mask of every object (body id in `names`) that shows in `bodies` (`shown`: the body ids
    that do, when already counted)."""
    return {names[b]: bodies == b for b in (body_counts(bodies) if shown is None else shown) if b in names}


def _read_only(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


class FrameFacts:
    """One frame and what it shows: body ids, object masks, boxes, visible objects, object metadata."""

    def __init__(self, frame: Frame):
        self.frame = frame
        self._bodies: np.ndarray | None = None
        self._counts: dict[int, int] | None = None
        self._masks: dict[str, np.ndarray] | None = None
        self._boxes: dict[str, list[int]] | None = None
        self._visible: dict[str, int] | None = None
        self._objects: list[dict[str, Any]] | None = None

    def bodies(self) -> np.ndarray:
        """Per-pixel body ids of this frame (read-only)."""
        if self._bodies is None:
            self._bodies = _read_only(body_ids(self.frame.seg))
        return self._bodies

    def counts(self) -> dict[int, int]:
        """Pixels of each body id in this frame (a histogram: no per-object mask is made)."""
        if self._counts is None:
            self._counts = body_counts(self.bodies())
        return self._counts

    def masks(self, names: Callable[[], dict[int, str]]) -> dict[str, np.ndarray]:
        """Object masks of this frame (read-only arrays); `names` maps body ids to object ids."""
        if self._masks is None:
            masks = object_masks(self.bodies(), names(), self.counts())
            self._masks = {oid: _read_only(m) for oid, m in masks.items()}
        return self._masks

    def boxes(self, names: Callable[[], dict[int, str]]) -> dict[str, list[int]]:
        """2D boxes of the objects in this frame."""
        if self._boxes is None:
            self._boxes = {oid: bbox_from_mask(m) for oid, m in self.masks(names).items()}
        return self._boxes

    def visible(self, names: Callable[[], dict[int, str]], min_pixels: int, max_distance: float,
                distance: Callable[[str], float]) -> dict[str, int]:
        """Objects with at least `min_pixels` pixels and within `max_distance`, with their pixel counts."""
        if self._visible is None:
            known = names()
            counts = {known[b]: n for b, n in self.counts().items() if b in known}
            self._visible = {oid: n for oid, n in counts.items()
                             if n >= min_pixels and distance(oid) <= max_distance}
        return self._visible

    def objects(self, compute: Callable[[], list[dict[str, Any]]]) -> list[dict[str, Any]]:
        """Per-object metadata of the world this frame shows (computed by `compute` once)."""
        if self._objects is None:
            self._objects = compute()
        return self._objects
