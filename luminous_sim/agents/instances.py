"""Instances from a predicted type map (the rgb track): each type's connected regions, placed in the agent's
own frame by the predicted depth and its own pose, are matched to the instances tracked so far of the same type
by the nearest distance between their points, so that an object keeps one id from frame to frame as the
simulator's segmentation would give it. What the agent holds floats in front of its camera: while it holds
something, a region that close is the held instance (of the held type, or of any type but a receptacle's: the
network may mistype it), never a new one."""

from __future__ import annotations

from dataclasses import dataclass, field

import cv2
import numpy as np

from luminous_sim.agents.camera import Intrinsics, unproject
from luminous_sim.agents.own_pose import OwnPose
from luminous_sim.vocab import ALL_TYPES, abilities

MIN_PIXELS = 24
"""Regions smaller than this (pixels, at the frame's size) are noise, not objects."""
MATCH_WITHIN = 0.2
"""Metres between a region's points and a tracked instance's within which they are the same instance (at
least; farther regions get `MATCH_PER_METRE` more, as predicted depth errs in proportion to depth)."""
MATCH_PER_METRE = 0.1
"""Metres of match distance added per metre of the region's median depth."""
HELD_WITHIN = 0.9
"""Metres of depth within which a region is the held object while the agent holds one (it floats about 0.6 m
away)."""
POINTS_KEPT = 400
"""Most points kept per tracked instance (the latest first)."""
RECEPTACLES = frozenset(i + 1 for i, t in enumerate(ALL_TYPES) if abilities(t).receptacle)
"""Type indices of receptacles: a close region of one is what the agent puts on, not what it holds (unless it
holds one of that type)."""
SAMPLE = 150
"""Most pixels of a region placed in 3D to match it."""


@dataclass
class Track:
    """A tracked instance: its type index and points in the own frame (and their bounds, to skip far ones)."""

    type_index: int
    points: np.ndarray
    low: np.ndarray = field(default_factory=lambda: np.full(3, np.inf))
    high: np.ndarray = field(default_factory=lambda: np.full(3, -np.inf))

    def add(self, points: np.ndarray) -> None:
        self.points = np.concatenate([points, self.points])[:POINTS_KEPT]
        self.low, self.high = self.points.min(axis=0), self.points.max(axis=0)


class InstanceTracker:
    """Stable instance ids for one episode's frames (ids from 1 up; -1 for no instance)."""

    def __init__(self, intrinsics: Intrinsics):
        self.intrinsics = intrinsics
        self.tracks: dict[int, Track] = {}
        self.next_id = 1

    def forget(self, body: int) -> None:
        """An instance that moved (picked up, sliced): where it was is no longer known, its id is kept."""
        if body in self.tracks:
            self.tracks[body] = Track(self.tracks[body].type_index, np.zeros((0, 3)))

    def update(self, types: np.ndarray, depth: np.ndarray, pose: OwnPose, held: int | None = None) -> np.ndarray:
        """The frame's instance ids (H, W) int32 from its predicted types (H, W) and depth (H, W) metres, seen from
        `pose`; `held` is the id of what the agent holds (None: nothing)."""
        ids = np.full(types.shape, -1, np.int32)
        held_type = self.tracks[held].type_index if held is not None and held in self.tracks else None
        rng = np.random.default_rng(0)  # the same sample of a region every time: deterministic ids
        for t in (int(t) for t in np.unique(types) if t > 0):
            count, labels, stats, _ = cv2.connectedComponentsWithStats((types == t).astype(np.uint8), connectivity=8)
            for c in range(1, count):
                if stats[c, cv2.CC_STAT_AREA] < MIN_PIXELS:
                    continue
                rows, cols = np.nonzero(labels == c)
                d = depth[rows, cols]
                if held is not None and float(np.median(d)) < HELD_WITHIN and (t == held_type or t not in RECEPTACLES):
                    ids[rows, cols] = held
                    continue
                pick = rng.choice(len(rows), SAMPLE, replace=False) if len(rows) > SAMPLE else slice(None)
                pts = unproject(d[pick], rows[pick], cols[pick], self.intrinsics, pose.x, pose.y, pose.yaw,
                                pose.horizon)
                body = self._match(t, pts, held, MATCH_WITHIN + MATCH_PER_METRE * float(np.median(d)))
                ids[rows, cols] = body
                self.tracks[body].add(pts)
        return ids

    def _match(self, type_index: int, points: np.ndarray, held: int | None, within: float) -> int:
        best, best_distance = None, within
        low, high = points.min(axis=0), points.max(axis=0)
        for body, track in self.tracks.items():
            if track.type_index != type_index or body == held or not len(track.points):
                continue
            if (low > track.high + within).any() or (high < track.low - within).any():
                continue  # the bounds alone are farther apart than a match
            gaps = ((points[:, None, :] - track.points[None, ::2, :]) ** 2).sum(-1)
            distance = float(np.sqrt(gaps.min()))
            if distance < best_distance:
                best, best_distance = body, distance
        if best is None:
            best = self.next_id
            self.next_id += 1
            self.tracks[best] = Track(type_index, np.zeros((0, 3)))
        return best
