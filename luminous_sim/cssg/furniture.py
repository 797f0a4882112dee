"""The furniture layer: sample each piece's position from its score field and its heading from its
heaviest relation, on the free-floor grid, footprint collision-free and clear of doors."""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.affinity

from luminous_sim.cssg.draft import SEGMENTED_FIXTURES, SceneDraft
from luminous_sim.cssg.grid import HEADINGS, FloorGrid
from luminous_sim.cssg.lattice import Lattice
from luminous_sim.cssg.reach import FloorPiece
from luminous_sim.cssg.requests import FIXTURE_ANCHOR, Request
from luminous_sim.cssg.scores import (
    GAP_RELATIONS,
    TEMPERATURE,
    TOLERANCE,
    Placed2D,
    cost_in_field,
    directional_wall_distance,
    holds,
    relation_field,
)
from luminous_sim.cssg.tables import room_defaults
from luminous_sim.cssg.walls import ABOVE_JITTER, BEHIND_SLACK, MARGIN, window_strips
from luminous_sim.scene import REACH, blocks_agent, footprint, front_zone, reach_of

WINDOW_BEHIND_COST = 2.0
"""Cost of a cell with a window behind, for a piece something is to hang above (the structure weight)."""
WRONG_HEADING_PENALTY = 0.5
"""metres of cost for standing at a heading other than the preferred one."""
REACHED_SHARE = 0.95
"""Share of the free floor (the agent's grid points clear of everything on the floor) that must stay connected
to the rest: ProcTHOR's "all floor space connected", with a little slack for pockets behind furniture."""
WORK_ZONE = 0.7
"""metres kept free in front of every fixture (counters, sink, stove, fridge, toilet, bathtub)."""
SEAT_COUNTERS = frozenset({"CounterTop"})
"""Fixtures whose work zone a seat at them may stand in (stools at a kitchen counter)."""


