"""A scene from given placements (a layout made elsewhere): the same validation as a generated scene, with
CSSG's own placement as the repair and CSSG's object layer to add what the layout lacks.

Floor pieces that stand outside the room, overlap an earlier piece or stand in a door's clearance are
moved to the nearest free cell of CSSG's floor grid (the least movement, at the nearest of CSSG's four
headings, leaving reachable what was), with what stands on them; one that cannot be moved within
MAX_MOVE makes the layout rejected. Wall pieces that cut into something are left out. A fixture that
brings parts along (a sink's basin and faucet) gets them where the layout does not give them. Small
objects without a support, the room type's default objects and the types the caller requires are
placed by the object layer (`place_object`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.assets.catalog import AssetEntry, Catalog, default_catalog
from luminous_sim.cssg.baseline import empty_cdf
from luminous_sim.cssg.draft import Placed, SceneDraft
from luminous_sim.cssg.furniture import FloorContext
from luminous_sim.cssg.grid import HEADINGS
from luminous_sim.cssg.objects import place_object
from luminous_sim.cssg.pipeline import Generated
from luminous_sim.cssg.reach import FloorPiece
from luminous_sim.cssg.requests import Request, requests_from_cdf
from luminous_sim.cssg.structure import add_anchors
from luminous_sim.cssg.tables import floor_relations, generation_layer, supports_for
from luminous_sim.cssg.validate import check_layout
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Layer, SceneObject, footprint, local_to_world, reach_of
from luminous_sim.scene.ids import thor_object_id

MAX_MOVE = 2.0
"""metres a floor piece may be moved to repair a layout; farther, and the layout is rejected."""
TURN_COST = 0.25
"""metres of movement one quarter turn counts as, when choosing the least change."""
OVERLAP_AREA = 1e-4
"""m^2 of footprint overlap that counts as two pieces running into each other (as the validation counts)."""
CANDIDATES = 400
"""Nearest free cells tried per heading before a piece is given up."""


@dataclass(frozen=True)
class Placement:
    """One object of a given layout, in the scene's conventions.

    `position` is the asset's base origin in the world and `yaw` its heading (as `SceneObject`); `entry` the
    (scaled) catalog entry. `parent` names another placement's `key`. `layer` None: the type's CSSG layer.
    An object-layer placement without a parent is placed by the object layer (its pose is not used).
    `object_id` is kept as the scene id when it is an AI2-THOR style id of its type not taken yet.
    """

    key: str
    entry: AssetEntry
    position: tuple[float, float, float]
    yaw: float = 0.0
    layer: Layer | None = None
    fixed: bool | None = None
    parent: str | None = None
    region: str | None = None
    name: str | None = None
    states: dict[str, bool] = field(default_factory=dict)
    color: tuple[float, float, float] | None = None
    color_seed: int | None = None
    object_id: str | None = None


@dataclass(frozen=True)
class Repair:
    """One change made to a given layout: `action` is moved, left_out or placed (by the object layer)."""

    key: str
    type: str
    action: str
    reason: str
    distance: float = 0.0
    """metres moved (for moved)."""
    turn: float = 0.0
    """radians turned (for moved)."""


@dataclass
class GivenScene:
    """A scene built from given placements: the generated scene and its report, the repairs, the scene id of
    each placement key, and why the layout is rejected (empty: accepted)."""

    generated: Generated
    repairs: list[Repair]
    ids: dict[str, str]
    problems: list[str]

    @property
    def ok(self) -> bool:
        return not self.problems and self.generated.report.ok


def _layer(p: Placement) -> Layer:
    if p.layer is not None:
        return p.layer
    own = generation_layer(p.entry.type)
    return "decoration" if own == "wall" else own  # type: ignore[return-value]


def _floor_piece(p: Placement) -> bool:
    return p.parent is None and _layer(p) in ("furniture", "fixture")


FLOOR_TOL = 0.01
"""metres between a small object's bottom and the floor within which it lies on the floor."""


def _lies_on_floor(p: Placement) -> bool:
    """A small object of a type that may lie on the floor (a basketball in a corner), resting there: kept where
    it is given, like a floor piece, instead of going to the object layer."""
    return bool(floor_relations(p.entry.type)) and abs(p.position[2] + p.entry.bbox_min[2]) <= FLOOR_TOL


