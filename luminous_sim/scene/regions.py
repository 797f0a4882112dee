"""Putting small objects on support surfaces and into interior volumes of placed receptacles."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise

import numpy as np
import shapely
from shapely import affinity
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.scene.model import SceneObject
from luminous_sim.scene.pose import rotate
from luminous_sim.scene.sight import shades

EDGE_INSET = 0.04


@dataclass(frozen=True)
class RegionSpot:
    """A receptacle region in world terms: centre, size, base height, yaw (of its host)."""

    host: SceneObject
    name: str
    kind: str
    center: tuple[float, float]
    size: tuple[float, float]
    floor_z: float
    clearance: float
    yaw: float
    gated: bool = False
    """Behind a door (fridge shelf, microwave, cabinet): things go in its front half, where they can be seen."""


def region_spots(host: SceneObject, entry: AssetEntry) -> list[RegionSpot]:
    """Every region of a placed receptacle, with joints at zero (closed), in world coordinates."""
    spots = []
    for r in entry.regions:
        c = np.array(r["center"]) + np.array(entry.link_origins[r["link"]])
        sx, sy, sz = r["size"]
        xy = rotate(c[:2][None], host.yaw)[0] + host.position[:2]
        if r["kind"] == "surface":
            floor_z, clearance = host.position[2] + c[2], sz
        else:
            floor_z, clearance = host.position[2] + c[2] - sz / 2, sz
        spots.append(RegionSpot(host, r["name"], r["kind"], (float(xy[0]), float(xy[1])), (sx, sy),
                                float(floor_z), float(clearance), host.yaw, gated=bool(r.get("requires_open"))))
    return spots


def fits(entry: AssetEntry, spot: RegionSpot) -> bool:
    """Whether the object could stand in the region at all (size and height)."""
    w, d, h = entry.dims
    return h <= spot.clearance + 1e-6 and min(w, d) <= min(spot.size) and max(w, d) <= max(spot.size)


def open_tops(entry: AssetEntry) -> set[str]:
    """Names of the vessel regions open at the top (a pan, bowl, pot, basin or garbage can: a volume with
    no door and nothing over it): what goes in may stand out over the rim, as an apple does from a pan in
    AI2-THOR, so their height does not limit what they take."""
    roofs = shades(entry)
    return {r["name"] for r in entry.regions if r["kind"] == "volume" and not r.get("requires_open")
            and roofs[r["name"]].roof is None}


PACK_GAP = 0.01
"""Metres a put slid against a region's edge keeps off it."""


def edge_slides(got: tuple, spot) -> list[tuple]:
    """`got` (x, y, z, yaw, footprint) moved within the region to its nearest corner, then to the nearest edge
    across the footprint's short side, then along its long side: candidates that leave the most room beside."""
    x, y, z, yaw, fp = got
    c, s_ = math.cos(spot.yaw), math.sin(spot.yaw)
    pts = np.array(fp.exterior.coords) - np.array(spot.center)
    local = np.column_stack([pts[:, 0] * c + pts[:, 1] * s_, -pts[:, 0] * s_ + pts[:, 1] * c])
    lo, hi = local.min(axis=0), local.max(axis=0)
    half = np.array(spot.size) / 2 - PACK_GAP
    # per local axis, the shift to the nearer edge (0 where the footprint fills the region)
    shift = [(half[k] - hi[k]) if abs(half[k] - hi[k]) <= abs(lo[k] + half[k]) else -(lo[k] + half[k])
             for k in (0, 1)]
    short = int(np.argmin(hi - lo))
    moves = [(shift[0], shift[1]), (shift[0], 0.0) if short == 0 else (0.0, shift[1]),
             (0.0, shift[1]) if short == 0 else (shift[0], 0.0)]
    out = []
    for du, dv in moves:
        if abs(du) < 1e-4 and abs(dv) < 1e-4:
            continue
        dx, dy = du * c - dv * s_, du * s_ + dv * c
        out.append((x + dx, y + dy, z, yaw, affinity.translate(fp, dx, dy)))
    return out


