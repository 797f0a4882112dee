"""Real rooms as the reference for the category measures: the object types of AI2-THOR's 120 ALFRED rooms, from
the lists ALFRED publishes with its layouts (`FloorPlan<N>-objects.json`), and, where ALFRED's trajectories are
given, how many instances of each movable type a trajectory's scene holds (`scene.object_poses`).

What it can count: which types a room holds (every type, fixtures and furniture included), and instances of the
types ALFRED moves about (`object_poses` names only pickupable and movable objects, so a room's counters or
chairs are never counted). The shipped file (`data/alfred_rooms.json`) is made by this module's converter::

    python -m luminous_sim.cssg.reference ../shared/alfred/layouts ../shared/alfred/valid_seen TRAIN_DIR

and a test makes it again from `../shared/alfred` and compares.
"""

from __future__ import annotations

import json
import sys
from collections import Counter, defaultdict
from collections.abc import Iterable
from functools import cache
from importlib import resources
from pathlib import Path
from statistics import median
from typing import Any

from luminous_sim.errors import LuminousError
from luminous_sim.fileio import write_atomic
from luminous_sim.rooms import scene_room_type

REFERENCE_FILE = "alfred_rooms.json"
ROOMS_PER_TYPE = 30


def _scene_numbers() -> list[int]:
    return [h * 100 + i for h in (0, 2, 3, 4) for i in range(1, ROOMS_PER_TYPE + 1)]


def alfred_reference(layouts_dir: Path, trajectory_dirs: Iterable[Path] = ()) -> dict[str, Any]:
    """Each ALFRED room's types (`FloorPlan<N>-objects.json` under `layouts_dir`), grouped by room type, and, from
    every `traj_data.json` under `trajectory_dirs`, the median over a room's trajectories of each movable type's
    instance count."""
    rooms: dict[str, dict[str, list[str]]] = defaultdict(dict)
    for n in _scene_numbers():
        path = Path(layouts_dir) / f"FloorPlan{n}-objects.json"
        try:
            types = json.loads(path.read_text())
        except (OSError, ValueError) as e:
            raise LuminousError(f"{path}: cannot read ALFRED's object list ({e})") from e
        if not isinstance(types, list) or not all(isinstance(t, str) for t in types):
            raise LuminousError(f"{path}: expected a JSON list of object type names")
        rooms[scene_room_type(n)][str(n)] = sorted(set(types))
    counts: dict[int, list[Counter]] = defaultdict(list)
    trajectories = 0
    for folder in trajectory_dirs:
        for path in sorted(Path(folder).rglob("traj_data.json")):
            scene = json.loads(path.read_text())["scene"]
            counts[int(scene["scene_num"])].append(
                Counter(p["objectName"].split("_")[0] for p in scene["object_poses"]))
            trajectories += 1
    instances: dict[str, dict[str, dict[str, float]]] = defaultdict(dict)
    for n, per in sorted(counts.items()):
        types = sorted({t for c in per for t in c})
        instances[scene_room_type(n)][str(n)] = {t: float(median(c.get(t, 0) for c in per)) for t in types}
    return {"source": "ALFRED's FloorPlan<N>-objects.json (types present) and traj_data.json scene.object_poses "
                      "(instances of movable types, the median over a room's trajectories)",
            "trajectories": trajectories,
            "room_types": {rt: {"rooms": rooms[rt], "instances": instances.get(rt, {})} for rt in sorted(rooms)}}


@cache
def _shipped() -> dict[str, Any]:
    return json.loads(resources.files("luminous_sim.cssg").joinpath(f"data/{REFERENCE_FILE}").read_text())


def reference_rooms(room_type: str) -> list[frozenset[str]]:
    """The types present in each of AI2-THOR's 30 ALFRED rooms of `room_type` (the shipped reference)."""
    rooms = _shipped()["room_types"][room_type]["rooms"]
    return [frozenset(rooms[k]) for k in sorted(rooms, key=int)]


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if not args:
        print("usage: python -m luminous_sim.cssg.reference LAYOUTS_DIR [TRAJECTORY_DIR ...]", file=sys.stderr)
        return 2
    data = alfred_reference(Path(args[0]), [Path(a) for a in args[1:]])
    out = Path(str(resources.files("luminous_sim.cssg").joinpath(f"data/{REFERENCE_FILE}")))
    write_atomic(out, json.dumps(data, indent=1, sort_keys=True) + "\n")
    print(f"wrote {out}: {data['trajectories']} trajectories")
    return 0


if __name__ == "__main__":
    sys.exit(main())
