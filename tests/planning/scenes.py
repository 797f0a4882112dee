"""Hand-built pure WorldStates for the planner tests and benchmark: a kitchen and a bedroom."""

from __future__ import annotations

from typing import Any

from luminous_sim.states import WorldState
from tests.kitchen import FAUCETS, Layout, state_of, with_
from tests.kitchen import KITCHEN as SHARED_KITCHEN
from tests.kitchen import kitchen as shared_kitchen

KITCHEN = with_(
    SHARED_KITCHEN,
    Plate_1=("Plate", "CounterTop|2"),
    Apple_2=("Apple", "DiningTable|1"),
    Apple_3=("Apple", "Fridge|1"),
    Egg_1=("Egg", "Fridge|1"),
    Plate_2=("Plate", "Cabinet|1"),
)
"""The shared kitchen with more to choose from: three apples, two plates, an egg in the fridge."""
KITCHEN_FAUCETS = FAUCETS
KITCHEN_DIRTY = ("Mug|1", "Mug|2", "Plate|1", "Plate|2", "Bowl|1", "Cup|1", "Pot|1", "Pan|1")

BEDROOM: Layout = {
    "Desk|1": ("Desk", None),
    "DeskLamp|1": ("DeskLamp", "Desk|1"),
    "Bed|1": ("Bed", None),
    "Dresser|1": ("Dresser", None),
    "Drawer|1": ("Drawer", None),
    "Shelf|1": ("Shelf", None),
    "SideTable|1": ("SideTable", None),
    "GarbageCan|1": ("GarbageCan", None),
    "Safe|1": ("Safe", None),
    "Book|1": ("Book", "Bed|1"),
    "Book|2": ("Book", "Shelf|1"),
    "CellPhone|1": ("CellPhone", "Desk|1"),
    "CD|1": ("CD", "Drawer|1"),
    "AlarmClock|1": ("AlarmClock", "Dresser|1"),
    "Box|1": ("Box", "Dresser|1"),
    "KeyChain|1": ("KeyChain", "Box|1"),
    "Pillow|1": ("Pillow", "Bed|1"),
    "Laptop|1": ("Laptop", "Bed|1"),
    "Pen|1": ("Pen", "SideTable|1"),
    "Mug|1": ("Mug", "Desk|1"),
}


def kitchen(
    changes: dict[str, dict[str, Any]] | None = None,
    held: str | None = None,
    drop: tuple[str, ...] = (),
    **kwargs: Any,
) -> WorldState:
    """The kitchen: everything closed and off, the dishes dirty; `drop` leaves objects out."""
    dirty = {k: {"isDirty": True} for k in KITCHEN_DIRTY}
    for k, v in (changes or {}).items():
        dirty[k] = {**dirty.get(k, {}), **v}
    return shared_kitchen(dirty, held, layout=KITCHEN, drop=drop, **kwargs)


def bedroom(
    changes: dict[str, dict[str, Any]] | None = None, held: str | None = None, **kwargs: Any
) -> WorldState:
    """The bedroom: the desk lamp off, drawers, safe and box closed."""
    return state_of(BEDROOM, changes, held, **kwargs)