def can_hold(host: AssetEntry, thing: AssetEntry, count: int = 1) -> bool:
    """Whether `count` of `thing` fit upright side by side in one region of `host` (a row along either
    side, each turned either way): as tall as the region's clearance at most, unless it is open at the
    top. A static test of sizes: what else stands there is not counted."""
    w, d, h = thing.dims
    tops = open_tops(host) if any(r["kind"] == "volume" for r in host.regions) else set()
    for r in host.regions:
        sx, sy, sz = r["size"]
        if h > sz + 1e-6 and r["name"] not in tops:
            continue
        if any(count * a <= long + 1e-6 and b <= short + 1e-6
               for a, b in ((w, d), (d, w)) for long, short in ((sx, sy), (sy, sx))):
            return True
    return False


def sample_in_region(
    entry: AssetEntry, spot: RegionSpot, rng: np.random.Generator, occupied: list[Polygon], tries: int = 20,
    yaw_choices: int = 4, facing: tuple[float, float] | None = None,
    accept: Callable[[np.ndarray], bool] | None = None, max_fill: float = 1.0,
) -> tuple[float, float, float, float, Polygon] | None:
    """A free pose (x, y, z, yaw) for `entry` inside `spot`, avoiding `occupied` footprints (world xy).

    With `facing` (a world point), the object is turned (in quarter turns) to face it; with `accept`, a
    pose is kept only if the centre of its footprint (world xy) passes (the agent can see it there). A
    region whose footprints would cover more than `max_fill` of it is given up at once: random draws
    seldom pack tighter, and twenty failed draws cost more than the answer is worth.
    """
    lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
    if max_fill < 1.0 and (sum(o.area for o in occupied) + float(np.prod(hi - lo))
                           > max_fill * spot.size[0] * spot.size[1]):
        return None
    center_local = (lo + hi) / 2
    half = (hi - lo) / 2
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    taken = _Taken(occupied)
    fixed_k = None
    if facing is not None:
        d = np.array(facing) - np.array(spot.center)
        want = math.atan2(-d[0], d[1]) - spot.yaw
        fixed_k = round(want / (math.pi / 2)) % 4
    turned: dict[int, tuple[np.ndarray, np.ndarray]] = {}  # per quarter turn: centre and corners, rotated
    for _ in range(tries):
        k = fixed_k if fixed_k is not None else int(rng.integers(yaw_choices))
        rel_yaw = k * 2 * math.pi / yaw_choices
        ex, ey = (half if k % 2 == 0 else half[::-1]) if yaw_choices == 4 else (np.max(half),) * 2
        room_x, room_y = spot.size[0] / 2 - ex, spot.size[1] / 2 - ey
        if room_x < 0 or room_y < 0:
            continue
        # stay a few centimetres off the edges where the region allows it (cushions and rims are rounded)
        room_x -= min(EDGE_INSET, room_x / 2)
        room_y -= min(EDGE_INSET, room_y / 2)
        px = rng.uniform(-room_x, room_x)
        py = rng.uniform(0.0 if spot.gated else -room_y, room_y)  # gated volumes: the front half
        target = rotate(np.array([[px, py]]), spot.yaw)[0] + spot.center
        yaw = spot.yaw + rel_yaw
        if k not in turned:
            turned[k] = rotate(center_local[None], yaw)[0], rotate(corners, yaw)
        origin = target - turned[k][0]
        ring = turned[k][1] + origin
        if taken.hits(ring) or (accept is not None and not accept(target)):
            continue
        return float(origin[0]), float(origin[1]), spot.floor_z - entry.bbox_min[2] + 0.002, yaw, Polygon(ring)
    return None


SCAN_STEP = 0.02
"""Spacing (m) of the systematic scan that follows random draws that found no free pose."""
MAX_SCAN = 800
"""Lattice points a scan may visit per quarter turn (the spacing grows on large regions)."""


