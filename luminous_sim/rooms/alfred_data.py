"""ALFRED's scenes: numbering, room types, seen/unseen splits, and reading the layout files.

Files per scene N in a layouts folder (ALFRED's `gen/layouts`): `FloorPlan<N>-layout.npy` (the
(x, z) points, on a 0.25 m grid, where the agent can stand), `FloorPlan<N>-objects.json` (object
types present) and `FloorPlan<N>-openable.json` (receptacle objectIds `Type|x|y|z[|Part]` mapped to
an interaction pose). Positions come out in our frame: THOR (x, z) -> (x, y).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from luminous_sim.errors import RoomError

CELL = 0.25

ALFRED_SPLITS: dict[str, tuple[int, ...]] = {
    "valid_unseen": (10, 219, 308, 424),
    "tests_unseen": (9, 29, 215, 226, 315, 325, 404, 425),
}
"""ALFRED's unseen scenes (spec/alfred.md section 3.2); every other scene is seen (train)."""

ROOM_TYPE_BY_HUNDRED = {0: "Kitchen", 2: "LivingRoom", 3: "Bedroom", 4: "Bathroom"}


def scene_numbers() -> list[int]:
    """ALFRED's 120 scene numbers: 1-30, 201-230, 301-330, 401-430."""
    return [h * 100 + i for h in (0, 2, 3, 4) for i in range(1, 31)]


def scene_room_type(scene: int) -> str:
    """Room type of a scene: 1-30 Kitchen, 201-230 LivingRoom, 301-330 Bedroom, 401-430 Bathroom."""
    hundred, rest = divmod(scene, 100)
    if hundred not in ROOM_TYPE_BY_HUNDRED or not 1 <= rest <= 30:
        raise RoomError(
            f"FloorPlan{scene} is not an ALFRED scene (expected 1-30, 201-230, 301-330 or 401-430)"
        )
    return ROOM_TYPE_BY_HUNDRED[hundred]


def scene_split(scene: int) -> str:
    """ALFRED split of a scene's room structure: `valid_unseen`, `tests_unseen` or `seen`."""
    scene_room_type(scene)
    for split, scenes in ALFRED_SPLITS.items():
        if scene in scenes:
            return split
    return "seen"


def splits_document() -> dict[str, object]:
    """The content of `splits.json`: scene names per split, and each scene's split."""
    names = {f"FloorPlan{n}": scene_split(n) for n in scene_numbers()}
    return {
        "source": "ALFRED json_2.1.0 scene sets (spec/alfred.md section 3.2); seen = train scenes",
        "splits": {
            split: [f"FloorPlan{n}" for n in scene_numbers() if scene_split(n) == split]
            for split in ("seen", "valid_unseen", "tests_unseen")
        },
        "scene_split": names,
    }


@dataclass(frozen=True)
class AlfredLayout:
    """One scene's ALFRED layout data, in our frame (THOR x -> x, THOR z -> y)."""

    scene: int
    points: np.ndarray
    objects: tuple[str, ...]
    receptacles: tuple[tuple[str, float, float, float], ...]  # (type, x, y, height)

    def positions(self, object_type: str) -> list[tuple[float, float]]:
        """Floor positions of the receptacles of a type, in file order."""
        return [(x, y) for t, x, y, _ in self.receptacles if t == object_type]


def read_layout(layouts_dir: str | Path, scene: int) -> AlfredLayout:
    """Read `FloorPlan<scene>-layout.npy`, `-objects.json` and (if present) `-openable.json`."""
    base = Path(layouts_dir)
    npy = base / f"FloorPlan{scene}-layout.npy"
    if not npy.is_file():
        raise RoomError(f"{npy}: no such layout file")
    try:
        pts = np.asarray(np.load(npy), dtype=float).reshape(-1, 2)
    except (OSError, ValueError) as exc:
        raise RoomError(f"{npy}: not a (N, 2) numpy array ({exc})") from None
    if len(pts) == 0:
        raise RoomError(f"{npy}: no reachable points")
    objects: tuple[str, ...] = ()
    obj_file = base / f"FloorPlan{scene}-objects.json"
    if obj_file.is_file():
        objects = tuple(sorted(set(_read_json(obj_file))))
    recs = []
    open_file = base / f"FloorPlan{scene}-openable.json"
    if open_file.is_file():
        for key in sorted(_read_json(open_file)):
            parts = key.split("|")
            try:
                recs.append((parts[0], float(parts[1]), float(parts[3]), float(parts[2])))
            except (IndexError, ValueError):
                raise RoomError(f"{open_file}: objectId {key!r} is not Type|x|y|z") from None
    pts = np.round(pts / CELL) * CELL
    pts = np.unique(pts, axis=0)
    return AlfredLayout(scene, pts, objects, tuple(recs))


def _read_json(path: Path):
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, json.JSONDecodeError) as exc:
        raise RoomError(f"{path}: cannot read JSON ({exc})") from None
