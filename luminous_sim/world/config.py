"""A World's sensor and agent settings."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal


@dataclass(frozen=True)
class WorldConfig:
    """Sensor and agent settings (ALFRED's by default)."""

    width: int = 300
    height: int = 300
    fov: float = 60.0
    render: bool = True
    renderer: Literal["auto", "tiny", "egl"] = "auto"
    visibility_distance: float = 1.5
    min_visible_pixels: int = 10
    settle_steps: int = 240
    interaction_steps: int = 60
