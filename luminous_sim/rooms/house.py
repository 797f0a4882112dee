"""Floor plans of houses: a rectangular outline cut into rooms by recursive subdivision (as ProcTHOR does),
doorways between rooms so that every room can be walked to, windows on outside walls.

`plan_house` draws the partition (the rooms in a random order, split into two groups, the rectangle cut
across its longer side in proportion to the groups' target areas, and so on down to one room a cell),
keeps the first partition whose cells have sensible sizes and share a wall wherever the spec asks for a
door, then adds doorways: one per asked-for pair, then more (living rooms first) until the rooms are
connected. Each room then gets a shell of its own (its floor inside the walls, its doors, a kitchen's or
bathroom's fixtures, windows on its outside walls) in which CSSG furnishes it; the house shell holds the
whole outline, the interior walls with their doorways and every room's outline.

Walls lie on the 0.25 m agent grid (centre lines of interior walls, doorways' ends), so the agent's grid
passes every doorway. Every draw comes from the Generator given: same spec and seed, same plan.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from shapely.geometry import LineString, Polygon

from luminous_sim.errors import RoomError
from luminous_sim.rooms.checks import shell_problems
from luminous_sim.rooms.fixtures import plan_fixtures
from luminous_sim.rooms.generate import ROOM_SPECS, WALL_HEIGHT, draw_windows, snapped_uniform
from luminous_sim.rooms.geometry import canonical_ring, r4, snap, snap_up
from luminous_sim.rooms.shell import (
    Door,
    HouseDoor,
    HousePlan,
    HouseRoom,
    InteriorWall,
    RoomShell,
    Window,
    make_shell,
    walls_from_outline,
)

__all__ = ["FRONT_DOOR", "MIN_SIDE", "WALL_THICKNESS", "FloorPlan", "RoomRequest", "plan_house"]

FRONT_DOOR = "FrontDoor"
"""The id of a house's exterior doorway, in its room's shell and in the house shell's `doors`."""

GRID = 0.25
"""Walls and doorways snap to the agent's grid."""
WALL_THICKNESS = 0.1
DOOR_WIDTH = 1.0
"""Wide enough that at least two rows of the agent's 0.25 m grid pass, 0.2 m clear of either jamb."""
DOOR_HEIGHT = 2.1
DOOR_MARGIN = 0.3
"""Least distance (m) from a doorway to the end of the wall segment two rooms share."""
MIN_SIDE = 2.0
MAX_ASPECT = 2.5
PLAN_ATTEMPTS = 400
ROOM_DRAWS = 6
"""Times a room's fixtures and windows are drawn on one partition before the partition is redrawn."""
MAX_SIDE = 30.0
OUTLINE_EVERY = 40
L_NOTCH_SHARE = 0.2
"""About the share of an L room's rectangle its notch takes (its rectangle is drawn that much larger)."""
L_NOTCH = (0.3, 0.5)
"""An L room's notch, as a share of its rectangle's width and of its depth (each drawn in this range)."""
L_ARM = 1.5
"""Least width (m) of an L room's arms beside its notch; also the notch's least side."""
"""Without a given size, the outline is drawn again (a little larger) after this many failed partitions."""


@dataclass(frozen=True)
class RoomRequest:
    """A room the house must have: a name, a room type and optional floor-area bounds (m^2)."""

    name: str
    room_type: str
    min_area: float | None = None
    max_area: float | None = None
    shape: str = "rect"
    """"rect", or "L": the room's rectangle loses a corner of the house outline (`plan_house`)."""

    def area_range(self) -> tuple[float, float]:
        """The floor area drawn for the room (its rectangle, for an L: the notch comes off it): within its
        bounds, else the lower half of its type's range."""
        lo_t, hi_t = ROOM_SPECS[self.room_type].area
        lo = self.min_area if self.min_area is not None else lo_t
        hi = self.max_area if self.max_area is not None else max(lo, (lo_t + hi_t) / 2)
        grow = 1.0 / (1.0 - L_NOTCH_SHARE) if self.shape == "L" else 1.0
        return (lo * grow, max(lo, hi) * grow)

    def min_side(self) -> float:
        return max(MIN_SIDE, ROOM_SPECS[self.room_type].min_side)


