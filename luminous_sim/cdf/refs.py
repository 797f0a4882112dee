"""References from a CDF to things outside it (room structures, assets): checked, never used as paths.

A reference must match SAFE_REF, so it can never name a path (no separators, no `..`). Rooms resolve
only through `luminous_sim.rooms.library.has_room` and assets only through
`luminous_sim.assets.catalog.has_asset`; both are imported lazily, and until those modules exist a
reference is accepted when it has the shape of a library name.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable

SAFE_REF = re.compile(r"[A-Za-z0-9_\-]+")
SAFE_REF_PATTERN = r"^[A-Za-z0-9_\-]+$"
ROOM_NAME_FALLBACK = re.compile(r"FloorPlan\d+|(kitchen|living_room|bedroom|bathroom)_[a-z0-9_]+")
ASSET_NAME_FALLBACK = re.compile(r"[A-Z][A-Za-z]+_\d{2}")

_FLOORPLAN = re.compile(r"FloorPlan(\d+)")
_PROCEDURAL_PREFIX = {"kitchen": "Kitchen", "living_room": "LivingRoom", "bedroom": "Bedroom", "bathroom": "Bathroom"}
_FLOORPLAN_HUNDREDS = {0: "Kitchen", 2: "LivingRoom", 3: "Bedroom", 4: "Bathroom"}


def check_safe_ref(value: str, what: str) -> str:
    """Return `value` if it is a safe reference, else raise ValueError saying what was expected."""
    if not SAFE_REF.fullmatch(value):
        raise ValueError(
            f"{what} reference {value!r} must match {SAFE_REF_PATTERN} "
            "(letters, digits, '_' and '-' only: no path separators, no '..')"
        )
    return value


def _lookup(module: str, func: str) -> Callable[[str], bool] | None:
    try:
        mod = importlib.import_module(module)
    except Exception:  # noqa: BLE001 - a sibling module mid-development must not break CDF loading
        return None
    found = getattr(mod, func, None)
    return found if callable(found) else None


def _resolve(name: str, module: str, func: str, fallback: re.Pattern[str]) -> bool:
    lookup = _lookup(module, func)
    if lookup is None:
        return bool(fallback.fullmatch(name))
    try:
        return bool(lookup(name))
    except Exception:  # noqa: BLE001 - a failing lookup means "not found", reported as a CDF error
        return False


def room_exists(name: str) -> bool:
    """Whether the room-structure library has a room called `name` (a safe reference)."""
    return _resolve(name, "luminous_sim.rooms.library", "has_room", ROOM_NAME_FALLBACK)


def asset_exists(name: str) -> bool:
    """Whether the asset catalog has an asset called `name` (a safe reference)."""
    return _resolve(name, "luminous_sim.assets.catalog", "has_asset", ASSET_NAME_FALLBACK)


def check_room(name: str) -> str:
    """Return a safe, known room name, else raise ValueError."""
    check_safe_ref(name, "room")
    if not room_exists(name):
        raise ValueError(
            f"unknown room {name!r}; expected a room-library name such as 'FloorPlan12' or a "
            "procedural room such as 'kitchen_rect'"
        )
    return name


def check_asset(name: str) -> str:
    """Return a safe, known asset name, else raise ValueError."""
    check_safe_ref(name, "asset")
    if not asset_exists(name):
        raise ValueError(f"unknown asset {name!r}; expected an asset-catalog name such as 'Mug_01'")
    return name


def room_type_of(name: str) -> str | None:
    """The room type a room name implies (ALFRED's FloorPlan numbering or a procedural prefix), if any."""
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
