"""Training the speaker: data split, vocabularies, teacher-forced epochs, resumable checkpoints."""

from __future__ import annotations

import random
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import torch
from torch import nn

from luminous_sim.language.speaker.batching import collate, shuffled_batches
from luminous_sim.language.speaker.checkpoint import load_checkpoint, save_checkpoint
from luminous_sim.language.speaker.dataset import (
    Example,
    build_examples,
    load_trajectories,
    split_trajectories,
)
from luminous_sim.language.speaker.errors import SpeakerError
from luminous_sim.language.speaker.evaluate import EvalReport, evaluate
from luminous_sim.language.speaker.features import FEATURE_DIM
from luminous_sim.language.speaker.generate import Speaker
from luminous_sim.language.speaker.model import SpeakerConfig, SpeakerModel
from luminous_sim.language.speaker.records import Trajectory
from luminous_sim.language.speaker.runtime import deterministic
from luminous_sim.language.speaker.vocab import Vocab

DEFAULT_DIMS: dict[str, Any] = {"emb_dim": 64, "hid_dim": 128, "dropout": 0.2}
"""Model dimensions used unless ``dims`` overrides them."""


@dataclass
class TrainReport:
    """What a training call did.

    Attributes:
        losses: Mean per-token training loss of every epoch so far (a resumed run includes the
            earlier ones).
        examples: Training examples (step + goal).
        vocab_size: Word (target) vocabulary size.
        seconds: Wall time of this call.
        epochs_run: Epochs run by this call.
        held_out: Trajectories held out from training.
        evaluation: BLEU on the held-out trajectories (when there are any and ``eval_beam`` is set).
    """

    losses: list[float]
    examples: int
    vocab_size: int
    seconds: float
    epochs_run: int = 0
    held_out: int = 0
    evaluation: EvalReport | None = None


def prepare_data(
    data_dir: str | Path, args: dict[str, Any]
) -> tuple[list[Example], list[Trajectory]]:
    """Load, split by trajectory and subsample: (training examples, held-out trajectories)."""
    trajs = load_trajectories(
        data_dir, features=args["features"], max_trajectories=args["max_trajectories"]
    )
    train_trajs, held = split_trajectories(trajs, args["held_out"], args["seed"])
    examples = build_examples(train_trajs)
    if args["max_examples"] is not None and len(examples) > args["max_examples"]:
        keep = sorted(
            random.Random(args["seed"]).sample(range(len(examples)), args["max_examples"])
        )
        examples = [examples[i] for i in keep]
    if not examples:
        raise SpeakerError(f"{data_dir}: no annotated training examples")
    return examples, held


def _epoch(
    model: SpeakerModel,
    opt: torch.optim.Optimizer,
    examples: Sequence[Example],
    src: Vocab,
    tgt: Vocab,
    args: dict[str, Any],
    epoch: int,
) -> float:
    model.train()
    loss_fn = nn.CrossEntropyLoss(ignore_index=Vocab.pad_id, reduction="sum")
    total, tokens = 0.0, 0
    for chunk in shuffled_batches(examples, args["batch_size"], args["seed"] * 100_003 + epoch):
        batch = collate(chunk, src, tgt, model.config.feat_dim, args["max_tgt_len"])
        logits = model(batch.src, batch.lengths, batch.features, batch.tgt_in)
        n = int((batch.tgt_out != Vocab.pad_id).sum())
        loss = loss_fn(logits.reshape(-1, logits.size(-1)), batch.tgt_out.reshape(-1))
        opt.zero_grad()
        (loss / n).backward()
        nn.utils.clip_grad_norm_(model.parameters(), 5.0)
        opt.step()
        total, tokens = total + loss.item(), tokens + n
    return total / max(tokens, 1)


