"""Where a put lands: a free, stable pose in the receptacle's open regions, within reach of the agent
and in its view where it can be (AI2-THOR puts things where the agent looks). The same search, given
its own random stream, is the dry run planning uses to ask whether something would fit."""

from __future__ import annotations

import math
from dataclasses import replace as dc_replace
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.scene import (
    View,
    edge_slides,
    hang_pose,
    hanger_back,
    open_tops,
    region_spots,
    sample_in_region,
    scan_region,
    shades,
)
from luminous_sim.scene.model import SceneObject
from luminous_sim.states.model import WorldState
from luminous_sim.vocab import HANGERS, PILING_RECEPTACLES, abilities
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT
from luminous_sim.world.asset_loader import base_link_pose
from luminous_sim.world.client import body_aabb
from luminous_sim.world.hand import release
from luminous_sim.world.reach import type_of

if TYPE_CHECKING:
    from luminous_sim.world.world import World

Spot = tuple[float, float, float, float]
"""A put pose: x, y, z of the base link and yaw."""

CENTRED_ON = frozenset({"StoveBurner"})
"""Receptacles that take a vessel larger than their support, centred on it (a pan's handle over the edge
of its burner, as AI2-THOR sets pans and pots on burners)."""
VIEW_TRIES = 8
"""Draws of a put pose looking for one in the agent's view."""
SCAN_VIEW_CHECKS = 12
"""Scanned poses tried for a clear view before a put takes the first free one (or a dry run gives up)."""


def place(world: World, state: WorldState, oid: str, receptacle: str, rng: np.random.Generator) -> Failure | None:
    """Put the held object at a free, stable spot of the receptacle's open regions (None), or say why not."""
    got = find_spot(world, state, oid, receptacle, rng, dry_run=False)
    if isinstance(got, Failure):
        return got
    release(world, state, oid, got)
    if type_of(state, receptacle) in HANGERS:  # it hangs there, held by the hanger, as scene generation hangs it
        world.client.changeDynamics(world.built.objects[oid].body, -1, mass=0.0)
    return None


