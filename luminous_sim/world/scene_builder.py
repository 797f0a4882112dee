"""Build a Scene into one PyBullet client: floor, walls with openings, ceiling, the outdoors around the room,
and every object; then settle."""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import pairwise

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.assets.materials import palette
from luminous_sim.scene import Scene, SceneError, SceneObject
from luminous_sim.world.asset_loader import (
    LoadedAsset,
    base_link_pose,
    load_asset,
    set_joint,
    show_state,
)
from luminous_sim.world.client import BulletClient, new_client, p


@dataclass
class BuiltScene:
    """A scene living in a client: object id -> loaded asset, and the structure bodies."""

    client: BulletClient
    scene: Scene
    objects: dict[str, LoadedAsset]
    floor: int
    walls: list[int] = field(default_factory=list)
    painted_structure: list[int] = field(default_factory=list)
    """Visual-only copies of the floor slabs, walls, ceiling and outdoors, made after the objects so that
    TinyRenderer paints them last (see `paint_structure_last`); the physical bodies keep alpha 0."""
    overhead: list[int] = field(default_factory=list)
    """The ceiling, its light and the outdoors beyond windows and doorways as drawn (their painted copies where
    the structure is painted last), left out of top-down views."""
    outdoors: list[int] = field(default_factory=list)
    """The outdoors as drawn (the last of `overhead`): ground, sky and sky walls, axis-aligned boxes seen only
    through doorways and windows (see `world.portals`)."""
    slabs: list[int] = field(default_factory=list)
    """The visible floor slabs (physical bodies; `floor` is the hidden slab under them all)."""

    def close(self) -> None:
        """Disconnect the scene's PyBullet client."""
        self.client.disconnect()

    def pose_of(self, object_id: str) -> tuple[np.ndarray, float]:
        """Base-link position and yaw of an object now."""
        pos, orn = base_link_pose(self.client, self.objects[object_id].body)
        return np.array(pos), float(self.client.getEulerFromQuaternion(orn)[2])


def _box(client: BulletClient, center, size, yaw: float, rgba) -> int:
    half = [s / 2 for s in size]
    shape = client.createCollisionShape(p.GEOM_BOX, halfExtents=half)
    visual = client.createVisualShape(p.GEOM_BOX, halfExtents=half, rgbaColor=list(rgba))
    return client.createMultiBody(0, shape, visual, list(center), client.getQuaternionFromEuler([0, 0, yaw]))


def paint_structure_last(client: BulletClient, bodies: list[int]) -> dict[int, int]:
    """Give each visible structure box a visual-only copy (no collision, no mass) made now, after the objects,
    and hide the original's visual; each original's copy, in the order made.

    TinyRenderer draws visuals in the order they were made and shades every pixel that passes the depth
    test, so the floor and walls, made first, were shaded in full and then painted over by everything in
    front of them. Drawn last, nearest first (floor and walls, then the ceiling, then the outdoors, which
    only windows and doorways show), their hidden pixels fail the depth test and are never shaded, with the
    same pixels (tests/world/test_culling.py). Painting the floor and walls last but the ceiling and the
    outdoors still first costs more than it saves: those, drawn into an empty frame, are shaded in full and
    then painted over (15% slower at 300x300, measured). The physical bodies, their ids and the physics are
    unchanged; a frame's segmentation shows a copy's id where it showed the original's (neither is an object).
    """
    copies: dict[int, int] = {}
    for body in bodies:
        shape = client.getVisualShapeData(body)[0]
        if shape[7][3] == 0:
            continue
        pos, orn = client.getBasePositionAndOrientation(body)
        visual = client.createVisualShape(p.GEOM_BOX, halfExtents=[d / 2 for d in shape[3]], rgbaColor=list(shape[7]))
        copies[body] = client.createMultiBody(0, -1, visual, pos, orn)
        client.changeVisualShape(body, -1, rgbaColor=[*shape[7][:3], 0.0])
    return copies


