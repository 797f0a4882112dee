"""Navigation scored the way the field scores it (Anderson et al. 2018, "On Evaluation of Embodied Navigation
Agents"; the RoboTHOR and Habitat ObjectNav protocol): a goal's *success region* on the agent's grid, geodesic
distances to it, a start drawn at least a minimum geodesic distance away, and SPL and soft SPL at the end.

Definitions (all distances in metres, on the agent's navigation grid: 0.25 m points, 4-connected, the moves
MoveAhead makes; turns and looks cost no distance):

* An instance's distance from the agent is the *horizontal* distance from the agent's position to the
  instance's axis-aligned footprint (its AABB projected on the floor), so that it does not depend on the
  camera height (ALFRED's camera is 1.576 m up: a camera-to-object distance of 1.0 m would rule out every
  object on the floor).
* The *success region* of a goal is the set of grid points from which success is possible, occlusion and
  heading aside: for `objectnav`, within the success distance of a target instance and within ALFRED's
  visibility distance (1.5 m, camera to the nearest point of the AABB) of it; for `objectnav_pickup`, within
  the visibility distance (ALFRED's interaction reach) of an instance.
* `l`, the shortest path length (`shortest_path_length`): the geodesic distance from the start to the
  nearest point of the success region. It is a lower bound on the path of any successful episode (the
  agent must stand in the region to succeed), so SPL <= 1 always; the oracle reaches SPL 1 whenever the
  nearest region point has a view of the target.
* `start_distance`: the geodesic distance from the start to the nearest target instance's own grid point
  (the grid point nearest its footprint); usually at least `l` (not always: that point may lie outside the
  success region, under an object high on a wall).
* `p`, the agent's path length (`path_length`): 0.25 m per successful MoveAhead.
* `d_T` (`distance_to_goal`): the geodesic distance from where the agent ends to the success region.
* SPL = S * l / max(p, l); soft SPL (Habitat) = max(0, 1 - d_T / l) * l / max(p, l).

A goal takes part by having `object_type`, `instances(view)` and `region(view)` (`NavScored`); the env then
puts the start figures in the reset's `info` and the end figures in the last step's (`NavScore`).
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

import numpy as np

from luminous_sim.env.history import Sent
from luminous_sim.world import AgentPose, World, WorldView
from luminous_sim.world.agent import CAMERA_HEIGHT, GRID

Key = tuple[int, int]
UNREACHABLE = math.inf


@runtime_checkable
class NavScored(Protocol):
    """A goal scored with a success region (see the module docstring)."""

    object_type: str

    def instances(self, view: WorldView) -> tuple[str, ...]:
        """The target instances (those of the type that some reachable pose can see), sorted."""
        ...

    def region(self, view: WorldView) -> frozenset[Key]:
        """The grid keys from which success is possible (occlusion and heading aside)."""
        ...


def footprint_distances(points: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Horizontal distance from each (x, y) point to the box's footprint [lo.x, hi.x] x [lo.y, hi.y] (0 inside)."""
    dx = np.maximum(np.maximum(lo[0] - points[:, 0], points[:, 0] - hi[0]), 0.0)
    dy = np.maximum(np.maximum(lo[1] - points[:, 1], points[:, 1] - hi[1]), 0.0)
    return np.hypot(dx, dy)