@dataclass(frozen=True)
class FloorPlan:
    """A drawn house: its shell (outline, interior walls, doorways, rooms) and each room's own shell."""

    shell: RoomShell
    rooms: tuple[RoomShell, ...]


@dataclass(frozen=True)
class _Cell:
    name: str
    x0: float
    y0: float
    x1: float
    y1: float

    def area(self) -> float:
        return (self.x1 - self.x0) * (self.y1 - self.y0)


Split = tuple[tuple[float, float], tuple[float, float]]


def plan_house(rooms: Sequence[RoomRequest], rng: np.random.Generator, *, size: tuple[float, float] | None = None,
               adjacency: Sequence[tuple[str, str]] = (), name: str = "house",
               front_door: str | bool | None = None) -> FloorPlan:
    """Draw a house's floor plan.

    Args:
        rooms: the rooms, at least two, with unique names.
        rng: source of every draw.
        size: the outline (width along x, depth along y, metres); default from the rooms' drawn areas.
        adjacency: pairs of room names that must share a wall with a doorway in it.
        name: the house shell's name.
        front_door: the room whose outside wall holds the house's one exterior doorway (`FRONT_DOOR`);
            default (None or True) the first room; False for a house without one (drawn as before front
            doors existed: the same plan for the same seed).

    Raises:
        RoomError: bad input (naming it), or no plan meeting the sizes and adjacency in PLAN_ATTEMPTS draws.
    """
    _check_input(rooms, adjacency)
    front = front_door if isinstance(front_door, str) else (rooms[0].name if front_door is not False else "")
    if front and front not in {r.name for r in rooms}:
        raise RoomError(f"house front door: unknown room {front!r}; expected one of {', '.join(r.name for r in rooms)}")
    width, depth = size if size is not None else _outline_size(rooms, rng, 0)
    if not (MIN_SIDE <= width <= MAX_SIDE and MIN_SIDE <= depth <= MAX_SIDE):
        raise RoomError(f"house size {width:g} x {depth:g} m: expected sides within {MIN_SIDE:g}..{MAX_SIDE:g} m")
    height = snapped_uniform(rng, WALL_HEIGHT)
    wanted = {frozenset(p) for p in adjacency}
    why = "no partition drawn"
    for attempt in range(PLAN_ATTEMPTS):
        if size is None and attempt and attempt % OUTLINE_EVERY == 0:
            width, depth = _outline_size(rooms, rng, attempt // OUTLINE_EVERY)
        targets = [(r.name, float(rng.uniform(*r.area_range()))) for r in rooms]
        order = _corners_first([targets[int(i)] for i in rng.permutation(len(targets))], rooms)
        cells: list[_Cell] = []
        splits: list[Split] = []
        _partition(0.0, 0.0, width, depth, order, rng, cells, splits, {r.name: r.min_side() for r in rooms})
        notches = _notches(cells, rooms, rng, width, depth)
        if isinstance(notches, str):
            why = notches
            continue
        why = (_size_problem(cells, rooms, width, depth, notches)
               or (_front_problem(cells, front, width, depth) if front else None) or "")
        if why:
            continue
        doors = _doors(cells, splits, wanted, {r.name: r.room_type for r in rooms}, rng)
        if isinstance(doors, str):
            why = doors
            continue
        plan = _furnish_shells(cells, splits, doors, rooms, rng, _Outline(width, depth, notches), height, name, front)
        if isinstance(plan, str):
            why = plan
            continue
        return plan
    raise RoomError(f"no floor plan for {len(rooms)} rooms in {width:g} x {depth:g} m within {PLAN_ATTEMPTS} "
                    f"draws (last: {why}); expected a larger house, fewer rooms or looser area bounds and adjacency")


def _check_input(rooms: Sequence[RoomRequest], adjacency: Sequence[tuple[str, str]]) -> None:
    if len(rooms) < 2:
        raise RoomError(f"a house needs at least 2 rooms, got {len(rooms)}")
    names = [r.name for r in rooms]
    if len(set(names)) != len(names):
        raise RoomError(f"house room names must be unique, got {', '.join(names)}")
    for r in rooms:
        if r.room_type not in ROOM_SPECS:
            raise RoomError(f"house room {r.name!r}: unknown room type {r.room_type!r}; expected one of "
                            f"{', '.join(ROOM_SPECS)}")
    for a, b in adjacency:
        for n in (a, b):
            if n not in names:
                raise RoomError(f"house adjacency {a}-{b}: unknown room {n!r}; expected one of {', '.join(names)}")


@dataclass(frozen=True)
class _Outline:
    """The house outline: a width x depth rectangle less the L rooms' notches (room name -> x0, y0, x1, y1)."""

    width: float
    depth: float
    notches: dict[str, tuple[float, float, float, float]]

    def polygon(self) -> Polygon:
        shape = Polygon([(0, 0), (self.width, 0), (self.width, self.depth), (0, self.depth)])
        for x0, y0, x1, y1 in self.notches.values():
            shape = shape.difference(Polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)]))
        return shape