@dataclass
class FloorContext:
    """Everything the furniture layer reads and updates while placing one scene."""

    draft: SceneDraft
    grid: FloorGrid
    wall_dirs: np.ndarray
    centroid: tuple[float, float]
    placed: dict[str, Placed2D]
    alternates: dict[str, list[Placed2D]] = None  # type: ignore[assignment]
    """A name bound to one segment of a fixture (a kitchen's counter) relates to any of its segments."""
    pieces: list[FloorPiece] = None  # type: ignore[assignment]
    """The cells of everything on the floor that the agent must be able to reach."""
    clear: np.ndarray = None  # type: ignore[assignment]
    """Which of the agent's grid points (`lattice`) are clear of every floor obstacle placed so far."""
    fields: dict = None  # type: ignore[assignment]
    """Relation fields computed so far (they depend on the room, the subject and the anchor only)."""
    lattice: Lattice = None  # type: ignore[assignment]
    """The agent's 0.25 m grid in this room."""
    seat_zone: np.ndarray = None  # type: ignore[assignment]
    """Cells kept free only as the work zone in front of a plain counter run (no sink, stove or appliance in
    front of them, no door's clearance): where a stool at the counter may stand (`seat_zone_open`)."""

    @classmethod
    def create(cls, draft: SceneDraft) -> FloorContext:
        poly = draft.shell.polygon()
        grid = FloorGrid.from_polygon(poly)
        for zone in draft.shell.door_clearance_zones():
            grid.block(zone)
        pieces = []
        blocked_before = ~grid.free
        counter = np.zeros(grid.shape, dtype=bool)
        for p in draft.placed:
            if p.obj.parent is None:
                grid.block(p.footprint)
                pieces.append(FloorPiece.of(p.obj.id, grid._cells(p.footprint), reach_of(p.entry, p.obj.position[2])))
                if p.obj.layer == "fixture":  # keep the work zone in front of counters and appliances
                    zone = front_zone(p.entry, p.obj.position[0], p.obj.position[1], p.obj.yaw, WORK_ZONE)
                    if p.obj.type in SEAT_COUNTERS:
                        counter |= grid._cells(zone)
                    grid.block(zone)
        other = np.zeros(grid.shape, dtype=bool)  # everything but the counters' own zones
        for p in draft.placed:
            if p.obj.parent is None:
                other |= grid._cells(p.footprint)
            if p.obj.layer == "fixture" and p.obj.type not in SEAT_COUNTERS:
                # nor in front of a sink, a stove (its burners and knobs sit in the run) or an appliance
                other |= grid._cells(_in_front(p.footprint, p.obj.yaw, WORK_ZONE + p.entry.dims[1]))
        c = poly.centroid
        lattice = Lattice.of(draft.shell, grid)
        clear = lattice.open_among(p.footprint for p in draft.placed if blocks_agent(p.obj, p.entry))
        ctx = cls(draft, grid, directional_wall_distance(grid), (c.x, c.y), {}, {}, pieces, clear, {}, lattice,
                  counter & ~other & ~blocked_before & grid.room)
        for p in draft.placed:  # the room's fixtures as anchors of implicit rules ("@CounterTop": any run)
            name = FIXTURE_ANCHOR + p.obj.type
            if p.obj.layer == "fixture" and p.obj.parent is None and name not in ctx.placed:
                register(ctx, name, p.obj, p.entry)
        return ctx

    @contextmanager
    def seat_zone_open(self, req: Request) -> Iterator[None]:
        """While placing a seat at a counter (a request with a rule's variant tag: a bar stool), the counters'
        work zone is the only free floor (it stands at the counter's front, not beside its end); whatever
        the seat then takes of it stays taken."""
        if req.tag is None:
            yield
            return
        before = self.grid.free.copy()  # the zone is blocked there, so a seat placed in it stays blocked
        self.grid.set_free(self.seat_zone.copy())
        try:
            yield
        finally:
            self.seat_zone = self.seat_zone & self.grid.free
            self.grid.set_free(before)

    def walkable(self, clear: np.ndarray) -> np.ndarray:
        """Fine-grid cells under the agent's grid points in the largest 4-connected part of those
        `clear` (an array over `lattice`), where the agent can walk."""
        return self.lattice.walkable(clear)

    def keeps_everything_reachable(self, fp, reach: float = REACH, cut_off: bool = False) -> bool:
        """Whether adding footprint `fp` leaves every floor piece (and itself, within `reach`) within reach of
        walkable floor, and (unless `cut_off` may be) no more than 1 - REACHED_SHARE of the free floor cut off
        from the rest (a bed across an L-shaped room's second wing); a room already below that may lose no more."""
        new = FloorPiece.of("new", self.grid._cells(fp), reach)
        clear = self.clear & ~self.lattice.near(fp)
        walk = self.walkable(clear)
        if not walk.any() or not all(p.reachable(walk) for p in self.pieces + [new]):
            return False
        if cut_off:
            return True
        share = self.lattice.connected_share(clear)
        return share >= REACHED_SHARE or share >= self.lattice.connected_share(self.clear)

    def commit(self, object_id: str, fp, reach: float = REACH) -> None:
        piece = FloorPiece.of(object_id, self.grid._cells(fp), reach)
        self.clear &= ~self.lattice.near(fp)
        self.pieces.append(piece)
        self.grid.block(fp)

    def remove(self, gone: set[str], fp) -> None:
        """Take the floor pieces `gone` (standing on footprint `fp`) out again."""
        self.grid.unblock(fp)
        self.clear = self.lattice.open_among(p.footprint for p in self.draft.placed if blocks_agent(p.obj, p.entry))
        self.pieces = [p for p in self.pieces if p.id not in gone]

    def snapshot(self) -> tuple:
        """What placing a piece changes, to go back to with `restore`."""
        return (self.grid.free.copy(), self.clear.copy(), list(self.pieces), dict(self.placed),
                dict(self.alternates), self.seat_zone.copy())

    def restore(self, snap: tuple) -> None:
        free, clear, pieces, placed, alternates, seat_zone = snap
        self.seat_zone = seat_zone.copy()
        self.grid.set_free(free.copy())
        self.clear, self.pieces = clear.copy(), list(pieces)
        self.placed, self.alternates = dict(placed), dict(alternates)

    def anchor(self, name: str | None) -> Placed2D | None:
        return self.placed.get(name) if name else None

    def anchors(self, name: str | None) -> list[Placed2D | None]:
        """Every placed thing `name` may refer to (one, or all segments of a bound fixture)."""
        if name and name in self.alternates:
            return list(self.alternates[name])
        return [self.anchor(name)]

    def relation_field(self, relation: str, entry, anchor: Placed2D | None) -> tuple[np.ndarray, np.ndarray | None]:
        """`scores.relation_field` in this room, computed once per relation, subject size and anchor pose."""
        key = (relation, _entry_key(entry), None if relation in UNARY or anchor is None
               else (anchor.x, anchor.y, anchor.yaw, _entry_key(anchor.entry)))
        hit = self.fields.get(key)
        if hit is None:
            hit = relation_field(relation, self.grid, entry, anchor, self.wall_dirs, self.centroid)
            for a in hit:
                if a is not None:
                    a.flags.writeable = False
            self.fields[key] = hit
        return hit

    def field(self, relation: str, entry, name: str | None) -> tuple[np.ndarray, np.ndarray | None]:
        """The relation's cost field, the cheapest over everything `name` may refer to."""
        best, heading = None, None
        for anchor in self.anchors(name):
            cost, head = self.relation_field(relation, entry, anchor)
            if best is None:
                best, heading = cost, head
            else:
                better = cost < best
                if head is not None and heading is not None:  # per cell (over headings: the least cost)
                    cell_better = better if better.ndim == 2 else _least(cost) < _least(best)
                    heading = np.where(cell_better, head, heading)
                best = np.where(better, cost, best)
        return best, heading

    def cost_at(self, relation: str, entry, name: str | None, x: float, y: float, yaw: float | None = None) -> float:
        return min(cost_in_field(relation, self.relation_field(relation, entry, a), self.grid, entry, self.wall_dirs,
                                 x, y, yaw) for a in self.anchors(name))

    def gap(self, entry, name: str | None, x: float, y: float, yaw: float) -> float | None:
        """Least distance (m) between the footprint of `entry` at (x, y, yaw) and that of anything `name`
        refers to; None for a room element (a wall) or a name not placed."""
        anchors = [a for a in self.anchors(name) if a is not None]
        if not anchors:
            return None
        fp = footprint(entry, x, y, yaw)
        return min(float(fp.distance(footprint(a.entry, a.x, a.y, a.yaw))) for a in anchors)

    def check(self, relation: str, entry, name: str | None, x: float, y: float,
              yaw: float | None = None) -> tuple[bool, float, float | None]:
        """(met, cost, gap) of a floor relation with the subject's origin at (x, y) and heading `yaw`: the
        one test the generator places by and the validation report applies (`scores.holds`). The gap
        between the footprints is measured for GAP_RELATIONS when the heading is known, else None."""
        cost = self.cost_at(relation, entry, name, x, y, yaw)
        gap = self.gap(entry, name, x, y, yaw) if relation in GAP_RELATIONS and yaw is not None else None
        return holds(relation, cost, gap), cost, gap


