"""Learned depth and segmentation for the `rgb` track (`Perception`): an RGB frame to per-pixel object types
(the env's `instance_types` coding) and depth in metres, by the `perception_net` U-Net trained on the
simulator's own labels (`train_perception`, `luminous agents train-perception`). A checkpoint records the
data manifest digest and the command that made it. `default_perception` is the checkpoint named by
`LUMINOUS_PERCEPTION`, else the one shipped in the package (none ships yet: docs/perception.md)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import cv2
import numpy as np
import torch

from luminous_sim.agents.checkpoints import load_checkpoint, save_checkpoint
from luminous_sim.agents.perception_net import PerceptionNet, PerceptionShape
from luminous_sim.errors import LuminousError

FORMAT = "luminous-perception-net/1"
PERCEPTION_FILE = Path(__file__).parent / "data" / "perception.pt"
"""Where the shipped checkpoint lives (package data) once one ships."""
PERCEPTION_VAR = "LUMINOUS_PERCEPTION"
"""The environment variable naming a perception checkpoint for `default_perception` (and so `modular_rgb`
under `luminous eval`, whose agent runs in a child process)."""
MIN_DEPTH, MAX_DEPTH = 0.05, 15.0
"""The depths the network predicts between (metres; the log-depth head is clipped to them)."""


class PerceptionError(LuminousError):
    """A perception checkpoint that cannot be read, or bad input to training or prediction."""


def to_input(rgb: np.ndarray, side: int) -> np.ndarray:
    """An (H, W, 3) uint8 frame as the network's input: (3, side, side) float32 in 0..1 (area-resized)."""
    small = cv2.resize(np.ascontiguousarray(rgb), (side, side), interpolation=cv2.INTER_AREA)
    return np.ascontiguousarray(small.transpose(2, 0, 1), dtype=np.float32) / 255.0


class Perception:
    """The trained network and what made it (`record`: data digest, command, settings, scores per epoch)."""

    def __init__(self, net: PerceptionNet, record: dict[str, Any]):
        self.net = net.eval()
        self.record = record

    @property
    def side(self) -> int:
        return self.net.shape.side

    def predict(self, rgb: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """One frame's types (H, W) int32 (`instance_types` coding) and depth (H, W) float32 metres, at the frame's
        own size.

        Raises:
            PerceptionError: not an (H, W, 3) image.
        """
        types, depth = self.predict_many(np.asarray(rgb)[None])
        return types[0], depth[0]

    def predict_many(self, frames: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """A batch (N, H, W, 3) uint8: types (N, H, W) int32 and depth (N, H, W) float32 metres."""
        frames = np.asarray(frames)
        if frames.ndim != 4 or frames.shape[-1] != 3 or min(frames.shape[1:3]) < 1:
            raise PerceptionError(f"expected RGB frames of shape (N, H, W, 3), got {frames.shape}")
        h, w = frames.shape[1:3]
        x = torch.from_numpy(np.stack([to_input(f, self.side) for f in frames]))
        with torch.no_grad():
            logits, log_depth = self.net(x)
        # each pixel the type of the network's pixel it falls in, and depth interpolated between them
        small = logits.argmax(1).numpy().astype(np.int32)
        near = np.clip(log_depth.numpy(), np.log(MIN_DEPTH), np.log(MAX_DEPTH))
        types = np.stack([cv2.resize(t, (w, h), interpolation=cv2.INTER_NEAREST) for t in small])
        depth = np.stack([np.exp(cv2.resize(d, (w, h), interpolation=cv2.INTER_LINEAR)) for d in near])
        return types.astype(np.int32), depth.astype(np.float32)

    def save(self, path: Path) -> None:
        """Write the checkpoint atomically (the same network, the same bytes)."""
        save_checkpoint({"format": FORMAT, "shape": self.net.shape.to_dict(), "model": self.net.state_dict(),
                         "record": self.record}, path)

    @classmethod
    def load(cls, path: Path) -> Perception:
        """A perception network from its checkpoint.

        Raises:
            PerceptionError: missing, unreadable, or not a perception checkpoint.
        """
        data = load_checkpoint(path, FORMAT, "perception", "luminous agents train-perception", PerceptionError)
        try:
            shape = data["shape"]
            net = PerceptionNet(PerceptionShape(int(shape["side"]), tuple(int(c) for c in shape["channels"]),
                                                int(shape["classes"]), bool(shape.get("coords", False))))
            net.load_state_dict(data["model"])
            return cls(net, dict(data["record"]))
        except (KeyError, TypeError, ValueError, RuntimeError) as exc:  # RuntimeError: weights of other shapes
            raise PerceptionError(f"{path}: a perception checkpoint with a missing or damaged part "
                                  f"({type(exc).__name__}: {str(exc)[:120]})") from None


_DEFAULT: dict[str, Perception] = {}


def default_perception() -> Perception:
    """The checkpoint `LUMINOUS_PERCEPTION` names, else the shipped one (each loaded once).

    Raises:
        PerceptionError: the named checkpoint cannot be read, or none is named and none ships.
    """
    named = os.environ.get(PERCEPTION_VAR, "")
    path = Path(named) if named else PERCEPTION_FILE
    if not named and not path.is_file():
        raise PerceptionError(f"no perception network ships with this version yet: train one with `luminous agents "
                              f"train-perception` (docs/perception.md) and name it in {PERCEPTION_VAR}, or pass "
                              "ModularAgent(..., perception=Perception.load(path))")
    if str(path) not in _DEFAULT:
        _DEFAULT[str(path)] = Perception.load(path)
    return _DEFAULT[str(path)]