def _corners_first(order: list[tuple[str, float]], rooms: Sequence[RoomRequest]) -> list[tuple[str, float]]:
    """The drawn order with the L rooms moved to its ends (the first and the last room of a partition each get
    a corner of the outline, where an L room's notch goes); unchanged without L rooms."""
    shaped = {r.name for r in rooms if r.shape == "L"}
    if not shaped:
        return order
    ls = [t for t in order if t[0] in shaped]
    rest = [t for t in order if t[0] not in shaped]
    return ls[:1] + rest + ls[1:]


def _notches(cells: list[_Cell], rooms: Sequence[RoomRequest], rng: np.random.Generator, width: float,
             depth: float) -> dict[str, tuple[float, float, float, float]] | str:
    """Each L room's notch: a rectangle at a corner of the outline that its cell holds, L_NOTCH of its sides,
    its arms at least L_ARM wide; a string says which L room has no outline corner or is too small."""
    shaped = {r.name: r for r in rooms if r.shape == "L"}
    out: dict[str, tuple[float, float, float, float]] = {}
    for c in cells:
        if c.name not in shaped:
            continue
        corners = [(x, y) for x in (c.x0, c.x1) for y in (c.y0, c.y1) if x in (0.0, width) and y in (0.0, depth)]
        if not corners:
            return f"L room {c.name} holds no corner of the house outline"
        cx, cy = corners[int(rng.integers(len(corners)))]
        w, d = c.x1 - c.x0, c.y1 - c.y0
        nw, nd = (snap(float(rng.uniform(*L_NOTCH)) * side, GRID) for side in (w, d))
        arm = L_ARM + WALL_THICKNESS / 2
        if min(nw, nd) < L_ARM or w - nw < arm or d - nd < arm:
            return f"L room {c.name} is too small for a notch ({w:g} x {d:g} m)"
        x0 = c.x0 if cx == c.x0 else r4(c.x1 - nw)
        y0 = c.y0 if cy == c.y0 else r4(c.y1 - nd)
        out[c.name] = (x0, y0, r4(x0 + nw), r4(y0 + nd))
    return out


def _outline_size(rooms: Sequence[RoomRequest], rng: np.random.Generator, redraw: int) -> tuple[float, float]:
    """An outline for the rooms' mean areas (and some slack, 3% more at each redraw), of a drawn aspect."""
    total = sum(float(np.mean(r.area_range())) for r in rooms) * (1.1 + 0.03 * redraw)
    aspect = float(rng.uniform(1.0, 1.6))
    width = min(MAX_SIDE, max(MIN_SIDE, snap((total * aspect) ** 0.5, GRID)))
    depth = min(MAX_SIDE, max(MIN_SIDE, snap(total / width, GRID)))
    return width, depth


