"""The test suite's one hand-built kitchen, as a pure WorldState, and the builder for such states.

The state-rule, planner and task tests all build on `KITCHEN`; tests that need more (a second
apple, an egg on the counter) add it on top with `with_`, where what they rely on can be seen.
"""

from __future__ import annotations

from typing import Any

from luminous_sim.states import ObjectState, WorldState

Layout = dict[str, tuple[str, str | None]]
"""id -> (type, parent id)."""

KITCHEN: Layout = {
    "CounterTop|1": ("CounterTop", None),
    "CounterTop|2": ("CounterTop", None),
    "DiningTable|1": ("DiningTable", None),
    "Fridge|1": ("Fridge", None),
    "Microwave|1": ("Microwave", "CounterTop|1"),
    "Cabinet|1": ("Cabinet", None),
    "Cabinet|2": ("Cabinet", None),
    "Drawer|1": ("Drawer", None),
    "Sink|1": ("Sink", None),
    "SinkBasin|1": ("SinkBasin", "Sink|1"),
    "Faucet|1": ("Faucet", "Sink|1"),
    "Faucet|2": ("Faucet", None),
    "GarbageCan|1": ("GarbageCan", None),
    "StoveBurner|1": ("StoveBurner", None),
    "StoveBurner|2": ("StoveBurner", None),
    "StoveKnob|1": ("StoveKnob", None),
    "StoveKnob|2": ("StoveKnob", None),
    "Toaster|1": ("Toaster", "CounterTop|1"),
    "CoffeeMachine|1": ("CoffeeMachine", "CounterTop|1"),
    "Apple|1": ("Apple", "CounterTop|1"),
    "Plate|1": ("Plate", "DiningTable|1"),
    "Mug|1": ("Mug", "CounterTop|1"),
    "Mug|2": ("Mug", "DiningTable|1"),
    "Bowl|1": ("Bowl", "DiningTable|1"),
    "Cup|1": ("Cup", "DiningTable|1"),
    "Knife|1": ("Knife", "Drawer|1"),
    "Fork|1": ("Fork", "Drawer|1"),
    "Potato|1": ("Potato", "DiningTable|1"),
    "Tomato|1": ("Tomato", "DiningTable|1"),
    "Bread|1": ("Bread", "CounterTop|1"),
    "Lettuce|1": ("Lettuce", "CounterTop|1"),
    "Pot|1": ("Pot", "StoveBurner|1"),
    "Pan|1": ("Pan", "CounterTop|1"),
    "Kettle|1": ("Kettle", "CounterTop|1"),
    "DishSponge|1": ("DishSponge", "CounterTop|2"),
    "Box|1": ("Box", "Cabinet|1"),
    "CD|1": ("CD", "Box|1"),
    "Laptop|1": ("Laptop", "DiningTable|1"),
    "WineBottle|1": ("WineBottle", "CounterTop|1"),
}
CONTROLS = {"StoveKnob|1": "StoveBurner|1", "StoveKnob|2": "StoveBurner|2"}
FAUCETS = {"Faucet|1": "SinkBasin|1"}  # Faucet|2 serves no known basin


def state_of(
    layout: Layout,
    changes: dict[str, dict[str, Any]] | None = None,
    held: str | None = None,
    **kwargs: Any,
) -> WorldState:
    """A state with every object as laid out, some fields changed; `held` is lifted (no parent).

    Changes for ids the layout lacks are ignored; `kwargs` go to `WorldState.of`.
    """
    changes = {k: dict(v) for k, v in (changes or {}).items()}
    if held is not None:
        changes[held] = {**changes.get(held, {}), "parent": None, "isPickedUp": True}
    objs = [
        ObjectState(oid, kind, **{"parent": parent, **changes.get(oid, {})})
        for oid, (kind, parent) in layout.items()
    ]
    return WorldState.of(objs, held=held, **kwargs)


def kitchen(
    changes: dict[str, dict[str, Any]] | None = None,
    held: str | None = None,
    *,
    layout: Layout = KITCHEN,
    drop: tuple[str, ...] = (),
    **kwargs: Any,
) -> WorldState:
    """The kitchen (or a layout built on it): all closed, off and clean unless `changes` say so.

    `drop` leaves objects out; the knobs switch their burners and Faucet|1 fills SinkBasin|1
    where both are left.
    """
    kept = {k: v for k, v in layout.items() if k not in drop}
    kwargs.setdefault("controls", {k: b for k, b in CONTROLS.items() if k in kept and b in kept})
    kwargs.setdefault("faucet_basin", {f: b for f, b in FAUCETS.items() if f in kept and b in kept})
    return state_of(kept, changes, held, **kwargs)


def with_(layout: Layout, **extra: tuple[str, str | None] | None) -> Layout:
    """A copy of a layout with objects added (keyword `Type_k` for `Type|k`), moved or removed."""
    out = dict(layout)
    for key, value in extra.items():
        oid = key.replace("_", "|")
        if value is None:
            out.pop(oid, None)
        else:
            out[oid] = value
    return out


def without(layout: Layout, *types: str) -> Layout:
    """A copy of a layout without the objects of the given types (what they held stays)."""
    return {k: v for k, v in layout.items() if v[0] not in types}
