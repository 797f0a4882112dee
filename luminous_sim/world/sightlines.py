"""Which objects an agent could see from somewhere it can stand: rays from the camera at every reachable
grid point within reach to points on the object, as AI2-THOR tests visibility by raycasts to an
object's visibility points. A few thousand rays per scene in one `rayTestBatch`, no rendering.

Used to keep objects no one can see out of sampled tasks, and to report them per generated scene.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.states.model import WorldState
from luminous_sim.states.rules import enclosing_closed
from luminous_sim.vocab import abilities
from luminous_sim.world.agent import CAMERA_HEIGHT, HORIZON_MAX
from luminous_sim.world.client import body_aabb

if TYPE_CHECKING:
    from luminous_sim.world.world import World

OVERSHOOT = 0.3
"""Metres a sight line runs past its target point."""
RAY_BATCH = 16383
"""PyBullet's limit on rays per rayTestBatch call (with 16,384 it silently returns nothing)."""
MAX_PITCH_DOWN = HORIZON_MAX + 30.0
"""Steepest downward sight line the camera can frame (the lowest horizon plus half the 60-degree fov)."""
KEPT_ANSWERS = 16
"""`world_unseen` answers remembered per process (a dataset build solves several tasks in one layout)."""
_ANSWERS: OrderedDict[tuple[Any, ...], frozenset[str]] = OrderedDict()


def sight_targets(state: WorldState) -> dict[str, str]:
    """Objects to interact with (pick up, switch, open, put into), each with what must be seen to reach
    it: itself, or the innermost closed container shutting it in."""
    out = {}
    for oid, o in state.objects.items():
        ab = abilities(o.object_type)
        if oid != state.held and (ab.pickupable or ab.toggleable or ab.openable or ab.receptacle):
            out[oid] = enclosing_closed(state, oid) or oid
    return out


def unseen(client, state: WorldState, bodies: dict[str, int], points: np.ndarray, reach: float) -> set[str]:
    """The `sight_targets` whose target no sight line from `points` meets."""
    targets = sight_targets(state)
    seen = seeable_bodies(client, {t: bodies[t] for t in set(targets.values()) if t in bodies}, points, reach)
    return {oid for oid, t in targets.items() if not seen.get(t, False)}


def world_unseen(world: World, state: WorldState) -> set[str]:
    """`unseen` in a World, for the object states `state`. A world whose physics is as built (untouched,
    see `world.restore`) has the same geometry as every world built from the same scene with the same
    settings, so the answer is remembered by scene, settings, catalog and sight targets, and a new World
    of that scene (the next task in the same layout) is not cast thousands of rays again."""
    bodies = {oid: lo.body for oid, lo in world.built.objects.items()}
    if world.client.touched:
        return unseen(world.client, state, bodies, world.nav.points(), world.config.visibility_distance)
    key = (world.scene_digest(), world.config, world.catalog, frozenset(sight_targets(state).items()))
    if key not in _ANSWERS:
        _ANSWERS[key] = frozenset(unseen(world.client, state, bodies, world.nav.points(),
                                         world.config.visibility_distance))
        while len(_ANSWERS) > KEPT_ANSWERS:
            _ANSWERS.popitem(last=False)
    _ANSWERS.move_to_end(key)
    return set(_ANSWERS[key])


def scene_digest(scene: Any) -> str:
    """sha256 of a scene's JSON: equal for equal scenes."""
    return hashlib.sha256(scene.to_json().encode()).hexdigest()


def _targets(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Points an eye may see the object by: its centre, four near its top, and two near the ends of its
    long horizontal axis (a towel bar hidden in the middle by the towel on it)."""
    c = (lo + hi) / 2
    top = hi[2] - 0.2 * (hi[2] - lo[2])
    q = (hi - lo) / 4
    end = np.zeros(3)
    axis = int(np.argmax((hi - lo)[:2]))
    end[axis] = 0.375 * (hi - lo)[axis]
    return np.array([c, [c[0], c[1], top], [c[0] - q[0], c[1] - q[1], top], [c[0] + q[0], c[1] - q[1], top],
                     [c[0], c[1] + q[1], top], c - end, c + end])


def seeable(world: World, object_ids: list[str], reach: float | None = None) -> dict[str, bool]:
    """For each object: whether a straight sight line from the camera at some reachable grid point hits
    it first, within `reach` (the visibility distance) and within the camera's pitch range."""
    bodies = {oid: world.built.objects[oid].body for oid in object_ids}
    return seeable_bodies(world.client, bodies, world.nav.points(), reach or world.config.visibility_distance)


def seeable_bodies(client, bodies: dict[str, int], points: np.ndarray, reach: float) -> dict[str, bool]:
    """`seeable` for bodies in any PyBullet client, the agent standing at `points` ((N, 2) metres)."""
    out = {oid: False for oid in bodies}
    froms, tos, owners = [], [], []
    for oid, body in bodies.items():
        lo, hi = body_aabb(client, body)
        eyes = np.column_stack([points, np.full(len(points), CAMERA_HEIGHT)])
        near = np.linalg.norm(np.clip(eyes, lo, hi) - eyes, axis=1) <= reach  # as World.object_distance
        for t in _targets(lo, hi):
            d_xy = np.hypot(points[:, 0] - t[0], points[:, 1] - t[1])
            pitch = np.degrees(np.arctan2(CAMERA_HEIGHT - t[2], np.maximum(d_xy, 1e-6)))
            for eye in eyes[near & (pitch <= MAX_PITCH_DOWN)]:
                ray = t - eye
                # carried on past the point, which may lie in a hollow (a bowl's middle) the ray never meets
                end = t + ray / max(np.linalg.norm(ray), 1e-6) * OVERSHOOT
                froms.append(tuple(float(v) for v in eye))
                tos.append(tuple(float(v) for v in end))
                owners.append((oid, body))
    hits = []
    for k in range(0, len(froms), RAY_BATCH):
        hits += client.rayTestBatch(froms[k:k + RAY_BATCH], tos[k:k + RAY_BATCH])
    for (oid, body), hit in zip(owners, hits, strict=True):
        if hit[0] == body:
            out[oid] = True
    return out