def _partition(x0: float, y0: float, x1: float, y1: float, items: list[tuple[str, float]], rng: np.random.Generator,
               cells: list[_Cell], splits: list[Split], sides: dict[str, float]) -> None:
    """Cut the rectangle into one cell per item, in proportion to their areas (and no part narrower than its
    rooms' least side, `sides`, where the rectangle allows), recording the cuts."""
    if len(items) == 1:
        cells.append(_Cell(items[0][0], x0, y0, x1, y1))
        return
    # balanced cuts mostly (two small rooms then share a part instead of each getting a sliver)
    total = sum(a for _, a in items)
    shares = np.array([sum(a for _, a in items[:k]) / total for k in range(1, len(items))])
    weights = np.exp(-8.0 * np.abs(shares - 0.5))
    k = 1 + int(rng.choice(len(shares), p=weights / weights.sum()))
    first, rest = items[:k], items[k:]
    share = sum(a for _, a in first) / sum(a for _, a in items)
    w, d = x1 - x0, y1 - y0
    # cut so that the two parts are as square as they can be, mostly: a cut along a thin strip leaves slivers
    worst_x = max(_aspect(share * w, d), _aspect((1 - share) * w, d))
    worst_y = max(_aspect(w, share * d), _aspect(w, (1 - share) * d))
    across_x = (worst_x <= worst_y) == (rng.random() < 0.85)
    # each part at least as wide as the widest of its rooms needs
    need_a = snap_up(max(sides[n] for n, _ in first) + WALL_THICKNESS / 2, GRID)
    need_b = snap_up(max(sides[n] for n, _ in rest) + WALL_THICKNESS / 2, GRID)
    if across_x:
        x = min(max(snap(x0 + share * w, GRID), r4(x0 + need_a)), r4(x1 - need_b))
        splits.append(((x, y0), (x, y1)))
        _partition(x0, y0, x, y1, first, rng, cells, splits, sides)
        _partition(x, y0, x1, y1, rest, rng, cells, splits, sides)
    else:
        y = min(max(snap(y0 + share * d, GRID), r4(y0 + need_a)), r4(y1 - need_b))
        splits.append(((x0, y), (x1, y)))
        _partition(x0, y0, x1, y, first, rng, cells, splits, sides)
        _partition(x0, y, x1, y1, rest, rng, cells, splits, sides)


def _aspect(a: float, b: float) -> float:
    return max(a, b) / max(min(a, b), 1e-9)


def _inner(cell: _Cell, width: float, depth: float) -> tuple[float, float, float, float]:
    """The cell's floor inside its walls: half an interior wall off every side that is not outside."""
    h = WALL_THICKNESS / 2
    return (cell.x0 + (h if cell.x0 > 0 else 0.0), cell.y0 + (h if cell.y0 > 0 else 0.0),
            cell.x1 - (h if cell.x1 < width else 0.0), cell.y1 - (h if cell.y1 < depth else 0.0))


def _size_problem(cells: list[_Cell], rooms: Sequence[RoomRequest], width: float, depth: float,
                  notches: dict[str, tuple[float, float, float, float]]) -> str | None:
    by_name = {r.name: r for r in rooms}
    for c in cells:
        r = by_name[c.name]
        x0, y0, x1, y1 = _inner(c, width, depth)
        w, d = x1 - x0, y1 - y0
        n = notches.get(c.name)
        area = w * d - ((n[2] - n[0]) * (n[3] - n[1]) if n else 0.0)
        if min(w, d) < r.min_side():
            return f"room {c.name} is {min(w, d):.2f} m narrow (a {r.room_type} needs {r.min_side():g} m)"
        if max(w, d) / min(w, d) > MAX_ASPECT:
            return f"room {c.name} is {max(w, d) / min(w, d):.1f} times longer than wide"
        if (r.min_area is not None and area < r.min_area) or (r.max_area is not None and area > r.max_area):
            return f"room {c.name} has {area:.1f} m^2, outside its area bounds"
    return None