def _z_range(p: Placement) -> tuple[float, float]:
    return p.position[2] + p.entry.bbox_min[2], p.position[2] + p.entry.bbox_max[2]


Solid = list[tuple[Polygon, tuple[float, float], str]]
"""Footprints, height ranges and keys of the free-standing things kept so far."""


def _runs_into(fp: Polygon, z: tuple[float, float], others: Solid) -> str | None:
    for ofp, oz, key in others:
        if z[0] < oz[1] - 0.005 and oz[0] < z[1] - 0.005 and fp.intersection(ofp).area > OVERLAP_AREA:
            return key
    return None


def _problems(p: Placement, shell: RoomShell, doors: list[Polygon], solid: Solid) -> list[str]:
    """Why a free-standing piece cannot stay where it is (empty: it can)."""
    fp = footprint(p.entry, p.position[0], p.position[1], p.yaw)
    out = []
    if _floor_piece(p) and not shell.polygon().buffer(1e-3).contains(fp):
        out.append("outside the room")
    if _floor_piece(p):
        for door, zone in zip(shell.doors, doors):
            if fp.intersection(zone).area > OVERLAP_AREA:
                out.append(f"blocks door {door.id}")
    hit = _runs_into(fp, _z_range(p), solid)
    if hit is not None:
        out.append(f"overlaps {hit}")
    return out


def _order(placements: list[Placement]) -> tuple[list[Placement], list[Repair]]:
    """Placements with every parent before its children; those whose parent is unknown (or a cycle) left out."""
    by_key = {p.key: p for p in placements}
    done: set[str] = set()
    out: list[Placement] = []
    dropped: list[Repair] = []
    for p in placements:
        chain: list[Placement] = []
        q: Placement | None = p
        while q is not None and q.key not in done and q not in chain:
            chain.append(q)
            q = by_key.get(q.parent) if q.parent is not None else None
        if q is not None and q in chain:  # a cycle: none of it can stand
            for c in chain:
                if c.key not in done:
                    done.add(c.key)
                    dropped.append(Repair(c.key, c.entry.type, "left_out", "its support chain is a cycle"))
            continue
        for c in reversed(chain):
            if c.parent is not None and c.parent not in by_key:
                dropped.append(Repair(c.key, c.entry.type, "left_out", f"unknown parent {c.parent!r}"))
            elif c.parent is not None and c.parent in {d.key for d in dropped}:
                dropped.append(Repair(c.key, c.entry.type, "left_out", f"its parent {c.parent} was left out"))
            else:
                out.append(c)
            done.add(c.key)
    return out, dropped


def _add(draft: SceneDraft, p: Placement, x: float, y: float, yaw: float, parent_id: str | None) -> SceneObject:
    layer = _layer(p)
    fixed = p.fixed if p.fixed is not None else layer != "object"
    oid = p.object_id
    if oid is None or oid in draft.taken_ids or oid.split("|")[0] != p.entry.type:
        oid = thor_object_id(p.entry.type, (x, y, p.position[2]), draft.taken_ids)
    draft.taken_ids.add(oid)
    seed = int(draft.rng.integers(2**31)) if p.color_seed is None else p.color_seed
    obj = SceneObject(id=oid, type=p.entry.type, asset=p.entry.id, position=(x, y, p.position[2]), yaw=yaw,
                      layer=layer, fixed=fixed, parent=parent_id, region=p.region, name=p.name, states=p.states,
                      color_seed=seed, scale=p.entry.scale, color=p.color)
    draft.placed.append(Placed(obj, p.entry, footprint(p.entry, obj.position[0], obj.position[1], obj.yaw)))
    return obj


