"""LUMINOUS's evaluation splits (paper section 4.3): ALFRED's room structures with new layouts.

- **S+** (Seen Plus): 10 room structures per room type drawn from ALFRED's training (seen) scenes, one new
  layout each; the paper generated 1,405 trajectories in these 40 scenes.
- **U+** (Unseen Plus): the 4 room structures of ALFRED's valid_unseen split, 4 new layouts each (16
  scenes; 435 trajectories in the paper).
- **U+test**: the same over the 8 structures of ALFRED's tests_unseen split (beyond the paper).

What episode `i` of a split is (its layout, task, start and initial state) is frozen in the split's shipped
manifest and defined by `luminous_sim.benchmark` (layer L4, which may generate scenes); this module holds
the structures the splits draw their layouts from.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from luminous_sim.errors import LuminousError
from luminous_sim.rooms import ALFRED_SPLITS, scene_split
from luminous_sim.vocab import ROOM_TYPES

SEEN_PER_ROOM_TYPE = 10
"""Training structures per room type in S+ (the paper's "10 room structures ... for each room type")."""
SPLIT_SEED = 2021
"""Seed of the draw of S+'s structures (fixed: the split is part of the benchmark's definition)."""


class SplitError(LuminousError):
    """An unknown split name or an index outside a split."""


@dataclass(frozen=True)
class PlusSplit:
    """A split's room structures and how many layouts each gets."""

    name: str
    structures: tuple[str, ...]
    layouts: int
    code: int
    """A number that keeps the seeds of different splits apart."""


def _numbers(scenes: list[int]) -> tuple[str, ...]:
    return tuple(f"FloorPlan{n}" for n in sorted(scenes))


def _seen_structures() -> tuple[str, ...]:
    rng = np.random.default_rng(SPLIT_SEED)
    chosen: list[int] = []
    for hundred in (0, 2, 3, 4):
        seen = [hundred * 100 + i for i in range(1, 31) if scene_split(hundred * 100 + i) == "seen"]
        chosen.extend(int(n) for n in rng.choice(seen, SEEN_PER_ROOM_TYPE, replace=False))
    return _numbers(chosen)


PLUS_SPLITS: dict[str, PlusSplit] = {
    "S+": PlusSplit("S+", _seen_structures(), layouts=1, code=1),
    "U+": PlusSplit("U+", _numbers(list(ALFRED_SPLITS["valid_unseen"])), layouts=4, code=2),
    "U+test": PlusSplit("U+test", _numbers(list(ALFRED_SPLITS["tests_unseen"])), layouts=4, code=3),
}
"""The splits by name."""


def plus_split(name: str) -> PlusSplit:
    """The split called `name` (S+, U+ or U+test).

    Raises:
        SplitError: no such split.
    """
    if name not in PLUS_SPLITS:
        raise SplitError(f"unknown split {name!r}; expected one of {', '.join(PLUS_SPLITS)}")
    return PLUS_SPLITS[name]


def oct21_document(built: dict[str, list[str]],
                   annotations: int | Mapping[str, int] = 3) -> dict[str, list[dict[str, object]]]:
    """An ALFRED `oct21.json`-style split file: per split, one entry per (trajectory, annotation index),
    `{"repeat_idx": k, "task": "<task dir>/<trial dir>"}`, trajectories in the order given; `annotations`:
    how many each trajectory has (one number for all, or per trajectory).
    """
    def count(task: str) -> int:
        return annotations if isinstance(annotations, int) else annotations[task]

    return {name: [{"repeat_idx": k, "task": task} for task in tasks for k in range(count(task))]
            for name, tasks in built.items()}


assert set(ROOM_TYPES) == {"Kitchen", "LivingRoom", "Bedroom", "Bathroom"}, "S+ draws 10 per ALFRED room type"
