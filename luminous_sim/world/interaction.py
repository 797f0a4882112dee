"""ALFRED's interaction actions in the PyBullet world: target resolution, visibility and reach, the
pure object-state rules (`luminous_sim.states`), and their physical side (joints, holding, placing,
slicing, state visuals)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.scene import View, region_spots, sample_in_region, scan_region, shades
from luminous_sim.states import effects as fx
from luminous_sim.states import rules
from luminous_sim.states.model import ObjectState, WorldState
from luminous_sim.vocab import abilities
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT
from luminous_sim.world.asset_loader import base_link_pose, load_asset, set_joint, show_state
from luminous_sim.world.doors import hits_agent, swept_boxes
from luminous_sim.world.masks import resolve_point, resolve_target, rle_to_mask

if TYPE_CHECKING:
    from luminous_sim.world.world import StepResult, World

HAND_AHEAD, HAND_DROP = 0.45, 0.35
SETTLE_AFTER = frozenset({"PutObject", "SliceObject"})
MOVABLE = frozenset({"Bowl", "Box", "Cup", "Mug", "Pan", "Plate", "Pot", "SinkBasin", "BathtubBasin"})
"""Receptacles where things may pile up or rest across the rim when they do not fit side by side."""
"""Actions after which physics must run (things were placed); joints and holding are kinematic."""
"""Where a held object floats: ahead of and below the camera, as AI2-THOR shows it."""


def initial_state(world: World) -> WorldState:
    """The pure state of a freshly built scene."""
    objs = {}
    for o in world.scene.objects:
        objs[o.id] = ObjectState(
            o.id, o.type, isOpen=bool(o.states.get("isOpen", False)), isToggled=bool(o.states.get("isToggled", False)),
            isDirty=bool(o.states.get("isDirty", False)), parent=o.parent, temperature=_temperature(o.states),
            isFilledWithLiquid=bool(o.states.get("isFilled", False)),
        )
    slices = {oid: loaded.entry.slices["count"] for oid, loaded in world.built.objects.items() if loaded.entry.slices}
    return WorldState(objs, held=None, heated=frozenset(), cooled=frozenset(), cleaned=frozenset(),
                      controls=_controls(world), faucet_basin=_faucet_basins(world), slice_counts=slices)


def _temperature(states: dict) -> str:
    """A CDF's initial isHot/isCold as a temperature (physical only: ALFRED's isHot means "was heated")."""
    return "Hot" if states.get("isHot") else "Cold" if states.get("isCold") else "RoomTemp"


def _nearest(world: World, oid: str, candidates: list[str]) -> str | None:
    if not candidates:
        return None
    here = np.array(world.scene.object(oid).position)
    return min(candidates, key=lambda c: (float(np.linalg.norm(np.array(world.scene.object(c).position) - here)), c))


def _faucet_basins(world: World) -> dict[str, str]:
    basins = [o.id for o in world.scene.objects if o.type in ("SinkBasin", "BathtubBasin")]
    return {o.id: b for o in world.scene.objects if o.type == "Faucet" for b in [_nearest(world, o.id, basins)] if b}


def _controls(world: World) -> dict[str, str]:
    burners = [o.id for o in world.scene.objects if o.type == "StoveBurner"]
    out = {}
    for o in world.scene.objects:
        if o.type == "StoveKnob":
            free = [b for b in burners if b not in out.values()] or burners
            b = _nearest(world, o.id, free)
            if b:
                out[o.id] = b
    return out


VIEW_TRIES = 8
"""Draws of a put pose looking for one in the agent's view."""
SCAN_VIEW_CHECKS = 12
"""Scanned poses tried for a clear view before a put takes the first free one (or a dry run gives up)."""


