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


def face_distance(object_type: str) -> str:
    """How far a piece of this type faces what it faces from: "close" (a seat at a table), "group" (an
    armchair in a seating group) or "view" (across the room), by the implicit rule table."""
    return str(_load("implicit_rules.json")["face_distance"].get(object_type, "view"))


def needs(object_type: str) -> tuple[str, ...]:
    """Types one of which a room must have before it gets a default piece of this type (a chair needs a
    table to sit at); empty when it needs none."""
    return tuple(_load("implicit_rules.json")["needs"].get(object_type, ()))


HOST_PRIOR = 1.0
"""Pseudo-count of every receptacle type in the back-off weights (`fallback_weight`)."""


def ruled_out(object_type: str, receptacle_type: str) -> bool:
    """Whether the placement table rules this host out for a default object of this type, although the
    compatibility table allows it ("never_on": no baseball bat on a bed)."""
    return receptacle_type in placement()["never_on"].get(object_type, ())


def host_weight(object_type: str, receptacle_type: str) -> float:
    """How likely an object of this type with no on/in relation rests on/in a receptacle of that type: how often
    ALFRED's scenes put it there (data/object_hosts.json; 0 for a host they never used, or one ruled out)."""
    if ruled_out(object_type, receptacle_type):
        return 0.0
    return float(object_hosts().get(object_type, {}).get(receptacle_type, 0))


def fallback_weight(object_type: str, receptacle_type: str) -> float:
    """The back-off where a room holds none of the hosts ALFRED used for this type (or ALFRED never placed it):
    how often ALFRED's scenes put anything on/in that receptacle type, plus HOST_PRIOR; 0 for one ruled out.
    The compatibility table (`supports_for`) decides which receptacles may be weighed at all."""
    if ruled_out(object_type, receptacle_type):
        return 0.0
    return HOST_PRIOR + _host_totals().get(receptacle_type, 0)


@cache
def _host_totals() -> dict[str, int]:
    totals: dict[str, int] = {}
    for counts in object_hosts().values():
        for rec, k in counts.items():
            totals[rec] = totals.get(rec, 0) + k
    return totals


def object_hosts() -> dict[str, dict[str, int]]:
    """Per object type, how often ALFRED's scenes put it on/in each receptacle type (data/object_hosts.json)."""
    return _load("object_hosts.json")["hosts"]


def floor_relations(object_type: str) -> tuple[str, ...]:
    """The floor relations ("in_corner", "against_wall") by which a default object of this type may lie on the
    floor (placement.json's on_floor); empty for a type that never does."""
    return tuple(placement()["on_floor"].get(object_type, ()))


def floor_share(object_type: str) -> float:
    """ALFRED's share of this type's placements that rest on the floor (data/object_hosts.json's floor); 0 for a
    type it never shows."""
    got = _load("object_hosts.json").get("floor", {}).get(object_type)
    return got["on_floor"] / got["placements"] if got and got["placements"] else 0.0
