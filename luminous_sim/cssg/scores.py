"""Relations as score fields: each relation gives a cost in metres for every candidate cell (lower is
better) and, where it has one, a preferred heading per cell. CSSG sums weighted costs and samples
P(p) proportional to exp(-s_p / TEMPERATURE); the heaviest relation with a heading sets the rotation.
A field is (rows, columns), or (heading, rows, columns) where the cost depends on the subject's heading
(`beside`: a piece turned the other way is wider along the anchor's side)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.cssg.grid import HEADINGS, RES, FloorGrid
from luminous_sim.cssg.tables import face_distance
from luminous_sim.scene import minimum_filter_box
from luminous_sim.vocab.agent_body import AGENT_RADIUS

TEMPERATURE = 0.05
"""metres of cost per e-fold of probability."""
NEAR, FAR, AWAY, WALL_CLEAR = 1.2, 2.5, 1.5, 0.6
GAP = 0.02
FACE_BANDS = {"close": (-0.15, 0.35), "group": (0.2, 1.2), "view": (0.8, 3.0)}
"""Distance band (m) from the subject's front edge to the anchor's footprint edge, by the subject's face
distance (`tables.face_distance`: a seat at a table, an armchair in a seating group, across the room)."""
FACE_OVERLAP = 0.25
"""How far (m) within the span of the anchor's side a piece that faces it must stand."""
ACROSS_BAND = (1.2, 3.5)
"""Distance (m) between the fronts of a piece `across_from` its anchor and the anchor (a TV and a sofa)."""
WALKWAY = 2 * AGENT_RADIUS
"""The narrowest gap (m) between two footprints that the agent walks through: its grid points keep
AGENT_RADIUS from every footprint (`scene.reachable_grid`)."""
BESIDE_GAP = 0.05
"""Gap (m) between a piece `beside` its anchor and the anchor's side at which the relation costs nothing."""
GAP_RELATIONS = frozenset({"beside", "near", "far", "away_from"})
"""Relations about distance: a check of one to an object reports the gap between the two footprints."""
TOLERANCE = {"against_wall": 0.12, "in_corner": 0.3, "in_centre": 0.6, "beside": WALKWAY - BESIDE_GAP,
             "near": 0.0, "far": 0.0,
             "away_from": 0.15, "face": 0.15, "in_front_of": 0.4, "behind": 0.4, "left_of": 0.4, "right_of": 0.4,
             "aligned_with": 0.15, "at_head_of": 0.2, "across_from": 0.2}
"""Cost at or below which a relation counts as met (used by the validation report)."""


def holds(relation: str, cost: float, gap: float | None = None) -> bool:
    """Whether a relation counts as met: its cost within TOLERANCE and, for `beside`, its footprint `gap`
    (where known) narrower than WALKWAY, so that the agent cannot walk between the two."""
    if cost > TOLERANCE.get(relation, 0.3) + 1e-6:
        return False
    return relation != "beside" or gap is None or gap < WALKWAY


@dataclass(frozen=True)
class Placed2D:
    """An already placed anchor, seen from above."""

    type: str
    x: float
    y: float
    yaw: float
    entry: AssetEntry

    @property
    def front(self) -> np.ndarray:
        return np.array([-math.sin(self.yaw), math.cos(self.yaw)])

    @property
    def lateral(self) -> np.ndarray:
        return np.array([math.cos(self.yaw), math.sin(self.yaw)])

    def half(self) -> tuple[float, float]:
        """Half width (local x) and half depth (local y) of the footprint."""
        return self.entry.dims[0] / 2, self.entry.dims[1] / 2

    def center(self) -> np.ndarray:
        lo, hi = np.array(self.entry.bbox_min[:2]), np.array(self.entry.bbox_max[:2])
        c = (lo + hi) / 2
        return np.array([self.x, self.y]) + c[0] * self.lateral + c[1] * self.front


def heading_index(dx: np.ndarray, dy: np.ndarray) -> np.ndarray:
    """Index into HEADINGS of the cardinal heading that turns an asset's front towards (dx, dy).

    The nearest of yaw = atan2(-dx, dy) in quarter turns; at exact diagonals the y axis wins.
    """
    dx, dy = np.asarray(dx), np.asarray(dy)
    along_y = np.abs(dy) >= np.abs(dx)
    return np.where(along_y, np.where(dy >= 0, 0, 2), np.where(dx < 0, 1, 3))


