"""ALFRED's agent pose on the grid: position (metres, on multiples of 0.25), rotation in quarter turns
(0 = +y, ALFRED's north; 1 = +x, east), camera horizon in degrees (positive looks down)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from luminous_sim.vocab.agent_body import CAMERA_HEIGHT, HORIZON_MAX, HORIZON_MIN

__all__ = ["CAMERA_HEIGHT", "HORIZON_MAX", "HORIZON_MIN", "AgentPose"]

GRID = 0.25
ROTATE_STEP = 90
HORIZON_STEP = 15
AGENT_Y = 0.9009995
"""AI2-THOR's agent origin height (init_action.y), reported in metadata for ALFRED compatibility."""


@dataclass(frozen=True)
class AgentPose:
    x: float
    y: float
    rotation: int = 0  # degrees, one of 0, 90, 180, 270
    horizon: int = 30

    def forward(self) -> tuple[float, float]:
        a = math.radians(self.rotation)
        return (round(math.sin(a), 9), round(math.cos(a), 9))

    def moved(self, distance: float = GRID) -> AgentPose:
        fx, fy = self.forward()
        return replace(self, x=round(self.x + fx * distance, 4), y=round(self.y + fy * distance, 4))

    def rotated(self, quarter_turns: int) -> AgentPose:
        return replace(self, rotation=(self.rotation + ROTATE_STEP * quarter_turns) % 360)

    def looked(self, steps: int) -> AgentPose | None:
        """Horizon changed by `steps` x 15 degrees (positive = down), or None outside -30..60."""
        h = self.horizon + HORIZON_STEP * steps
        return replace(self, horizon=h) if HORIZON_MIN <= h <= HORIZON_MAX else None

    def after(self, action: str) -> AgentPose:
        """The pose after a navigation action taken without hindrance (MoveAhead, Rotate*, Look*; a look past the
        horizon limits, or any other action, leaves it as it is): how a recorded trajectory's poses are replayed."""
        if action == "MoveAhead":
            return self.moved()
        if action in ("RotateLeft", "RotateRight"):
            return self.rotated(-1 if action == "RotateLeft" else 1)
        if action in ("LookUp", "LookDown"):
            return self.looked(-1 if action == "LookUp" else 1) or self
        return self

    def grid_key(self) -> tuple[int, int]:
        return (round(self.x / GRID), round(self.y / GRID))

    def eye(self, camera_height: float = CAMERA_HEIGHT) -> tuple[float, float, float]:
        return (self.x, self.y, camera_height)

    def view_direction(self) -> tuple[float, float, float]:
        fx, fy = self.forward()
        p = math.radians(self.horizon)
        return (fx * math.cos(p), fy * math.cos(p), -math.sin(p))

    def to_alfred(self) -> dict:
        """ALFRED's TeleportFull arguments (THOR axes: x, y up, z)."""
        return {"action": "TeleportFull", "x": self.x, "y": AGENT_Y, "z": self.y, "rotation": self.rotation,
                "horizon": self.horizon, "rotateOnTeleport": True}

    def location_string(self) -> str:
        """ALFRED's planner location `loc|x|z|rot|horizon` in grid units and a rotation index."""
        gx, gz = self.grid_key()
        return f"loc|{gx}|{gz}|{self.rotation // 90}|{self.horizon}"