def train(
    data_dir: str | Path,
    out_path: str | Path,
    epochs: int = 10,
    batch_size: int = 32,
    lr: float = 2e-3,
    seed: int = 0,
    max_examples: int | None = None,
    progress: bool = True,
    *,
    resume: bool = False,
    held_out: float = 0.1,
    max_trajectories: int | None = None,
    features: bool = False,
    dims: dict[str, Any] | None = None,
    min_freq: int = 2,
    max_tgt_len: int = 40,
    eval_beam: int | None = 1,
) -> TrainReport:
    """Train a speaker on the ALFRED-format trajectories under ``data_dir``.

    A seeded ``held_out`` fraction of trajectories is kept out of training and scored at the end.
    The checkpoint at ``out_path`` is replaced atomically after every epoch.

    Args:
        data_dir: Folder with ``traj_data.json`` files at any depth.
        out_path: Checkpoint file to write.
        epochs: Total epochs (with ``resume``, training continues until this many are done).
        batch_size: Examples per step.
        lr: Adam learning rate.
        seed: Seeds the split, subsampling, initialisation, shuffling and dropout.
        max_examples: Train on a seeded sample of at most this many examples.
        progress: Print one line per epoch to stderr.
        resume: Continue from ``out_path``; data selection, batch size, learning rate and dims come
            from the checkpoint, so the result equals an uninterrupted run.
        held_out: Fraction of trajectories held out.
        max_trajectories: Use only the first N trajectories (sorted paths).
        features: Use per-step colour-histogram features from ``raw_images/`` where present.
        dims: Overrides of :data:`DEFAULT_DIMS` (``emb_dim``, ``hid_dim``, ``dropout``).
        min_freq: Words seen fewer times become ``<unk>``.
        max_tgt_len: Longer instructions are cut to this many words.
        eval_beam: Beam width for the held-out BLEU (None: skip the evaluation).

    Returns:
        The :class:`TrainReport`.

    Raises:
        SpeakerError: Unreadable data or checkpoint, or nothing to train on.
    """
    start = time.perf_counter()
    if resume:
        ckpt = load_checkpoint(out_path)
        args = dict(ckpt["train_args"])
    else:
        ckpt = None
        args = {
            "seed": seed,
            "held_out": held_out,
            "max_examples": max_examples,
            "batch_size": batch_size,
            "max_trajectories": max_trajectories,
            "features": features,
            "min_freq": min_freq,
            "lr": lr,
            "max_tgt_len": max_tgt_len,
            "data_dir": str(data_dir),
        }
    unknown = set(dims or {}) - set(DEFAULT_DIMS)
    if unknown:
        raise SpeakerError(f"unknown model dims {sorted(unknown)}; known: {sorted(DEFAULT_DIMS)}")
    if epochs < 1 or args["batch_size"] < 1:
        raise SpeakerError(
            f"epochs and batch_size must be >= 1 (got {epochs}, {args['batch_size']})"
        )
    examples, held = prepare_data(data_dir, args)
    if ckpt is not None:
        src = Vocab.from_json(ckpt["src_vocab"], f"{out_path} src_vocab")
        tgt = Vocab.from_json(ckpt["tgt_vocab"], f"{out_path} tgt_vocab")
        config = SpeakerConfig.from_dict(dict(ckpt["config"]))
    else:
        src = Vocab.build([e.src for e in examples])
        tgt = Vocab.build([e.tgt for e in examples], min_freq=args["min_freq"])
        feat_dim = FEATURE_DIM if any(e.features is not None for e in examples) else 0
        if features and not feat_dim and progress:
            print(
                "speaker: no raw_images/ frames found; training without visual features",
                file=sys.stderr,
            )
        config = SpeakerConfig(
            len(src), len(tgt), feat_dim=feat_dim, **{**DEFAULT_DIMS, **(dims or {})}
        )
    losses: list[float] = list(ckpt["losses"]) if ckpt else []
    first = int(ckpt["epoch"]) if ckpt else 0
    with deterministic(args["seed"], ckpt.get("rng") if ckpt else None):
        model = SpeakerModel(config)
        opt = torch.optim.Adam(model.parameters(), lr=args["lr"])
        if ckpt is not None:
            model.load_state_dict(ckpt["model"])
            opt.load_state_dict(ckpt["optimizer"])
        for epoch in range(first, epochs):
            tic = time.perf_counter()
            losses.append(_epoch(model, opt, examples, src, tgt, args, epoch))
            save_checkpoint(
                out_path,
                {
                    "config": config.to_dict(),
                    "model": model.state_dict(),
                    "optimizer": opt.state_dict(),
                    "src_vocab": src.to_json(),
                    "tgt_vocab": tgt.to_json(),
                    "epoch": epoch + 1,
                    "losses": losses,
                    "train_args": args,
                    "rng": torch.get_rng_state(),
                    "held_out_keys": [t.key for t in held],
                },
            )
            if progress:
                print(
                    f"speaker: epoch {epoch + 1}/{epochs} loss {losses[-1]:.4f} "
                    f"({time.perf_counter() - tic:.1f} s)",
                    file=sys.stderr,
                )
    evaluation = None
    if held and eval_beam is not None:
        if progress:
            print(
                f"speaker: scoring {len(held)} held-out trajectories (beam {eval_beam})",
                file=sys.stderr,
            )
        evaluation = evaluate(Speaker(model, src, tgt), held, beam_width=eval_beam)
    return TrainReport(
        losses,
        len(examples),
        len(tgt),
        time.perf_counter() - start,
        max(epochs - first, 0),
        len(held),
        evaluation,
    )