def _front_problem(cells: list[_Cell], front: str, width: float, depth: float) -> str | None:
    """Why the front door's room has no outside wall long enough for the door, or None."""
    for c in cells:
        if c.name != front:
            continue
        sides = [c.y1 - c.y0 if c.x0 == 0 or c.x1 == width else 0.0, c.x1 - c.x0 if c.y0 == 0 or c.y1 == depth else 0.0]
        if max(sides) >= DOOR_WIDTH + 2 * DOOR_MARGIN + GRID:
            return None
    return f"room {front} (the front door's) has no outside wall long enough for a door"


def _shared(a: _Cell, b: _Cell) -> tuple[Split, float, float] | None:
    """The wall line two cells share, as (line through it, from, to along it), or None."""
    for p, q in ((a, b), (b, a)):
        if abs(p.x1 - q.x0) < 1e-6:
            lo, hi = max(p.y0, q.y0), min(p.y1, q.y1)
            if hi - lo > 1e-6:
                return (((p.x1, 0.0), (p.x1, 1.0)), lo, hi)
        if abs(p.y1 - q.y0) < 1e-6:
            lo, hi = max(p.x0, q.x0), min(p.x1, q.x1)
            if hi - lo > 1e-6:
                return (((0.0, p.y1), (1.0, p.y1)), lo, hi)
    return None


def _door_offsets(start: float, lo: float, hi: float) -> np.ndarray:
    """Offsets (from a wall's start at world coordinate `start`) of doorways within [lo, hi] along it (also
    from its start), DOOR_MARGIN clear of both ends, whose jambs lie on the world's 0.25 m grid."""
    first = np.ceil((start + lo + DOOR_MARGIN) / GRID - 1e-9)
    last = np.floor((start + hi - DOOR_MARGIN - DOOR_WIDTH) / GRID + 1e-9)
    return np.round(np.arange(first, last + 1) * GRID - start, 4)


def _doors(cells: list[_Cell], splits: list[Split], wanted: set[frozenset[str]], types: dict[str, str],
           rng: np.random.Generator) -> list[HouseDoor] | str:
    """Doorways: one for each asked-for pair, then (living rooms first) one for each pair of neighbours that
    joins two parts still apart, until every room is connected. A string says why none fits."""
    options: dict[frozenset[str], tuple[int, float, float]] = {}
    for i, a in enumerate(cells):
        for b in cells[i + 1:]:
            sh = _shared(a, b)
            if sh is None or len(_door_offsets(0.0, sh[1], sh[2])) == 0:
                continue
            (p, q), lo, hi = sh
            vertical = p[0] == q[0]
            for k, ((sx0, sy0), (sx1, sy1)) in enumerate(splits):
                if vertical and sx0 == sx1 and abs(sx0 - p[0]) < 1e-6 and sy0 - 1e-6 <= lo and hi <= sy1 + 1e-6:
                    options[frozenset((a.name, b.name))] = (k, lo - sy0, hi - sy0)
                    break
                if not vertical and sy0 == sy1 and abs(sy0 - p[1]) < 1e-6 and sx0 - 1e-6 <= lo and hi <= sx1 + 1e-6:
                    options[frozenset((a.name, b.name))] = (k, lo - sx0, hi - sx0)
                    break
    missing = sorted("-".join(sorted(pair)) for pair in wanted if pair not in options)
    if missing:
        return f"rooms {', '.join(missing)} share no wall long enough for a door"
    parent = {c.name: c.name for c in cells}

    def root(n: str) -> str:
        while parent[n] != n:
            n = parent[n]
        return n

    chosen = sorted(wanted, key=sorted)
    rest = sorted((pair for pair in options if pair not in wanted), key=sorted)
    keys = rng.random(len(rest))

    def preference(k: int) -> tuple[int, int, float]:
        kinds = [types[n] for n in rest[k]]
        return (-kinds.count("LivingRoom"), kinds.count("Bathroom"), float(keys[k]))

    rest = [rest[k] for k in sorted(range(len(rest)), key=preference)]
    for pair in chosen:
        one, two = sorted(pair)
        parent[root(one)] = root(two)
    for pair in rest:
        one, two = sorted(pair)
        if root(one) != root(two):
            parent[root(one)] = root(two)
            chosen.append(pair)
    if len({root(c.name) for c in cells}) > 1:
        return "the rooms cannot all be joined by doors"
    doors = []
    for n, pair in enumerate(chosen):
        k, lo, hi = options[pair]
        start = splits[k][0][1] if splits[k][0][0] == splits[k][1][0] else splits[k][0][0]
        us = _door_offsets(start, lo, hi)
        u = float(us[int(rng.integers(len(us)))])
        one, two = sorted(pair)
        doors.append(HouseDoor(id=f"HouseDoor_{n}", wall=f"iw{k}", offset=r4(u), width=DOOR_WIDTH,
                               height=DOOR_HEIGHT, rooms=(one, two)))
    return doors


