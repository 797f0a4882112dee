"""Training data for the learned layout model, without torch: rooms as rasters, furniture as binned boxes.

A room is seen in its own frame: centred on its outline's bounding box and scaled by half its longer side
(`RoomFrame`), so that every coordinate lies in [-1, 1]. The room is a `RASTER` x `RASTER` image with three
channels (floor, door clearances, the room's own fixtures: counters, sink, stove, fridge, toilet, bath),
its type and its size in metres; `occupancy` adds a fourth, the furniture placed so far. Its furniture
(free-standing pieces of CSSG's furniture layer) is a set of boxes: category, width, depth, height
(log-spaced bins), centre x and y (uniform bins, SUB a side in each image cell) and yaw (uniform bins over
a turn).

`cssg_layouts` draws the training layouts: CSSG scenes (`cssg.generate` with an empty CDF of the room
type) in procedural shells and in the rooms converted from AI2-THOR's FloorPlans. The converted rooms hold
the walls, doors, windows and fixture plan of each FloorPlan, not its furniture (ALFRED's layout files
give only where the agent can stand), so the furniture learned in them is CSSG's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely import affinity
from shapely.geometry import Polygon

from luminous_sim.layouts.model import Layout, LayoutObject
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.vocab import ROOM_TYPES

RASTER = 32
"""cells a side of the room's image."""
POS_BINS = 128
"""bins a side for centres: each image cell holds SUB x SUB of them."""
SUB = POS_BINS // RASTER
SIZE_BINS = 32
YAW_BINS = 16
SIZE_RANGE = (0.05, 4.0)
"""metres: the smallest and largest box side the size bins cover (log-spaced)."""
PROCEDURAL_SEED0 = 100_000
"""Procedural training shells use seeds from here, so that they are not the rooms of seeds 0, 1, ...
that benchmarks and examples generate."""


