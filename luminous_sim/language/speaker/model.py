"""The speaker network: token (+ feature) embeddings, a bidirectional GRU, an attentive decoder."""

from __future__ import annotations

from dataclasses import asdict, dataclass, fields
from typing import Any

import torch
from torch import nn
from torch.nn.utils.rnn import pack_padded_sequence, pad_packed_sequence

from luminous_sim.language.speaker.errors import SpeakerError


@dataclass(frozen=True)
class SpeakerConfig:
    """Model dimensions.

    Attributes:
        src_vocab_size: Source (action/object token) vocabulary size.
        tgt_vocab_size: Target (word) vocabulary size.
        emb_dim: Token embedding size.
        hid_dim: GRU hidden size (the encoder has ``hid_dim`` per direction).
        feat_dim: Per-step visual feature size; 0 for a model without features.
        dropout: Dropout on embeddings and the attentional output.
    """

    src_vocab_size: int
    tgt_vocab_size: int
    emb_dim: int = 64
    hid_dim: int = 128
    feat_dim: int = 0
    dropout: float = 0.2

    def to_dict(self) -> dict[str, Any]:
        """Plain-dict form for checkpoints."""
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> SpeakerConfig:
        """Inverse of :meth:`to_dict`; unknown keys are an error."""
        names = {f.name for f in fields(cls)}
        unknown = set(data) - names
        if unknown:
            raise SpeakerError(f"unknown speaker config keys: {sorted(unknown)}")
        return cls(**data)


class SpeakerModel(nn.Module):
    """Sequence-to-sequence speaker with Luong (general) attention and input feeding.

    Args:
        config: The dimensions.
    """

    def __init__(self, config: SpeakerConfig) -> None:
        super().__init__()
        self.config = config
        e, h = config.emb_dim, config.hid_dim
        self.src_emb = nn.Embedding(config.src_vocab_size, e, padding_idx=0)
        self.feat_proj = nn.Linear(config.feat_dim, e) if config.feat_dim > 0 else None
        self.encoder = nn.GRU(e, h, batch_first=True, bidirectional=True)
        self.memory_proj = nn.Linear(2 * h, h)
        self.init_h = nn.Linear(2 * h, h)
        self.tgt_emb = nn.Embedding(config.tgt_vocab_size, e, padding_idx=0)
        self.cell = nn.GRUCell(e + h, h)
        self.attn = nn.Linear(h, h, bias=False)
        self.combine = nn.Linear(2 * h, h)
        self.out = nn.Linear(h, config.tgt_vocab_size)
        self.drop = nn.Dropout(config.dropout)

    def encode(
        self, src: torch.Tensor, lengths: torch.Tensor, features: torch.Tensor | None = None
    ) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """Encode a padded batch.

        Args:
            src: ``[B, S]`` source ids.
            lengths: ``[B]`` true lengths.
            features: ``[B, S, feat_dim]`` or None (zeros).

        Returns:
            ``memory [B, S, H]``, ``mask [B, S]`` (True on real tokens), initial decoder state
            ``[B, H]``.
        """
        x = self.src_emb(src)
        if self.feat_proj is not None and features is not None:
            x = x + self.feat_proj(features)
        x = self.drop(x)
        packed = pack_padded_sequence(x, lengths.cpu(), batch_first=True, enforce_sorted=False)
        out, _ = pad_packed_sequence(
            self.encoder(packed)[0], batch_first=True, total_length=src.size(1)
        )
        mask = torch.arange(src.size(1))[None, :] < lengths[:, None]
        pooled = (out * mask[..., None]).sum(1) / lengths[:, None].clamp(min=1).to(out.dtype)
        return self.memory_proj(out), mask, torch.tanh(self.init_h(pooled))

    def decode_step(
        self,
        prev: torch.Tensor,
        state: torch.Tensor,
        feed: torch.Tensor,
        memory: torch.Tensor,
        mask: torch.Tensor,
    ) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """One decoder step.

        Args:
            prev: ``[B]`` previous word ids.
            state: ``[B, H]`` GRU state.
            feed: ``[B, H]`` previous attentional output (zeros at the first step).
            memory: ``[B, S, H]`` encoder memory.
            mask: ``[B, S]`` real-token mask.

        Returns:
            ``logits [B, V]``, new state, new attentional output.
        """
        state = self.cell(torch.cat([self.drop(self.tgt_emb(prev)), feed], dim=-1), state)
        scores = torch.bmm(memory, self.attn(state)[:, :, None]).squeeze(2)
        weights = torch.softmax(scores.masked_fill(~mask, float("-inf")), dim=-1)
        context = torch.bmm(weights[:, None, :], memory).squeeze(1)
        attentional = torch.tanh(self.combine(torch.cat([state, context], dim=-1)))
        return self.out(self.drop(attentional)), state, attentional

    def forward(
        self,
        src: torch.Tensor,
        lengths: torch.Tensor,
        features: torch.Tensor | None,
        tgt_in: torch.Tensor,
    ) -> torch.Tensor:
        """Teacher-forced logits ``[B, T, V]`` for decoder inputs ``tgt_in [B, T]``."""
        memory, mask, state = self.encode(src, lengths, features)
        feed = torch.zeros_like(state)
        logits = []
        for t in range(tgt_in.size(1)):
            step_logits, state, feed = self.decode_step(tgt_in[:, t], state, feed, memory, mask)
            logits.append(step_logits)
        return torch.stack(logits, dim=1)
