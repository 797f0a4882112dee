"""The instruction parser's network (torch): word embeddings, two convolutions over the goal directive (and,
when given, a separator and the step instructions; Kim 2014's text classifier, fast on one CPU thread) and,
in the `recurrent` shape, a bidirectional GRU over them; max- and mean-pooled, one classification head per
answer (ALFRED's task type and each of the five `pddl_params`: the argument's object type, "" for none;
`object_sliced` true or false), as FILM's and HLSM's parsers predict the task's template and arguments.

A pointer head (See et al. 2017's copy, over whole names) scores each object name the input contains
(`mentions`) as the value of each object slot, against "none of them": so a receptacle the classifier never
learnt as a parent can be read where the instruction names it, and context ("from the bowl", "in the bowl")
tells which name fills which slot."""

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
    pointers: int = 0
    """Slots the pointer head fills (the first `pointers` of the five), 0 for none."""
    recurrent: bool = False
    """A bidirectional GRU after the convolutions (context of the whole input at each word)."""
    embedding: int = 128
    hidden: int = 256
    dropout: float = 0.2

    def to_dict(self) -> dict[str, object]:
        return {**asdict(self), "answers": list(self.answers)}


class ParserNet(nn.Module):
    """Word ids (batch, length; 0 is padding) and mention spans -> one logits tensor per head, and the pointer's
    logits (batch, 1 + mentions, pointers; index 0 is "none of them")."""

    def __init__(self, shape: ParserShape):
        super().__init__()
        self.shape = shape
        h = shape.hidden
        self.embed = nn.Embedding(shape.words, shape.embedding, padding_idx=0)
        self.encoder = nn.Sequential(nn.Conv1d(shape.embedding, h, 3, padding=1), nn.ReLU(),
                                     nn.Conv1d(h, h, 3, padding=1), nn.ReLU())
        self.context = nn.GRU(h, h // 2, batch_first=True, bidirectional=True) if shape.recurrent else None
        self.drop = nn.Dropout(shape.dropout)
        self.heads = nn.ModuleList(nn.Linear(2 * h, n) for n in shape.answers)
        if shape.pointers:
            self.point = nn.Sequential(nn.Linear(3 * h, h // 2), nn.ReLU(), nn.Linear(h // 2, shape.pointers))
            self.point_none = nn.Linear(2 * h, shape.pointers)

    def forward(self, ids: torch.Tensor, spans: torch.Tensor | None = None,
                present: torch.Tensor | None = None) -> tuple[list[torch.Tensor], torch.Tensor | None]:
        """`spans` (batch, mentions, length) averages each mention's words; `present` (batch, mentions) marks the
        real mentions (the rest is padding)."""
        mask = (ids != 0).unsqueeze(-1)
        states = self.encoder(self.drop(self.embed(ids)).transpose(1, 2)).transpose(1, 2)
        if self.context is not None:
            states = self.context(states)[0]
        states = states.masked_fill(~mask, 0.0)
        mean = states.sum(1) / mask.sum(1).clamp(min=1)
        peak = states.masked_fill(~mask, -1e4).max(1).values
        pooled = self.drop(torch.cat([mean, peak], dim=-1))
        logits = [head(pooled) for head in self.heads]
        if not self.shape.pointers or spans is None or present is None:
            return logits, None
        named = torch.bmm(spans, states)  # (batch, mentions, hidden)
        both = torch.cat([self.drop(named), pooled.unsqueeze(1).expand(-1, named.shape[1], -1)], dim=-1)
        scores = self.point(both).masked_fill(~present.unsqueeze(-1), -1e4)
        return logits, torch.cat([self.point_none(pooled).unsqueeze(1), scores], dim=1)