def scan_region(entry: AssetEntry, spot: RegionSpot, occupied: list[Polygon], step: float = SCAN_STEP,
                accept: Callable[[np.ndarray], bool] | None = None):
    """Every free pose (x, y, z, yaw, footprint) for `entry` in `spot` on a `step` lattice and the four
    quarter turns, nearest the region's centre first: random draws miss the one gap left on a crowded
    side table, a scan does not (to within `step`). `accept` as in `sample_in_region`."""
    lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
    half = (hi - lo) / 2
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    taken = _Taken(occupied)
    step = max(step, math.sqrt(4 * spot.size[0] * spot.size[1] / MAX_SCAN))  # a long counter: coarser
    cands = []
    for k in range(4):
        ex, ey = half if k % 2 == 0 else half[::-1]
        room_x, room_y = spot.size[0] / 2 - ex, spot.size[1] / 2 - ey
        if room_x < 0 or room_y < 0:
            continue
        # the lattice, and flush against each edge (the one gap left beside a pan pushed to the other side)
        us = np.union1d(np.arange(-math.floor(room_x / step), math.floor(room_x / step) + 1) * step, [-room_x, room_x])
        vs = np.union1d(np.arange(-math.floor(room_y / step), math.floor(room_y / step) + 1) * step, [-room_y, room_y])
        for u in us:
            for v in vs:
                cands.append((u * u + v * v, k, float(u), float(v)))
    cands.sort()
    for _, k, u, v in cands:
        yaw = spot.yaw + k * math.pi / 2
        target = rotate(np.array([[u, v]]), spot.yaw)[0] + spot.center
        origin = target - rotate(((lo + hi) / 2)[None], yaw)[0]
        ring = rotate(corners, yaw) + origin
        if taken.hits(ring) or (accept is not None and not accept(target)):
            continue
        yield float(origin[0]), float(origin[1]), spot.floor_z - entry.bbox_min[2] + 0.002, yaw, Polygon(ring)


SQUARE_TOL = 1e-6
"""Metres an edge may be off axis-parallel and still count as square to the axes (walls snapped to 0.1 mm
turn things a hair off quarter turns)."""


class _Taken:
    """Footprints already in a region, for fast intersection tests: bounding boxes first, and the exact
    test only where boxes overlap and one of the two is not square to the axes."""

    def __init__(self, occupied: list[Polygon]):
        self.items = [(*o.bounds, _square(list(o.exterior.coords)), o) for o in occupied]

    def hits(self, ring: np.ndarray) -> bool:
        """Whether the polygon with corners `ring` intersects any of the footprints."""
        pts = ring.tolist()
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        x0, y0, x1, y1 = min(xs), min(ys), max(xs), max(ys)
        square = _square(pts + pts[:1])
        for bx0, by0, bx1, by1, box, geom in self.items:
            if bx0 > x1 or bx1 < x0 or by0 > y1 or by1 < y0:
                continue
            if (square and box) or shapely.intersects(shapely.polygons(ring), geom):
                return True
        return False


def _square(ring: list) -> bool:
    """Whether the closed ring (first point repeated last) is a rectangle square to the axes."""
    return len(ring) == 5 and all(abs(a[0] - b[0]) < SQUARE_TOL or abs(a[1] - b[1]) < SQUARE_TOL
                                  for a, b in pairwise(ring))


"""Receptacles that things hang on (a bar, a ring, a spindle) rather than stand in."""


def hanger_back(host: AssetEntry, region_name: str) -> float:
    """How far (m) behind the centre of a hanger's region its own back (the wall it is fixed to) is: what
    `hang_pose` clears."""
    region = next(r for r in host.regions if r["name"] == region_name)
    return region["center"][1] + host.link_origins[region["link"]][1] - host.bbox_min[1]


def hang_pose(entry: AssetEntry, spot: RegionSpot, host_back: float | None = None) -> tuple[float, float, float,
                                                                                          float, Polygon]:
    """The pose that hangs an object centred on a hanger's region, lengthwise along it.

    `host_back` is how far behind the region centre the hanger's back (the wall) is: the object is
    moved forward until its own back clears it.
    """
    lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
    centre = (lo + hi) / 2
    yaw = spot.yaw
    forward = 0.0
    if host_back is not None:
        forward = max(0.0, (hi[1] - lo[1]) / 2 - host_back + 0.01)
    front = rotate(np.array([[0.0, 1.0]]), yaw)[0]
    origin = np.array(spot.center) + front * forward - rotate(centre[None], yaw)[0]
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
    fp = Polygon(rotate(corners, yaw) + origin)
    return float(origin[0]), float(origin[1]), spot.floor_z - entry.bbox_min[2] + 0.002, yaw, fp