def directional_wall_distance(grid: FloorGrid) -> np.ndarray:
    """Distance (m) from each cell centre to the room edge towards -x, +x, -y, +y: shape (4, H, W)."""
    room = grid.room
    out = np.zeros((4,) + room.shape)
    for i, (axis, rev) in enumerate(((1, False), (1, True), (0, False), (0, True))):
        m = np.flip(room, axis) if rev else room
        run = _run_lengths(m, axis)
        out[i] = ((np.flip(run, axis) if rev else run) - 0.5) * RES
    return out


def _run_lengths(mask: np.ndarray, axis: int) -> np.ndarray:
    """Per cell, how many consecutive True cells along `axis` end at it (0 where False)."""
    shape = [1, 1]
    shape[axis] = mask.shape[axis]
    idx = np.arange(1, mask.shape[axis] + 1).reshape(shape)
    last_false = np.maximum.accumulate(np.where(mask, 0, idx), axis=axis)
    return np.where(mask, idx - last_false, 0)


def _half_extents(entry: AssetEntry) -> tuple[float, float]:
    return entry.dims[0] / 2, entry.dims[1] / 2


def _wall_clearance(wall_dist: np.ndarray, ex: float, ey: float) -> np.ndarray:
    """Per cell, how far a box of half extents `ex` (along x) and `ey` (along y) centred there stays from
    the nearest wall: the least wall distance under it (negative where it crosses a wall or leaves the grid)."""
    size = (2 * round(ey / RES) + 1, 2 * round(ex / RES) + 1)
    return minimum_filter_box(wall_dist, size, cval=-RES)


def _wall_clearances(grid: FloorGrid, hw: float, hd: float) -> tuple[np.ndarray, np.ndarray]:
    """`_wall_clearance` of a piece of half width `hw` and half depth `hd` at headings 0/180 (width along
    x) and 90/270 (width along y), computed once per room and size."""
    return (grid.memo(("wall_clearance", hw, hd), lambda: _wall_clearance(grid.wall_dist, hw, hd)),
            grid.memo(("wall_clearance", hd, hw), lambda: _wall_clearance(grid.wall_dist, hd, hw)))


