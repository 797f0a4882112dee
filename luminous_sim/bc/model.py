"""`BCPolicy`: a small language-conditioned policy over the env's discrete actions (torch).

It sees what the agent sees: the image (a 4-layer CNN), the instruction (a bag of word embeddings over
the env's fixed token vocabulary), the object type in each of the env's object slots, the last action
and whether it failed. Navigation and Stop are scored from the joint features; each interaction on slot t
is scored from the joint features, slot t's type and that type gated by the instruction (so "pick up the
fork" can pick the slot holding a Fork), with weights shared over slots. Empty slots get no probability.
Logits come out in the env's index order: 6 navigation/Stop, then interaction i on slot t at 6 + i*m + t.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import torch
from torch import nn

NON_TARGET = 6
"""Navigation actions and Stop, the indices before the interactions (`luminous_sim.env.actions`)."""
INTERACTIONS = 7


@dataclass(frozen=True)
class PolicyShape:
    """What a `BCPolicy` is built for (saved in its checkpoint)."""

    vocab: int
    """Instruction token ids (the env's vocabulary)."""
    types: int
    """Object type ids in an `objects` observation (0 for an empty slot)."""
    slots: int
    dim: int = 64

    @property
    def actions(self) -> int:
        return NON_TARGET + INTERACTIONS * self.slots

    def to_dict(self) -> dict[str, int]:
        return asdict(self)


class BCPolicy(nn.Module):
    """Action logits from (rgb, tokens, objects, previous action, previous failure); see the module docstring.

    The previous action is an index of the env's space, `actions` for none (the first step) or `actions + 1`
    for an action given in the dict form.
    """

    def __init__(self, shape: PolicyShape):
        super().__init__()
        self.shape = shape
        d = shape.dim
        self.cnn = nn.Sequential(
            nn.Conv2d(3, 16, 5, stride=2, padding=2), nn.ReLU(),
            nn.Conv2d(16, 32, 3, stride=2, padding=1), nn.ReLU(),
            nn.Conv2d(32, 32, 3, stride=2, padding=1), nn.ReLU(),
            nn.AdaptiveAvgPool2d(4), nn.Flatten(), nn.Linear(32 * 16, d), nn.ReLU(),
        )
        self.words = nn.Embedding(shape.vocab, d, padding_idx=0)
        self.types = nn.Embedding(shape.types, d, padding_idx=0)
        self.previous = nn.Embedding(shape.actions + 2, d)
        self.joint = nn.Sequential(nn.Linear(4 * d + 1, 2 * d), nn.ReLU(), nn.Linear(2 * d, 2 * d), nn.ReLU())
        self.moves = nn.Linear(2 * d, NON_TARGET)
        self.interact = nn.Sequential(nn.Linear(4 * d, 2 * d), nn.ReLU(), nn.Linear(2 * d, INTERACTIONS))

    def forward(self, rgb: torch.Tensor, tokens: torch.Tensor, objects: torch.Tensor, previous: torch.Tensor,
                failed: torch.Tensor) -> torch.Tensor:
        """Logits (B, actions) from rgb (B, H, W, 3) uint8, tokens (B, L), objects (B, S), previous (B,),
        failed (B,)."""
        image = self.cnn(rgb.permute(0, 3, 1, 2).float() / 255.0)
        present = (tokens > 0).float()
        words = (self.words(tokens) * present[..., None]).sum(1) / present.sum(1, keepdim=True).clamp(min=1)
        slot_types = self.types(objects)  # (B, S, d)
        seen = slot_types.sum(1) / (objects > 0).float().sum(1, keepdim=True).clamp(min=1)
        h = self.joint(torch.cat([image, words, seen, self.previous(previous), failed.float()[:, None]], 1))
        s = objects.shape[1]
        per_slot = torch.cat([h[:, None].expand(-1, s, -1), slot_types, slot_types * words[:, None]], 2)
        slot_logits = self.interact(per_slot)  # (B, S, 7)
        slot_logits = slot_logits.masked_fill((objects == 0)[..., None], -1e9)
        return torch.cat([self.moves(h), slot_logits.transpose(1, 2).reshape(len(h), -1)], 1)
