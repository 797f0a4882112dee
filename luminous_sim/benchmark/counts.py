"""How big each frozen split is and which layouts it draws from.

The counts are the paper's Table `tab:alfred_task_count` (order Pick, Pick Two, Examine, Clean, Heat, Cool,
Stack, i.e. ALFRED's seven task types in ALFRED's order): S+ 1,405 trajectories in 40 layouts (10 ALFRED
training structures per room type, one layout each), U+ 435 in 16 (ALFRED's 4 valid_unseen structures, four
layouts each). U+test (ALFRED's 8 tests_unseen structures, four layouts each; beyond the paper) takes U+'s
counts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from luminous_sim.rooms import scene_room_type
from luminous_sim.splits import plus_split
from luminous_sim.tasks import task_info
from luminous_sim.vocab import ALFRED_TASK_TYPES

PAPER_COUNTS: dict[str, tuple[int, ...]] = {
    "S+": (226, 167, 236, 210, 163, 202, 201),
    "U+": (27, 18, 178, 56, 21, 56, 79),
    "U+test": (27, 18, 178, 56, 21, 56, 79),
}
"""Trajectories per task type (in `ALFRED_TASK_TYPES` order) of each split."""


@dataclass(frozen=True)
class Layout:
    """One layout of a split: CSSG's furnishing of an ALFRED room structure from a seed."""

    floor_plan: str
    room_type: str
    layout: int
    """Which of the structure's layouts (0 .. layouts-1)."""
    layout_seed: int

    @property
    def name(self) -> str:
        return f"{self.floor_plan}/{self.layout}"


def type_counts(split: str) -> dict[str, int]:
    """Trajectories per task type of `split` (the paper's counts).

    Raises:
        SplitError: an unknown split.
    """
    plus_split(split)
    return dict(zip(ALFRED_TASK_TYPES, PAPER_COUNTS[split], strict=True))


def split_layouts(split: str) -> list[Layout]:
    """Every layout of `split`, structures in the split's order, then layouts in turn.

    Raises:
        SplitError: an unknown split.
    """
    s = plus_split(split)
    out = []
    for floor_plan in s.structures:
        number = int(floor_plan[len("FloorPlan"):])
        for k in range(s.layouts):
            seed = int(np.random.SeedSequence([s.code, number, k]).generate_state(1, dtype=np.uint32)[0])
            out.append(Layout(floor_plan, scene_room_type(number), k, seed))
    return out


def type_layouts(split: str, task_type: str) -> list[Layout]:
    """The layouts of `split` in a room type ALFRED generates `task_type` in."""
    rooms = task_info(task_type).rooms
    return [lay for lay in split_layouts(split) if lay.room_type in rooms]


def allocate(capacities: list[int], count: int) -> list[int]:
    """How many trajectories each layout gives: round robin over the layouts that still have a distinct task
    (`capacities[i]` of them), then, once every layout is out of distinct tasks, round robin over the layouts
    that have any (repeats: the same task from another start). Layouts with no task get none.

    Raises:
        ValueError: `count` > 0 and no layout has a task.
    """
    shares = [0] * len(capacities)
    usable = [i for i, c in enumerate(capacities) if c > 0]
    if count and not usable:
        raise ValueError("no layout holds a task of the type")
    left = count
    while left:
        fresh = [i for i in usable if shares[i] < capacities[i]]
        for i in fresh or usable:
            if not left:
                break
            shares[i] += 1
            left -= 1
    return shares