SEAT_SIDE = 0.15
"""metres either side of a sink, a stove or an appliance kept clear of seats at the counter."""


def _in_front(fp, yaw: float, depth: float):
    """The floor a footprint sweeps moving `depth` metres forward (towards its front at `yaw`), widened by
    SEAT_SIDE: where one stands to use it."""
    front = (-math.sin(yaw), math.cos(yaw))
    moved = shapely.affinity.translate(fp, front[0] * depth, front[1] * depth)
    return shapely.convex_hull(shapely.union(fp, moved)).buffer(SEAT_SIDE)


UNARY = frozenset({"against_wall", "in_corner", "in_centre"})
"""Relations whose field does not depend on an anchor."""


def _entry_key(entry) -> tuple:
    """What of an asset entry the relation fields depend on."""
    return (entry.type, *entry.dims, *entry.bbox_min, *entry.bbox_max)


def score(ctx: FloorContext, req: Request, entry) -> tuple[np.ndarray, np.ndarray | None]:
    """Weighted total cost per cell (per heading and cell where a relation's cost depends on the heading) and
    the heading field of the heaviest relation that has one."""
    total = np.zeros(ctx.grid.shape)
    heading, best_w = None, -1.0
    for rel in req.rels:
        anchor = ctx.anchor(rel.anchor)
        if rel.anchor and anchor is None and rel.anchor not in ("wall", "window", "door"):
            continue  # the anchor could not be placed; the report records the relation as unmet
        cost, head = ctx.field(rel.relation, entry, rel.anchor)
        total = total + rel.weight * cost  # (heading, row, column) once a relation's cost depends on the heading
        if head is not None and rel.weight > best_w:
            heading, best_w = head, rel.weight
    if req.clear_above:  # a painting is to hang above it: not in front of a window
        key = ("window_behind", entry.dims[1], req.clear_above)
        if key not in ctx.fields:
            mask = np.zeros(ctx.grid.shape, dtype=bool)
            widen = req.clear_above + MARGIN + ABOVE_JITTER
            for strip in window_strips(ctx.draft, entry.dims[1] + BEHIND_SLACK, widen):
                mask |= ctx.grid._cells(strip)
            ctx.fields[key] = mask
        total += WINDOW_BEHIND_COST * ctx.fields[key]
    return total, heading


