"""Padding examples into tensors."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np
import torch

from luminous_sim.language.speaker.dataset import Example
from luminous_sim.language.speaker.vocab import Vocab


@dataclass
class Batch:
    """A padded batch.

    Attributes:
        src: ``[B, S]`` source ids (``<pad>`` = 0).
        lengths: ``[B]`` source lengths.
        features: ``[B, S, D]`` aligned features, or None for a model without features.
        tgt_in: ``[B, T]`` decoder inputs (``<bos>`` + words).
        tgt_out: ``[B, T]`` decoder targets (words + ``<eos>``), padded with 0.
    """

    src: torch.Tensor
    lengths: torch.Tensor
    features: torch.Tensor | None
    tgt_in: torch.Tensor
    tgt_out: torch.Tensor


def encode_sources(
    sources: Sequence[Sequence[str]],
    features: Sequence[np.ndarray | None],
    vocab: Vocab,
    feat_dim: int,
) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor | None]:
    """Pad source token lists (and their aligned features) into ``(src, lengths, features)``.

    A source without features gets zeros when ``feat_dim > 0``; features are dropped when
    ``feat_dim == 0``.
    """
    lengths = [max(len(s), 1) for s in sources]
    src = torch.zeros(len(sources), max(lengths), dtype=torch.long)
    for b, toks in enumerate(sources):
        ids = vocab.encode(toks) or [vocab.unk_id]
        src[b, : len(ids)] = torch.tensor(ids, dtype=torch.long)
    feats = None
    if feat_dim > 0:
        feats = torch.zeros(len(sources), max(lengths), feat_dim)
        for b, f in enumerate(features):
            if f is not None and len(f):
                feats[b, : len(f)] = torch.as_tensor(np.asarray(f, dtype=np.float32))
    return src, torch.tensor(lengths, dtype=torch.long), feats


def collate(
    examples: Sequence[Example], src_vocab: Vocab, tgt_vocab: Vocab, feat_dim: int, max_tgt_len: int
) -> Batch:
    """Pad examples; targets longer than ``max_tgt_len`` words are cut (then ``<eos>``)."""
    src, lengths, feats = encode_sources(
        [e.src for e in examples], [e.features for e in examples], src_vocab, feat_dim
    )
    words = [tgt_vocab.encode(e.tgt[:max_tgt_len]) for e in examples]
    t = max(len(w) for w in words) + 1
    tgt_in = torch.zeros(len(examples), t, dtype=torch.long)
    tgt_out = torch.zeros(len(examples), t, dtype=torch.long)
    for b, ids in enumerate(words):
        tgt_in[b, : len(ids) + 1] = torch.tensor([tgt_vocab.bos_id, *ids])
        tgt_out[b, : len(ids) + 1] = torch.tensor([*ids, tgt_vocab.eos_id])
    return Batch(src, lengths, feats, tgt_in, tgt_out)


def shuffled_batches(
    examples: Sequence[Example], batch_size: int, seed: int
) -> Iterator[list[Example]]:
    """Examples in a seeded random order, ``batch_size`` at a time (last batch may be smaller)."""
    gen = torch.Generator().manual_seed(seed)
    order = torch.randperm(len(examples), generator=gen).tolist()
    for i in range(0, len(order), batch_size):
        yield [examples[j] for j in order[i : i + batch_size]]