def _furnish_shells(cells: list[_Cell], splits: list[Split], doors: list[HouseDoor], rooms: Sequence[RoomRequest],
                    rng: np.random.Generator, house: _Outline, height: float, name: str,
                    front: str) -> FloorPlan | str:
    """Each room's shell (doors, the front door in its room, fixtures, windows), then the house shell; a
    string says what did not fit."""
    walls = tuple(InteriorWall(id=f"iw{k}", start=a, end=b) for k, (a, b) in enumerate(splits))
    by_wall = {w.id: w for w in walls}
    outline = house.polygon()
    order = {r.name: i for i, r in enumerate(rooms)}
    shells: list[RoomShell] = []
    for cell in sorted(cells, key=lambda c: order[c.name]):
        req = rooms[order[cell.name]]
        mine = [d for d in doors if cell.name in d.rooms]
        shell = None
        for _ in range(ROOM_DRAWS):
            shell = _room_shell(cell, req, mine, by_wall, rng, house, height, cell.name == front)
            if shell is not None:
                break
        if shell is None:
            return f"room {cell.name}'s fixtures or doors do not fit"
        shells.append(shell)
    windows = _house_windows(shells, outline)
    entrance = _house_openings([s for s in shells if s.name == front], outline, "doors")
    plan = HousePlan(rooms=tuple(HouseRoom(name=s.name, room_type=s.room_type, outline=s.outline) for s in shells),
                     walls=walls, doors=tuple(doors))
    shell = make_shell(name=name, room_type=rooms[0].room_type, shape="rectilinear" if house.notches else "rect",
                       source="house", outline=list(outline.exterior.coords)[:-1], wall_height=height,
                       wall_thickness=WALL_THICKNESS, windows=tuple(windows), doors=tuple(entrance), house=plan)
    return FloorPlan(shell, tuple(shells))