def _nearest_pose(ctx: FloorContext, p: Placement) -> tuple[float, float, float] | None:
    """The free pose nearest to `p`'s (movement plus TURN_COST per quarter turn) within MAX_MOVE that keeps
    everything reachable, or None."""
    x0, y0 = p.position[0], p.position[1]
    gx, gy = ctx.grid.coords()
    dist = np.hypot(gx - x0, gy - y0)
    options = []
    for h in HEADINGS:
        turn = abs((h - p.yaw + math.pi) % (2 * math.pi) - math.pi)
        feas = ctx.grid.feasible(p.entry, h) & (dist <= MAX_MOVE)
        cells = np.flatnonzero(feas)
        cost = dist.ravel()[cells] + TURN_COST * turn / (math.pi / 2)
        best = cells[np.argsort(cost, kind="stable")[:CANDIDATES]]
        options += [(float(dist.ravel()[c]) + TURN_COST * turn / (math.pi / 2), h, int(c)) for c in best]
    reach = reach_of(p.entry, p.position[2])
    before = ctx.walkable(ctx.clear)
    reachable = [q for q in ctx.pieces if q.reachable(before)]  # what the layout left unreachable stays a problem
    for _, h, c in sorted(options, key=lambda o: (o[0], o[1], o[2])):
        x, y = float(gx.ravel()[c]), float(gy.ravel()[c])
        fp = footprint(p.entry, x, y, h)
        walk = ctx.walkable(ctx.clear & ~ctx.lattice.near(fp))
        new = FloorPiece.of(p.key, ctx.grid._cells(fp), reach)
        if walk.any() and all(q.reachable(walk) for q in reachable + [new]):
            return x, y, h
    return None


def _moved_child(child: Placement, host: Placement, x: float, y: float, yaw: float) -> tuple[float, float, float]:
    """Where a child goes when its host moves from its pose to (x, y, yaw): the same place relative to it."""
    dyaw = yaw - host.yaw
    c, s = math.cos(-host.yaw), math.sin(-host.yaw)
    dx, dy = child.position[0] - host.position[0], child.position[1] - host.position[1]
    local = (c * dx - s * dy, s * dx + c * dy)
    nx, ny = local_to_world(x, y, yaw, local)
    return nx, ny, child.yaw + dyaw


def place_given(shell: RoomShell, placements: list[Placement], seed: int = 0, catalog: Catalog | None = None, *,
                repair: bool = True, defaults: bool = False, required: tuple[str, ...] = (),
                generator: str = "layout", source: str = "", notes: dict | None = None) -> GivenScene:
    """A validated scene of `placements` in `shell` (see the module's docstring for the repairs).

    Args:
        defaults: also place the room type's default small objects (as CSSG draws them) that the layout
            does not have.
        required: object types that must be in the scene (placed by the object layer where missing);
            one that cannot be placed fails the report.
        repair: move pieces that are not where they may be; without it they stay and fail the report.

    The same inputs and seed give the same scene. Placements that need nothing repaired and no objects
    added come out as given: a CSSG scene passed through comes out equal.
    """
    catalog = catalog or default_catalog()
    rng = np.random.default_rng(np.random.SeedSequence([seed, 0]))
    draft = SceneDraft(shell, catalog, rng)
    ordered, repairs = _order(placements)
    doors = shell.door_clearance_zones()
    solid: Solid = []
    kept: list[Placement] = []
    deferred: list[tuple[Placement, list[str]]] = []
    gone: set[str] = {r.key for r in repairs}
    loose: list[Placement] = []
    for p in ordered:
        if p.parent in gone:
            gone.add(p.key)
            repairs.append(Repair(p.key, p.entry.type, "left_out", f"its parent {p.parent} was left out"))
            continue
        if p.parent is None and _layer(p) == "object" and not _lies_on_floor(p):
            loose.append(p)  # no support given: the object layer places it
            continue
        if p.parent is not None or not repair:
            kept.append(p)
            continue
        why = _problems(p, shell, doors, solid)
        if not why:
            kept.append(p)
            solid.append((footprint(p.entry, p.position[0], p.position[1], p.yaw), _z_range(p), p.key))
        elif _floor_piece(p):
            deferred.append((p, why))
        else:
            gone.add(p.key)
            repairs.append(Repair(p.key, p.entry.type, "left_out", "; ".join(why)))
    deferred_keys = {p.key for p, _ in deferred}
    ids: dict[str, str] = {}
    waiting: dict[str, list[Placement]] = {}
    for p in kept:
        if p.parent in deferred_keys or p.parent in waiting:
            waiting.setdefault(p.parent, []).append(p)  # type: ignore[arg-type]
            waiting.setdefault(p.key, [])
            continue
        ids[p.key] = _add(draft, p, p.position[0], p.position[1], p.yaw, ids.get(p.parent or "")).id
    problems: list[str] = []
    if deferred:
        ctx = FloorContext.create(draft)
        for p, why in sorted(deferred, key=lambda d: -d[0].entry.dims[0] * d[0].entry.dims[1]):
            pose = _nearest_pose(ctx, p)
            if pose is None:
                problems.append(f"{p.key} ({p.entry.type}): {'; '.join(why)}, and no free place within "
                                f"{MAX_MOVE:g} m keeps everything reachable")
                repairs.append(Repair(p.key, p.entry.type, "left_out", "; ".join(why)))
                _drop_children(p.key, waiting, repairs)
                continue
            x, y, yaw = pose
            obj = _add(draft, p, x, y, yaw, None)
            ids[p.key] = obj.id
            ctx.commit(obj.id, draft.placed[-1].footprint, reach_of(p.entry, obj.position[2]))
            turn = abs((yaw - p.yaw + math.pi) % (2 * math.pi) - math.pi)
            repairs.append(Repair(p.key, p.entry.type, "moved", "; ".join(why),
                                  round(math.hypot(x - p.position[0], y - p.position[1]), 3), round(turn, 4)))
            _add_children(draft, p, x, y, yaw, waiting, ids)
    repairs += [Repair(p.key, p.entry.type, "left_out", "a small object with nothing it may stand on")
                for p in loose if not supports_for(p.entry.type)]
    for host in [q for q in draft.placed if q.entry.anchors]:  # a sink's basin and faucet, unless given
        have = {q.obj.type for q in draft.placed if q.obj.parent == host.obj.id}
        if not have & {a["type"] for a in host.entry.anchors}:
            for part in add_anchors(draft, host.obj, host.entry):
                repairs.append(Repair(part.id, part.type, "placed", f"part of {host.obj.id}"))
    requests = _object_requests(shell, rng, draft, loose, defaults, required)
    by_name: dict[str, str] = {}
    occupied: dict = {}
    unplaced: list[str] = []
    for req in requests:
        if place_object(draft, req, by_name, occupied):
            ids.setdefault(req.name, by_name[req.name])
            repairs.append(Repair(req.name, req.type, "placed", "by the object layer"))
        else:
            unplaced.append(req.name)
    report = check_layout(draft, requests, FloorContext.create(draft), unplaced, 0)
    scene = draft.to_scene(generator, seed, source=source, notes=notes)
    return GivenScene(Generated(scene, report), repairs, ids, problems)


