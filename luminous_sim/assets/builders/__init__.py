"""Procedural builders, one module per family; importing this package registers them all."""

from luminous_sim.assets.builders import (  # noqa: F401
    bathroom,
    decor,
    electronics,
    food,
    household,
    kitchen,
    kitchenware,
    seating,
    storage,
    structure,
    tables,
    textiles,
    toiletries,
)