def find_spot(world: World, state: WorldState, oid: str, receptacle: str, rng: np.random.Generator,
              dry_run: bool, assume_open: bool = False, eye: tuple[float, float, float] | None = None,
              also: tuple[tuple[str, Spot], ...] = ()) -> Spot | Failure:
    """A free, stable pose (x, y, z, yaw) for `oid` in the receptacle's open regions, or why there
    is none. Nothing moves; `assume_open` counts the regions behind a closed door too.

    A real put lands within reach of the agent's eye (in view where it can): AI2-THOR puts things
    where the agent looks, so that they can be taken out again. A dry run asks for a pose within reach
    and in clear view of some place the agent can stand, or, with `eye`, what a real put from there
    would find; doors it counts as open are those the agent can open (not a dresser's drawers). `also`
    lists objects a dry run pretends are already put there, at their poses (the first of two things put
    in one place)."""
    real = not dry_run or eye is not None
    loaded_r = world.built.objects[receptacle]
    entry = world.built.objects[oid].entry
    openable = abilities(type_of(state, receptacle)).openable
    joints_open = (assume_open and openable) or state.objects[receptacle].isOpen
    host = _host_now(world, state, receptacle)
    reach = world.config.visibility_distance
    eyes = np.array(eye or world.agent.eye())[None] if real else _standing_eyes(world)
    lo_r, hi_r = body_aabb(world.client, loaded_r.body)
    top = float(hi_r[2])
    regions = [s for s in region_spots(host, loaded_r.entry)
               if not (s.name and _needs_open(loaded_r.entry, s.name) and not joints_open)]
    spots = [s for s in regions if _region_distance(s, eyes, top) <= reach]
    if not spots and real and np.linalg.norm(np.clip(eyes[0], lo_r, hi_r) - eyes[0]) <= reach:
        # regions are kept where they are with doors closed; a drawer slid out towards the agent is within
        # reach when its closed place is not, and the receptacle is what AI2-THOR measures reach to
        spots = regions
    if not spots:
        return Failure(FailureCode.NO_SPOT_IN_REACH, f"{receptacle} has no place to put things within reach")
    from luminous_sim.scene import footprint

    boxes, prints = [], []
    for other in state.contents(receptacle):
        if other == oid:
            continue
        loaded = world.built.objects[other]
        lo, hi = world.client.getAABB(loaded.body, -1)
        boxes.append((lo, hi))
        pos, yaw = world.built.pose_of(other)
        prints.append(footprint(loaded.entry, pos[0], pos[1], yaw))  # oriented, not the world AABB
    for other, (x, y, z, yaw) in also:
        e = world.built.objects[other].entry
        fp = footprint(e, x, y, yaw)
        x0, y0, x1, y1 = fp.bounds
        boxes.append(((x0, y0, z + e.bbox_min[2]), (x1, y1, z + e.bbox_max[2])))
        prints.append(fp)
    if type_of(state, receptacle) in HANGERS:
        return _hang_spot(world, entry, loaded_r.entry, spots, prints, rng) or Failure(
            FailureCode.RECEPTACLE_FULL, f"{receptacle} is full: something already hangs on it")
    open_top = open_tops(loaded_r.entry)
    order = _spot_order(world, spots, rng)
    # near the agent first (AI2-THOR puts things where the agent looks); then anywhere in a region it reaches:
    # the reach limit is on the receptacle, not on where in it the object lands (the bottom of a garbage can)
    hidden = None  # a real put's first pose out of the agent's view: taken only when no region has one in view
    last = None  # a real put's first pose in a region's back half out of reach of the eye: taken after that
    for anywhere in (False, True):
        for i in order:
            spot = spots[i]
            if entry.dims[2] > spot.clearance + 1e-6 and spot.name not in open_top:
                continue
            ceiling = spot.floor_z + spot.clearance
            occupied = [fp for (lo, hi), fp in zip(boxes, prints)  # only what is on this shelf
                        if lo[2] < ceiling and hi[2] > spot.floor_z - 0.01]
            got, seen = _sample_in_view(world, entry, spot, rng, occupied, eyes, real, host, top, anywhere,
                                        framed=_in_frame(world) if not dry_run else None)
            if got is not None and not seen:
                hidden = hidden or got  # a fridge's bottom shelf below the view: another shelf may be in it
                continue
            if got is None and spot.gated and not anywhere:  # the back half too, rather than refusing
                whole = dc_replace(spot, gated=False)
                got, seen = _sample_in_view(world, entry, whole, rng, occupied, eyes, real, host, top,
                                            framed=_in_frame(world) if not dry_run else None)
                if got is not None and not seen:
                    hidden = hidden or got
                    continue
                if got is None:  # room at all: a drawer's region stays where it is closed, out of reach
                    got = sample_in_region(entry, whole, rng, occupied, tries=60)
                    if got is not None and real:  # a real put's last resort, after every pose within reach
                        last = last or got
                        continue
            if got is None and type_of(state, receptacle) in PILING_RECEPTACLES and not anywhere:
                got = _stack_pose(entry, spot, boxes)
            if got is None and type_of(state, receptacle) in CENTRED_ON and not anywhere and not occupied:
                got = _centred_pose(entry, spot, spot.floor_z)
            if got is not None:
                return got[:4]
    chosen = hidden or last
    if chosen is not None:
        return chosen[:4]
    return Failure(FailureCode.RECEPTACLE_FULL, f"{receptacle} is full: no free, stable spot for {oid}")


def _hang_spot(world: World, entry, host_entry, spots: list, prints: list, rng: np.random.Generator) -> Spot | None:
    """A towel, a hand towel or a roll of toilet paper hangs centred on a free region of its hanger (a bar, a
    ring, a spindle), as scene generation hangs it (`scene.hang_pose`), whatever its size: AI2-THOR snaps it
    there. A region is free when nothing already hanging there overlaps that pose; near the agent first."""
    for i in _spot_order(world, spots, rng):
        spot = spots[i]
        x, y, z, yaw, fp = hang_pose(entry, spot, host_back=hanger_back(host_entry, spot.name))
        if not any(fp.intersects(other) and fp.intersection(other).area > 1e-6 for other in prints):
            return x, y, z, yaw
    return None


