"""Procedural builders, one module per family; importing this package registers them all."""

from luminous_sim.assets.builders import decor_structure, food, kitchen, kitchenware, seating  # noqa: F401
