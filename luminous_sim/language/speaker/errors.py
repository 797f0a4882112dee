"""The speaker's error type."""

from __future__ import annotations

from luminous_sim.errors import LuminousError


class SpeakerError(LuminousError):
    """Unreadable training data, a bad checkpoint, or a speaker asked for something it cannot do."""