@dataclass(frozen=True)
class RoomFrame:
    """The room's own frame: its bounding-box centre and half its longer side (metres)."""

    cx: float
    cy: float
    half: float

    @classmethod
    def of(cls, outline: tuple[tuple[float, float], ...]) -> RoomFrame:
        xs, ys = [p[0] for p in outline], [p[1] for p in outline]
        return cls((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, max(max(xs) - min(xs), max(ys) - min(ys)) / 2)

    def to_unit(self, x: float, y: float) -> tuple[float, float]:
        return (x - self.cx) / self.half, (y - self.cy) / self.half

    def to_world(self, u: float, v: float) -> tuple[float, float]:
        return self.cx + u * self.half, self.cy + v * self.half


def _bin(value: float, lo: float, hi: float, n: int) -> int:
    return int(min(n - 1, max(0, math.floor((value - lo) / (hi - lo) * n))))


def _centre(k: int, lo: float, hi: float, n: int) -> float:
    return lo + (k + 0.5) * (hi - lo) / n


def pos_bin(u: float) -> int:
    return _bin(u, -1.0, 1.0, POS_BINS)


def pos_value(k: int) -> float:
    return _centre(k, -1.0, 1.0, POS_BINS)


def size_bin(metres: float) -> int:
    return _bin(math.log(metres), math.log(SIZE_RANGE[0]), math.log(SIZE_RANGE[1]), SIZE_BINS)


def size_value(k: int) -> float:
    return math.exp(_centre(k, math.log(SIZE_RANGE[0]), math.log(SIZE_RANGE[1]), SIZE_BINS))


def yaw_bin(yaw: float) -> int:
    return round(yaw % (2 * math.pi) / (2 * math.pi) * YAW_BINS) % YAW_BINS


def yaw_value(k: int) -> float:
    return k * 2 * math.pi / YAW_BINS


def box_polygon(o: LayoutObject) -> Polygon:
    """The footprint of an object's box."""
    w, d = o.size[0] / 2, o.size[1] / 2
    rect = Polygon([(-w, -d), (w, -d), (w, d), (-w, d)])
    turned = affinity.rotate(rect, o.yaw, origin=(0, 0), use_radians=True)
    return affinity.translate(turned, o.position[0], o.position[1])


def is_fixture(o: LayoutObject) -> bool:
    """One of the room's own fixtures (given with the room, not generated)."""
    return o.parent is None and o.layer == "fixture"


def is_furniture(o: LayoutObject) -> bool:
    """A free-standing piece of furniture: what the model generates."""
    return o.parent is None and o.layer == "furniture"


def cell_centres() -> tuple[np.ndarray, np.ndarray]:
    """The unit-frame (u, v) of each raster cell's centre, as two RASTER x RASTER arrays (row = v)."""
    c = (np.arange(RASTER) + 0.5) / RASTER * 2 - 1
    return np.meshgrid(c, c)


@dataclass(frozen=True)
class Example:
    """One room and its furniture: `objects` rows are (category, w, d, h, x, y, yaw) bin indices."""

    room_type: int
    raster: np.ndarray
    extent: np.ndarray
    objects: np.ndarray


def occupancy(rows: np.ndarray, half: float) -> np.ndarray:
    """(RASTER, RASTER) float32: 1 where a cell centre lies in the footprint of one of the boxes of `rows`
    (bin rows as `Example.objects`) in a room of half side `half` metres."""
    u, v = cell_centres()
    out = np.zeros((RASTER, RASTER), dtype=np.float32)
    for row in rows:
        w, d = size_value(int(row[1])) / half / 2, size_value(int(row[2])) / half / 2
        du, dv = u - pos_value(int(row[4])), v - pos_value(int(row[5]))
        c, s = math.cos(yaw_value(int(row[6]))), math.sin(yaw_value(int(row[6])))
        inside = (np.abs(c * du + s * dv) <= w) & (np.abs(-s * du + c * dv) <= d)
        out[inside] = 1.0
    return out


def furniture_rows(objects: list[LayoutObject], frame: RoomFrame, vocab: list[str], turn: int = 0,
                   mirror: bool = False) -> np.ndarray:
    """Bin rows of the furniture, in the frame turned by `turn` quarter turns (after mirroring x)."""
    rows = []
    for o in objects:
        u, v = frame.to_unit(o.position[0], o.position[1])
        yaw = o.yaw
        if mirror:
            u, yaw = -u, -yaw
        for _ in range(turn):
            u, v, yaw = -v, u, yaw + math.pi / 2
        w, d = o.size[0], o.size[1]
        rows.append((vocab.index(o.category), size_bin(w), size_bin(d), size_bin(o.size[2]), pos_bin(u), pos_bin(v),
                     yaw_bin(yaw)))
    return np.array(rows, dtype=np.int64).reshape(-1, 7)


def _transformed(g: Polygon, frame: RoomFrame, turn: int, mirror: bool) -> Polygon:
    g = affinity.translate(g, -frame.cx, -frame.cy)
    if mirror:
        g = affinity.scale(g, -1, 1, origin=(0, 0))
    return affinity.translate(affinity.rotate(g, 90 * turn, origin=(0, 0)), frame.cx, frame.cy)


def room_view(shell: RoomShell, fixtures: list[Polygon], frame: RoomFrame, turn: int = 0,
              mirror: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The room as the model sees it, turned by `turn` quarter turns (after mirroring x): a (3, RASTER, RASTER)
    float32 image of floor, door clearances and fixtures, and its extent features (width and depth over
    8 m, half side over 4 m: the scale the unit frame hides)."""
    floor = _transformed(shell.polygon(), frame, turn, mirror)
    layers = ([floor], [_transformed(z, frame, turn, mirror) for z in shell.door_clearance_zones()],
              [_transformed(z, frame, turn, mirror) for z in fixtures])
    u, v = cell_centres()
    x, y = frame.cx + u * frame.half, frame.cy + v * frame.half
    img = np.zeros((3, RASTER, RASTER), dtype=np.float32)
    for ch, geoms in enumerate(layers):
        for g in geoms:
            img[ch] = np.maximum(img[ch], shapely.contains_xy(g, x, y))
    minx, miny, maxx, maxy = floor.bounds
    return img, np.array([(maxx - minx) / 8, (maxy - miny) / 8, frame.half / 4], dtype=np.float32)


def examples_of(layout: Layout, shell: RoomShell, vocab: list[str], augment: bool = True) -> list[Example]:
    """The training examples of one layout: as it is and, with `augment`, turned by quarter turns and mirrored
    (eight views of the same room, as ATISS augments its rooms)."""
    frame = RoomFrame.of(shell.outline)
    fixtures = [box_polygon(o) for o in layout.objects if is_fixture(o)]
    furniture = [o for o in layout.objects if is_furniture(o) and o.category in vocab]
    views = [(t, m) for m in (False, True) for t in range(4)] if augment else [(0, False)]
    out = []
    for turn, mirror in views:
        img, ext = room_view(shell, fixtures, frame, turn, mirror)
        out.append(Example(ROOM_TYPES.index(shell.room_type), img, ext,
                           furniture_rows(furniture, frame, vocab, turn, mirror)))
    return out


def training_shells(room_type: str, count: int) -> list[RoomShell]:
    """`count` rooms of a type: procedural shells (seeds from PROCEDURAL_SEED0) and AI2-THOR's converted
    FloorPlans (ALFRED's seen scenes only, so that its unseen ones stay unseen), alternately."""
    from luminous_sim.rooms import generate_shell
    from luminous_sim.rooms.alfred_data import ALFRED_SPLITS
    from luminous_sim.rooms.library import load_room, room_names

    unseen = {f"FloorPlan{n}" for ns in ALFRED_SPLITS.values() for n in ns}
    thor = [n for n in room_names(include_procedural=False) if n.startswith("FloorPlan") and n not in unseen]
    thor_rooms = [r for r in (load_room(n) for n in thor) if r.room_type == room_type]
    out = []
    for i in range(count):
        if i % 2 and thor_rooms:
            out.append(thor_rooms[(i // 2) % len(thor_rooms)])
        else:
            out.append(generate_shell(room_type, np.random.default_rng(PROCEDURAL_SEED0 + i)))
    return out


def cssg_layouts(per_type: int, catalog=None) -> list[tuple[Layout, RoomShell]]:
    """CSSG's layouts (empty CDF of each room type, seed i in room i) in `training_shells`; a room where
    CSSG finds no valid layout is skipped."""
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg import empty_cdf, generate
    from luminous_sim.errors import InfeasibleSceneError
    from luminous_sim.layouts.convert import layout_of_scene

    catalog = catalog or default_catalog()
    out = []
    for room_type in ROOM_TYPES:
        doc = empty_cdf(room_type)
        for i, shell in enumerate(training_shells(room_type, per_type)):
            try:
                scene = generate(doc, seed=i, room=shell, catalog=catalog).scene
            except InfeasibleSceneError:
                continue
            out.append((layout_of_scene(scene, catalog), shell))
    return out
