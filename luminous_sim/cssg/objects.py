"""The object layer: small things on support surfaces or inside receptacles, following the CDF's
on/in relations, ALFRED's compatibility table, and stable, collision-free spots within each region
that the agent can see from where it stands (not in drawers it cannot open, not at the back of a low
shelf)."""

from __future__ import annotations

import math
import zlib
from collections.abc import Callable
from functools import partial

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.cssg.draft import Placed, SceneDraft
from luminous_sim.cssg.requests import Request
from luminous_sim.cssg.tables import fallback_weight, host_weight, ruled_out, supports_for
from luminous_sim.cssg.walls import clashes
from luminous_sim.scene import (
    RegionSpot,
    Shade,
    View,
    blocks_agent,
    edge_slides,
    fits,
    hang_pose,
    hanger_back,
    reach_of,
    region_spots,
    rotate,
    sample_in_region,
    scan_region,
    shades,
)
from luminous_sim.vocab import HANGERS, abilities

MAX_FILL = 0.85
"""Share of a region that footprints may cover before the region counts as full."""


def _hosts(draft: SceneDraft, req: Request, by_name: dict[str, str],
           natural: bool = True) -> tuple[list[Placed], str | None]:
    """Candidate receptacles and the region kind wanted ("surface" for on, "volume" for in); with `natural`,
    for a default object, not those the placement table rules out for the type (`tables.ruled_out`)."""
    support = next((r for r in req.rels if r.relation in ("on", "in")), None)
    if support is not None:
        return draft.referents(by_name.get(support.anchor or "")), (
            "surface" if support.relation == "on" else "volume")
    allowed = {t for t in supports_for(req.type) if not natural or req.explicit or not ruled_out(req.type, t)}
    # default objects never go in wall-mounted cabinets (nobody standing on the floor could see them there), but
    # they do hang on the holders made for them
    return [p for p in draft.placed if p.obj.type in allowed
            and (p.obj.layer not in ("object", "decoration") or p.obj.type in HANGERS)], None


def _facing_point(draft: SceneDraft, req: Request, by_name: dict[str, str]) -> tuple[float, float] | None:
    rel = next((r for r in req.rels if r.relation == "face"), None)
    target = by_name.get(rel.anchor or "") if rel else None
    hit = next((p for p in draft.placed if p.obj.id == target), None)
    if hit is None:
        return None
    c = hit.footprint.centroid
    return (c.x, c.y)


FACING_OUT = frozenset({"appliance"})
"""Categories of objects whose front (a door, a drip tray, a screen: the asset's local +y) is turned to where the
agent stands, as in AI2-THOR, where a microwave never faces the wall or the fridge beside it. Turned at random, a
microwave faced the wall or along the counter into its neighbour, and what was put in it could not be seen, so
could not be pointed at to be taken out again."""

FRONT_CONE = math.cos(math.radians(45.0))
"""An agent stands in front of an object when it is within 45 degrees of the object's facing (and within reach)."""


def _fronts(points: np.ndarray, facing: np.ndarray, eyes: np.ndarray, reach: float) -> np.ndarray:
    """Per (N, 2) world point, how many `eyes` stand in front of it (within `FRONT_CONE` of the unit `facing`
    and within `reach`)."""
    delta = eyes[None] - points[:, None]  # (N, E, 2)
    d = np.maximum(np.hypot(delta[..., 0], delta[..., 1]), 1e-9)
    ahead = (delta @ facing) >= FRONT_CONE * d
    return (ahead & (d <= reach)).sum(axis=1)


