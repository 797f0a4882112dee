"""The rgb track's perception network (torch): a small U-Net (Ronneberger et al. 2015) from an RGB frame to
per-pixel object types (logits over `ALL_TYPES` plus "none") and depth (log metres), trained on the
simulator's exact labels (`perception_training`). Small enough to train on a CPU: four levels of two 3x3
convolutions each, bilinear upsampling, skip connections, one 1x1 head per output. Two more input channels
give each pixel's place in the whole frame (CoordConv, Liu et al. 2018): trained on crops, the network still
knows where in the frame a crop was (what is low in the frame is near the feet)."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import torch
from torch import nn
from torch.nn import functional as F

from luminous_sim.vocab import ALL_TYPES

CLASSES = len(ALL_TYPES) + 1
"""Type indices as the env's `instance_types` gives them: 0 for structure and none, `i + 1` for ALL_TYPES[i]."""


@dataclass(frozen=True)
class PerceptionShape:
    """The network's sizes: the input side (frames are resized to it), the channels per level, the classes."""

    side: int = 128
    channels: tuple[int, ...] = (16, 32, 64, 96, 128)
    classes: int = CLASSES
    coords: bool = True
    """Two input channels of each pixel's place in the frame (-1..1 down and across)."""

    def to_dict(self) -> dict[str, object]:
        return {**asdict(self), "channels": list(self.channels)}


def frame_coords(batch: int, height: int, width: int) -> torch.Tensor:
    """(batch, 2, height, width): each pixel's row and column in its frame, from -1 to 1 (pixel centres)."""
    rows = (torch.arange(height, dtype=torch.float32) + 0.5) / height * 2 - 1
    cols = (torch.arange(width, dtype=torch.float32) + 0.5) / width * 2 - 1
    grid = torch.stack(torch.meshgrid(rows, cols, indexing="ij"))
    return grid.expand(batch, 2, height, width)


def _block(c_in: int, c_out: int) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(c_in, c_out, 3, padding=1, bias=False), nn.BatchNorm2d(c_out),
                         nn.ReLU(inplace=True), nn.Conv2d(c_out, c_out, 3, padding=1, bias=False),
                         nn.BatchNorm2d(c_out), nn.ReLU(inplace=True))


class PerceptionNet(nn.Module):
    """(batch, 3, side, side) floats in 0..1 -> type logits (batch, classes, side, side) and log-depth
    (batch, side, side)."""

    def __init__(self, shape: PerceptionShape):
        super().__init__()
        self.shape = shape
        c = shape.channels
        first = 5 if shape.coords else 3
        self.down = nn.ModuleList(_block(a, b) for a, b in zip((first, *c[:-2]), c[:-1], strict=True))
        self.bottom = _block(c[-2], c[-1])
        self.up = nn.ModuleList(_block(c[i + 1] + c[i], c[i]) for i in reversed(range(len(c) - 1)))
        self.types = nn.Conv2d(c[0], shape.classes, 1)
        self.depth = nn.Conv2d(c[0], 1, 1)
        self.mean: torch.Tensor
        self.register_buffer("mean", torch.tensor([0.5, 0.5, 0.5]).view(1, 3, 1, 1))

    def forward(self, rgb: torch.Tensor, coords: torch.Tensor | None = None) -> tuple[torch.Tensor, torch.Tensor]:
        """`coords`: (batch, 2, h, w) of the pixels' places in their frame (a crop's); None for whole frames."""
        x = rgb - self.mean
        if self.shape.coords:
            x = torch.cat([x, frame_coords(len(x), x.shape[-2], x.shape[-1]) if coords is None else coords], 1)
        skips = []
        for block in self.down:
            x = block(x)
            skips.append(x)
            x = F.max_pool2d(x, 2)
        x = self.bottom(x)
        for block, skip in zip(self.up, reversed(skips), strict=True):
            x = F.interpolate(x, size=skip.shape[-2:], mode="bilinear", align_corners=False)
            x = block(torch.cat([x, skip], 1))
        return self.types(x), self.depth(x)[:, 0]
