"""A small kitchen as a pure WorldState, for the state-rule tests."""

from __future__ import annotations

from typing import Any

from luminous_sim.states import ObjectState, WorldState

LAYOUT: dict[str, tuple[str, str | None]] = {
    # id: (type, parent)
    "CounterTop|1": ("CounterTop", None),
    "DiningTable|1": ("DiningTable", None),
    "Fridge|1": ("Fridge", None),
    "Microwave|1": ("Microwave", "CounterTop|1"),
    "Cabinet|1": ("Cabinet", None),
    "Drawer|1": ("Drawer", None),
    "SinkBasin|1": ("SinkBasin", None),
    "Faucet|1": ("Faucet", None),
    "Faucet|2": ("Faucet", None),
    "StoveBurner|1": ("StoveBurner", None),
    "StoveBurner|2": ("StoveBurner", None),
    "StoveKnob|1": ("StoveKnob", None),
    "StoveKnob|2": ("StoveKnob", None),
    "Toaster|1": ("Toaster", "CounterTop|1"),
    "CoffeeMachine|1": ("CoffeeMachine", "CounterTop|1"),
    "Apple|1": ("Apple", "CounterTop|1"),
    "Plate|1": ("Plate", "CounterTop|1"),
    "Mug|1": ("Mug", "CounterTop|1"),
    "Cup|1": ("Cup", "CounterTop|1"),
    "Bowl|1": ("Bowl", "CounterTop|1"),
    "Knife|1": ("Knife", "Drawer|1"),
    "ButterKnife|1": ("ButterKnife", "CounterTop|1"),
    "Egg|1": ("Egg", "CounterTop|1"),
    "Bread|1": ("Bread", "CounterTop|1"),
    "Potato|1": ("Potato", "CounterTop|1"),
    "Tomato|1": ("Tomato", "CounterTop|1"),
    "Pot|1": ("Pot", "StoveBurner|1"),
    "Pan|1": ("Pan", "CounterTop|1"),
    "Kettle|1": ("Kettle", "CounterTop|1"),
    "Box|1": ("Box", "Cabinet|1"),
    "CD|1": ("CD", "Box|1"),
    "Laptop|1": ("Laptop", "DiningTable|1"),
    "WineBottle|1": ("WineBottle", "CounterTop|1"),
}
CONTROLS = {"StoveKnob|1": "StoveBurner|1", "StoveKnob|2": "StoveBurner|2"}
FAUCETS = {"Faucet|1": "SinkBasin|1"}  # Faucet|2 serves no known basin


def kitchen(
    changes: dict[str, dict[str, Any]] | None = None, held: str | None = None, **kwargs: Any
) -> WorldState:
    """The kitchen, everything closed and off, with per-object field changes and an optional held object."""
    changes = dict(changes or {})
    if held is not None:
        changes[held] = {**changes.get(held, {}), "parent": None, "isPickedUp": True}
    objs = []
    for oid, (kind, parent) in LAYOUT.items():
        fields: dict[str, Any] = {"parent": parent, **changes.get(oid, {})}
        objs.append(ObjectState(oid, kind, **fields))
    kwargs.setdefault("controls", CONTROLS)
    kwargs.setdefault("faucet_basin", FAUCETS)
    return WorldState.of(objs, held=held, **kwargs)


def diff(before: WorldState, after: WorldState) -> dict[str, dict[str, Any]]:
    """Changed fields per object id; a removed object maps to {"removed": True}, an added one to its fields."""
    out: dict[str, dict[str, Any]] = {}
    for oid, a in after.objects.items():
        b = before.get(oid)
        if b is None:
            out[oid] = {"added": a.object_type}
            continue
        changed = {k: v for k, v in vars(a).items() if getattr(b, k) != v}
        if changed:
            out[oid] = changed
    for oid in before.objects:
        if oid not in after:
            out[oid] = {"removed": True}
    return out
