"""What an episode has sent to its world so far: one `Sent` per action that reached it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any


@dataclass(frozen=True)
class Sent:
    """One action that reached the world: as the agent gave it, as sent, and whether it succeeded."""

    given: Any
    api: dict[str, Any]
    ok: bool
