"""Typed access to `data/alfred_vocab.json` (ALFRED gen/constants.py restated; see spec/alfred.md section 3)."""

from __future__ import annotations

import difflib
import json
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from luminous_sim.errors import VocabularyError


@cache
def vocab_data() -> dict[str, Any]:
    """The raw vocabulary document (read once)."""
    text = resources.files("luminous_sim.vocab").joinpath("data/alfred_vocab.json").read_text()
    return json.loads(text)


_D = vocab_data()
OBJECTS: tuple[str, ...] = tuple(_D["objects"])
"""ALFRED's 108 object types; the list order is the class index."""
SLICED_TYPES: dict[str, str] = dict(_D["sliced_types"])
"""Sliced type -> parent type (ALFRED's OBJ_PARENTS without the identity entries)."""
ALL_TYPES: tuple[str, ...] = OBJECTS + tuple(_D["extra_scene_types"]) + tuple(SLICED_TYPES)
ROOM_TYPES: tuple[str, ...] = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom")
_RECEPTACLE_OBJECTS: dict[str, frozenset[str]] = {
    k: frozenset(v) for k, v in _D["receptacle_objects"].items()
}


def _set(*keys: str) -> frozenset[str]:
    return frozenset(t for k in keys for t in _D[k])


_RECEPTACLES = _set("receptacles")
_MOVABLE = _set("movable_receptacles")
_OPENABLE = _set("openable", "openable_extra_thor")
_PICKUPABLE = _set("pickupable", "pickupable_extra_thor")
_TOGGLEABLE = _set("toggleable", "toggleable_extra_thor")
_SLICEABLE = _set("sliceable")
_HEATABLE = _set("heatable")
_COOLABLE = _set("coolable")
_CLEANABLE = _set("cleanable")
_DIRTYABLE = _set("dirtyable_thor")


@dataclass(frozen=True)
class Abilities:
    """What an object type can do (ALFRED's classes, plus AI2-THOR's extra openables/toggleables)."""

    pickupable: bool
    receptacle: bool
    openable: bool
    toggleable: bool
    sliceable: bool
    heatable: bool
    coolable: bool
    cleanable: bool
    dirtyable: bool
    movable_receptacle: bool

    def as_dict(self) -> dict[str, bool]:
        return dict(self.__dict__)


def check_type(object_type: str, where: str = "") -> str:
    """Return `object_type` if the vocabulary knows it, else raise a VocabularyError naming close matches."""
    if object_type in ALL_TYPES:
        return object_type
    hint = difflib.get_close_matches(object_type, ALL_TYPES, n=3)
    loc = f"{where}: " if where else ""
    extra = f"; did you mean {', '.join(hint)}?" if hint else ""
    raise VocabularyError(f"{loc}unknown object type {object_type!r}{extra}")


@cache
def abilities(object_type: str) -> Abilities:
    """The abilities of a known object type."""
    t = check_type(object_type)
    return Abilities(
        pickupable=t in _PICKUPABLE,
        receptacle=t in _RECEPTACLES,
        openable=t in _OPENABLE,
        toggleable=t in _TOGGLEABLE,
        sliceable=t in _SLICEABLE,
        heatable=t in _HEATABLE,
        coolable=t in _COOLABLE,
        cleanable=t in _CLEANABLE,
        dirtyable=t in _DIRTYABLE,
        movable_receptacle=t in _MOVABLE,
    )


def receptacle_objects(receptacle_type: str) -> frozenset[str]:
    """Object types ALFRED allows inside/on `receptacle_type` (empty for a non-receptacle)."""
    check_type(receptacle_type)
    return _RECEPTACLE_OBJECTS.get(receptacle_type, frozenset())


def can_contain(receptacle_type: str, object_type: str) -> bool:
    """Whether ALFRED's compatibility table lets `object_type` go in/on `receptacle_type`."""
    check_type(object_type)
    return object_type in receptacle_objects(receptacle_type)


def room_objects(room_type: str) -> dict[str, int]:
    """Object types found in ALFRED scenes of `room_type`, with how many of its 30 scenes hold each."""
    if room_type not in ROOM_TYPES:
        raise VocabularyError(f"unknown room type {room_type!r}; expected one of {', '.join(ROOM_TYPES)}")
    return dict(_D["rooms"][room_type]["objects"])


def parent_type(object_type: str) -> str:
    """`AppleSliced` -> `Apple`; every other type maps to itself (ALFRED's OBJ_PARENTS)."""
    return SLICED_TYPES.get(check_type(object_type), object_type)


def object_class_id(object_type: str) -> int:
    """ALFRED's class index (position in OBJECTS); raises for types outside the 108."""
    if object_type not in OBJECTS:
        raise VocabularyError(f"{object_type!r} is not one of ALFRED's 108 OBJECTS")
    return OBJECTS.index(object_type)
