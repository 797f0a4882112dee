"""The agent's pose as it keeps it itself, from its own successful moves (ALFRED's moves are exact): the start
is the origin, facing +y, looking 30 degrees down (ALFRED's start horizon). It is never read from the env."""

from __future__ import annotations

from dataclasses import dataclass, replace

STEP = 0.25
"""Metres of a MoveAhead (ALFRED's grid)."""
START_HORIZON = 30
"""ALFRED's start horizon (every trajectory's `init_action`)."""
HORIZON_RANGE = (-30, 60)
HEADINGS: tuple[tuple[int, int], ...] = ((0, 1), (1, 0), (0, -1), (-1, 0))
"""A move's step in nodes for each heading (quarter turns clockwise from the start's facing)."""


@dataclass(frozen=True)
class OwnPose:
    """A node of the 0.25 m grid, a heading in quarter turns and the camera's horizon (degrees down)."""

    node: tuple[int, int] = (0, 0)
    heading: int = 0
    horizon: int = START_HORIZON

    @property
    def x(self) -> float:
        return self.node[0] * STEP

    @property
    def y(self) -> float:
        return self.node[1] * STEP

    @property
    def yaw(self) -> float:
        return 90.0 * self.heading

    def ahead(self) -> tuple[int, int]:
        dx, dy = HEADINGS[self.heading]
        return (self.node[0] + dx, self.node[1] + dy)

    def after(self, action: str) -> OwnPose:
        """The pose after `action` succeeded."""
        if action == "MoveAhead":
            return replace(self, node=self.ahead())
        if action in ("RotateLeft", "RotateRight"):
            return replace(self, heading=(self.heading + (1 if action == "RotateRight" else -1)) % 4)
        if action in ("LookUp", "LookDown"):
            h = self.horizon + (15 if action == "LookDown" else -15)
            return replace(self, horizon=min(max(h, HORIZON_RANGE[0]), HORIZON_RANGE[1]))
        return self
