"""What the oracle produces: ALFRED's high-level plan and low-level actions (with bbox/point/mask
arguments), the frames, and how it ended."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from luminous_sim.errors import Failure, FailureCode


@dataclass
class Trajectory:
    """An expert demonstration in ALFRED's terms (exported to traj_data.json by the data layer)."""

    init_action: dict[str, Any]
    high_pddl: list[dict[str, Any]] = field(default_factory=list)
    low_actions: list[dict[str, Any]] = field(default_factory=list)
    images: list[dict[str, Any]] = field(default_factory=list)
    frames: list[np.ndarray] = field(default_factory=list)
    success: bool = False
    goal_conditions: tuple[int, int] = (0, 0)
    replans: int = 0
    planning_seconds: float = 0.0
    failure: str = ""
    failure_code: FailureCode | None = None
    """The last failure's code (None when nothing failed)."""
    failed_subgoals: list[str] = field(default_factory=list)
    """High-level action types whose execution failed (before a replan)."""
    failures: list[str] = field(default_factory=list)
    """Why each failed attempt failed, in order."""
    failure_codes: list[FailureCode] = field(default_factory=list)
    """The code of each of `failures`."""
    unreachable: list[str] = field(default_factory=list)
    """Objects no pose could see (left out of later plans, and of later task draws)."""
    full: list[str] = field(default_factory=list)
    """Receptacles a put found full, with no free spot at all (no later task draw asks to put things
    there); not those with room only out of reach from where the agent stood."""

    def fail(self, failure: Failure) -> None:
        """Record that an attempt failed, and why."""
        self.failure, self.failure_code = failure.message, failure.code
        self.failures.append(failure.message)
        self.failure_codes.append(failure.code)

    def add_frame(self, rgb: np.ndarray | None, high_idx: int, low_idx: int) -> None:
        if rgb is None:
            return
        self.images.append({"high_idx": high_idx, "image_name": f"{len(self.frames):09d}.png", "low_idx": low_idx})
        self.frames.append(rgb)
