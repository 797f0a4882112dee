"""Whether a finished scene is arranged as people arrange rooms: the measures of the natural-room rules,
read off the scene's geometry alone (so the uniform baseline is measured exactly as CSSG is).

- functional groups: seats at a table and facing it, bar stools at a counter's front and facing it, a sofa
  facing the TV or coffee table, armchairs facing the seating group, bedside tables at the bed's head, no
  sofa against a dining table, no drawer unit standing free of the walls;
- dead zones: the share of free floor the agent reaches, and the largest region it cannot walk into;
- alignment: floor furniture square to the (rectilinear) room;
- hosts: small objects on receptacles the placement table allows for them (no sports gear on a bed), on a
  receptacle ALFRED uses for them, and, lying on the floor (a basketball, a plunger), against a wall or in a
  corner.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import LineString, Polygon

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cssg.requests import rule_tags
from luminous_sim.cssg.tables import object_hosts, placement
from luminous_sim.scene import (
    STEP,
    Scene,
    SceneObject,
    Shade,
    View,
    blocks_agent,
    footprint,
    label4,
    region_spots,
    rotate,
    scene_reachable_grid,
    shades,
)
from luminous_sim.vocab import HANGERS, abilities
from luminous_sim.vocab.agent_body import AGENT_RADIUS

SEATS = frozenset({"Chair", "Stool", "Footstool"})
TABLES = frozenset({"DiningTable", "Desk", "CounterTop"})
SEAT_GAP, SEAT_RAY = 0.5, 1.2
"""A seat is at a table within SEAT_GAP m of it, facing it when a ray SEAT_RAY m long from its centre meets it."""
VIEW_RAY = 4.0
"""How far (m) a sofa or an armchair looks for what it faces."""
COUNTERS = frozenset({"CounterTop"})
"""What a bar stool (a Chair variant with an implicit rule's variant tag) stands at."""
SOFA_TARGETS = frozenset({"TVStand", "CoffeeTable"})
GROUP = frozenset({"Sofa", "CoffeeTable", "TVStand", "Ottoman"})
"""The seating group an armchair faces."""
HEAD_GAP, HEAD_DEPTH = 0.3, 0.7
"""A bedside table is within HEAD_GAP m of the bed, its centre within HEAD_DEPTH m of the bed's head end."""
DINING_CLEAR = 0.5
"""Least gap (m) between a sofa and a dining table."""
WALL_GAP = 0.15
"""A piece stands against a wall when its back is within this many metres of one."""
SQUARE_TOL = math.radians(2.0)


@dataclass(frozen=True)
class Check:
    """One natural-room rule applied to one object of a scene."""

    rule: str
    subject: str
    met: bool


def _front(yaw: float) -> np.ndarray:
    return np.array([-math.sin(yaw), math.cos(yaw)])


def _floor_pieces(scene: Scene, catalog: Catalog) -> dict[str, tuple[SceneObject, Polygon]]:
    """Free-standing things on the floor (furniture and fixtures) with their footprints."""
    out = {}
    for o in scene.objects:
        if o.parent is None and o.layer in ("furniture", "fixture"):
            e = catalog.for_object(o)
            out[o.id] = (o, footprint(e, o.position[0], o.position[1], o.yaw))
    return out


def _ray(fp: Polygon, yaw: float, length: float) -> LineString:
    c = np.array(fp.centroid.coords[0])
    return LineString([c, c + length * _front(yaw)])


def _front_strip(fp: Polygon, yaw: float, length: float) -> Polygon:
    """What the middle half of a piece's front looks out on, `length` metres ahead (a sofa's view)."""
    front = _front(yaw)
    side = np.array([front[1], -front[0]])
    c = np.array(fp.centroid.coords[0])
    rel = [np.array(p) - c for p in fp.exterior.coords]
    half = max(abs(float(np.dot(r, side))) for r in rel) / 2
    ahead = max(float(np.dot(r, front)) for r in rel)
    a, b = c + ahead * front, c + (ahead + length) * front
    return Polygon([a - half * side, a + half * side, b + half * side, b - half * side])


def _back_gap(fp: Polygon, yaw: float, room: Polygon) -> float:
    """Distance (m) from the middle of a footprint's back edge to the room's outline."""
    front = _front(yaw)
    c = np.array(fp.centroid.coords[0])
    back = min(float(np.dot(np.array(p) - c, front)) for p in fp.exterior.coords)
    return float(room.exterior.distance(shapely.Point(c + back * front)))


def functional_checks(scene: Scene, catalog: Catalog | None = None) -> list[Check]:
    """The functional-group rules that apply in this scene, one check per object they apply to."""
    catalog = catalog or default_catalog()
    pieces = _floor_pieces(scene, catalog)
    room = scene.room.polygon()

    def of(types: frozenset[str] | set[str]) -> list[tuple[SceneObject, Polygon]]:
        return [v for v in pieces.values() if v[0].type in types]

    out: list[Check] = []
    tables = of(TABLES)
    for o, fp in of(SEATS):
        ray = _ray(fp, o.yaw, SEAT_RAY)
        met = any(fp.distance(t) <= SEAT_GAP and ray.intersects(t) for _, t in tables)
        out.append(Check("seat at a table, facing it", o.id, met))
    targets = of(SOFA_TARGETS)
    if targets:
        for o, fp in of({"Sofa"}):
            view = _front_strip(fp, o.yaw, VIEW_RAY)
            out.append(Check("sofa facing the TV or coffee table", o.id, any(view.intersects(t) for _, t in targets)))
    group = of(GROUP)
    for o, fp in of({"ArmChair"}):
        if group:
            ray = _ray(fp, o.yaw, VIEW_RAY)
            out.append(Check("armchair facing the seating group", o.id, any(ray.intersects(t) for _, t in group)))
        else:
            out.append(Check("armchair facing the seating group", o.id, _back_gap(fp, o.yaw, room) <= WALL_GAP))
    beds = of({"Bed"})
    if beds:
        for o, fp in of({"SideTable"}):
            out.append(Check("side table at the bed's head", o.id, any(_at_head(fp, b, bfp) for b, bfp in beds)))
    dining = of({"DiningTable"})
    for o, fp in of({"Sofa"}):
        if dining:
            out.append(Check("sofa clear of the dining table", o.id,
                             all(fp.distance(t) >= DINING_CLEAR for _, t in dining)))
    for o, fp in of({"Drawer"}):
        out.append(Check("drawer unit against a wall", o.id, _back_gap(fp, o.yaw, room) <= WALL_GAP))
    counters = of(COUNTERS)
    for o, fp in of(SEATS):
        if set(catalog.for_object(o).tags) & rule_tags():  # a bar stool: at a counter, facing its front
            ray = _ray(fp, o.yaw, SEAT_RAY)
            out.append(Check("stool at a counter, facing it", o.id,
                             any(fp.distance(t) <= SEAT_GAP and ray.intersects(t) and _faces_front(o, c)
                                 for c, t in counters)))
    return out


def _faces_front(seat: SceneObject, counter: SceneObject) -> bool:
    """Whether a seat looks at a counter's front (the two face each other), not at its end."""
    return float(np.dot(_front(seat.yaw), _front(counter.yaw))) < -0.9


def _at_head(fp: Polygon, bed: SceneObject, bed_fp: Polygon) -> bool:
    """Whether footprint `fp` stands beside the bed, near its head end (the bed's back)."""
    if fp.distance(bed_fp) > HEAD_GAP:
        return False
    front = _front(bed.yaw)
    depths = [float(np.dot(np.array(p), front)) for p in bed_fp.exterior.coords]
    head = min(depths)
    return float(np.dot(np.array(fp.centroid.coords[0]), front)) - head <= HEAD_DEPTH


@dataclass(frozen=True)
class FloorReach:
    """The agent's grid points clear of everything on the floor, and how many of them it reaches."""

    free: int
    reached: int
    largest_cut_off: float
    """Area (m^2, STEP x STEP per point) of the largest connected region the agent cannot walk into."""

    @property
    def share(self) -> float:
        return self.reached / self.free if self.free else 1.0


def floor_reach(scene: Scene, catalog: Catalog | None = None) -> FloorReach:
    """How much of the free floor the agent reaches from its start (anywhere in the largest connected part,
    where the simulator puts it)."""
    catalog = catalog or default_catalog()
    pts = scene.room.grid_points(STEP, clearance=AGENT_RADIUS, avoid_fixtures=False).reshape(-1, 2)
    obstacles = [footprint(e, o.position[0], o.position[1], o.yaw)
                 for o in scene.objects if blocks_agent(o, e := catalog.for_object(o))]
    if len(pts) and obstacles:
        hit = np.zeros(len(pts), dtype=bool)
        hit[shapely.STRtree(obstacles).query(shapely.points(pts), predicate="dwithin", distance=AGENT_RADIUS)[0]] = True
        pts = pts[~hit]
    if len(pts) == 0:
        return FloorReach(0, 0, 0.0)
    keys = np.round(pts / STEP).astype(int)
    keys -= keys.min(axis=0)
    image = np.zeros(tuple(keys.max(axis=0) + 1), dtype=bool)
    image[keys[:, 0], keys[:, 1]] = True
    labels, _ = label4(image)
    sizes = sorted(np.bincount(labels[keys[:, 0], keys[:, 1]])[1:], reverse=True)
    return FloorReach(len(pts), int(sizes[0]), float(sizes[1]) * STEP * STEP if len(sizes) > 1 else 0.0)


def alignment_checks(scene: Scene) -> list[Check]:
    """Floor furniture square to the room (the rooms are rectilinear): parallel to the wall it stands
    against, and aligned with the room (hence with its group) in the open."""
    out = []
    for o in scene.objects:
        if o.parent is None and o.layer == "furniture":
            off = abs((o.yaw + math.pi / 4) % (math.pi / 2) - math.pi / 4)
            out.append(Check("square to the room", o.id, off <= SQUARE_TOL))
    return out


def host_checks(scene: Scene, catalog: Catalog | None = None) -> list[Check]:
    """Small objects on a host the placement table does not rule out for their type (`never_on`), and, for
    types ALFRED's scenes tell us about (data/object_hosts.json), on a host they use for it: over every such
    object, and over those whose room holds a receptacle of a type ALFRED uses for it with a region the agent
    can reach into from where it stands (where the rule applies; elsewhere CSSG backs off to the compatibility
    table). A region the agent cannot see into within reach (a bathtub's bottom) holds nothing it could pick up,
    so it does not count; nor does a cabinet on the wall, where no one standing
    on the floor sees in (CSSG puts no default object there)."""
    catalog = catalog or default_catalog()
    never = placement()["never_on"]
    seen = object_hosts()
    by_id = {o.id: o for o in scene.objects}
    eyes = scene_reachable_grid(scene, catalog).reshape(-1, 2)
    usable = {o.type for o in scene.objects if o.type in _host_types()
              and (o.layer != "decoration" or o.type in HANGERS)  # not a wall cabinet above the counter
              and _reached(o, catalog.for_object(o), eyes)}
    out = []
    for o in scene.objects:
        host = by_id.get(o.parent or "")
        if o.layer != "object" or host is None:
            continue
        if o.type in never:
            out.append(Check("not on a host ruled out", o.id, host.type not in never[o.type]))
        if o.type in seen:
            met = host.type in seen[o.type]
            out.append(Check("on ALFRED's host (any room)", o.id, met))
            if usable & set(seen[o.type]):
                out.append(Check("on ALFRED's host (room has one)", o.id, met))
    return out


SMALL = 0.05
"""Height (m) of the small object the agent must see and reach in a region for the region to count."""


def _reached(host: SceneObject, entry, eyes: np.ndarray) -> bool:
    """Whether the agent, standing on one of `eyes` (its reachable grid), sees and reaches a small object
    somewhere on a 3 x 3 lattice over one of the host's regions (as CSSG's object layer tests its spots): a
    bathtub's bottom is too low, too far in and behind its rim."""
    shade = shades(entry)
    for spot in region_spots(host, entry):
        if spot.gated and not abilities(host.type).openable:
            continue
        local = [(fx * spot.size[0] / 3, fy * spot.size[1] / 3) for fx in (-1, 0, 1) for fy in (-1, 0, 1)]
        points = rotate(np.array(local), spot.yaw) + np.array(spot.center)
        view = View(shade.get(spot.name, Shade()), host.position[:2], host.yaw, eyes,
                    around=(spot.center, 0.5 * float(np.hypot(*spot.size))))
        if view.sees_each(points, (spot.floor_z + 0.5 * SMALL, spot.floor_z + 0.8 * SMALL)).any():
            return True
    return False


def _host_types() -> set[str]:
    return {t for hosts in object_hosts().values() for t in hosts}


def floor_object_checks(scene: Scene, catalog: Catalog | None = None) -> list[Check]:
    """Small objects lying or standing on the floor (no host): against a wall or in a corner, as ALFRED's
    scenes keep them, not in the middle of the room."""
    catalog = catalog or default_catalog()
    room = scene.room.polygon()
    out = []
    for o in scene.objects:
        if o.layer == "object" and o.parent is None:
            fp = footprint(catalog.for_object(o), o.position[0], o.position[1], o.yaw)
            out.append(Check("on the floor, against a wall", o.id, _back_gap(fp, o.yaw, room) <= WALL_GAP))
    return out
