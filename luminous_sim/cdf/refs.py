"""References from a CDF to things outside it (rooms, assets): checked, never used as paths.

A reference must match SAFE_REF, so it can never name a path (no separators, no `..`). Rooms resolve
only through `luminous_sim.rooms.library.has_room` and assets only through
`luminous_sim.assets.catalog.has_asset`; both are imported lazily, and until those modules exist a
reference is accepted when it has the shape of a library name.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable, Container

SAFE_REF = re.compile(r"[A-Za-z0-9_\-]+")
SAFE_REF_PATTERN = r"^[A-Za-z0-9_\-]+$"
ROOM_NAME_FALLBACK = re.compile(r"FloorPlan\d+|(kitchen|living_room|bedroom|bathroom)_[a-z0-9_]+")
ASSET_NAME_FALLBACK = re.compile(r"[A-Z][A-Za-z]+_\d{2}")

_FLOORPLAN = re.compile(r"FloorPlan(\d+)")
_PROCEDURAL_PREFIX = {
    "kitchen": "Kitchen",
    "living_room": "LivingRoom",
    "bedroom": "Bedroom",
    "bathroom": "Bathroom",
}
_FLOORPLAN_HUNDREDS = {0: "Kitchen", 2: "LivingRoom", 3: "Bedroom", 4: "Bathroom"}


def check_safe_ref(value: str, what: str) -> str:
    """Return `value` if it is a safe reference, else raise ValueError saying what was expected."""
    if not SAFE_REF.fullmatch(value):
        raise ValueError(
            f"{what} reference {value!r} must match {SAFE_REF_PATTERN} "
            "(letters, digits, '_' and '-' only: no path separators, no '..')"
        )
    return value


def _import(module: str) -> object | None:
    try:
        return importlib.import_module(module)
    except Exception:
        return None


def _safely(func: Callable[[str], object], name: str) -> object:
    try:
        return func(name)
    except Exception:
        return None


def room_exists(name: str) -> bool:
    """Whether the room-structure library has a room called `name` (a safe reference)."""
    lookup = getattr(_import("luminous_sim.rooms.library"), "has_room", None)
    if not callable(lookup):
        return bool(ROOM_NAME_FALLBACK.fullmatch(name))
    return bool(_safely(lookup, name))


def _catalog() -> object | None:
    """The asset catalog (`has_asset` or `default_catalog()`), or None when it cannot be had."""
    module = _import("luminous_sim.assets.catalog")
    if module is None:
        return None
    if callable(getattr(module, "has_asset", None)):
        return module
    factory = getattr(module, "default_catalog", None)
    if not callable(factory):
        return None
    try:
        return factory()
    except Exception:
        return None


def asset_exists(name: str) -> bool:
    """Whether the asset catalog has an asset called `name` (a safe reference)."""
    catalog = _catalog()
    if catalog is None:
        return bool(ASSET_NAME_FALLBACK.fullmatch(name))
    has = getattr(catalog, "has_asset", None)
    if callable(has):
        return bool(_safely(has, name))
    if isinstance(catalog, Container):  # a Catalog: `in` asks whether it has the asset
        return bool(_safely(lambda n: n in catalog, name))
    return False


def asset_type(name: str) -> str | None:
    """The object type of a known asset (from the catalog, else its `Type_NN` shape)."""
    catalog = _catalog()
    getter = getattr(catalog, "get", None)
    if callable(getter):
        entry_type = getattr(_safely(getter, name), "type", None)
        return entry_type if isinstance(entry_type, str) else None
    if catalog is None and ASSET_NAME_FALLBACK.fullmatch(name):
        return name.rsplit("_", 1)[0]
    return None


def check_room(name: str) -> str:
    """Return a safe, known room name, else raise ValueError."""
    check_safe_ref(name, "room")
    if not room_exists(name):
        module = _import("luminous_sim.rooms.library")
        library_error = getattr(module, "room_files", None)
        problem = None
        if callable(library_error):  # a broken library (an incomplete install) is said as such
            try:
                library_error()
            except Exception as exc:
                problem = str(exc)
        explain = getattr(module, "missing_room", None)
        detail = problem or (_safely(explain, name) if callable(explain) else None)
        raise ValueError(f"unknown room {name!r}; expected a room-library name such as 'FloorPlan12' or a "
                         "procedural room such as 'kitchen_rect'" + (f" ({detail})" if isinstance(detail, str) else ""))
    return name


def check_asset(name: str) -> str:
    """Return a safe, known asset name, else raise ValueError."""
    check_safe_ref(name, "asset")
    if not asset_exists(name):
        raise ValueError(f"unknown asset {name!r}; expected an asset-catalog name such as 'Mug_01'")
    return name


def room_type_of(name: str) -> str | None:
    """The room type a room name implies (FloorPlan numbers or a procedural prefix)."""
    m = _FLOORPLAN.fullmatch(name)
    if m:
        n = int(m.group(1))
        if 1 <= n % 100 <= 30:
            return _FLOORPLAN_HUNDREDS.get(n // 100)
        return None
    for prefix, room_type in _PROCEDURAL_PREFIX.items():
        if name.startswith(prefix + "_"):
            return room_type
    return None
