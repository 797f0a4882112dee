"""Training the rgb track's perception (`train_perception`, `luminous agents train-perception`) on perception
datasets (`luminous dataset perception`): type cross-entropy (classes weighted by their inverse fourth-root
pixel frequency, so that a knife counts beside the floor; the head's bias starts at the classes' log
frequencies) plus L1 on log-depth, Adam with a cosine schedule,
flips and brightness jitter. It learns on crops of the frames (a quarter of the pixels: four times the steps
for the same CPU), most of them centred on a pixel of a type tasks name, each with its place in the frame
(the network's coordinate channels); it predicts whole frames. Every tenth shard is held apart and scored
after each epoch (`perception_scores`). The same data, settings, thread count and torch version give the
same bytes."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import cv2
import numpy as np
import torch
from torch.nn import functional as F

from luminous_sim.agents.perception import MAX_DEPTH, MIN_DEPTH, Perception, PerceptionError, to_input
from luminous_sim.agents.perception_net import CLASSES, PerceptionNet, PerceptionShape, frame_coords
from luminous_sim.agents.perception_scores import TASK_NAMED, PerceptionScores

HELD_APART_EVERY = 10
"""Shard `k` (in dataset order) is held apart for scoring when `k % HELD_APART_EVERY == HELD_APART_EVERY - 1`."""


@dataclass(frozen=True)
class PerceptionSettings:
    """How the network is trained (the defaults made the shipped checkpoint)."""

    seed: int = 0
    epochs: int = 5
    batch: int = 32
    lr: float = 2e-3
    depth_weight: float = 3.0
    side: int = 128
    channels: tuple[int, ...] = (12, 24, 48, 96, 128)
    threads: int = 2
    crop: int = 64
    """The side of the training crops (the network's `side` for whole frames)."""
    on_objects: float = 0.75
    """The share of crops centred on a pixel of a type tasks name (the rest anywhere)."""
    max_frames: int = 0
    """Frames kept from the data (the first ones in dataset order); 0 for all."""

    def to_dict(self) -> dict[str, Any]:
        return {**asdict(self), "channels": list(self.channels)}


@dataclass
class Frames:
    """Frames at the network's side: inputs (N, 3, s, s) float32, types (N, s, s) int64, depth (N, s, s) metres,
    and each frame's room type."""

    rgb: np.ndarray
    types: np.ndarray
    depth: np.ndarray
    rooms: list[str]


def read_frames(datasets: Sequence[Path], side: int, max_frames: int = 0
                ) -> tuple[Frames, Frames, list[dict[str, Any]]]:
    """The training and held-apart frames of the given perception datasets, and what each dataset is (its
    manifest's digest and frame count, for the checkpoint's record).

    Raises:
        PerceptionError: an evaluation dataset (a split's entries), an unfinished one, or no frames.
        PerceptionDataError: a dataset that cannot be read (a missing or altered shard).
    """
    from luminous_sim.data.perception_frames import iter_shards, manifest_digest, read_header

    parts: dict[bool, list[tuple[np.ndarray, np.ndarray, np.ndarray, str]]] = {False: [], True: []}
    sources, kept, k = [], 0, 0
    for data in datasets:
        header = read_header(data)
        if header["evaluation"]:
            raise PerceptionError(f"{data}: an evaluation dataset (entries of {header['evaluation']}); its frames "
                                  "never feed training")
        if not header.get("complete") or header.get("manifest_sha256") != manifest_digest(data):
            raise PerceptionError(f"{data}: an unfinished perception dataset (its build stopped or is running, or its "
                                  "manifest changed since): run its `luminous dataset perception` command again")
        frames = 0
        for record, arrays in iter_shards(data):
            if max_frames and kept >= max_frames:
                break
            n = len(arrays["rgb"]) if not max_frames else min(len(arrays["rgb"]), max_frames - kept)
            apart = k % HELD_APART_EVERY == HELD_APART_EVERY - 1
            for i in range(n):
                parts[apart].append((to_input(arrays["rgb"][i], side),
                                     cv2.resize(arrays["types"][i], (side, side), interpolation=cv2.INTER_NEAREST),
                                     cv2.resize(arrays["depth"][i], (side, side), interpolation=cv2.INTER_NEAREST),
                                     str(record["room_type"])))
            frames += n
            kept += n
            k += 1
        sources.append({"manifest_sha256": header["manifest_sha256"], "frames": frames, "seed": header["seed"]})
    if not parts[False]:
        raise PerceptionError(f"{', '.join(map(str, datasets))}: no frames to train on")

    def stack(items: list[tuple[np.ndarray, np.ndarray, np.ndarray, str]]) -> Frames:
        if not items:
            return Frames(np.zeros((0, 3, side, side), np.float32), np.zeros((0, side, side), np.int64),
                          np.zeros((0, side, side), np.float32), [])
        return Frames(np.stack([i[0] for i in items]), np.stack([i[1] for i in items]).astype(np.int64),
                      np.stack([i[2] for i in items]).astype(np.float32) / 1000.0, [i[3] for i in items])

    return stack(parts[False]), stack(parts[True]), sources


def class_weights(types: np.ndarray) -> np.ndarray:
    """Cross-entropy weights: (median frequency / frequency) ** 0.25 of the classes present, within 0.2..5."""
    counts = np.bincount(types.ravel(), minlength=CLASSES)[:CLASSES].astype(np.float64)
    present = counts > 0
    weights = np.ones(CLASSES)
    weights[present] = np.clip((np.median(counts[present]) / counts[present]) ** 0.25, 0.2, 5.0)
    return weights.astype(np.float32)


def class_priors(types: np.ndarray) -> np.ndarray:
    """Each class's log share of the pixels (one pixel added to each, so none is -inf): the type head's first
    bias, so that training starts from the classes' frequencies rather than from uniform guesses."""
    counts = np.bincount(types.ravel(), minlength=CLASSES)[:CLASSES].astype(np.float64) + 1.0
    return np.log(counts / counts.sum()).astype(np.float32)


def score(net: PerceptionNet, frames: Frames, batch: int = 64) -> dict[str, dict[str, float | int]]:
    """The network's scores on frames at its own side (per room type and over all)."""
    scores = PerceptionScores()
    net.eval()
    with torch.no_grad():
        for s in range(0, len(frames.rgb), batch):
            logits, log_depth = net(torch.from_numpy(frames.rgb[s:s + batch]))
            types = logits.argmax(1).numpy()
            depth = log_depth.clamp(np.log(MIN_DEPTH), np.log(MAX_DEPTH)).exp().numpy()
            for i in range(len(types)):
                scores.add(frames.rooms[s + i], types[i], frames.types[s + i], depth[i], frames.depth[s + i])
    return scores.summary()


def train_perception(datasets: Sequence[Path], settings: PerceptionSettings | None = None, command: str = "",
                     progress: bool = False) -> Perception:
    """Train the network on the datasets' frames (`settings.seed`, `settings.threads` torch threads).

    Args:
        command: the command line that asked for this (recorded in the checkpoint).

    Raises:
        PerceptionError: no frames, or an evaluation dataset among `datasets`.
    """
    settings = settings or PerceptionSettings()
    train, apart, sources = read_frames(datasets, settings.side, settings.max_frames)
    threads = torch.get_num_threads()
    deterministic = torch.are_deterministic_algorithms_enabled()
    torch.set_num_threads(settings.threads)
    torch.use_deterministic_algorithms(True)
    try:
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(settings.seed)
            net, epochs = _fit(train, apart, settings, progress)
    finally:
        torch.set_num_threads(threads)
        torch.use_deterministic_algorithms(deterministic)
    record = {"data": sources, "command": command, "settings": settings.to_dict(), "torch": str(torch.__version__),
              "frames": {"train": len(train.rgb), "held_apart": len(apart.rgb)}, "epochs": epochs}
    return Perception(net, record)


def _fit(train: Frames, apart: Frames, settings: PerceptionSettings, progress: bool
         ) -> tuple[PerceptionNet, list[dict[str, Any]]]:
    net = PerceptionNet(PerceptionShape(settings.side, settings.channels))
    bias = net.types.bias
    assert bias is not None, "the type head has a bias"
    with torch.no_grad():
        bias.copy_(torch.from_numpy(class_priors(train.types)))
    weights = torch.from_numpy(class_weights(train.types))
    named = torch.zeros(CLASSES, dtype=torch.bool)
    named[list(TASK_NAMED)] = True
    grid = frame_coords(1, settings.side, settings.side)[0]
    size = min(settings.crop, settings.side)
    optimiser = torch.optim.Adam(net.parameters(), lr=settings.lr)
    steps_per_epoch = (len(train.rgb) + settings.batch - 1) // settings.batch
    schedule = torch.optim.lr_scheduler.CosineAnnealingLR(optimiser, max(1, settings.epochs * steps_per_epoch))
    order = torch.Generator().manual_seed(settings.seed)
    rgb, types = torch.from_numpy(train.rgb), torch.from_numpy(train.types)
    log_depth = torch.from_numpy(np.log(np.clip(train.depth, MIN_DEPTH, MAX_DEPTH)))
    valid = torch.from_numpy(train.depth > 0)
    epochs: list[dict[str, Any]] = []
    for epoch in range(settings.epochs):
        net.train()
        total, seen = 0.0, 0
        for batch in torch.randperm(len(rgb), generator=order).split(settings.batch):
            corners = [_corner(types[i], named, size, settings, order) for i in batch.tolist()]
            crop = [(slice(None), slice(r, r + size), slice(c, c + size)) for r, c in corners]
            x = torch.stack([rgb[i][s] for i, s in zip(batch.tolist(), crop, strict=True)])
            g = torch.stack([grid[s] for s in crop])
            t, d, v = (torch.stack([a[i][s[1:]] for i, s in zip(batch.tolist(), crop, strict=True)])
                       for a in (types, log_depth, valid))
            flip = torch.rand(len(batch), generator=order) < 0.5
            x, t, d, v = (torch.where(flip.view(-1, *[1] * (a.dim() - 1)), a.flip(-1), a) for a in (x, t, d, v))
            g = torch.where(flip.view(-1, 1, 1, 1), g.flip(-1) * torch.tensor([1.0, -1.0]).view(1, 2, 1, 1), g)
            x = (x * (0.8 + 0.4 * torch.rand(len(batch), 1, 1, 1, generator=order))).clamp(0, 1)
            logits, pred_depth = net(x, g)
            loss = F.cross_entropy(logits, t, weight=weights)
            loss = loss + settings.depth_weight * (pred_depth - d).abs()[v].mean()
            optimiser.zero_grad()
            loss.backward()
            optimiser.step()
            schedule.step()
            total += float(loss.detach()) * len(batch)
            seen += len(batch)
        row: dict[str, Any] = {"epoch": epoch + 1, "loss": round(total / max(seen, 1), 5)}
        if len(apart.rgb):
            row["held_apart"] = score(net, apart)["all"]
        epochs.append(row)
        if progress:
            print(f"epoch {epoch + 1}/{settings.epochs}: {row}", file=sys.stderr, flush=True)
    return net.eval(), epochs


def _corner(types: torch.Tensor, named: torch.Tensor, size: int, settings: PerceptionSettings,
            order: torch.Generator) -> tuple[int, int]:
    """A `size` crop's top-left corner: centred on a random pixel of a type tasks name (`settings.on_objects` of
    the time, where the frame has one), else anywhere."""
    room = settings.side - size
    if float(torch.rand(1, generator=order)) < settings.on_objects:
        pixels = named[types].nonzero()
        if len(pixels):
            r, c = pixels[int(torch.randint(len(pixels), (1,), generator=order))].tolist()
            half = size // 2
            return min(max(r - half, 0), room), min(max(c - half, 0), room)
    r, c = torch.randint(room + 1, (2,), generator=order).tolist()
    return int(r), int(c)
