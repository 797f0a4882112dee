"""The placement rule tables (data files in `data/`), loaded once."""

from __future__ import annotations

import json
from functools import cache
from importlib import resources
from typing import Any

from luminous_sim.vocab import (
    FIXTURE_TYPES,
    FURNITURE_TYPES,
    WALL_TYPES,
    abilities,
    receptacle_objects,
    vocab_data,
)


@cache
def _load(name: str) -> dict[str, Any]:
    return json.loads(resources.files("luminous_sim.cssg").joinpath(f"data/{name}").read_text())


def placement() -> dict[str, Any]:
    return _load("placement.json")


def room_defaults(room_type: str) -> dict[str, Any]:
    return _load("room_defaults.json")[room_type]


def generation_layer(object_type: str) -> str:
    """How CSSG places a type: fixture, furniture, wall or object (the first that lists it, in that order).

    Not the CDF's placement-order layer (`cdf.layers.layer_of`); both read their type lists from `vocab`.
    """
    if object_type in FIXTURE_TYPES:
        return "fixture"
    if object_type in FURNITURE_TYPES:
        return "furniture"
    if object_type in WALL_TYPES:
        return "wall"
    return "object"


def wall_height(object_type: str) -> float:
    """Height of the bottom of a wall-hung object above the floor."""
    return float(placement()["wall_height"][object_type])


@cache
def supports_for(object_type: str) -> frozenset[str]:
    """Receptacle types an object may rest on/in: ALFRED's table for pickupables, else our supports table."""
    extra = placement()["supports"].get(object_type)
    if extra is not None:
        return frozenset(extra)
    if not abilities(object_type).pickupable:
        return frozenset()
    return frozenset(r for r in placement_receptacles() if object_type in receptacle_objects(r))


@cache
def placement_receptacles() -> tuple[str, ...]:
    return tuple(sorted(vocab_data()["receptacle_objects"]))