def _apply_states(client: BulletClient, obj: SceneObject, loaded: LoadedAsset) -> None:
    if obj.states.get("isOpen"):
        for j in loaded.entry.joints:
            if j["role"] in ("door", "drawer", "lid"):
                set_joint(client, loaded, j["name"], j["upper"])
    else:
        for j in loaded.entry.joints:
            if j["kind"] != "fixed":
                set_joint(client, loaded, j["name"], j["lower"])
    if obj.states.get("isToggled"):
        show_state(client, loaded, "on", True)
    if obj.states.get("isDirty"):
        show_state(client, loaded, "dirty", True)


def floor_rectangles(poly) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """Cover a rectilinear floor polygon with axis-aligned rectangles (vertical strips between vertices).

    Each strip's part of the polygon is a rectangle, up to floating point: two vertices meant to share an
    x (2.755 and 2.7550000000000003 after buffering) leave a sliver of the neighbouring strip hanging off
    it, and the bounds of that shape would cover floor outside the outline. Such a shape is cut at the
    strip's middle instead, where it is the strip's true cross-section.
    """
    from shapely.geometry import LineString, box

    xs = sorted({round(x, 6) for x, _ in poly.exterior.coords})
    miny, maxy = poly.bounds[1], poly.bounds[3]
    out = []
    for x0, x1 in pairwise(xs):
        piece = poly.intersection(box(x0, miny - 1, x1, maxy + 1))
        for g in getattr(piece, "geoms", [piece]):
            if g.area > 1e-9:
                bx0, by0, bx1, by1 = g.bounds
                if g.area >= (bx1 - bx0) * (by1 - by0) - 1e-9:
                    out.append(((bx0, by0), (bx1, by1)))
                    continue
                mid = g.intersection(LineString([((x0 + x1) / 2, by0 - 1), ((x0 + x1) / 2, by1 + 1)]))
                for span in getattr(mid, "geoms", [mid]):
                    if span.length > 1e-9:
                        out.append(((bx0, span.bounds[1]), (bx1, span.bounds[3])))
    return out


MAX_DEEP_OVERLAPS = 8
"""The most movable objects one movable object may lie deep inside (boxes sharing over half the smaller one's
volume) before a scene is refused as not physical: generated scenes have none, and objects stacked into one spot
(300 of them: about 240 s of settling, each step colliding every pair) have hundreds."""
OVERLAP_SHARE = 0.5
OVERLAP_CHUNK = 256


def _world_boxes(objects: list[SceneObject], catalog: Catalog) -> tuple[np.ndarray, np.ndarray]:
    """Axis-aligned world boxes (lo, hi; n x 3) of the objects' assets at their poses and scales."""
    lo, hi = np.empty((len(objects), 3)), np.empty((len(objects), 3))
    for i, obj in enumerate(objects):
        entry = catalog.for_object(obj)
        (x0, y0, z0), (x1, y1, z1) = entry.bbox_min, entry.bbox_max
        c, s = np.cos(obj.yaw), np.sin(obj.yaw)
        corners = np.array([(x, y) for x in (x0, x1) for y in (y0, y1)]) @ np.array([[c, s], [-s, c]])
        px, py, pz = obj.position
        lo[i] = (px + corners[:, 0].min(), py + corners[:, 1].min(), pz + z0)
        hi[i] = (px + corners[:, 0].max(), py + corners[:, 1].max(), pz + z1)
    return lo, hi


def check_stacking(scene: Scene, catalog: Catalog) -> None:
    """Refuse a scene whose movable objects are stacked into one another (deterministic, before any physics).

    Raises:
        SceneError: a movable object lies deep inside more than `MAX_DEEP_OVERLAPS` others (not its parent or
            children): the worst one is named with how many.
    """
    movable = [o for o in scene.objects if not o.fixed]
    if len(movable) <= MAX_DEEP_OVERLAPS:
        return
    lo, hi = _world_boxes(movable, catalog)
    volume = np.prod(np.maximum(hi - lo, 1e-6), axis=1)
    index = {o.id: i for i, o in enumerate(movable)}
    family = [(i, index[o.parent]) for i, o in enumerate(movable) if o.parent in index]
    counts = np.zeros(len(movable), dtype=int)
    for start in range(0, len(movable), OVERLAP_CHUNK):
        rows = slice(start, start + OVERLAP_CHUNK)
        shared = np.prod(np.clip(np.minimum(hi[rows, None], hi[None]) - np.maximum(lo[rows, None], lo[None]), 0, None),
                         axis=2)
        deep = shared > OVERLAP_SHARE * np.minimum(volume[rows, None], volume[None])
        for i in range(deep.shape[0]):
            deep[i, start + i] = False
        for a, b in family:  # a child inside its receptacle is designed to be there
            for r, c in ((a, b), (b, a)):
                if start <= r < start + deep.shape[0]:
                    deep[r - start, c] = False
        counts[rows] = deep.sum(axis=1)
    worst = int(np.argmax(counts))
    if counts[worst] > MAX_DEEP_OVERLAPS:
        raise SceneError(f"lies deep inside {counts[worst]} other movable objects (at most {MAX_DEEP_OVERLAPS}: "
                         "luminous_sim.world.scene_builder.MAX_DEEP_OVERLAPS); objects stacked into one another are "
                         "not a physical scene", object_id=movable[worst].id, field="position")