def _facing_out(draft: SceneDraft, spot: RegionSpot, entry) -> tuple[tuple[float, float], Callable] | None:
    """For an object of a `FACING_OUT` category: a point for it to face and a test of its footprint's centre
    (the agent can stand in front of it there, within reach). The host's front is kept where the agent can stand
    in front of some of the region (a counter's), else the side it can stand in front of most (a table whose
    front is against a wall). None for other objects, or where the agent stands in front of no side (turned at
    random, as before)."""
    if entry.category not in FACING_OUT:
        return None
    _, eyes = _eyes(draft)
    if not len(eyes):
        return None
    eyes = np.asarray(eyes, dtype=float).reshape(-1, 2)
    local = [(fx * spot.size[0] / 3, fy * spot.size[1] / 3) for fx in (-1, 0, 1) for fy in (-1, 0, 1)]
    points = rotate(np.array(local), spot.yaw) + spot.center
    reach = reach_of(entry, spot.floor_z - entry.bbox_min[2])
    counts = []
    for k in (0, 1, 3, 2):  # the host's front first, then its sides, then its back
        facing = rotate(np.array([[0.0, 1.0]]), spot.yaw + k * math.pi / 2)[0]
        counts.append((int(_fronts(points, facing, eyes, reach).sum()), facing))
    n, facing = counts[0] if counts[0][0] else max(counts, key=lambda c: c[0])
    if not n:
        return None

    def in_front(xy: np.ndarray) -> bool:
        return bool(_fronts(np.asarray(xy, dtype=float)[None], facing, eyes, reach)[0])
    return (spot.center[0] + float(facing[0]), spot.center[1] + float(facing[1])), in_front


def _spots(draft: SceneDraft, host: Placed) -> list[RegionSpot]:
    """`region_spots` of a placed receptacle, computed once per draft and pose, less the regions behind
    doors the agent cannot open (a dresser's drawers: ALFRED opens Drawers, not Dressers)."""
    o = host.obj
    key = ("spots", o.id, o.position, o.yaw, host.entry.id, host.entry.scale)
    if key not in draft.memo:
        openable = abilities(o.type).openable
        draft.memo[key] = [s for s in region_spots(o, host.entry) if openable or not s.gated]
    return draft.memo[key]


def _shade(draft: SceneDraft, host: Placed, region: str) -> Shade:
    key = ("shades", host.entry.id, host.entry.scale)
    if key not in draft.memo:
        draft.memo[key] = shades(host.entry)
    return draft.memo[key].get(region, Shade())


def _eyes(draft: SceneDraft) -> tuple[int, np.ndarray]:
    """Where the agent can stand, as the finished scene will be checked, and a version number that changes
    when it does (objects on furniture do not change it; a plant on the floor, or going back, may)."""
    counted, version, eyes = draft.memo.get("eyes", (0, -1, None))
    if (eyes is None or counted > len(draft.placed)
            or any(blocks_agent(p.obj, p.entry) for p in draft.placed[counted:])):
        version, eyes = version + 1, draft.reachable_grid()
    draft.memo["eyes"] = (len(draft.placed), version, eyes)
    return version, eyes


def _view(draft: SceneDraft, spot: RegionSpot) -> View:
    version, eyes = _eyes(draft)
    key = ("view", spot.host.id, spot.name, version)
    if key not in draft.memo:
        host = next(p for p in draft.placed if p.obj.id == spot.host.id)
        draft.memo[key] = View(_shade(draft, host, spot.name), host.obj.position[:2], host.obj.yaw, eyes,
                               around=(spot.center, 0.5 * float(np.hypot(*spot.size))))
    return draft.memo[key]


def _heights(spot: RegionSpot, height: float) -> tuple[float, float]:
    """Where sight lines aim at an object of `height` in `spot` (as world/sightlines.py aims)."""
    return spot.floor_z + 0.5 * height, spot.floor_z + 0.8 * height


def _sees(view: View, heights: tuple[float, float], xy: np.ndarray) -> bool:
    return view.sees((float(xy[0]), float(xy[1])), heights)


