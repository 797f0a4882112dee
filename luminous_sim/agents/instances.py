"""Instances from a predicted type map (the rgb track): each type's connected regions, placed in the agent's
own frame by the predicted depth and its own pose, are matched to the instances tracked so far of the same type
by the nearest distance between their points, so that an object keeps one id from frame to frame as the
simulator's segmentation would give it. What the agent holds floats in front of its camera: a region of the
held type that close is the held instance, never a new one."""

from __future__ import annotations

from dataclasses import dataclass

import cv2
import numpy as np

from luminous_sim.agents.camera import Intrinsics, unproject
from luminous_sim.agents.own_pose import OwnPose

MIN_PIXELS = 24
"""Regions smaller than this (pixels, at the frame's size) are noise, not objects."""
MATCH_WITHIN = 0.2
"""Metres between a region's points and a tracked instance's within which they are the same instance."""
HELD_WITHIN = 0.9
"""Metres of depth within which a region of the held type is the held object (it floats about 0.6 m away)."""
POINTS_KEPT = 400
"""Most points kept per tracked instance (the latest first)."""
SAMPLE = 150
"""Most pixels of a region placed in 3D to match it."""


@dataclass
class Track:
    """A tracked instance: its type index and points in the own frame."""

    type_index: int
    points: np.ndarray


class InstanceTracker:
    """Stable instance ids for one episode's frames (ids from 1 up; -1 for no instance)."""

    def __init__(self, intrinsics: Intrinsics):
        self.intrinsics = intrinsics
        self.tracks: dict[int, Track] = {}
        self.next_id = 1

    def forget(self, body: int) -> None:
        """An instance that moved (picked up, sliced): where it was is no longer known, its id is kept."""
        if body in self.tracks:
            self.tracks[body].points = np.zeros((0, 3))

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
                if held is not None and t == held_type and float(np.median(d)) < HELD_WITHIN:
                    ids[rows, cols] = held
                    continue
                pick = rng.choice(len(rows), SAMPLE, replace=False) if len(rows) > SAMPLE else slice(None)
                pts = unproject(d[pick], rows[pick], cols[pick], self.intrinsics, pose.x, pose.y, pose.yaw,
                                pose.horizon)
                body = self._match(t, pts, held)
                ids[rows, cols] = body
                track = self.tracks[body]
                track.points = np.concatenate([pts, track.points])[:POINTS_KEPT]
        return ids

    def _match(self, type_index: int, points: np.ndarray, held: int | None) -> int:
        best, best_distance = None, MATCH_WITHIN
        for body, track in self.tracks.items():
            if track.type_index != type_index or body == held or not len(track.points):
                continue
            gaps = np.linalg.norm(points[:, None, :] - track.points[None, :, :], axis=-1)
            distance = float(gaps.min())
            if distance < best_distance:
                best, best_distance = body, distance
        if best is None:
            best = self.next_id
            self.next_id += 1
            self.tracks[best] = Track(type_index, np.zeros((0, 3)))
        return best