def build_scene(scene: Scene, catalog: Catalog | None = None, client: BulletClient | None = None,
                settle_steps: int = 240, lod: bool = False, structure_last: bool = True) -> BuiltScene:
    """Create the room and objects in `client` (a new DIRECT one by default) and let them settle; `lod`
    loads the assets' level-of-detail visuals, `structure_last` paints the floor and walls after the objects
    (`paint_structure_last`); neither changes the physics.

    Raises:
        SceneError: objects stacked into one another (`check_stacking`), before anything is loaded.
    """
    catalog = catalog or default_catalog()
    check_stacking(scene, catalog)
    client = client or new_client()
    room = scene.room
    minx, miny, maxx, maxy = room.bounds
    rng = np.random.default_rng(scene.seed)
    floor_rgba = palette("floor")[int(rng.integers(len(palette("floor"))))]
    wall_rgba = palette("wall")[int(rng.integers(len(palette("wall"))))]
    t = room.wall_thickness
    floor = _box(client, ((minx + maxx) / 2, (miny + maxy) / 2, -0.15),
                 (maxx - minx + 2 * t, maxy - miny + 2 * t, 0.1), 0.0, (1, 1, 1, 0))
    slabs = []
    for lo, hi in floor_rectangles(room.polygon().buffer(t / 2, join_style="mitre")):
        slab = _box(client, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, -0.05), (hi[0] - lo[0], hi[1] - lo[1], 0.1),
                    0.0, floor_rgba)
        client.changeDynamics(slab, -1, lateralFriction=0.9)
        slabs.append(slab)
    walls = [_box(client, w.center, w.size, w.yaw, wall_rgba) for w in room.wall_boxes()]
    ceiling = _ceiling(client, room)
    outdoors = _outdoors(client, room)
    overhead = ceiling + outdoors
    objects: dict[str, LoadedAsset] = {}
    for obj in scene.objects:
        entry = catalog.for_object(obj)
        loaded = load_asset(client, entry, obj.position, obj.yaw, fixed=obj.fixed,
                            rng=np.random.default_rng(obj.color_seed), color=obj.color, lod=lod)
        _apply_states(client, obj, loaded)
        objects[obj.id] = loaded
    painted = paint_structure_last(client, slabs + walls + overhead) if structure_last else {}
    built = BuiltScene(client, scene, objects, floor, walls, list(painted.values()),
                       [painted.get(b, b) for b in overhead], [painted.get(b, b) for b in outdoors], slabs)
    settle(built, settle_steps)
    return built


CEILING_RGBA = (0.94, 0.93, 0.9, 1.0)
LIGHT_RGBA = (1.0, 0.97, 0.86, 1.0)
LIGHT_SIZE = (0.45, 0.45, 0.04)
GROUND_RGBA = (0.42, 0.5, 0.36, 1.0)
SKY_RGBA = (0.62, 0.78, 0.93, 1.0)
OUTDOORS = 4.0
"""Metres from the room's outline to the sky around it (within the egocentric camera's 20 m far plane)."""
SKY_HEIGHT = 8.0