def relation_field(
    relation: str, grid: FloorGrid, subject: AssetEntry, anchor: Placed2D | None, wall_dirs: np.ndarray,
    centroid: tuple[float, float],
) -> tuple[np.ndarray, np.ndarray | None]:
    """(cost per cell, preferred heading index per cell or None) of `subject relation anchor`."""
    gx, gy = grid.coords()
    hw, hd = _half_extents(subject)
    back = -subject.bbox_min[1]
    if relation == "against_wall":
        return np.abs(_behind(grid, wall_dirs) - back - GAP), _wall_heading(grid)
    if relation == "in_corner":
        # back to the nearest wall and a side to the perpendicular one: half extents along world x and y
        # depend on which way the piece faces
        sideways = _wall_heading(grid) % 2 == 0
        along_x = np.where(sideways, hw, hd)
        along_y = np.where(sideways, hd, hw)
        dx, dy = _corner_distances(grid, wall_dirs)
        return np.abs(dx - along_x - GAP) + np.abs(dy - along_y - GAP), _wall_heading(grid)
    if relation == "in_centre":
        return np.hypot(gx - centroid[0], gy - centroid[1]), None
    if anchor is None:  # relations to the room structure ("away_from wall")
        if relation == "away_from":  # the clearance of the piece's own edges, turned the better way
            along_x, along_y = _wall_clearances(grid, hw, hd)
            return (np.maximum(0.0, WALL_CLEAR - np.maximum(along_x, along_y)),
                    np.where(along_x >= along_y, 0, 1).astype(np.int8))
        return np.zeros(grid.shape), None
    ac = anchor.center()
    ahw, ahd = anchor.half()
    if relation in ("near", "far", "away_from"):
        dist = np.hypot(gx - ac[0], gy - ac[1])
        if relation == "near":
            return np.maximum(0.0, dist - (NEAR + max(ahw, ahd) + max(hw, hd))), None
        if relation == "far":
            return np.maximum(0.0, FAR - dist), None
        return np.maximum(0.0, AWAY + max(ahw, ahd) - dist), None
    if relation not in ("beside", "left_of", "right_of", "in_front_of", "behind", "face", "aligned_with",
                        "at_head_of", "across_from"):
        return np.zeros(grid.shape), None  # support and wall-layer relations are not floor fields
    lat, fr = anchor.lateral, anchor.front
    same = np.full(grid.shape, heading_index(np.array(fr[0]), np.array(fr[1])))
    u = (gx - ac[0]) * lat[0] + (gy - ac[1]) * lat[1]
    v = (gx - ac[0]) * fr[0] + (gy - ac[1]) * fr[1]
    if relation == "beside":
        return _beside(grid, subject, anchor), same
    if relation in ("left_of", "right_of"):
        # next to the anchor's side, anywhere along its depth as long as the subject stays within it
        side = ahw + hw + 0.05
        along = {"left_of": -u, "right_of": u}[relation]
        slack = max(ahd - hd, 0.0) + 0.1
        return np.abs(along - side) + np.maximum(0.0, np.abs(v) - slack), same
    if relation == "at_head_of":
        # beside the anchor with the backs flush: a bedside table at the head of a bed
        side = ahw + hw + 0.05
        return np.abs(np.abs(u) - side) + np.abs(v + ahd - hd), same
    if relation == "across_from":
        # in front of the anchor's front, within its width, facing it from viewing distance
        out = v - ahd - hd
        lo, hi = ACROSS_BAND
        cost = np.maximum(0.0, np.abs(u) - max(ahw - hw / 2, 0.05)) + np.maximum(0.0, lo - out) + \
            np.maximum(0.0, out - hi)
        return cost, heading_index(ac[0] - gx, ac[1] - gy)
    if relation in ("in_front_of", "behind"):
        # within the anchor's width, and from touching its front (back) to half a metre away
        out = (v if relation == "in_front_of" else -v) - ahd - hd
        cost = np.maximum(0.0, np.abs(u) - max(ahw - hw / 2, 0.05)) + np.maximum(0.0, -0.15 - out) + \
            np.maximum(0.0, out - 0.5)
        if relation == "in_front_of":
            return cost, heading_index(ac[0] - gx, ac[1] - gy)
        return cost, same
    if relation == "face":
        edge = np.hypot(np.maximum(np.abs(u) - ahw, 0.0), np.maximum(np.abs(v) - ahd, 0.0)) - hd
        lo, hi = FACE_BANDS[face_distance(subject.type)]
        # squarely in front of one of the anchor's sides, not off its corner (facing it, not past it)
        corner = np.maximum(0.0, np.minimum(np.abs(u) - ahw, np.abs(v) - ahd) + FACE_OVERLAP)
        # turned square to the side it stands out from (not towards the centre of a long table)
        off_front = (np.abs(v) - ahd) >= (np.abs(u) - ahw)
        sv, su = -np.sign(v), -np.sign(u)
        dx = np.where(off_front, sv * fr[0], su * lat[0])
        dy = np.where(off_front, sv * fr[1], su * lat[1])
        return np.maximum(0.0, lo - edge) + np.maximum(0.0, edge - hi) + corner, heading_index(dx, dy)
    # aligned_with: centres on a line (either axis), or backs or fronts flush
    options = [np.abs(u), np.abs(v), np.abs(v - hd + ahd), np.abs(v + hd - ahd)]
    return np.min(options, axis=0), same