def _host_now(world: World, state: WorldState, receptacle: str) -> SceneObject:
    """The receptacle as a SceneObject at its current pose (movable receptacles move)."""
    obj = world.scene.object(receptacle) if receptacle in {o.id for o in world.scene.objects} else None
    body = world.built.objects[receptacle].body
    pos, orn = base_link_pose(world.client, body)
    yaw = world.client.getEulerFromQuaternion(orn)[2]
    base = obj or SceneObject(id=receptacle, type=type_of(state, receptacle),
                              asset=world.built.objects[receptacle].entry.id, position=pos, layer="object")
    return base.model_copy(update={"position": tuple(round(v, 4) for v in pos), "yaw": round(yaw, 5)})


def _in_frame(world: World, margin: float = 0.9):
    """Whether a point lies inside the agent's current picture (within `margin` of its half-angles): a ray
    from the eye is clear of a basin's rim at 45 degrees to the side too, where the camera does not look."""
    pose, fov = world.agent, math.radians(world.config.fov)
    forward = np.array(pose.view_direction())
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    aspect = world.config.width / world.config.height
    tan_v = math.tan(fov / 2) * margin
    tan_h = math.tan(fov / 2) * aspect * margin
    eye = np.array(pose.eye())

    def inside(point: np.ndarray) -> bool:
        d = point - eye
        depth = float(d @ forward)
        return depth > 0 and abs(float(d @ right)) <= tan_h * depth and abs(float(d @ up)) <= tan_v * depth

    return inside


def _sample_in_view(world: World, entry, spot, rng: np.random.Generator, occupied: list, eyes: np.ndarray,
                    real: bool, host: SceneObject, top: float, anywhere: bool = False,
                    framed=None) -> tuple[tuple | None, bool]:
    """A free pose in the region within reach of one of `eyes` ((N, 3)) and, among a few draws, one
    such an eye has a clear line to: AI2-THOR puts things where the agent can see them, not behind a
    basin's near rim where they could not be picked up again. A real put (one eye, the agent's) falls
    back on a pose out of clear view; a dry run does not. Under a shelf or table top, only where
    scene generation's sight model sees it (its front), since the top hides the rest. Returns the pose
    (or None) and whether it is in clear view.

    `anywhere`: the pose need not be within reach of an eye, only the region (as AI2-THOR limits the
    distance to the receptacle, not to where the object lands in it); it must still be in sight of an
    eye that reaches the region (`top` is the receptacle's top). `framed`: for a put from where the agent
    stands, whether a point is in its picture (a pose in clear view must also be in frame)."""
    first = None
    reach = world.config.visibility_distance
    height = entry.bbox_max[2] - entry.bbox_min[2]
    mid = spot.floor_z + 0.002 + height / 2
    if anywhere:
        eyes = eyes[_box_distances(spot, eyes, top) <= reach]
        if not len(eyes):
            return None, False
    shade = shades(world.built.objects[spot.host.id].entry).get(spot.name)
    view = (View(shade, host.position[:2], host.yaw, eyes[:, :2], reach=math.inf if anywhere else None)
            if shade and shade.roof else None)

    def in_reach(xy: np.ndarray) -> bool:
        if view is not None:
            return view.sees((float(xy[0]), float(xy[1])), (mid, spot.floor_z + 0.8 * height))
        if anywhere:
            return True
        return bool(np.any(np.linalg.norm(eyes - np.array([xy[0], xy[1], mid]), axis=1) <= reach))

    def clear_view(got) -> bool:
        x, y, z = got[:3]
        centre = np.array([x, y, z + (entry.bbox_min[2] + entry.bbox_max[2]) / 2])
        if framed is not None and not framed(centre):
            return False
        near = eyes if anywhere else eyes[np.linalg.norm(eyes - centre, axis=1) <= reach + 0.01]
        hits = world.client.rayTestBatch(near.tolist(), [centre.tolist()] * len(near))
        return any(h[0] == -1 for h in hits)

    def packed(got):
        """The pose slid to the nearest corner of the region, else the nearest edge across the object's short
        side (so a second pan still fits beside the first), where that is free, reached and in clear view."""
        for cand in edge_slides(got, spot):
            fp = cand[4]
            c = fp.centroid
            if (not any(fp.intersects(o) for o in occupied) and in_reach(np.array([c.x, c.y]))
                    and clear_view(cand)):
                return cand
        return got

    for _ in range(VIEW_TRIES):
        got = sample_in_region(entry, spot, rng, occupied, tries=60, accept=in_reach)
        if got is None:  # a tight fit (a box beside a remote) may take more draws
            continue
        first = first or (got if real else None)
        if clear_view(got):
            return packed(got), True
    # no random draw was in clear view (a basin's near rim hides most of it), or none found room (the gap left
    # on a crowded table): scan the region for the first few poses in clear view before settling for one that is not
    for i, got in enumerate(scan_region(entry, spot, occupied, accept=in_reach)):
        if clear_view(got):
            return got, True
        first = first or (got if real else None)
        if i + 1 >= SCAN_VIEW_CHECKS:
            break
    return first, False


