"""Room shells from ALFRED's AI2-THOR floor layouts (`FloorPlan<N>-layout.npy` and friends).

ALFRED gives, per scene, the 0.25 m grid points the agent can stand on (furniture excluded), the
object types present, and (in `-openable.json`) receptacle objectIds, which encode positions as
`Type|x|y|z`. The walls themselves are not given, so the converter estimates them:

1. Outline. Each reachable point becomes a 0.25 m cell; the cells are grown by `REACH_MARGIN`
   (0.425 m, so a wall lies 0.55 m beyond the outermost reachable point: furniture along walls
   removed reachable space) and joined with a `OBJECT_HALF` square (0.25 m) around each
   receptacle (cabinets, fridge, sink, bed... stand against walls). Parts are bridged, gaps narrower
   than 1 m closed, holes (furniture islands) filled, vertices snapped to 5 cm, and steps and
   notches removed greedily (each removal changing at most 1 square metre or 3% of the area) while
   every reachable point keeps 0.25 m from the walls, so `grid_points()` recovers it.
2. Fixtures (`alfred_fixtures`, built by `fixture_plan`): kitchens get counter runs, sink, stove
   and fridge; bathrooms a toilet, sink and bathtub (or shower stall), where ALFRED's objects are.
3. One door where the reachable area comes closest to a wall (no furniture there), free of
   fixtures; a window on the longest other wall when the scene lists a Window.

AI2-THOR (x, z) becomes our (x, y); the grid stays aligned, so the agent's positions carry over.
Conversion is deterministic; `convert_all` writes one JSON file per scene plus `splits.json`.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterable, Sequence
from pathlib import Path

import numpy as np
import shapely
from shapely.geometry import Polygon

from luminous_sim.errors import RoomError
from luminous_sim.rooms.alfred_data import (
    ALFRED_SPLITS,
    CELL,
    AlfredLayout,
    read_layout,
    scene_numbers,
    scene_room_type,
    scene_split,
    splits_document,
)
from luminous_sim.rooms.alfred_fixtures import plan_from_layout
from luminous_sim.rooms.fixtures import plan_fixtures
from luminous_sim.rooms.geometry import (
    canonical_ring,
    merge_intervals,
    r4,
    rect_polygon,
    snap_down,
    snap_up,
)
from luminous_sim.rooms.placement import STEP, free_offsets
from luminous_sim.rooms.rectilinear import rectilinear_outline
from luminous_sim.rooms.shell import (
    Door,
    RoomShell,
    Wall,
    Window,
    make_shell,
    save_shell,
    walls_from_outline,
)

__all__ = [
    "ALFRED_SPLITS",
    "AlfredLayout",
    "convert_all",
    "convert_layout",
    "convert_scene",
    "floor_outline",
    "read_layout",
    "scene_numbers",
    "scene_room_type",
    "scene_split",
    "splits_document",
]

REACH_MARGIN = 0.425
REQUIRED_HALF = 0.25
OBJECT_HALF = 0.25
OBJECT_REQUIRED_HALF = 0.15
CLOSE_RADIUS = 0.5
MAX_SLIDE_AREA = 1.0
MAX_SLIDE_FRACTION = 0.03
GRID = 0.05
WALL_HEIGHT = 2.6
WALL_THICKNESS = 0.12
DOOR_WIDTH = 0.9
DOOR_HEIGHT = 2.05
DOOR_CLEARANCE = 1.0
DOOR_END_MARGIN = 0.2
WINDOW_WIDTH = 1.2
WINDOW_SILL = 0.9
WINDOW_SILL_OVER_COUNTER = 1.05
WINDOW_HEIGHT = 1.2


def _squares(points: Iterable[tuple[float, float]], half: float, outward: bool = False):
    boxes = []
    for x, y in points:
        if outward:
            boxes.append(
                rect_polygon(
                    snap_down(x - half, GRID),
                    snap_down(y - half, GRID),
                    snap_up(x + half, GRID),
                    snap_up(y + half, GRID),
                )
            )
        else:
            boxes.append(rect_polygon(x - half, y - half, x + half, y + half))
    return shapely.union_all(boxes) if boxes else Polygon()


def floor_outline(layout: AlfredLayout) -> Polygon:
    """The estimated floor outline (step 1 of the module docstring)."""
    obj_xy = [(x, y) for _, x, y, _ in layout.receptacles]
    cells = _squares(map(tuple, layout.points), CELL / 2)
    preferred = shapely.union_all(
        [cells.buffer(REACH_MARGIN, join_style="mitre"), _squares(obj_xy, OBJECT_HALF, True)]
    )
    required = shapely.union_all(
        [
            _squares(map(tuple, layout.points), REQUIRED_HALF),
            _squares(obj_xy, OBJECT_REQUIRED_HALF, True),
        ]
    )
    return rectilinear_outline(
        required, preferred, GRID, CLOSE_RADIUS, MAX_SLIDE_AREA, MAX_SLIDE_FRACTION
    )


# ---------------------------------------------------------------------------------- openings


def _door(
    walls: Sequence[Wall], floor: Polygon, feet: Sequence[Polygon], points: np.ndarray
) -> Door | None:
    best, best_key = None, None
    for wi, wall in enumerate(walls):
        offs = free_offsets(
            wall, DOOR_WIDTH, DOOR_CLEARANCE, floor, feet, end_margin=DOOR_END_MARGIN
        )
        if not len(offs):
            continue
        uv = wall.local(points)
        for u in offs:
            inside = (
                (uv[:, 0] > u)
                & (uv[:, 0] < u + DOOR_WIDTH)
                & (uv[:, 1] > 0)
                & (uv[:, 1] < DOOR_CLEARANCE)
            )
            key = (
                -int(inside.sum()),
                -round(wall.length, 4),
                round(abs(u + DOOR_WIDTH / 2 - wall.length / 2), 4),
                wi,
            )
            if best_key is None or key < best_key:
                best, best_key = (wall, float(u)), key
    if best is None:
        return None
    return Door(
        id="Door_0",
        wall=best[0].id,
        offset=r4(best[1]),
        width=DOOR_WIDTH,
        height=DOOR_HEIGHT,
        swing_clearance=DOOR_CLEARANCE,
        hinge="start",
    )


def _window(shell: RoomShell) -> Window | None:
    feet = shell.fixture_footprints()
    heights = {c.id: c.height for c in shell.fixtures.counters}
    heights.update({s.id: s.height for s in shell.fixtures.slots})
    door_walls = {d.wall for d in shell.doors}
    best, best_key = None, None
    for wi, wall in enumerate(shell.walls):
        width = min(WINDOW_WIDTH, snap_down(wall.length - 2 * 0.3, STEP))
        if width < 0.6:
            continue
        band = wall.rect(0.0, wall.length, 0.0, 0.05)
        low = [
            (fid, poly)
            for fid, poly in feet.items()
            if band.intersects(poly) and band.intersection(poly).area > 1e-6
        ]
        sill = WINDOW_SILL_OVER_COUNTER if low else WINDOW_SILL
        blocked = [d.span for d in shell.doors if d.wall == wall.id]
        for fid, poly in low:
            if heights[fid] > sill - 0.05:
                uv = wall.local(np.asarray(band.intersection(poly).exterior.coords))
                blocked.append((uv[:, 0].min(), uv[:, 0].max()))
        blocked = merge_intervals((a - 0.3, b + 0.3) for a, b in blocked)
        lo, hi = 0.3, wall.length - 0.3 - width
        for u in np.round(
            np.arange(math.ceil(lo / STEP - 1e-9), math.floor(hi / STEP + 1e-9) + 1) * STEP, 4
        ):
            if any(u < b - 1e-6 and u + width > a + 1e-6 for a, b in blocked):
                continue
            key = (
                wall.id in door_walls,
                -round(wall.length, 4),
                round(abs(u + width / 2 - wall.length / 2), 4),
                wi,
            )
            if best_key is None or key < best_key:
                best, best_key = (
                    Window(
                        id="Window_0",
                        wall=wall.id,
                        offset=float(u),
                        width=width,
                        sill_height=sill,
                        height=min(WINDOW_HEIGHT, r4(WALL_HEIGHT - 0.2 - sill)),
                    ),
                    key,
                )
    return best


# ------------------------------------------------------------------------------ entry points


def convert_layout(layout: AlfredLayout) -> RoomShell:
    """Convert one scene's ALFRED layout to a RoomShell named `FloorPlan<N>`.

    Raises:
        RoomError: the layout cannot be made into a valid shell.
    """
    room_type = scene_room_type(layout.scene)
    name = f"FloorPlan{layout.scene}"
    ring = canonical_ring(floor_outline(layout).exterior.coords)
    walls = walls_from_outline(ring)
    floor = Polygon(ring)
    rng = np.random.default_rng(layout.scene)
    plan = plan_from_layout(room_type, layout, walls, floor) or plan_fixtures(
        room_type, walls, floor, rng
    )
    if plan is None:
        raise RoomError(f"{name}: no {room_type.lower()} fixture plan fits the converted outline")
    n = len(ring)
    shape = "rect" if n == 4 else "L" if n == 6 else "rectilinear"
    base = make_shell(
        name=name,
        room_type=room_type,
        shape=shape,
        source=f"alfred:{name}",
        outline=ring,
        wall_height=WALL_HEIGHT,
        wall_thickness=WALL_THICKNESS,
        fixtures=plan,
    )
    feet = list(base.fixture_footprints().values())
    door = _door(walls, floor, feet, layout.points)
    if door is None:
        raise RoomError(f"{name}: no wall has room for a door clear of the fixtures")
    shell = base.model_copy(update={"doors": (door,)})
    if "Window" in layout.objects:
        window = _window(shell)
        if window is not None:
            shell = shell.model_copy(update={"windows": (window,)})
    return RoomShell.from_dict(shell.model_dump(), where=name)


def convert_scene(layouts_dir: str | Path, scene: int) -> RoomShell:
    """Read and convert one ALFRED scene."""
    return convert_layout(read_layout(layouts_dir, scene))


def convert_all(
    layouts_dir: str | Path,
    out_dir: str | Path,
    scenes: Sequence[int] | None = None,
    progress: Callable[[int], None] | None = None,
) -> list[Path]:
    """Convert ALFRED scenes and write `FloorPlan<N>.json` files and `splits.json` into `out_dir`.

    Args:
        layouts_dir: folder with `FloorPlan<N>-layout.npy` (and `-objects.json`, `-openable.json`).
        out_dir: output folder (created).
        scenes: scene numbers; default all 120 that have a layout file in `layouts_dir`.
        progress: called with each scene number once it is written.

    Returns:
        The room files written, in scene order.

    Raises:
        RoomError: a missing folder, unreadable file, or a scene that cannot be converted.
    """
    src = Path(layouts_dir)
    if not src.is_dir():
        raise RoomError(f"{src}: no such layouts folder")
    if scenes is None:
        scenes = [n for n in scene_numbers() if (src / f"FloorPlan{n}-layout.npy").is_file()]
        if not scenes:
            raise RoomError(f"{src}: no FloorPlan<N>-layout.npy files")
    out = Path(out_dir)
    written = []
    for n in scenes:
        written.append(save_shell(convert_scene(src, n), out / f"FloorPlan{n}.json"))
        if progress is not None:
            progress(n)
    out.mkdir(parents=True, exist_ok=True)
    (out / "splits.json").write_text(
        json.dumps(splits_document(), sort_keys=True, indent=1) + "\n", encoding="utf-8"
    )
    return written
