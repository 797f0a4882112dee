"""How objects are named in instructions: "apple", "coffee machine", "slice of apple"."""

from __future__ import annotations

import re

SPECIAL = {"TVStand": "tv stand", "CD": "cd", "CounterTop": "counter", "SinkBasin": "sink", "BathtubBasin": "bathtub",
           "StoveBurner": "stove burner", "Glassbottle": "glass bottle", "GarbageCan": "trash can",
           "DiningTable": "table", "SideTable": "side table", "CoffeeTable": "coffee table"}


def spoken(object_type: str) -> str:
    """`CoffeeMachine` -> "coffee machine"; `AppleSliced` -> "slice of apple"."""
    if object_type.endswith("Sliced"):
        return f"slice of {spoken(object_type[:-6])}"
    if object_type in SPECIAL:
        return SPECIAL[object_type]
    return " ".join(w.lower() for w in re.findall(r"[A-Z][a-z]*|[a-z]+", object_type))