def _drop_children(key: str, waiting: dict[str, list[Placement]], repairs: list[Repair]) -> None:
    for child in waiting.get(key, []):
        repairs.append(Repair(child.key, child.entry.type, "left_out", f"its parent {key} was left out"))
        _drop_children(child.key, waiting, repairs)


def _add_children(draft: SceneDraft, host: Placement, x: float, y: float, yaw: float,
                  waiting: dict[str, list[Placement]], ids: dict[str, str]) -> None:
    for child in waiting.get(host.key, []):
        cx, cy, cyaw = _moved_child(child, host, x, y, yaw)
        ids[child.key] = _add(draft, child, cx, cy, cyaw, ids[host.key]).id
        _add_children(draft, child, cx, cy, cyaw, waiting, ids)


def _object_requests(shell: RoomShell, rng: np.random.Generator, draft: SceneDraft, loose: list[Placement],
                     defaults: bool, required: tuple[str, ...]) -> list[Request]:
    """What the object layer is to place: the layout's unsupported objects, the room's defaults (optional) and
    the required types the scene lacks. Without relations: each goes on any compatible receptacle."""
    have = {p.obj.type for p in draft.placed}
    out = [Request(p.key, p.entry.type, "object", False, p.entry.id, dict(p.states)) for p in loose
           if supports_for(p.entry.type)]
    have |= {p.entry.type for p in loose}
    for t in required:
        if t not in have:
            out.append(Request(f"{t.lower()}_required", t, "object", True))
            have.add(t)
    if defaults:
        for r in requests_from_cdf(empty_cdf(shell.room_type), shell.room_type, rng, area=shell.area):
            if r.layer == "object" and r.type not in have:
                out.append(Request(r.name, r.type, "object", False))
                have.add(r.type)
    return out
