"""Physical validation of a built scene: interpenetrating bodies, and objects that moved or fell while
settling. Uses closest points (not contacts) so that static-static pairs, which PyBullet never
collides, are checked too."""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, field
from itertools import combinations

import numpy as np

from luminous_sim.scene import Scene
from luminous_sim.vocab.agent_body import VISIBILITY_DISTANCE
from luminous_sim.world.client import body_aabb
from luminous_sim.world.scene_builder import BuiltScene, build_scene, settle, settle_report

PENETRATION_TOL = 0.01
"""Interpenetration deeper than 1 cm is a defect."""


@dataclass
class PhysicsReport:
    interpenetrations: list[dict] = field(default_factory=list)
    moved: dict[str, float] = field(default_factory=dict)
    fell: list[str] = field(default_factory=list)
    unseeable: list[str] = field(default_factory=list)
    """Objects to interact with (or the closed containers holding them) that no reachable pose has a
    sight line to: not a physics defect, but an agent could never interact with them."""
    seconds: dict[str, float] = field(default_factory=dict)
    """Wall-clock time of each stage: build (load into PyBullet), settle (collisions and stepping), sight."""

    @property
    def ok(self) -> bool:
        return not self.interpenetrations and not self.fell and not self.moved

    def to_dict(self) -> dict:
        """The report as written next to a scene: without timings, so the same scene gives the same file."""
        out = {**asdict(self), "ok": self.ok}
        del out["seconds"]
        return out


def interpenetrations(built: BuiltScene, tol: float = PENETRATION_TOL) -> list[dict]:
    """Pairs of bodies (objects and walls) that overlap by more than `tol`."""
    client = built.client
    named = {loaded.body: oid for oid, loaded in built.objects.items()}
    named.update({b: f"wall#{i}" for i, b in enumerate(built.walls)})
    parent = {o.id: o.parent for o in built.scene.objects}
    boxes = {b: body_aabb(client, b) for b in named}
    out = []
    for a, b in combinations(sorted(named), 2):
        (alo, ahi), (blo, bhi) = boxes[a], boxes[b]
        if np.any(alo > bhi + tol) or np.any(blo > ahi + tol):
            continue
        na, nb = named[a], named[b]
        if parent.get(na) == nb or parent.get(nb) == na:
            continue  # a basin in its sink, a burner on its counter: designed to touch
        pts = client.getClosestPoints(a, b, distance=0.0)
        depth = min((p[8] for p in pts), default=0.0)
        if depth < -tol:
            out.append({"a": na, "b": nb, "depth": round(float(-depth), 4)})
    return out


COLLISION_TOL = 0.005
"""Collision meshes that overlap by more than this (m) collide: pieces placed touching (a sink between counter runs)
read 2 mm, PyBullet's margin on convex hulls."""


@dataclass
class CollisionMeasure:
    """PhyScene's object collision rate on the objects' collision meshes: the share of objects that overlap
    another object (walls apart), support and containment excluded (a thing and anything on or in it, at any
    depth: an apple on a plate in a cabinet touches neither by design)."""

    objects: int
    colliding: list[str] = field(default_factory=list)
    pairs: list[dict] = field(default_factory=list)

    @property
    def rate(self) -> float:
        return len(self.colliding) / self.objects if self.objects else 0.0

    def to_dict(self) -> dict:
        return {"objects": self.objects, "colliding": self.colliding, "pairs": self.pairs,
                "rate": round(self.rate, 4), "any": bool(self.colliding)}


def _ancestors(scene: Scene) -> dict[str, set[str]]:
    parent = {o.id: o.parent for o in scene.objects}
    out: dict[str, set[str]] = {}
    for oid in parent:
        seen, up = set(), parent[oid]
        while up is not None and up not in seen:
            seen.add(up)
            up = parent.get(up)
        out[oid] = seen
    return out


def object_collisions(built: BuiltScene, tol: float = COLLISION_TOL) -> CollisionMeasure:
    """Which objects of a built scene overlap another by more than `tol` (closest points on their collision
    meshes, so that fixed pairs, which PyBullet never collides, are checked too)."""
    client = built.client
    named = {loaded.body: oid for oid, loaded in built.objects.items()}
    above = _ancestors(built.scene)
    boxes = {b: body_aabb(client, b) for b in named}
    colliding: set[str] = set()
    pairs = []
    for a, b in combinations(sorted(named), 2):
        (alo, ahi), (blo, bhi) = boxes[a], boxes[b]
        if np.any(alo > bhi + tol) or np.any(blo > ahi + tol):
            continue
        na, nb = named[a], named[b]
        if na in above.get(nb, ()) or nb in above.get(na, ()):
            continue
        depth = min((p[8] for p in client.getClosestPoints(a, b, distance=0.0)), default=0.0)
        if depth < -tol:
            colliding.update((na, nb))
            pairs.append({"a": na, "b": nb, "depth": round(float(-depth), 4)})
    return CollisionMeasure(len(named), sorted(colliding), pairs)


def scene_collisions(scene: Scene, tol: float = COLLISION_TOL) -> CollisionMeasure:
    """`object_collisions` of a scene as it was generated (built, not settled)."""
    built = build_scene(scene, settle_steps=0)
    try:
        built.client.performCollisionDetection()
        return object_collisions(built, tol)
    finally:
        built.client.disconnect()


def unseeable_objects(built: BuiltScene) -> list[str]:
    """Objects to interact with that no sight line from the reachable grid meets (through a closed
    container's door: the container must be seen)."""
    from luminous_sim.scene import scene_reachable_grid
    from luminous_sim.states.model import ObjectState, WorldState
    from luminous_sim.world.sightlines import unseen

    state = WorldState.of([ObjectState(o.id, o.type, isOpen=bool(o.states.get("isOpen", False)), parent=o.parent)
                           for o in built.scene.objects])
    bodies = {oid: lo.body for oid, lo in built.objects.items()}
    return sorted(unseen(built.client, state, bodies, scene_reachable_grid(built.scene), VISIBILITY_DISTANCE))


def check_physics(scene: Scene, settle_steps: int = 240) -> PhysicsReport:
    """Build the scene, look for interpenetrations, settle, and report what moved or fell."""
    t0 = time.perf_counter()
    built = build_scene(scene, settle_steps=0)
    try:
        t1 = time.perf_counter()
        client = built.client
        client.performCollisionDetection()
        report = PhysicsReport(interpenetrations=interpenetrations(built))
        settle(built, settle_steps)
        settled = settle_report(built)
        report.moved, report.fell = settled.moved, settled.fell
        t2 = time.perf_counter()
        report.unseeable = unseeable_objects(built)
        report.seconds = {"build": t1 - t0, "settle": t2 - t1, "sight": time.perf_counter() - t2}
        return report
    finally:
        built.client.disconnect()