class Interactions:
    """The interaction half of a World; keeps the pure state in step with the physics."""

    def __init__(self, world: World):
        self.world = world
        self.state = initial_state(world)
        self.rng = np.random.default_rng(np.random.SeedSequence([world.scene.seed, 7]))

    # ------------------------------------------------------------------ queries

    @property
    def held(self) -> str | None:
        return self.state.held

    def type_of(self, oid: str | None) -> str:
        return self.state.objects[oid].object_type if oid in self.state.objects else ""

    def _interactable(self, oid: str) -> bool:
        ab = abilities(self.type_of(oid))
        return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable or ab.sliceable

    def _resolve(self, act: dict[str, Any], key: str = "objectId") -> str | None:
        """An object id from the action: given directly, or from a mask (RLE) or a point."""
        if act.get(key):
            return str(act[key])
        seg = self.world.instance_ids()
        inst = {b: o for b, o in self.world.body_to_object().items()}
        if act.get("mask") is not None:
            mask = rle_to_mask(act["mask"], seg.shape) if not isinstance(act["mask"], np.ndarray) else act["mask"]
            return resolve_target(mask, seg, inst, self.held, self._interactable)
        if act.get("point") is not None:
            return resolve_point(tuple(act["point"]), seg, inst, self.held, self._interactable)
        return None

    def open_container_in_view(self, oid: str) -> str | None:
        """The open container `oid` sits in, if that container is visible and within reach: AI2-THOR
        lets the agent take things out of an open fridge or microwave it is looking into, however few
        pixels of them show."""
        parent = self.state.objects[oid].parent if oid in self.state.objects else None
        if parent is None or not self.state.objects[parent].isOpen:
            return None
        if parent in self.world.visible_objects() and self.world.object_distance(oid) <= \
                self.world.config.visibility_distance:
            return parent
        return None

    def _in_reach(self, oid: str) -> str | None:
        """None if the object is visible and within reach (or in an open container in view), else why not."""
        if oid not in self.world.built.objects:
            return f"unknown object id {oid!r}"
        visible = self.world.visible_objects()
        if oid not in visible and self.open_container_in_view(oid) is None:
            d = self.world.object_distance(oid)
            if d > self.world.config.visibility_distance:
                return f"{oid} is too far away ({d:.2f} m > {self.world.config.visibility_distance} m)"
            return f"{oid} is not visible from here"
        return None

    # ------------------------------------------------------------------ dispatch

    def run(self, name: str, act: dict[str, Any]) -> StepResult:
        from luminous_sim.world.world import StepResult

        if name == "PutObject":
            target = act.get("objectId") or self.held
            receptacle = self._resolve(act, "receptacleObjectId")
            if target is None:
                return StepResult(False, "nothing is held", act)
            if receptacle is None:
                return StepResult(False, "PutObject needs receptacleObjectId, a mask or a point", act)
            if target != self.held:
                return StepResult(False, f"{target} is not the held object", act)
            why = self._in_reach(receptacle)
        else:
            target = self._resolve(act)
            receptacle = None
            if target is None:
                return StepResult(False, f"{name} needs an objectId, a mask or a point on an object", act)
            why = self._in_reach(target)
        if why:
            return StepResult(False, why, act)
        err = rules.check(name, self.state, target, receptacle)
        if not err and name == "OpenObject" and hits_agent(swept_boxes(self.world, target), self.world.agent.x,
                                                            self.world.agent.y):
            err = f"{target} cannot be opened: it would hit the agent (step back first)"
        if err:
            return StepResult(False, err, act)
        effects = rules.effects(name, self.state, target, receptacle)
        err = self._apply_physical(name, effects, target, receptacle)
        if err:
            return StepResult(False, err, act)
        self.state = rules.apply(self.state, effects)
        if name in SETTLE_AFTER:
            self._settle()
        elif self.held:
            self.carry(self.held)
        return StepResult(True, "", act)

    # ------------------------------------------------------------------ physical side

    def _settle(self) -> None:
        for _ in range(self.world.config.interaction_steps):
            self.world.client.stepSimulation()
        if self.held:
            self.carry(self.held)

    def _apply_physical(self, name: str, effects: list, target: str, receptacle: str | None) -> str | None:
        if name == "PutObject":
            err = self._place(target, receptacle)
            if err:
                return err
        for e in effects:
            if isinstance(e, fx.MoveJoint):
                self._move_joint(e.object_id, e.open)
            elif isinstance(e, fx.ShowVisual):
                loaded = self.world.built.objects.get(e.object_id)
                if loaded is not None:
                    show_state(self.world.client, loaded, e.state, e.visible)
            elif isinstance(e, fx.Attach):
                self._grab(e.object_id)
            elif isinstance(e, fx.Slice):
                self._slice(e.object_id, e.sliced_type)
        return None

    def _family(self, oid: str) -> list[str]:
        """The object and everything resting in or on it, recursively."""
        out = [oid]
        for c in self.state.contents(oid, recursive=True):
            if c in self.world.built.objects:
                out.append(c)
        return out

    def _move_rigidly(self, oids: list[str], old: tuple, new: tuple) -> None:
        """Move bodies as one rigid group from frame `old` to frame `new` (pos, orn)."""
        c = self.world.client
        inv = c.invertTransform(*old)
        for oid in oids:
            body = self.world.built.objects[oid].body
            pos, orn = c.getBasePositionAndOrientation(body)
            rel = c.multiplyTransforms(inv[0], inv[1], pos, orn)
            npos, norn = c.multiplyTransforms(new[0], new[1], rel[0], rel[1])
            c.resetBasePositionAndOrientation(body, npos, norn)
            c.resetBaseVelocity(body, [0, 0, 0], [0, 0, 0])

    def _set_held_physics(self, oid: str, held: bool) -> None:
        c = self.world.client
        loaded = self.world.built.objects[oid]
        links = [-1] + list(range(c.getNumJoints(loaded.body)))
        for link in links:
            c.setCollisionFilterGroupMask(loaded.body, link, 0 if held else 1, 0 if held else -1)
        mass = 0.0 if held else loaded.entry.mass
        c.changeDynamics(loaded.body, -1, mass=mass)

    def _hand_frame(self) -> tuple:
        pose = self.world.agent
        fx_, fy_ = pose.forward()
        eye = np.array(pose.eye())
        pos = eye + np.array([fx_, fy_, 0.0]) * HAND_AHEAD - np.array([0, 0, HAND_DROP])
        orn = self.world.client.getQuaternionFromEuler([0, 0, -math.radians(pose.rotation)])
        return tuple(pos), orn

    def _grab(self, oid: str) -> None:
        family = self._family(oid)
        for o in family:
            self._set_held_physics(o, True)
        body = self.world.built.objects[oid].body
        old = base_link_pose(self.world.client, body)
        self._move_rigidly(family, old, self._hand_frame())

    def carry(self, oid: str) -> None:
        """Keep the held object (and what it carries) in front of the camera after the agent moves."""
        body = self.world.built.objects[oid].body
        self._move_rigidly(self._family(oid), base_link_pose(self.world.client, body), self._hand_frame())

    def _host_now(self, receptacle: str):
        """The receptacle as a SceneObject at its current pose (movable receptacles move)."""
        obj = self.world.scene.object(receptacle) if receptacle in {o.id for o in self.world.scene.objects} else None
        body = self.world.built.objects[receptacle].body
        pos, orn = base_link_pose(self.world.client, body)
        yaw = self.world.client.getEulerFromQuaternion(orn)[2]
        from luminous_sim.scene.model import SceneObject

        base = obj or SceneObject(id=receptacle, type=self.type_of(receptacle),
                                  asset=self.world.built.objects[receptacle].entry.id, position=pos, layer="object")
        return base.model_copy(update={"position": tuple(round(v, 4) for v in pos), "yaw": round(yaw, 5)})

    def find_spot(self, oid: str, receptacle: str, rng: np.random.Generator | None = None,
                  assume_open: bool = False, eye: tuple[float, float, float] | None = None,
                  also: tuple[tuple[str, tuple[float, float, float, float]], ...] = (),
                  ) -> tuple[float, float, float, float] | str:
        """A free, stable pose (x, y, z, yaw) for `oid` in the receptacle's open regions, or why there
        is none. Nothing moves; with `rng` given the world's own random stream is left untouched;
        `assume_open` counts the regions behind a closed door too.

        A real put lands within reach of the agent's eye (in view where it can): AI2-THOR puts things
        where the agent looks, so that they can be taken out again. A dry run (`rng` given) asks for a
        pose within reach and in clear view of some place the agent can stand, or, with `eye`, what a
        real put from there would find; doors it counts as open are those the agent can open (not a
        dresser's drawers). `also` lists objects a dry run pretends are already put there, at their poses
        (the first of two things put in one place)."""
        real = rng is None or eye is not None
        rng = self.rng if rng is None else rng
        loaded_r = self.world.built.objects[receptacle]
        entry = self.world.built.objects[oid].entry
        openable = abilities(self.type_of(receptacle)).openable
        joints_open = (assume_open and openable) or self.state.objects[receptacle].isOpen
        host = self._host_now(receptacle)
        reach = self.world.config.visibility_distance
        eyes = np.array(eye or self.world.agent.eye())[None] if real else self._standing_eyes()
        spots = [s for s in region_spots(host, loaded_r.entry)
                 if not (s.name and _needs_open(loaded_r.entry, s.name) and not joints_open)
                 and _region_distance(s, eyes) <= reach]
        if not spots:
            return f"{receptacle} has no place to put things within reach"
        from luminous_sim.scene import footprint

        boxes, prints = [], []
        for other in self.state.contents(receptacle):
            if other == oid:
                continue
            loaded = self.world.built.objects[other]
            lo, hi = self.world.client.getAABB(loaded.body, -1)
            boxes.append((lo, hi))
            pos, yaw = self.world.built.pose_of(other)
            prints.append(footprint(loaded.entry, pos[0], pos[1], yaw))  # oriented, not the world AABB
        for other, (x, y, z, yaw) in also:
            e = self.world.built.objects[other].entry
            fp = footprint(e, x, y, yaw)
            x0, y0, x1, y1 = fp.bounds
            boxes.append(((x0, y0, z + e.bbox_min[2]), (x1, y1, z + e.bbox_max[2])))
            prints.append(fp)
        for i in self._spot_order(spots, rng):
            spot = spots[i]
            if entry.dims[2] > spot.clearance + 1e-6:
                continue
            top = spot.floor_z + spot.clearance
            occupied = [fp for (lo, hi), fp in zip(boxes, prints)  # only what is on this shelf
                        if lo[2] < top and hi[2] > spot.floor_z - 0.01]
            got = self._sample_in_view(entry, spot, rng, occupied, eyes, real, host)
            if got is None and spot.gated:  # the back half too, rather than refusing
                from dataclasses import replace as dc_replace

                got = sample_in_region(entry, dc_replace(spot, gated=False), rng, occupied, tries=60)
            if got is None and self.type_of(receptacle) in MOVABLE:
                got = self._stack_pose(entry, spot, boxes)
            if got is not None:
                return got[:4]
        return f"{receptacle} is full: no free, stable spot for {oid}"

    def _sample_in_view(self, entry, spot, rng: np.random.Generator, occupied: list, eyes: np.ndarray,
                        real: bool, host):
        """A free pose in the region within reach of one of `eyes` ((N, 3)) and, among a few draws, one
        such an eye has a clear line to: AI2-THOR puts things where the agent can see them, not behind a
        basin's near rim where they could not be picked up again. A real put (one eye, the agent's) falls
        back on a pose out of clear view; a dry run does not. Under a shelf or table top, only where
        scene generation's sight model sees it (its front), since the top hides the rest."""
        first = None
        reach = self.world.config.visibility_distance
        height = entry.bbox_max[2] - entry.bbox_min[2]
        mid = spot.floor_z + 0.002 + height / 2
        shade = shades(self.world.built.objects[spot.host.id].entry).get(spot.name)
        view = View(shade, host.position[:2], host.yaw, eyes[:, :2]) if shade and shade.roof else None

        def in_reach(xy: np.ndarray) -> bool:
            if view is not None:
                return view.sees((float(xy[0]), float(xy[1])), (mid, spot.floor_z + 0.8 * height))
            return bool(np.any(np.linalg.norm(eyes - np.array([xy[0], xy[1], mid]), axis=1) <= reach))

        def clear_view(got) -> bool:
            x, y, z = got[:3]
            centre = np.array([x, y, z + (entry.bbox_min[2] + entry.bbox_max[2]) / 2])
            near = eyes[np.linalg.norm(eyes - centre, axis=1) <= reach + 0.01]
            hits = self.world.client.rayTestBatch(near.tolist(), [centre.tolist()] * len(near))
            return any(h[0] == -1 for h in hits)

        drawn = False
        for _ in range(VIEW_TRIES):
            got = sample_in_region(entry, spot, rng, occupied, tries=60, accept=in_reach)
            if got is None:  # a tight fit (a box beside a remote) may take more draws
                continue
            drawn = True
            first = first or (got if real else None)
            if clear_view(got):
                return got
        if drawn:
            return first
        # no draw found room: scan for the gap left on a crowded table (the first few in clear view)
        for i, got in enumerate(scan_region(entry, spot, occupied, accept=in_reach)):
            if clear_view(got):
                return got
            first = first or (got if real else None)
            if i + 1 >= SCAN_VIEW_CHECKS:
                break
        return first

    def _standing_eyes(self) -> np.ndarray:
        """The camera over every place the agent can stand, (N, 3)."""
        pts = self.world.nav.points()
        return np.column_stack([pts, np.full(len(pts), CAMERA_HEIGHT)])

    def _spot_order(self, spots: list, rng: np.random.Generator) -> list[int]:
        """Regions to try: those the agent could see and reach from here first (in random order), as
        AI2-THOR puts things where the agent looks, so they can be taken out again from the same spot."""
        order = list(range(len(spots)))
        rng.shuffle(order)
        eye = np.array(self.world.agent.eye())
        reach = self.world.config.visibility_distance

        def far(i: int) -> bool:
            sp = spots[i]
            return float(np.linalg.norm(np.array([*sp.center, sp.floor_z]) - eye)) > reach

        return sorted(order, key=far)

    def _place(self, oid: str, receptacle: str) -> str | None:
        """Put the held object at a free, stable spot of the receptacle's open regions."""
        got = self.find_spot(oid, receptacle)
        if isinstance(got, str):
            return got
        x, y, z, yaw = got
        body = self.world.built.objects[oid].body
        c = self.world.client
        new = ((x, y, z), c.getQuaternionFromEuler([0, 0, yaw]))
        family = self._family(oid)
        self._move_rigidly(family, base_link_pose(c, body), new)
        for o in family:
            self._set_held_physics(o, False)
        return None

    def _stack_pose(self, entry, spot, boxes) -> tuple | None:
        """A bowl, plate, mug or pan takes more than fits side by side: the next thing goes on top of
        what is there, or across the rim when it is longer than the vessel is wide (a knife in a mug)."""
        x, y = spot.center
        tops = [hi[2] for lo, hi in boxes if lo[0] < x < hi[0] and lo[1] < y < hi[1]]
        z_base = max(tops) if tops else spot.floor_z
        if entry.dims[0] > spot.size[0] or entry.dims[1] > spot.size[1]:
            z_base = max(z_base, spot.floor_z + min(spot.clearance, 0.12))  # across the opening
        if z_base + entry.dims[2] > spot.floor_z + spot.clearance + 0.25:
            return None
        lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
        centre = (lo + hi) / 2
        c, s_ = math.cos(spot.yaw), math.sin(spot.yaw)
        ox = x - (centre[0] * c - centre[1] * s_)
        oy = y - (centre[0] * s_ + centre[1] * c)
        return ox, oy, z_base - entry.bbox_min[2] + 0.003, spot.yaw, None

    def set_dirty(self, oid: str, dirty: bool = True) -> None:
        """Make an object dirty or clean (scene set-up, as ALFRED's `dirty_and_empty` does)."""
        loaded = self.world.built.objects.get(oid)
        if loaded is None or oid not in self.state.objects:
            return
        self.state = rules.apply(self.state, [fx.SetState(oid, "isDirty", dirty)]) \
            if self.state.objects[oid].isDirty != dirty else self.state
        show_state(self.world.client, loaded, "dirty", dirty)

    def _move_joint(self, oid: str, open_: bool) -> None:
        loaded = self.world.built.objects[oid]
        c = self.world.client
        for j in loaded.entry.joints:
            if j["role"] not in ("door", "drawer", "lid"):
                continue
            link = loaded.link_index[j["child"]]
            before = c.getLinkState(loaded.body, link, computeForwardKinematics=True)[4:6]
            set_joint(c, loaded, j["name"], j["upper"] if open_ else j["lower"])
            after = c.getLinkState(loaded.body, link, computeForwardKinematics=True)[4:6]
            if j["role"] == "drawer":  # what lies in a drawer slides out with it
                inside = [o for o in self.state.contents(oid, recursive=True) if self._in_link(o, oid, j["child"])]
                self._move_rigidly(inside, before, after)

    def _in_link(self, oid: str, host: str, link: str) -> bool:
        """Whether an object sits in a region that belongs to `link` of `host` (a drawer's inside)."""
        scene_ids = {o.id: o for o in self.world.scene.objects}
        region = scene_ids[oid].region if oid in scene_ids else None
        entry = self.world.built.objects[host].entry
        return any(r["name"] == region and r["link"] == link for r in entry.regions)

    def _slice(self, oid: str, sliced_type: str | None) -> None:
        """Replace the object by its slices, laid out as its catalog SliceSpec says."""
        loaded = self.world.built.objects[oid]
        spec = loaded.entry.slices
        if not spec or sliced_type is None:
            return
        variants = self.world.catalog.of_type(spec["type"])
        if not variants:
            return
        from luminous_sim.assets.catalog import scaled

        slice_entry = scaled(next((e for e in variants if e.variant == loaded.entry.variant), variants[0]),
                             loaded.entry.scale)
        c = self.world.client
        pos, orn = base_link_pose(c, loaded.body)
        c.removeBody(loaded.body)
        del self.world.built.objects[oid]
        for i, (sx, sy, sz, syaw) in enumerate(spec["poses"]):
            wpos, _ = c.multiplyTransforms(pos, orn, [sx, sy, sz + 0.002], [0, 0, 0, 1])
            yaw = c.getEulerFromQuaternion(orn)[2] + syaw
            new = load_asset(c, slice_entry, wpos, yaw, rng=np.random.default_rng(i))
            self.world.built.objects[f"{oid}|{sliced_type}_{i + 1}"] = new


def _region_distance(spot, eyes: np.ndarray) -> float:
    """Metres from the nearest of `eyes` ((N, 3)) to the nearest point of a region's floor."""
    if len(eyes) == 0:
        return math.inf
    c, s = math.cos(spot.yaw), math.sin(spot.yaw)
    rel = eyes[:, :2] - np.array(spot.center)
    local = np.column_stack([rel[:, 0] * c + rel[:, 1] * s, -rel[:, 0] * s + rel[:, 1] * c])  # into the region frame
    half = np.array(spot.size) / 2
    flat = np.linalg.norm(local - np.clip(local, -half, half), axis=1)
    return float(np.min(np.hypot(flat, eyes[:, 2] - spot.floor_z)))


def _needs_open(entry, region_name: str) -> bool:
    return any(r["name"] == region_name and r.get("requires_open") for r in entry.regions)