def _seen_somewhere(draft: SceneDraft, spot: RegionSpot, height: float) -> bool:
    """Whether some point of a 3 x 3 lattice over the spot is seen (spots no one sees are not drawn)."""
    key = ("seen", spot.host.id, spot.name, round(height, 1), _eyes(draft)[0])
    if key not in draft.memo:
        local = [(fx * spot.size[0] / 3, fy * spot.size[1] / 3) for fx in (-1, 0, 1) for fy in (-1, 0, 1)]
        points = rotate(np.array(local), spot.yaw) + spot.center
        draft.memo[key] = bool(_view(draft, spot).sees_each(points, _heights(spot, round(height, 1))).any())
    return draft.memo[key]


def _eligible(draft: SceneDraft, entry, hosts: list[Placed], kind: str | None) -> list[RegionSpot]:
    """The regions of `hosts` (of `kind`, if given) that could hold `entry` where the agent sees it."""
    key = ("eligible", entry.id, entry.scale, kind, tuple(h.obj.id for h in hosts), _eyes(draft)[0])
    if key not in draft.memo:
        draft.memo[key] = [s for h in hosts for s in _spots(draft, h)
                           if (kind is None or s.kind == kind)
                           and (h.obj.type in HANGERS or (fits(entry, s) and _seen_somewhere(draft, s, entry.dims[2])))]
    return draft.memo[key]


def _draw_spot(spots: list[RegionSpot], object_type: str, by_frequency: bool, rng: np.random.Generator) -> int:
    """Index of a spot drawn uniformly or (for an object the CDF does not put anywhere) with each host type as
    likely as ALFRED's scenes put this type there (`tables.host_weight`), that weight shared among the spots of
    all hosts of that type. Where no spot is on a host ALFRED used for the type, the back-off
    (`tables.fallback_weight`: how often ALFRED puts anything there) weighs the compatible hosts instead."""
    if not by_frequency:
        return int(rng.integers(len(spots)))
    per_type: dict[str, int] = {}
    for s in spots:
        per_type[s.host.type] = per_type.get(s.host.type, 0) + 1
    w = np.array([host_weight(object_type, s.host.type) / per_type[s.host.type] for s in spots])
    if not w.any():
        w = np.array([fallback_weight(object_type, s.host.type) / per_type[s.host.type] for s in spots])
    if not w.any():  # a CDF object with nowhere better to go (a baseball bat in a room with only a bed)
        w = np.ones(len(spots))
    return int(min(np.searchsorted(np.cumsum(w), rng.random() * w.sum(), side="right"), len(spots) - 1))


def place_object(draft: SceneDraft, req: Request, by_name: dict[str, str],
                 occupied: dict[tuple[str, str], list[Polygon]], natural: bool = True) -> bool:
    """Place one object request; False if no compatible region has room for it. Without `natural` (the
    uniform baseline), every compatible region is as likely as any other."""
    hosts, kind = _hosts(draft, req, by_name, natural)
    facing = _facing_point(draft, req, by_name)
    variants = req.variants(draft.catalog)
    for _ in range(6):
        if not variants:
            return False
        entry = variants[int(draft.rng.integers(len(variants)))]
        spots = _eligible(draft, entry, hosts, kind)
        if not spots:
            continue
        spot = spots[_draw_spot(spots, req.type, natural and kind is None, draft.rng)]
        key = (spot.host.id, spot.name)
        if key not in occupied:  # whatever already stands there (burners on a counter) takes room
            occupied[key] = [p.footprint for p in draft.placed if p.obj.parent == spot.host.id]
        hanging = spot.host.type in HANGERS
        if hanging:
            host = next(p for p in draft.placed if p.obj.id == spot.host.id)
            got = None if occupied[key] else hang_pose(entry, spot, host_back=hanger_back(host.entry, spot.name))
            if got is not None and clashes(draft, entry, got[0], got[1], got[3], got[2] + entry.bbox_min[2],
                                           ignore=spot.host.id):
                got = None  # a towel hanging down into what stands below its holder
        else:
            sees = partial(_sees, _view(draft, spot), _heights(spot, entry.dims[2]))
            face, accept = facing, sees
            out = _facing_out(draft, spot, entry) if facing is None else None
            if out is not None:  # an appliance: its front to where the agent stands, and the agent in front of it
                face, accept = out[0], (lambda xy, front=out[1], sees=sees: front(xy) and sees(xy))
            got = sample_in_region(entry, spot, draft.rng, occupied[key], facing=face, accept=accept,
                                   max_fill=MAX_FILL)
        if got is None:
            continue
        x, y, z, yaw, fp = got
        occupied[key].append(fp)
        obj = draft.add(entry, x, y, z, yaw, "object", fixed=hanging, parent=spot.host.id, region=spot.name,
                        name=req.name, states=req.states, color=req.colour())
        by_name[req.name] = obj.id
        return True
    return False


