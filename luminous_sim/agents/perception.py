"""Learned depth and segmentation for the `rgb` track (`Perception`): an RGB frame to per-pixel object types
(the env's `instance_types` coding) and depth in metres, by the `perception_net` U-Net trained on the
simulator's own labels (`train_perception`, `luminous agents train-perception`). The checkpoint ships in the
package (`default_perception`); it records the data manifest digest and the command that made it."""

from __future__ import annotations

import io
import os
import tempfile
from pathlib import Path
from typing import Any

import cv2
import numpy as np
import torch
from torch.nn import functional as F

from luminous_sim.agents.perception_net import PerceptionNet, PerceptionShape
from luminous_sim.errors import LuminousError

FORMAT = "luminous-perception-net/1"
PERCEPTION_FILE = Path(__file__).parent / "data" / "perception.pt"
"""The shipped checkpoint (package data)."""
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
            logits = F.interpolate(logits, size=(h, w), mode="bilinear", align_corners=False)
            depth = F.interpolate(log_depth[:, None], size=(h, w), mode="bilinear", align_corners=False)[:, 0]
        depth = depth.clamp(np.log(MIN_DEPTH), np.log(MAX_DEPTH)).exp()
        return logits.argmax(1).numpy().astype(np.int32), depth.numpy().astype(np.float32)

    def save(self, path: Path) -> None:
        """Write the checkpoint atomically (the same network, the same bytes)."""
        payload = {"format": FORMAT, "shape": self.net.shape.to_dict(), "model": self.net.state_dict(),
                   "record": self.record}
        buffer = io.BytesIO()
        torch.save(payload, buffer)
        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        try:
            with os.fdopen(fd, "wb") as fh:
                fh.write(buffer.getvalue())
            os.replace(tmp, path)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise

    @classmethod
    def load(cls, path: Path) -> Perception:
        """A perception network from its checkpoint.

        Raises:
            PerceptionError: missing, unreadable, or not a perception checkpoint.
        """
        from luminous_sim.language.speaker.checkpoint import torch_reason

        path = Path(path)
        if not path.is_file():
            raise PerceptionError(f"{path}: no such perception checkpoint (luminous agents train-perception "
                                  "writes one)")
        try:
            data = torch.load(path, map_location="cpu", weights_only=True)
        except Exception as exc:  # torch's unpickler raises any type on foreign bytes
            raise PerceptionError(f"{path}: not a readable perception checkpoint ({torch_reason(exc)})") from None
        if not isinstance(data, dict) or data.get("format") != FORMAT:
            raise PerceptionError(f"{path}: not a perception checkpoint (expected format {FORMAT})")
        try:
            shape = data["shape"]
            net = PerceptionNet(PerceptionShape(int(shape["side"]), tuple(int(c) for c in shape["channels"]),
                                                int(shape["classes"])))
            net.load_state_dict(data["model"])
            return cls(net, dict(data["record"]))
        except (KeyError, TypeError, ValueError, RuntimeError) as exc:  # RuntimeError: weights of other shapes
            raise PerceptionError(f"{path}: a perception checkpoint with a missing or damaged part "
                                  f"({type(exc).__name__}: {str(exc)[:120]})") from None


_DEFAULT: Perception | None = None


def default_perception() -> Perception:
    """The shipped perception network (loaded once)."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = Perception.load(PERCEPTION_FILE)
    return _DEFAULT
