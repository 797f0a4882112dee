"""The room library: shipped room files (`cdf/rooms/**/<name>.json`) and procedural room names.

A name is only ever a bare word (`^[A-Za-z0-9_-]+$`); it is looked up as `<name>.json` inside the
library folders, never used as a path, so `../x` or `/etc/passwd` cannot reach outside them.
Folders searched, in order: the package's shipped room library (`luminous_sim.resources.room_library_dir`:
ALFRED's FloorPlans converted, in subfolders), then each folder in the `LUMINOUS_ROOM_LIBRARY` environment
variable (separated by `os.pathsep`). The first match wins. A shipped library without ALFRED's floor plans is an
incomplete install, and an error, never an empty list.

Procedural names mean "generate a room of this type and shape": `kitchen`, `kitchen_rect`,
`kitchen_L`, `kitchen_two_zone`, and the same for `living_room`, `bedroom` and `bathroom` (the
bare type draws its shape). `shell_for(name, rng)` resolves both kinds.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np

from luminous_sim.errors import RoomError
from luminous_sim.resources import room_library_dir
from luminous_sim.rooms.generate import SHAPES, generate_shell, snake
from luminous_sim.rooms.shell import NAME_PATTERN, RoomShell, load_shell
from luminous_sim.vocab import ROOM_TYPES

ENV_VAR = "LUMINOUS_ROOM_LIBRARY"
SHIPPED_DIR = room_library_dir()
ALFRED_ROOM = re.compile(r"FloorPlan\d+")
NOT_ROOMS = frozenset({"splits", "index"})
"""File stems in library folders that hold metadata, not rooms."""

_NAME = re.compile(NAME_PATTERN)
PROCEDURAL: dict[str, tuple[str, str | None]] = {
    f"{snake(t)}{'_' + s if s else ''}": (t, s) for t in ROOM_TYPES for s in (None, *SHAPES)
}
"""Procedural name -> (room type, shape or None)."""


def check_name(name: str) -> str:
    """Return `name` if it is a valid room name, else raise RoomError."""
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise RoomError(
            f"invalid room name {name!r}: a room name may contain only letters, digits, "
            "'_' and '-' "
            "(it names a file in the room library, not a path)"
        )
    return name


def library_dirs() -> list[Path]:
    """Folders searched for room files: the shipped one, then `LUMINOUS_ROOM_LIBRARY` entries."""
    dirs = [SHIPPED_DIR]
    for entry in os.environ.get(ENV_VAR, "").split(os.pathsep):
        if entry.strip():
            dirs.append(Path(entry.strip()).expanduser().resolve())
    return dirs


def room_files() -> dict[str, Path]:
    """Every room file in the library folders, by name (the first folder holding a name wins).

    Raises:
        RoomError: the shipped library holds none of ALFRED's floor plans (an incomplete install).
    """
    found: dict[str, Path] = {}
    if not SHIPPED_DIR.is_dir() or not any(ALFRED_ROOM.fullmatch(p.stem) for p in SHIPPED_DIR.rglob("*.json")):
        raise RoomError(f"the room library at {SHIPPED_DIR} holds none of ALFRED's floor plans (FloorPlan<N>.json): "
                        "the package is incomplete; reinstall luminous-sim (pip install --force-reinstall "
                        "luminous-sim)")
    for base in library_dirs():
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*.json")):
            stem = path.stem
            if stem in NOT_ROOMS or not _NAME.fullmatch(stem) or stem in found:
                continue
            resolved = path.resolve()
            if resolved.is_relative_to(base.resolve()):
                found[stem] = resolved
    return found


def room_names(include_procedural: bool = True) -> list[str]:
    """Names of the library's room files (sorted), then the procedural names if asked."""
    names = sorted(room_files(), key=_natural)
    if include_procedural:
        names += [n for n in PROCEDURAL if n not in names]
    return names


def _natural(name: str) -> tuple:
    return tuple(int(p) if p.isdigit() else p for p in re.split(r"(\d+)", name))


def is_procedural(name: str) -> bool:
    """Whether `name` is a procedural room name (and no room file of that name shadows it)."""
    return name in PROCEDURAL and name not in room_files()


def missing_room(name: str) -> str:
    """Why `name` is not a room: where it was looked for and what provides rooms."""
    dirs = ", ".join(map(str, library_dirs()))
    return (f"no room {name!r} in the room library (no {name}.json in {dirs}; not a procedural name such as "
            f"{', '.join(list(PROCEDURAL)[:2])}): `luminous rooms list` lists every room; {ENV_VAR}=DIR adds a "
            "folder of your own rooms")


def has_room(name: str) -> bool:
    """Whether `name` is a room file in the library or a procedural name (invalid names: False)."""
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        return False
    return name in PROCEDURAL or name in room_files()


def room_path(name: str) -> Path:
    """The file of a library room; RoomError for an invalid or unknown name."""
    files = room_files()
    if check_name(name) not in files:
        if name in PROCEDURAL:
            raise RoomError(f"{name!r} is a procedural room name, not a file of the room library: use "
                            "shell_for(name, rng)")
        raise RoomError(missing_room(name))
    return files[name]


def load_room(name: str) -> RoomShell:
    """Load a room file from the library by name.

    Raises:
        RoomError: an invalid name, a name not in the library, or a malformed file.
    """
    return load_shell(room_path(name))


def shell_for(name: str, rng: np.random.Generator) -> RoomShell:
    """Resolve any room name: a library file (rng unused) or a procedural name (uses rng)."""
    check_name(name)
    if is_procedural(name):
        room_type, shape = PROCEDURAL[name]
        return generate_shell(room_type, rng, shape, name=name)
    return load_room(name)