def _held_entry(draft: SceneDraft, object_type: str, by_name: dict[str, str], requests: list[Request]):
    """The asset a put will bring of `object_type`: the CDF's own object of that type where it is placed
    already, else the variant with the largest footprint (so that whichever is drawn fits)."""
    ids = {by_name[r.name] for r in requests if r.type == object_type and r.name in by_name}
    placed = next((p.entry for p in draft.placed if p.obj.id in ids), None)
    if placed is not None:
        return placed
    variants = draft.catalog.of_type(object_type)
    return max(variants, key=lambda e: e.dims[0] * e.dims[1]) if variants else None


def reserve_for_goal(draft: SceneDraft, requests: list[Request], by_name: dict[str, str],
                     occupied: dict[tuple[str, str], list[Polygon]]) -> list[tuple[str, str]]:
    """Keep room in each receptacle the CDF's goal puts things in (`Request.goal_puts`) before the room's
    default objects fill it: the footprints of as many of the put things as the goal puts there, side by
    side in one region where the agent sees them (hung, on a hanger), are marked taken. A receptacle with
    no such room is left as it is. Draws come from a stream of their own (the sample's is not touched).
    Returns the (host id, region) pairs reserved."""
    done = []
    for req in requests:
        if not req.goal_puts or req.name not in by_name:
            continue
        hosts = draft.referents(by_name[req.name])
        for object_type, count in sorted(req.goal_puts.items()):
            entry = _held_entry(draft, object_type, by_name, requests)
            if entry is None:
                continue
            rng = np.random.default_rng(zlib.crc32(f"{req.name}:{object_type}".encode()))
            spots = _eligible(draft, entry, hosts, None)
            for i in rng.permutation(len(spots)):
                spot = spots[int(i)]
                key = (spot.host.id, spot.name)
                taken = occupied.get(key)
                if taken is None:
                    taken = [p.footprint for p in draft.placed if p.obj.parent == spot.host.id]
                kept = _reserve_in(draft, entry, spot, taken, count, rng)
                if kept:
                    occupied[key] = taken + kept
                    done.append(key)
                    break
    return done


def _reserve_in(draft: SceneDraft, entry, spot: RegionSpot, taken: list[Polygon], count: int,
                rng: np.random.Generator) -> list[Polygon]:
    """Footprints for `count` of `entry` in the spot beside what is `taken` (one, hung, on a free hanger);
    [] when they do not all fit."""
    if spot.host.type in HANGERS:
        host = next(p for p in draft.placed if p.obj.id == spot.host.id)
        return [] if taken else [hang_pose(entry, spot, host_back=hanger_back(host.entry, spot.name))[4]]
    kept: list[Polygon] = []
    accept = partial(_sees, _view(draft, spot), _heights(spot, entry.dims[2]))
    for _ in range(count):
        got = sample_in_region(entry, spot, rng, taken + kept, tries=40, accept=accept)
        if got is None:
            got = next(scan_region(entry, spot, taken + kept, accept=accept), None)
        if got is None:
            return []
        if count > 1:  # against an edge, leaving room beside it for the next
            got = next((c for c in edge_slides(got, spot) if not any(c[4].intersects(o) for o in taken + kept)
                        and accept(np.array(c[4].centroid.coords[0]))), got)
        kept.append(got[4])
    return kept