def _ceiling(client: BulletClient, room) -> list[int]:
    """A ceiling slab over the walls' outline at wall height, and a ceiling light in the middle of the room."""
    t = room.wall_thickness
    h = room.wall_height
    out = [_box(client, ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, h + 0.05), (hi[0] - lo[0], hi[1] - lo[1], 0.1),
                0.0, CEILING_RGBA)
           for lo, hi in floor_rectangles(room.polygon().buffer(t / 2, join_style="mitre"))]
    c = room.polygon().representative_point() if not room.polygon().contains(room.polygon().centroid) \
        else room.polygon().centroid
    out.append(_box(client, (c.x, c.y, h - LIGHT_SIZE[2] / 2), LIGHT_SIZE, 0.0, LIGHT_RGBA))
    return out


def _outdoors(client: BulletClient, room) -> list[int]:
    """Ground and sky around the room, seen through its windows and doorways instead of the void."""
    minx, miny, maxx, maxy = room.bounds
    x0, y0, x1, y1 = minx - OUTDOORS, miny - OUTDOORS, maxx + OUTDOORS, maxy + OUTDOORS
    cx, cy, w, d = (x0 + x1) / 2, (y0 + y1) / 2, x1 - x0, y1 - y0
    out = [_box(client, (cx, cy, -0.25), (w, d, 0.1), 0.0, GROUND_RGBA),
           _box(client, (cx, cy, SKY_HEIGHT), (w, d, 0.1), 0.0, SKY_RGBA)]
    z, tall = (SKY_HEIGHT - 0.3) / 2, SKY_HEIGHT + 0.3  # from below the ground up: no gap at the horizon
    for center, size in (((cx, y0, z), (w, 0.1, tall)), ((cx, y1, z), (w, 0.1, tall)),
                         ((x0, cy, z), (0.1, d, tall)), ((x1, cy, z), (0.1, d, tall))):
        out.append(_box(client, center, size, 0.0, SKY_RGBA))
    return out


REST_SPEED, REST_SPIN = 0.005, 0.05
"""Metres and radians per second under which a body counts as at rest."""
MIN_SETTLE_STEPS, REST_CHECK = 60, 12
"""Steps always taken (a quarter second: long enough for a tipping object to gather speed), and how
often rest is checked after that."""


def settle(built: BuiltScene, max_steps: int = 240) -> int:
    """Step the simulation until every movable object is at rest, or for `max_steps`; the steps taken.

    Things are placed 2 mm above their support and come to rest within a few dozen steps; stopping then,
    rather than always simulating a full second, makes building a kitchen several times faster. The
    same scene always takes the same number of steps.
    """
    c = built.client
    moving = [built.objects[o.id].body for o in built.scene.objects if not o.fixed and o.id in built.objects]
    for step in range(1, max_steps + 1):
        c.stepSimulation()
        if step >= MIN_SETTLE_STEPS and step % REST_CHECK == 0 and all(_at_rest(c, b) for b in moving):
            return step
    return max_steps


def _at_rest(client, body: int) -> bool:
    lin, ang = client.getBaseVelocity(body)
    return float(np.linalg.norm(lin)) < REST_SPEED and float(np.linalg.norm(ang)) < REST_SPIN


@dataclass(frozen=True)
class SettleReport:
    """How far each movable object went while settling, and which ones fell or left their support."""

    moved: dict[str, float]
    fell: list[str]


MOVED_XY, MOVED_Z, FELL_Z = 0.01, 0.02, 0.05
"""An object *moved* if it slid or rolled more than 1 cm, or rose or sank more than 2 cm (settling a few
millimetres onto its support is not moving); it *fell* if it ended more than 5 cm lower."""


def settle_report(built: BuiltScene) -> SettleReport:
    """Compare every movable object's pose now with its scene pose."""
    moved, fell = {}, []
    for obj in built.scene.objects:
        if obj.fixed:
            continue
        pos, _ = built.pose_of(obj.id)
        delta = pos - np.array(obj.position)
        if float(np.linalg.norm(delta[:2])) > MOVED_XY or abs(float(delta[2])) > MOVED_Z:
            moved[obj.id] = round(float(np.linalg.norm(delta)), 4)
        if delta[2] < -FELL_Z:
            fell.append(obj.id)
    return SettleReport(moved, fell)
