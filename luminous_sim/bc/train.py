"""Behaviour cloning: cross-entropy of `BCPolicy`'s logits against the oracle's discrete actions.

Deterministic given the seed: the weights, the shuffling and the torch threads (one by default) are fixed,
so the same demonstrations and seed give the same checkpoint, bit for bit. The checkpoint (written
atomically) holds the weights, the policy's shape, the env options it was trained for and the loss curve.
"""

from __future__ import annotations

import io
import pickle
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import torch
from torch import nn

from luminous_sim.bc.demos import TOKENS, Demo, demos_env, load_demos
from luminous_sim.bc.model import BCPolicy, PolicyShape
from luminous_sim.env.vocabulary import vocabulary
from luminous_sim.errors import LuminousError, path_kind
from luminous_sim.fileio import write_atomic
from luminous_sim.limits import MAX_CHECKPOINT_BYTES
from luminous_sim.vocab import ALL_TYPES

FORMAT = "luminous-bc/1"


@dataclass(frozen=True)
class TrainResult:
    """What a training run did: its checkpoint, mean loss per epoch, training accuracy at the end."""

    checkpoint: Path
    demos: int
    samples: int
    losses: tuple[float, ...]
    accuracy: float


def samples(demos: list[Demo], n_actions: int) -> dict[str, torch.Tensor]:
    """The labelled steps of the demonstrations as tensors (rgb, tokens, objects, previous, failed, action)."""
    rgb, tokens, objects, previous, failed, action = [], [], [], [], [], []
    for d in demos:
        before = np.concatenate([[n_actions], np.where(d.actions[:-1] >= 0, d.actions[:-1], n_actions + 1)])
        keep = d.actions >= 0
        rgb.append(d.rgb[keep])
        objects.append(d.objects[keep])
        tokens.append(np.repeat(d.tokens[None], keep.sum(), 0))
        previous.append(before[keep])
        failed.append(d.failed[keep])
        action.append(d.actions[keep])
    out = {"rgb": np.concatenate(rgb), "tokens": np.concatenate(tokens), "objects": np.concatenate(objects),
           "previous": np.concatenate(previous), "failed": np.concatenate(failed), "action": np.concatenate(action)}
    return {k: torch.from_numpy(np.ascontiguousarray(v)) for k, v in out.items()}


def shape_for(slots: int) -> PolicyShape:
    return PolicyShape(vocab=len(vocabulary()), types=len(ALL_TYPES) + 1, slots=slots)


def train_bc(demo_dir: Path, out: Path, *, epochs: int = 20, batch_size: int = 64, lr: float = 1e-3, seed: int = 0,
             threads: int = 1, max_steps: int | None = None,
             progress: Callable[[int, float], None] | None = None) -> TrainResult:
    """Train a `BCPolicy` on the demonstrations in `demo_dir`; write the checkpoint to `out`.

    Args:
        epochs: passes over the labelled steps.
        max_steps: stop after this many optimiser steps (for quick checks).
        progress: called with (epoch, mean loss) after each epoch.

    Raises:
        LuminousError: no demonstrations, or none with a labelled step.
    """
    demos = load_demos(demo_dir)
    env = demos_env(demo_dir)
    slots = int(env["object_slots"])
    shape = shape_for(slots)
    data = samples(demos, shape.actions)
    n = len(data["action"])
    if n == 0:
        raise LuminousError(f"{demo_dir}: the demonstrations have no labelled step")
    old_threads = torch.get_num_threads()
    torch.set_num_threads(threads)
    try:
        torch.manual_seed(seed)
        model = BCPolicy(shape)
        optimiser = torch.optim.Adam(model.parameters(), lr=lr)
        loss_fn = nn.CrossEntropyLoss()
        order = torch.Generator().manual_seed(seed)
        losses: list[float] = []
        step = 0
        for epoch in range(epochs):
            model.train()
            total, count = 0.0, 0
            for batch in torch.randperm(n, generator=order).split(batch_size):
                logits = model(*(data[k][batch] for k in ("rgb", "tokens", "objects", "previous", "failed")))
                loss = loss_fn(logits, data["action"][batch])
                optimiser.zero_grad()
                loss.backward()
                optimiser.step()
                total, count, step = total + loss.item() * len(batch), count + len(batch), step + 1
                if max_steps is not None and step >= max_steps:
                    break
            losses.append(total / count)
            if progress is not None:
                progress(epoch, losses[-1])
            if max_steps is not None and step >= max_steps:
                break
        accuracy = _accuracy(model, data)
    finally:
        torch.set_num_threads(old_threads)
    meta = {"format": FORMAT, "shape": shape.to_dict(), "env": env, "tokens": TOKENS,
            "seed": seed, "epochs": len(losses), "demos": len(demos), "samples": n, "losses": losses,
            "accuracy": accuracy}
    buf = io.BytesIO()
    torch.save({"meta": meta, "state_dict": model.state_dict()}, buf)
    write_atomic(out, buf.getvalue())
    return TrainResult(out, len(demos), n, tuple(losses), accuracy)


@torch.no_grad()
def _accuracy(model: BCPolicy, data: dict[str, torch.Tensor]) -> float:
    model.eval()
    hits = 0
    for batch in torch.arange(len(data["action"])).split(256):
        logits = model(*(data[k][batch] for k in ("rgb", "tokens", "objects", "previous", "failed")))
        hits += int((logits.argmax(1) == data["action"][batch]).sum())
    return hits / len(data["action"])


def load_checkpoint(path: Path) -> tuple[BCPolicy, dict[str, Any]]:
    """The policy of a checkpoint (in eval mode) and its metadata.

    Raises:
        LuminousError: the file is missing or not a checkpoint of this format.
    """
    if not path.exists():
        raise LuminousError(f"{path}: no such checkpoint (train one with `luminous bc train`)")
    kind = path_kind(path)
    if kind != "a regular file":
        raise LuminousError(f"{path}: {kind}; expected a behaviour-cloning checkpoint (.pt)")
    if path.stat().st_size > MAX_CHECKPOINT_BYTES:
        raise LuminousError(f"{path}: {path.stat().st_size:,} bytes; a behaviour-cloning checkpoint is at most "
                            f"{MAX_CHECKPOINT_BYTES:,} bytes (luminous_sim.limits.MAX_CHECKPOINT_BYTES)")
    try:
        saved = torch.load(path, map_location="cpu", weights_only=True)
        meta = saved["meta"]
        if meta.get("format") != FORMAT:
            raise LuminousError(f"{path}: checkpoint format {meta.get('format')!r}, expected {FORMAT!r}")
        model = BCPolicy(PolicyShape(**meta["shape"]))
        model.load_state_dict(saved["state_dict"])
    except (RuntimeError, KeyError, TypeError, ValueError, OSError, EOFError, pickle.UnpicklingError) as exc:
        reason = " ".join(str(exc).split())  # torch's messages run over several lines
        reason = reason if len(reason) <= 160 else reason[:157] + "..."
        raise LuminousError(f"{path}: not a behaviour-cloning checkpoint ({type(exc).__name__}: {reason})") from None
    model.eval()
    return model, meta