def hard_relations_met(ctx: FloorContext, req: Request, entry, x: float, y: float, yaw: float | None = None,
                       implicit: bool = False) -> bool:
    """Whether the CDF's hard floor relations of `req` (and, with `implicit`, its implicit rules) hold
    with its origin at (x, y) and heading `yaw`."""
    for rel in req.rels:
        if not ((rel.explicit and rel.hard) or (implicit and not rel.explicit)) or rel.relation not in TOLERANCE:
            continue
        if rel.anchor and ctx.anchor(rel.anchor) is None and rel.anchor not in ("wall", "window", "door"):
            return False
        if not ctx.check(rel.relation, entry, rel.anchor, x, y, yaw)[0]:
            return False
    return True


REACH_REDRAWS = 12
"""Draws of one piece that may block the agent's way (or cut floor off) before they use up its tries."""
REJECT_CELLS = 3
"""Cells either side of a draw that blocked the way that are not drawn again (at that heading)."""


def place_piece(ctx: FloorContext, req: Request, tries: int = 6, layer: str = "furniture") -> Placed2D | None:
    """Place one furniture request (or, with `layer` "object", a small thing lying on the floor); None if no
    variant fits anywhere.

    Cells are drawn with P proportional to exp(-cost / T); a draw that breaks one of the CDF's hard
    relations is redrawn, and the last try takes the cheapest feasible cell instead.
    """
    draft = ctx.draft
    rng = draft.rng
    variants = req.variants(draft.catalog)
    if not variants:
        return None
    fields: dict[tuple, tuple] = {}

    def field_of(entry) -> tuple:
        key = _entry_key(entry)
        if key not in fields:
            fields[key] = score(ctx, req, entry), np.stack([ctx.grid.feasible(entry, h) for h in HEADINGS])
        return fields[key]

    rejected: dict[tuple, np.ndarray] = {}
    redraws = 0
    # a piece the room must have (its bed) may cut floor off where it cannot help it: the least it can
    essential = req.explicit or req.type in room_defaults(draft.shell.room_type).get("essential", ())
    fallback: tuple | None = None
    attempt = -1
    while attempt < tries - 1:
        attempt += 1
        if attempt == tries - 1 and len(variants) > 1:  # the variant that fits best (a smaller table)
            entry = min(variants, key=lambda e: _cheapest(*field_of(e)))
        else:
            entry = variants[int(rng.integers(len(variants)))]
        (cost, heading), feas = field_of(entry)
        if _entry_key(entry) in rejected:
            feas = feas & ~rejected[_entry_key(entry)]
        if not feas.any():
            continue
        pick = _draw(cost, heading, feas, rng, cheapest=attempt == tries - 1)
        k, r, c = np.unravel_index(pick, feas.shape)
        x, y, yaw = float(ctx.grid.xs[c]), float(ctx.grid.ys[r]), HEADINGS[int(k)]
        # early draws must also honour the implicit rules; later ones only the CDF's hard relations
        if attempt < tries - 1 and not hard_relations_met(ctx, req, entry, x, y, yaw, implicit=attempt < tries // 2):
            continue
        fp, reach = footprint(entry, x, y, yaw), reach_of(entry, -entry.bbox_min[2])
        if not ctx.keeps_everything_reachable(fp, reach):
            # not here, nor right beside here; and a draw that would block the way does not use up a try
            mask = rejected.setdefault(_entry_key(entry), np.zeros(feas.shape, dtype=bool))
            mask[k, max(r - REJECT_CELLS, 0):r + REJECT_CELLS + 1, max(c - REJECT_CELLS, 0):c + REJECT_CELLS + 1] = True
            if redraws < REACH_REDRAWS:
                redraws += 1
                attempt -= 1
            if essential and ctx.keeps_everything_reachable(fp, reach, cut_off=True) and (
                    req.explicit or hard_relations_met(ctx, req, entry, x, y, yaw, implicit=True)):
                share = ctx.lattice.connected_share(ctx.clear & ~ctx.lattice.near(fp))
                if fallback is None or share > fallback[0]:
                    fallback = (share, entry, x, y, yaw)
            continue
        placed = _put(ctx, req, entry, x, y, yaw, layer)
        if placed is not None or fallback is None:
            return placed
        break
    if fallback is not None:  # a room too small to keep all its floor connected still gets its bed
        return _put(ctx, req, *fallback[1:])
    return None


def _put(ctx: FloorContext, req: Request, entry, x: float, y: float, yaw: float,
         layer: str = "furniture") -> Placed2D | None:
    """Add a piece where it was drawn (None: a default piece that breaks one of its implicit rules there, which
    is better left out); furniture is fixed, a small object on the floor is not."""
    if not req.explicit and not hard_relations_met(ctx, req, entry, x, y, yaw, implicit=True):
        return None
    draft = ctx.draft
    obj = draft.add(entry, x, y, -entry.bbox_min[2], yaw, layer, fixed=layer != "object", name=req.name,  # type: ignore[arg-type]
                    states=req.states, color=req.colour())
    ctx.commit(obj.id, draft.placed[-1].footprint, reach_of(entry, obj.position[2]))
    placed = Placed2D(req.type, x, y, yaw, entry)
    ctx.placed[req.name] = placed
    ctx.placed[obj.id] = placed
    return placed


def _cheapest(field: tuple[np.ndarray, np.ndarray | None], feas: np.ndarray) -> float:
    """The least cost (with the heading penalty) over the feasible cells and headings; inf if none."""
    cost, heading = field
    cand = np.flatnonzero(feas)
    return float(_cell_values(cost, heading, cand).min()) if len(cand) else math.inf


def _least(cost: np.ndarray) -> np.ndarray:
    """Per cell, the least cost over the headings of a (heading, row, column) field; a 2-D field as it is."""
    return cost if cost.ndim == 2 else cost.min(axis=0)


def _cell_values(cost: np.ndarray, heading: np.ndarray | None, cand: np.ndarray) -> np.ndarray:
    """Cost of each candidate flat index into (heading, row, column): the cell's cost (at that heading, for
    a field per heading), plus WRONG_HEADING_PENALTY off the preferred heading (none without a heading field)."""
    plane = cost.shape[-2] * cost.shape[-1]
    cells = cand % plane
    vals = cost.ravel()[cand if cost.ndim == 3 else cells]
    if heading is not None:
        vals = vals + WRONG_HEADING_PENALTY * (heading.ravel()[cells] != cand // plane)
    return vals


def _draw(cost: np.ndarray, heading: np.ndarray | None, feas: np.ndarray, rng: np.random.Generator,
          cheapest: bool) -> int:
    """A flat index into (heading, row, column), drawn with P proportional to exp(-cost / TEMPERATURE) over
    the feasible ones (or the cheapest feasible one); the preferred heading is free, the others cost
    WRONG_HEADING_PENALTY more. Without a heading field, one heading is drawn for all cells."""
    if heading is None:
        heading = np.full(cost.shape[-2:], int(rng.integers(4)))
    cand = np.flatnonzero(feas)
    vals = _cell_values(cost, heading, cand)
    if cheapest:
        return int(cand[np.argmin(vals)])
    cdf = np.cumsum(np.exp(-(vals - vals.min()) / TEMPERATURE))
    return int(cand[min(int(np.searchsorted(cdf, rng.random() * cdf[-1], side="right")), len(cand) - 1)])


def register(ctx: FloorContext, name: str, placed_obj, entry) -> None:
    """Make an already placed object (a bound fixture) an anchor under a CDF name."""
    p2 = Placed2D(placed_obj.type, placed_obj.position[0], placed_obj.position[1], placed_obj.yaw, entry)
    ctx.placed[name] = p2
    if placed_obj.type in SEGMENTED_FIXTURES:
        ctx.alternates[name] = [Placed2D(p.obj.type, p.obj.position[0], p.obj.position[1], p.obj.yaw, p.entry)
                                for p in ctx.draft.placed if p.obj.type == placed_obj.type]