def camera_distances(points: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Distance from the camera (at ALFRED's height over each point) to the box's nearest point, as AI2-THOR
    and `World.object_distance` measure it."""
    dz = max(lo[2] - CAMERA_HEIGHT, CAMERA_HEIGHT - hi[2], 0.0)
    return np.hypot(footprint_distances(points, lo, hi), dz)


def footprint_distance(pose: AgentPose, box: tuple[np.ndarray, np.ndarray]) -> float:
    """Horizontal distance from the agent to a box's footprint."""
    return float(footprint_distances(np.array([[pose.x, pose.y]]), box[0], box[1])[0])


def grid_keys(view: WorldView) -> tuple[list[Key], np.ndarray]:
    """The navigation grid's keys (sorted) and their points in metres."""
    keys = sorted(view.nav.keys)
    return keys, np.array(keys, dtype=float).reshape(-1, 2) * GRID


def region_of(view: WorldView, object_ids: Iterable[str], *, within: float | None,
              reach: float) -> frozenset[Key]:
    """Grid keys within `within` m (horizontal, to the footprint; None: no such bound) of one of the objects
    and within `reach` m of it from the camera."""
    keys, points = grid_keys(view)
    inside = np.zeros(len(keys), bool)
    for oid in object_ids:
        lo, hi = view.aabb(oid)
        ok = camera_distances(points, lo, hi) <= reach
        if within is not None:
            ok &= footprint_distances(points, lo, hi) <= within
        inside |= ok
    return frozenset(k for k, ok in zip(keys, inside, strict=True) if ok)


def grid_distances(keys: frozenset[Key], sources: Iterable[Key]) -> dict[Key, int]:
    """Steps (0.25 m each, 4-connected) from the nearest source to every key reachable from one."""
    dist = {s: 0 for s in sources if s in keys}
    queue = deque(dist)
    while queue:
        k = queue.popleft()
        for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            n = (k[0] + dx, k[1] + dy)
            if n in keys and n not in dist:
                dist[n] = dist[k] + 1
                queue.append(n)
    return dist


def nearest_keys(view: WorldView, object_ids: Iterable[str]) -> list[Key]:
    """Each object's own grid point: the key nearest its footprint."""
    keys, points = grid_keys(view)
    out = []
    for oid in object_ids:
        lo, hi = view.aabb(oid)
        out.append(keys[int(np.argmin(footprint_distances(points, lo, hi)))])
    return out


def start_keys(view: WorldView, region: frozenset[Key], min_distance: float) -> list[Key]:
    """The grid keys at least `min_distance` m (geodesic) from the region and connected to it, sorted."""
    field = grid_distances(view.nav.keys, region)
    need = math.ceil(round(min_distance / GRID, 6))
    return sorted(k for k, d in field.items() if d >= need)


def draw_start(view: WorldView, region: frozenset[Key], min_distance: float,
               rng: np.random.Generator) -> AgentPose | None:
    """A start drawn uniformly over the grid points at least `min_distance` m from the region (facing one of
    the four headings, drawn too; horizon 30, ALFRED's start), or None when no point is that far."""
    keys = start_keys(view, region, min_distance)
    if not keys:
        return None
    gx, gy = keys[int(rng.integers(len(keys)))]
    return AgentPose(gx * GRID, gy * GRID, 90 * int(rng.integers(4)), 30)


def path_length(history: Sequence[Sent]) -> float:
    """The agent's path in metres: 0.25 m per successful MoveAhead (the only action that moves it)."""
    return GRID * sum(1 for s in history if s.ok and s.api.get("action") == "MoveAhead")


def spl(success: bool, shortest: float, path: float) -> float:
    """Anderson et al.'s SPL of one episode: S * l / max(p, l)."""
    if not success:
        return 0.0
    return 1.0 if shortest <= 0 else shortest / max(path, shortest)


def soft_spl(distance_to_goal: float, shortest: float, path: float) -> float:
    """Habitat's soft SPL of one episode: max(0, 1 - d_T / d_0) * d_0 / max(p, d_0)."""
    if shortest <= 0:
        return 1.0 if distance_to_goal <= 0 else 0.0
    progress = max(0.0, 1.0 - distance_to_goal / shortest) if math.isfinite(distance_to_goal) else 0.0
    return progress * shortest / max(path, shortest)


@dataclass(frozen=True)
class NavScore:
    """One episode's navigation figures, fixed at its start (the region and the distances to it)."""

    field: dict[Key, int]
    """Grid key -> steps to the success region (keys that cannot reach it are absent)."""
    shortest: float
    start_distance: float
    instances: int
    distractor_types: int
    start_room: str | None = None
    """In a house: the room the agent starts in (None in a single room)."""
    target_rooms: tuple[str, ...] = ()
    """In a house: the rooms that hold a target instance."""

    @classmethod
    def start(cls, goal: NavScored, world: World) -> NavScore:
        """The figures of an episode in `world`, at its start."""
        view = world.view()
        state = view.state
        region = goal.region(view)
        field = grid_distances(view.nav.keys, region)
        here = world.agent.grid_key()
        targets = goal.instances(view)
        from_start = grid_distances(view.nav.keys, [here])
        own = [from_start.get(k) for k in nearest_keys(view, targets)]
        reachable = [d for d in own if d is not None]
        start_distance = GRID * min(reachable) if reachable else UNREACHABLE
        shortest = GRID * field[here] if here in field else UNREACHABLE
        types = {st.object_type for st in state.objects.values()} - {goal.object_type}
        shell = view.scene.room
        if shell.house is None:
            return cls(field, shortest, start_distance, len(targets), len(types))
        rooms = set()
        for oid in targets:
            lo, hi = view.aabb(oid)
            rooms.add(shell.room_at(float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2))
        return cls(field, shortest, start_distance, len(targets), len(types),
                   shell.room_at(world.agent.x, world.agent.y), tuple(sorted(r for r in rooms if r is not None)))

    def at_start(self) -> dict[str, Any]:
        """The reset's figures."""
        out: dict[str, Any] = {"shortest_path_length": self.shortest, "start_distance": self.start_distance,
                               "target_instances": self.instances, "distractor_types": self.distractor_types}
        if self.start_room is not None:
            out.update(start_room=self.start_room, target_rooms=self.target_rooms,
                       cross_room=self.start_room not in self.target_rooms)
        return out

    def at_end(self, agent: AgentPose, history: Sequence[Sent], success: bool) -> dict[str, Any]:
        """The last step's figures: success, SPL, soft SPL and what they are made of."""
        here = agent.grid_key()
        d_t = GRID * self.field[here] if here in self.field else UNREACHABLE
        p = path_length(history)
        return {"success": success, "spl": spl(success, self.shortest, p),
                "soft_spl": soft_spl(d_t, self.shortest, p), "path_length": p, "distance_to_goal": d_t,
                "shortest_path_length": self.shortest}


def nav_score(goal: object, world: World) -> NavScore | None:
    """The figures of an episode whose goal is `NavScored`, else None."""
    return NavScore.start(goal, world) if isinstance(goal, NavScored) else None