def _room_shell(cell: _Cell, req: RoomRequest, doors: list[HouseDoor], walls: dict[str, InteriorWall],
                rng: np.random.Generator, house: _Outline, height: float, front: bool = False) -> RoomShell | None:
    x0, y0, x1, y1 = _inner(cell, house.width, house.depth)
    floor = Polygon([(x0, y0), (x1, y0), (x1, y1), (x0, y1)])
    notch = house.notches.get(cell.name)
    if notch is not None:
        nx0, ny0, nx1, ny1 = notch
        floor = floor.difference(Polygon([(nx0, ny0), (nx1, ny0), (nx1, ny1), (nx0, ny1)]))
    outline = house.polygon()
    base = make_shell(name=req.name, room_type=req.room_type, shape="L" if notch else "rect", source="house",
                      outline=list(floor.exterior.coords)[:-1], wall_height=height, wall_thickness=WALL_THICKNESS)
    outside = {w.id for w in base.walls
               if outline.exterior.distance(LineString([w.start, w.end]).centroid) < 1e-6}
    room_doors = []
    for k, d in enumerate(doors):
        line = walls[d.wall].wall
        ends = np.array([line.point(d.offset), line.point(d.offset + d.width)])
        for w in base.walls:
            uv = w.local(ends)
            if np.allclose(uv[:, 1], -WALL_THICKNESS / 2, atol=1e-6) and uv[:, 0].min() >= -1e-6 \
                    and uv[:, 0].max() <= w.length + 1e-6:
                room_doors.append(Door(id=f"Door_{k}", wall=w.id, offset=r4(float(uv[:, 0].min())), width=d.width,
                                       height=d.height, swing_clearance=r4(d.width + 0.1)))
                break
        else:
            return None
    if front:
        entrance = _front_door(base, outside, rng)
        if entrance is None:
            return None
        room_doors.append(entrance)
    keep = [base.wall(d.wall).rect(d.offset, d.offset + d.width, 0.0, d.swing_clearance) for d in room_doors]
    fixtures = plan_fixtures(req.room_type, base.walls, base.polygon(), rng, keep)
    if fixtures is None:
        return None
    shell = base.model_copy(update={"doors": tuple(room_doors), "fixtures": fixtures})
    windows = draw_windows(shell, rng, ROOM_SPECS[req.room_type], outside=outside)
    shell = RoomShell.from_dict({**shell.model_dump(), "windows": windows}, where=f"room {req.name!r}")
    return None if shell_problems(shell) else shell


def _front_door(base: RoomShell, outside: set[str], rng: np.random.Generator) -> Door | None:
    """The house's front door on one of the room's outside walls, DOOR_MARGIN clear of its ends, its jambs
    on the agent's grid (so that the grid passes it); None when no outside wall is long enough."""
    options: list[tuple[str, float]] = []
    for w in base.walls:
        if w.id not in outside:
            continue
        axis = 0 if abs(w.direction[0]) > 0.5 else 1
        sign = w.direction[axis]
        start = w.start[axis]
        for u in _door_offsets(0.0, 0.0, w.length):
            jamb = start + sign * u
            if abs(jamb / GRID - round(jamb / GRID)) < 1e-6:
                options.append((w.id, float(u)))
    if not options:
        return None
    wall, u = options[int(rng.integers(len(options)))]
    return Door(id=FRONT_DOOR, wall=wall, offset=r4(u), width=DOOR_WIDTH, height=DOOR_HEIGHT,
                swing_clearance=r4(DOOR_WIDTH + 0.1))


def _house_windows(shells: list[RoomShell], outline: Polygon) -> list[Window]:
    """Every room's windows, placed on the house's outside walls."""
    return [Window(id=f"Window_{k}", wall=wall, offset=offset, width=win.width, sill_height=win.sill_height,
                   height=win.height)
            for k, (win, wall, offset) in enumerate(_on_outline(shells, outline, "windows"))]


def _house_openings(shells: list[RoomShell], outline: Polygon, kind: str) -> list[Door]:
    """The rooms' doors on the house's outside walls (the front door), as the house shell's doors."""
    return [Door(id=d.id, wall=wall, offset=offset, width=d.width, height=d.height, swing_clearance=0.0)
            for d, wall, offset in _on_outline(shells, outline, kind)]


def _on_outline(shells: list[RoomShell], outline: Polygon, kind: str) -> list[tuple[Any, str, float]]:
    """The rooms' `kind` (windows or doors) that lie on the house's outside walls: (item, house wall, offset)."""
    house_walls = walls_from_outline(canonical_ring(outline.exterior.coords))
    out: list[tuple[Any, str, float]] = []
    for s in shells:
        for item in getattr(s, kind):
            wall = s.wall(item.wall)
            ends = np.array([wall.point(item.offset), wall.point(item.offset + item.width)])
            for hw in house_walls:
                uv = hw.local(ends)
                if np.allclose(uv[:, 1], 0.0, atol=1e-6):
                    out.append((item, hw.id, r4(float(uv[:, 0].min()))))
                    break
    return out