def _standing_eyes(world: World) -> np.ndarray:
    """The camera over every place the agent can stand, (N, 3)."""
    pts = world.nav.points()
    return np.column_stack([pts, np.full(len(pts), CAMERA_HEIGHT)])


def _spot_order(world: World, spots: list, rng: np.random.Generator) -> list[int]:
    """Regions to try: those the agent could see and reach from here first (in random order), as
    AI2-THOR puts things where the agent looks, so they can be taken out again from the same spot."""
    order = list(range(len(spots)))
    rng.shuffle(order)
    eye = np.array(world.agent.eye())
    reach = world.config.visibility_distance

    def far(i: int) -> bool:
        sp = spots[i]
        return float(np.linalg.norm(np.array([*sp.center, sp.floor_z]) - eye)) > reach

    return sorted(order, key=far)


def _stack_pose(entry, spot, boxes) -> tuple | None:
    """A bowl, plate, mug or pan takes more than fits side by side: the next thing goes on top of
    what is there, or across the rim when it is longer than the vessel is wide (a knife in a mug)."""
    x, y = spot.center
    tops = [hi[2] for lo, hi in boxes if lo[0] < x < hi[0] and lo[1] < y < hi[1]]
    z_base = max(tops) if tops else spot.floor_z
    if entry.dims[0] > spot.size[0] or entry.dims[1] > spot.size[1]:
        z_base = max(z_base, spot.floor_z + min(spot.clearance, 0.12))  # across the opening
    if z_base + entry.dims[2] > spot.floor_z + spot.clearance + 0.25:
        return None
    return _centred_pose(entry, spot, z_base)


def _centred_pose(entry, spot, z_base: float) -> tuple:
    """The object's box centred over the region, its bottom at `z_base`, turned as the region is."""
    x, y = spot.center
    lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
    centre = (lo + hi) / 2
    c, s_ = math.cos(spot.yaw), math.sin(spot.yaw)
    ox = x - (centre[0] * c - centre[1] * s_)
    oy = y - (centre[0] * s_ + centre[1] * c)
    return ox, oy, z_base - entry.bbox_min[2] + 0.003, spot.yaw, None


def _box_distances(spot, eyes: np.ndarray, top: float) -> np.ndarray:
    """Metres from each of `eyes` ((N, 3)) to the nearest point of a region's volume: its footprint from
    its floor up to its ceiling or the receptacle's `top`, whichever is lower. This is the part of the
    receptacle that holds the region (AI2-THOR's Drawer, Cabinet or GarbageCan), whose nearest point
    AI2-THOR measures reach to."""
    c, s = math.cos(spot.yaw), math.sin(spot.yaw)
    rel = eyes[:, :2] - np.array(spot.center)
    local = np.column_stack([rel[:, 0] * c + rel[:, 1] * s, -rel[:, 0] * s + rel[:, 1] * c])  # into the region frame
    half = np.array(spot.size) / 2
    flat = np.linalg.norm(local - np.clip(local, -half, half), axis=1)
    ceiling = max(spot.floor_z, min(spot.floor_z + spot.clearance, top))
    return np.hypot(flat, eyes[:, 2] - np.clip(eyes[:, 2], spot.floor_z, ceiling))


def _region_distance(spot, eyes: np.ndarray, top: float) -> float:
    """Metres from the nearest of `eyes` to the region's volume (`_box_distances`)."""
    return float(np.min(_box_distances(spot, eyes, top))) if len(eyes) else math.inf


def _needs_open(entry, region_name: str) -> bool:
    return any(r["name"] == region_name and r.get("requires_open") for r in entry.regions)
