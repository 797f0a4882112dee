"""Hand-built pure WorldStates for the planner tests and benchmark: a kitchen and a bedroom."""

from __future__ import annotations

from typing import Any

from luminous_sim.states import ObjectState, WorldState

KITCHEN: dict[str, tuple[str, str | None]] = {
    # id: (type, parent)
    "CounterTop|1": ("CounterTop", None),
    "CounterTop|2": ("CounterTop", None),
    "DiningTable|1": ("DiningTable", None),
    "Fridge|1": ("Fridge", None),
    "Microwave|1": ("Microwave", "CounterTop|1"),
    "Cabinet|1": ("Cabinet", None),
    "Cabinet|2": ("Cabinet", None),
    "Drawer|1": ("Drawer", None),
    "Sink|1": ("Sink", None),
    "SinkBasin|1": ("SinkBasin", None),
    "Faucet|1": ("Faucet", None),
    "GarbageCan|1": ("GarbageCan", None),
    "StoveBurner|1": ("StoveBurner", None),
    "CoffeeMachine|1": ("CoffeeMachine", "CounterTop|2"),
    "Apple|1": ("Apple", "CounterTop|1"),
    "Apple|2": ("Apple", "DiningTable|1"),
    "Apple|3": ("Apple", "Fridge|1"),
    "Egg|1": ("Egg", "Fridge|1"),
    "Plate|1": ("Plate", "CounterTop|2"),
    "Plate|2": ("Plate", "Cabinet|1"),
    "Mug|1": ("Mug", "CounterTop|1"),
    "Mug|2": ("Mug", "Cabinet|2"),
    "Bowl|1": ("Bowl", "DiningTable|1"),
    "Cup|1": ("Cup", "DiningTable|1"),
    "Knife|1": ("Knife", "Drawer|1"),
    "Fork|1": ("Fork", "Drawer|1"),
    "Potato|1": ("Potato", "CounterTop|2"),
    "Tomato|1": ("Tomato", "DiningTable|1"),
    "Bread|1": ("Bread", "CounterTop|2"),
    "Lettuce|1": ("Lettuce", "CounterTop|1"),
    "Pot|1": ("Pot", "StoveBurner|1"),
    "Pan|1": ("Pan", "CounterTop|1"),
    "DishSponge|1": ("DishSponge", "CounterTop|2"),
}
KITCHEN_FAUCETS = {"Faucet|1": "SinkBasin|1"}
KITCHEN_DIRTY = ("Mug|1", "Mug|2", "Plate|1", "Plate|2", "Bowl|1", "Cup|1", "Pot|1", "Pan|1")

BEDROOM: dict[str, tuple[str, str | None]] = {
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


def _build(
    layout: dict[str, tuple[str, str | None]],
    changes: dict[str, dict[str, Any]] | None,
    held: str | None,
    **kwargs: Any,
) -> WorldState:
    changes = dict(changes or {})
    if held is not None:
        changes[held] = {**changes.get(held, {}), "parent": None, "isPickedUp": True}
    objs = []
    for oid, (kind, parent) in layout.items():
        fields: dict[str, Any] = {"parent": parent, **changes.get(oid, {})}
        objs.append(ObjectState(oid, kind, **fields))
    return WorldState.of(objs, held=held, **kwargs)


def kitchen(
    changes: dict[str, dict[str, Any]] | None = None,
    held: str | None = None,
    drop: tuple[str, ...] = (),
    **kwargs: Any,
) -> WorldState:
    """The kitchen: everything closed and off, the dishes dirty; `drop` leaves objects out."""
    base = {k: {"isDirty": True} for k in KITCHEN_DIRTY}
    for k, v in (changes or {}).items():
        base[k] = {**base.get(k, {}), **v}
    layout = {k: v for k, v in KITCHEN.items() if k not in drop}
    kwargs.setdefault(
        "faucet_basin", {f: b for f, b in KITCHEN_FAUCETS.items() if f in layout and b in layout}
    )
    return _build(layout, {k: v for k, v in base.items() if k in layout}, held, **kwargs)


def bedroom(
    changes: dict[str, dict[str, Any]] | None = None, held: str | None = None, **kwargs: Any
) -> WorldState:
    """The bedroom: the desk lamp off, drawers, safe and box closed."""
    return _build(BEDROOM, changes, held, **kwargs)
