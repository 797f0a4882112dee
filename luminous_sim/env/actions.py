"""The flat action space: ALFRED's navigation actions, Stop, and each interaction on a k x k grid of image
points, and the full ALFRED form (a dict) that `LuminousEnv.step` takes as well.

Index layout (k = `grid`, n = k * k)::

    0..4   MoveAhead, RotateLeft, RotateRight, LookUp, LookDown
    5      Stop
    6 + i * n + r * k + c   interaction i (PickupObject, PutObject, OpenObject, CloseObject,
                            ToggleObjectOn, ToggleObjectOff, SliceObject) at grid row r, column c

Grid point (r, c) is the pixel at the centre of that cell: x = (c + 0.5) * width / k, y likewise.
An interaction's point goes to `World.step` as ALFRED's `point` target (`PutObject` puts the held object
on what the point shows).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

NAVIGATION: tuple[str, ...] = ("MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown")
STOP = "Stop"
STOP_NAMES = frozenset({STOP, "<<stop>>"})
"""Names that end the episode: ours, and the stop token of ALFRED's models."""
INTERACTIONS: tuple[str, ...] = (
    "PickupObject", "PutObject", "OpenObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff", "SliceObject",
)
ALFRED_ACTIONS = frozenset(NAVIGATION + INTERACTIONS)
"""What the dict form may name (besides Stop): ALFRED's low-level actions, no teleports."""


def nav_api(name: str) -> dict[str, Any]:
    """The api action ALFRED sends for a navigation step."""
    if name == "MoveAhead":
        return {"action": "MoveAhead", "forceAction": True, "moveMagnitude": 0.25}
    return {"action": name, "forceAction": True}


@dataclass(frozen=True)
class ActionTable:
    """Discrete index <-> api action, for one image size and grid."""

    width: int
    height: int
    grid: int

    @property
    def n(self) -> int:
        """The number of discrete actions."""
        return len(NAVIGATION) + 1 + len(INTERACTIONS) * self.grid**2

    @property
    def first_interaction(self) -> int:
        return len(NAVIGATION) + 1

    def point(self, cell: int) -> tuple[int, int]:
        """The (x, y) pixel of grid cell `cell` (row-major)."""
        r, c = divmod(cell, self.grid)
        return int((c + 0.5) * self.width / self.grid), int((r + 0.5) * self.height / self.grid)

    def points(self) -> list[tuple[int, int]]:
        """Every grid point, in cell order."""
        return [self.point(i) for i in range(self.grid**2)]

    def decode(self, index: int) -> dict[str, Any]:
        """The api action of a discrete index (`{"action": "Stop"}` for Stop).

        Raises:
            IndexError: the index is outside the space.
        """
        if not 0 <= index < self.n:
            raise IndexError(f"action {index} is outside 0..{self.n - 1}")
        if index < len(NAVIGATION):
            return nav_api(NAVIGATION[index])
        if index == len(NAVIGATION):
            return {"action": STOP}
        kind, cell = divmod(index - self.first_interaction, self.grid**2)
        x, y = self.point(cell)
        api: dict[str, Any] = {"action": INTERACTIONS[kind], "point": [x, y]}
        if INTERACTIONS[kind] == "PutObject":
            api.update(forceAction=True, placeStationary=True)
        return api

    def index(self, name: str, cell: int | None = None) -> int:
        """The discrete index of a navigation action, Stop, or an interaction at grid cell `cell`."""
        if name in NAVIGATION:
            return NAVIGATION.index(name)
        if name in STOP_NAMES:
            return len(NAVIGATION)
        if cell is None or not 0 <= cell < self.grid**2:
            raise ValueError(f"{name} needs a grid cell in 0..{self.grid**2 - 1}, got {cell}")
        return self.first_interaction + INTERACTIONS.index(name) * self.grid**2 + cell

    def cell_on(self, mask: np.ndarray) -> int | None:
        """The first grid cell (row-major) whose point lies on a boolean (H, W) mask, if any."""
        for cell, (x, y) in enumerate(self.points()):
            if mask[y, x]:
                return cell
        return None

    def labels(self) -> list[str]:
        """A readable name per index: `MoveAhead`, `Stop`, `PickupObject@(r,c)`."""
        out = list(NAVIGATION) + [STOP]
        for name in INTERACTIONS:
            out += [f"{name}@({r},{c})" for r in range(self.grid) for c in range(self.grid)]
        return out
