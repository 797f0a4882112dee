"""The one error hierarchy. A user's bad input raises a subclass whose message names what is wrong and where."""

from __future__ import annotations


class LuminousError(Exception):
    """Base class for every error Luminous-Sim raises on purpose."""


class VocabularyError(LuminousError, KeyError):
    """An object type, room type or ability that the vocabulary does not know."""

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return str(self.args[0]) if self.args else ""


class AssetError(LuminousError):
    """An asset that cannot be built, found, imported or loaded."""


class CDFError(LuminousError):
    """A malformed or inconsistent Challenge Definition Format document."""


class InfeasibleSceneError(LuminousError):
    """CSSG could not satisfy a CDF within its sampling budget."""


class PlanningError(LuminousError):
    """The oracle planner found no plan, or execution diverged beyond repair."""


class RoomError(LuminousError):
    """A room structure that is malformed, cannot be generated, converted or found in the library."""
