"""The paper's verb table (LUMINOUS, Table 1) as data: several verbs per action, chosen with a seeded rng."""

from __future__ import annotations

from luminous_sim.language.names import IN, preposition

VERBS: dict[str, tuple[str, ...]] = {
    "GotoLocation": ("go to", "walk to", "head to", "find"),
    "PickupObject": ("pick up", "take", "grab", "carry"),
    "PutObject": ("put", "place", "set"),
    "SliceObject": ("slice", "cut"),
    "CoolObject": ("chill", "cool"),
    "HeatObject": ("heat", "cook", "warm up"),
    "CleanObject": ("clean", "wash", "rinse"),
    "ToggleObjectOn": ("turn on", "switch on"),
    "ToggleObjectOff": ("turn off", "switch off"),
    "OpenObject": ("open",),
    "CloseObject": ("close", "shut"),
}

PREPOSITION = {"in": tuple(sorted(IN))}
"""Receptacles things go *in*; everything else they go *on* (`language.names.IN`)."""

COLOUR_NAMES: dict[str, tuple[float, float, float]] = {
    "red": (0.8, 0.15, 0.15), "green": (0.3, 0.6, 0.25), "blue": (0.2, 0.35, 0.7), "yellow": (0.95, 0.8, 0.3),
    "white": (0.95, 0.95, 0.93), "black": (0.12, 0.12, 0.12), "brown": (0.45, 0.3, 0.18),
    "grey": (0.55, 0.57, 0.6), "orange": (0.9, 0.5, 0.15), "pink": (0.9, 0.6, 0.65), "beige": (0.85, 0.78, 0.65),
}


def colour_word(rgb: tuple[float, float, float]) -> str:
    """The nearest of a few everyday colour names."""
    return min(COLOUR_NAMES, key=lambda n: sum((a - b) ** 2 for a, b in zip(rgb, COLOUR_NAMES[n])))


__all__ = ["COLOUR_NAMES", "PREPOSITION", "VERBS", "colour_word", "preposition"]
