"""Data for the state rules: which types cook, gate access, or switch off; slices.

The action names, fillable vessels and slicing tools are vocabulary (`luminous_sim.vocab`)."""

from __future__ import annotations

from luminous_sim.vocab import SLICED_TYPES, vocab_data

HIGH_LEVEL_ONLY: dict[str, str] = {
    "CleanObject": "PutObject into a SinkBasin, then ToggleObjectOn its Faucet",
    "HeatObject": "PutObject into a Microwave, CloseObject, then ToggleObjectOn",
    "CoolObject": "PutObject into a Fridge, then CloseObject",
}
"""Planner actions with no low-level counterpart -> the low-level actions that achieve them."""

GATING_OPENABLE: frozenset[str] = frozenset(vocab_data()["openable"])
"""ALFRED's OPENABLE_CLASS_LIST (Fridge, Cabinet, Microwave, Drawer, Safe, Box): while closed,
nothing inside can be reached and nothing can be put in. AI2-THOR's extra openables (Laptop,
Toilet, LaundryHamper) open and close but do not gate access; ALFRED's plans put things on a
closed Toilet."""

FOOD_COOKABLE: frozenset[str] = frozenset(
    {
        "Apple",
        "AppleSliced",
        "Bread",
        "BreadSliced",
        "Egg",
        "Lettuce",
        "LettuceSliced",
        "Potato",
        "PotatoSliced",
        "Tomato",
        "TomatoSliced",
    }
)
"""Food that becomes isCooked when heated."""

OFF_WHEN_OPENED: frozenset[str] = frozenset({"Microwave"})
"""Devices that AI2-THOR switches off when their door is opened."""

CLOSED_TO_SWITCH_ON: frozenset[str] = frozenset({"Microwave"})
"""Devices that must be closed before they can be switched on."""

SLICE_OF: dict[str, str] = {parent: sliced for sliced, parent in SLICED_TYPES.items()}
"""Sliceable parent type -> its sliced type (Apple -> AppleSliced); Egg is sliceable, has none."""

DEFAULT_SLICE_COUNTS: dict[str, int] = {
    "Apple": 6,
    "Bread": 10,
    "Lettuce": 6,
    "Potato": 6,
    "Tomato": 5,
}
"""Pieces per parent when `WorldState.slice_counts` does not say (first asset variant's count)."""


def slice_id(parent_id: str, sliced_type: str, index: int) -> str:
    """ALFRED's id of a slice (0-based `index`): ``Apple|x|y|z|AppleSliced_1`` for index 0.

    ALFRED's slice id format (`Apple|x|y|z|AppleSliced_1`).
    """
    return f"{parent_id}|{sliced_type}_{index + 1}"
