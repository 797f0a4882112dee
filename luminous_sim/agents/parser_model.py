"""The instruction parser's network (torch): word embeddings, two convolutions over the goal directive (and,
when given, a separator and the step instructions; Kim 2014's text classifier, fast on one CPU thread), max-
and mean-pooled, and one classification head per answer: ALFRED's task type and each of the five
`pddl_params` (the argument's object type, "" for none; `object_sliced` true or false), as FILM's and HLSM's
parsers predict the task's template and arguments."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import torch
from torch import nn

PAD, UNK, SEP = "<pad>", "<unk>", "<sep>"
"""The padding word (index 0), an unknown word, and the separator between the directive and the steps."""


@dataclass(frozen=True)
class ParserShape:
    """The network's sizes: the vocabulary, the answers per head, the embedding and hidden widths."""

    words: int
    answers: tuple[int, ...]
    """The number of answers of each head: the task type, then the five slots."""
    embedding: int = 128
    hidden: int = 256
    dropout: float = 0.2

    def to_dict(self) -> dict[str, object]:
        return {**asdict(self), "answers": list(self.answers)}


class ParserNet(nn.Module):
    """Word ids (batch, length; 0 is padding) -> one logits tensor per head."""

    def __init__(self, shape: ParserShape):
        super().__init__()
        self.shape = shape
        self.embed = nn.Embedding(shape.words, shape.embedding, padding_idx=0)
        self.encoder = nn.Sequential(nn.Conv1d(shape.embedding, shape.hidden, 3, padding=1), nn.ReLU(),
                                     nn.Conv1d(shape.hidden, shape.hidden, 3, padding=1), nn.ReLU())
        self.drop = nn.Dropout(shape.dropout)
        self.heads = nn.ModuleList(nn.Linear(2 * shape.hidden, n) for n in shape.answers)

    def forward(self, ids: torch.Tensor) -> list[torch.Tensor]:
        mask = (ids != 0).unsqueeze(-1)
        states = self.encoder(self.drop(self.embed(ids)).transpose(1, 2)).transpose(1, 2)
        states = states.masked_fill(~mask, 0.0)
        mean = states.sum(1) / mask.sum(1).clamp(min=1)
        peak = states.masked_fill(~mask, -1e4).max(1).values
        pooled = self.drop(torch.cat([mean, peak], dim=-1))
        return [head(pooled) for head in self.heads]
