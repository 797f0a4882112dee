"""Room structures (layer L1, pure): shells, procedural generation, ALFRED conversion, library.

A `RoomShell` is a room's fixed structure: floor outline, walls with thickness and height, doors,
windows, named zones and, for kitchens and bathrooms, the fixtures LUMINOUS keeps (counter runs,
sink, stove, fridge; toilet, sink, bathtub). Shells come from `generate_shell` (procedural), from
`convert_scene` (ALFRED's AI2-THOR layouts), or from the library (`load_room`, `shell_for`).
"""

from luminous_sim.rooms.alfred_convert import (
    ALFRED_SPLITS,
    convert_all,
    convert_scene,
    scene_room_type,
    scene_split,
)
from luminous_sim.rooms.checks import shell_problems
from luminous_sim.rooms.generate import ROOM_SPECS, SHAPES, generate_shell
from luminous_sim.rooms.library import has_room, load_room, room_names, shell_for
from luminous_sim.rooms.shell import (
    CounterRun,
    Door,
    FixturePlan,
    FixtureSlot,
    RoomShell,
    Wall,
    WallBox,
    Window,
    Zone,
    load_shell,
    save_shell,
)

__all__ = [
    "ALFRED_SPLITS",
    "ROOM_SPECS",
    "SHAPES",
    "CounterRun",
    "Door",
    "FixturePlan",
    "FixtureSlot",
    "RoomShell",
    "Wall",
    "WallBox",
    "Window",
    "Zone",
    "convert_all",
    "convert_scene",
    "generate_shell",
    "has_room",
    "load_room",
    "load_shell",
    "room_names",
    "save_shell",
    "scene_room_type",
    "scene_split",
    "shell_for",
    "shell_problems",
]
