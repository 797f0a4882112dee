"""How well perception sees, in the field's measures: the mean IoU over the object types ALFRED's tasks name
(`TASK_NAMED`: what is picked up, put in or on, toggled or sliced) and depth's absolute relative error, each
per room type, accumulated over frames (IoU's intersections and unions summed over every frame of a room type
before they are divided, as semantic segmentation is scored)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.agents.perception_net import CLASSES
from luminous_sim.vocab import ALL_TYPES, abilities

TASK_NAMED = tuple(i + 1 for i, t in enumerate(ALL_TYPES)
                   if (a := abilities(t)).pickupable or a.receptacle or a.toggleable or a.sliceable)
"""Type indices (`instance_types` coding) of the types a task may name: pickupable objects, receptacles,
toggleables (the lamps of look_at_obj_in_light) and sliceables."""


@dataclass
class _Room:
    intersection: np.ndarray = field(default_factory=lambda: np.zeros(CLASSES, np.int64))
    union: np.ndarray = field(default_factory=lambda: np.zeros(CLASSES, np.int64))
    truth: np.ndarray = field(default_factory=lambda: np.zeros(CLASSES, np.int64))
    abs_rel: float = 0.0
    pixels: int = 0
    frames: int = 0


class PerceptionScores:
    """Accumulates frames' predictions against their labels, per room type."""

    def __init__(self) -> None:
        self.rooms: dict[str, _Room] = {}

    def add(self, room_type: str, types: np.ndarray, true_types: np.ndarray, depth: np.ndarray,
            true_depth: np.ndarray) -> None:
        """One frame (or a batch of them): predicted and true types (same shape, `instance_types` coding), predicted
        and true depth in metres (pixels with no true depth, <= 0, are left out)."""
        room = self.rooms.setdefault(room_type, _Room())
        room.frames += 1 if np.ndim(true_types) <= 2 else int(np.shape(true_types)[0])
        types, true_types = np.asarray(types).ravel(), np.asarray(true_types).ravel()
        both = np.bincount(true_types[types == true_types], minlength=CLASSES)[:CLASSES]
        predicted = np.bincount(types, minlength=CLASSES)[:CLASSES]
        truth = np.bincount(true_types, minlength=CLASSES)[:CLASSES]
        room.intersection += both
        room.union += predicted + truth - both
        room.truth += truth
        d, t = np.asarray(depth, np.float64).ravel(), np.asarray(true_depth, np.float64).ravel()
        valid = t > 0
        room.abs_rel += float((np.abs(d[valid] - t[valid]) / t[valid]).sum())
        room.pixels += int(valid.sum())

    def to_counts(self) -> dict[str, dict[str, Any]]:
        """What has been accumulated, as JSON (per room type), for `add_counts` to merge elsewhere."""
        return {name: {"intersection": r.intersection.tolist(), "union": r.union.tolist(), "truth": r.truth.tolist(),
                       "abs_rel": r.abs_rel, "pixels": r.pixels, "frames": r.frames} for name, r in self.rooms.items()}

    def add_counts(self, counts: dict[str, dict[str, Any]]) -> None:
        """Merge counts of `to_counts` (another run's frames) into these."""
        for name, c in counts.items():
            room = self.rooms.setdefault(name, _Room())
            room.intersection += np.asarray(c["intersection"], np.int64)
            room.union += np.asarray(c["union"], np.int64)
            room.truth += np.asarray(c["truth"], np.int64)
            room.abs_rel += float(c["abs_rel"])
            room.pixels += int(c["pixels"])
            room.frames += int(c["frames"])

    @staticmethod
    def _summary(room: _Room) -> dict[str, float | int]:
        named = [c for c in TASK_NAMED if room.truth[c] > 0]
        ious = [room.intersection[c] / room.union[c] for c in named]
        correct = int(room.intersection.sum())
        return {"frames": room.frames, "types": len(named), "miou": round(float(np.mean(ious)) if ious else 0.0, 4),
                "pixel_accuracy": round(correct / max(int(room.truth.sum()), 1), 4),
                "depth_abs_rel": round(room.abs_rel / max(room.pixels, 1), 4)}

    def summary(self) -> dict[str, dict[str, float | int]]:
        """Per room type and over all (`"all"`): frames, the task-named types present in the labels, their mean
        IoU, the share of pixels of the right type (structure and none included), depth's absolute relative
        error."""
        out = {name: self._summary(room) for name, room in sorted(self.rooms.items())}
        total = _Room()
        for room in self.rooms.values():
            total.intersection += room.intersection
            total.union += room.union
            total.truth += room.truth
            total.abs_rel += room.abs_rel
            total.pixels += room.pixels
            total.frames += room.frames
        out["all"] = self._summary(total)
        return out


def score_dataset(perception: Any, data: Path, batch: int = 16) -> dict[str, dict[str, float | int]]:
    """A `Perception`'s scores on every frame of a perception dataset, predicted and scored at the frames' size.

    Raises:
        PerceptionDataError: the dataset cannot be read (a missing or altered shard).
    """
    from luminous_sim.data.perception_frames import iter_shards

    scores = PerceptionScores()
    for record, arrays in iter_shards(data):
        for s in range(0, len(arrays["rgb"]), batch):
            types, depth = perception.predict_many(arrays["rgb"][s:s + batch])
            scores.add(str(record["room_type"]), types, arrays["types"][s:s + batch].astype(np.int64), depth,
                       arrays["depth"][s:s + batch] / 1000.0)
    return scores.summary()