def _beside(grid: FloorGrid, subject: AssetEntry, anchor: Placed2D) -> np.ndarray:
    """The cost of `subject beside anchor` per subject heading, shape (4, rows, columns).

    How far the gap between the subject's footprint and the anchor's left or right side is from BESIDE_GAP,
    plus how far the subject's centre lies beyond the anchor's depth (beyond half the anchor's depth less
    half its own, and 0.1 m). The gap is exact for footprints square to the anchor, so a cost within
    TOLERANCE["beside"] means a gap of at most WALKWAY.
    """
    gx, gy = grid.coords()
    ac, (ahw, ahd), (hw, hd) = anchor.center(), anchor.half(), _half_extents(subject)
    lat, fr = anchor.lateral, anchor.front
    mid = (np.array(subject.bbox_min[:2]) + np.array(subject.bbox_max[:2])) / 2
    out = np.empty((len(HEADINGS),) + grid.shape)
    for k, yaw in enumerate(HEADINGS):
        turn = yaw - anchor.yaw
        c, s = abs(math.cos(turn)), abs(math.sin(turn))
        ex, ey = c * hw + s * hd, s * hw + c * hd  # half extents along the anchor's side and depth
        dx = gx + mid[0] * math.cos(yaw) - mid[1] * math.sin(yaw) - ac[0]
        dy = gy + mid[0] * math.sin(yaw) + mid[1] * math.cos(yaw) - ac[1]
        gap = np.abs(dx * lat[0] + dy * lat[1]) - ahw - ex
        v = dx * fr[0] + dy * fr[1]
        out[k] = np.abs(gap - BESIDE_GAP) + np.maximum(0.0, np.abs(v) - (max(ahd - ey, 0.0) + 0.1))
    return out


def _wall_heading(grid: FloorGrid) -> np.ndarray:
    """Per cell, the heading that turns a piece's back to the nearest wall."""
    return grid.memo("wall_heading", lambda: heading_index(grid.wall_normal[..., 0], grid.wall_normal[..., 1]))


def _behind(grid: FloorGrid, wall_dirs: np.ndarray) -> np.ndarray:
    """Per cell, the distance to the wall behind a piece that turns its back to the nearest wall."""
    def make() -> tuple[np.ndarray, np.ndarray]:
        return wall_dirs, np.take_along_axis(wall_dirs, BACK_DIRECTION[_wall_heading(grid)][None], 0)[0]

    return grid.memo(("behind", id(wall_dirs)), make)[1]


def _corner_distances(grid: FloorGrid, wall_dirs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per cell, the distance to the nearest wall along x and along y."""
    def make() -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
        return wall_dirs, (np.minimum(wall_dirs[0], wall_dirs[1]), np.minimum(wall_dirs[2], wall_dirs[3]))

    return grid.memo(("corner", id(wall_dirs)), make)[1]


BACK_DIRECTION = np.array([2, 1, 3, 0])
"""For heading k (front +y, -x, -y, +x), the index into directional_wall_distance of the wall behind."""
HEADING_RELATIONS = frozenset({"face", "in_front_of", "against_wall", "across_from"})
"""Relations that are only met when the subject also has the heading they ask for."""
WRONG_HEADING_COST = 1.0


def cost_in_field(relation: str, field: tuple[np.ndarray, np.ndarray | None], grid: FloorGrid, subject: AssetEntry,
                  wall_dirs: np.ndarray, x: float, y: float, yaw: float | None = None) -> float:
    """The relation's cost at one placed origin (for the validation report), read off its already computed
    field (`relation_field`); with `yaw`, a relation that asks for a heading costs WRONG_HEADING_COST more
    when the subject does not have it."""
    cost, head = field
    r, c = grid.cell(x, y)
    r, c = min(max(r, 0), grid.shape[0] - 1), min(max(c, 0), grid.shape[1] - 1)
    if relation == "against_wall" and yaw is not None:  # the wall behind the piece as it actually stands
        k = round(yaw / (math.pi / 2)) % 4
        return float(abs(wall_dirs[BACK_DIRECTION[k], r, c] + 0.0 - (-subject.bbox_min[1]) - GAP))
    # away_from the walls (the only away_from field with a heading), as the piece actually stands
    if relation == "away_from" and head is not None and yaw is not None:
        clearance = _wall_clearances(grid, *_half_extents(subject))[round(yaw / (math.pi / 2)) % 2]
        return max(0.0, WALL_CLEAR - float(clearance[r, c]))
    if cost.ndim == 3:  # a cost per heading: the one it stands at, or the least where that is not known
        cost = cost[int(np.argmin(cost[:, r, c])) if yaw is None else round(yaw / (math.pi / 2)) % 4]
    extra = 0.0
    if yaw is not None and head is not None and relation in HEADING_RELATIONS:
        extra = WRONG_HEADING_COST * (int(head[r, c]) != round(yaw / (math.pi / 2)) % 4)
    return float(cost[r, c]) + extra
