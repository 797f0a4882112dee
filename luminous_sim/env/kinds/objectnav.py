"""`objectnav`: ObjectNav as RoboTHOR and Habitat score it. The agent is told a type ("find the bed") and must
call Stop with an instance of that type visible (ALFRED's visibility: at least the pixel threshold of it in
view, within ALFRED's 1.5 m visibility distance from the camera) and within the success distance
(`success_distance`, 1.0 m by default, horizontal, to the instance's footprint: RoboTHOR's ObjectNav
challenge counts Stop with the target visible within 1.0 m, and Habitat's ObjectNav goal view points are
within 1.0 m of the object). The episode ends at Stop either way; Stop without such a view is a failure.

The start is drawn uniformly over the grid points at least `min_start_distance` m (geodesic, on the agent's
grid) from the success region of every target instance (`navscore`), so that no episode is won where it
starts. Targets: the types an agent can interact with (as `goto_object`'s) with an instance that some
reachable pose can see without opening anything (one shut in a fridge or a drawer does not count); the room
holds other types beside it (distractors; the reset's `info["distractor_types"]` counts them). The oracle
walks the shortest path (fewest MoveAheads, then fewest turns) to the nearest grid point from which an
instance is seen within the success distance, and its plan ends with Stop (the env's expert answers Stop
once its plan is done).
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import Any

import networkx as nx
import numpy as np

from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.env.kinds.options import SUCCESS_DISTANCE
from luminous_sim.env.navscore import Key, footprint_distance, grid_distances, region_of, start_keys
from luminous_sim.episodes import ExpertPlan, Goal
from luminous_sim.scene import Scene
from luminous_sim.states import enclosing_closed
from luminous_sim.tasks import TaskSamplingError
from luminous_sim.vocab import abilities
from luminous_sim.world import AgentPose, World, WorldView
from luminous_sim.world.agent import CAMERA_HEIGHT, GRID, HORIZON_MAX, HORIZON_MIN

OBJECTNAV_TEMPLATE = "find the {obj}"
MOVE_COST, TURN_COST = 1.0, 1e-3
"""Edge costs of the oracle's path: fewest moves first (its path length is then the geodesic), then turns."""
MAX_VIEWS = 120
"""Candidate views the oracle renders before it gives up."""


def seeable_instances(view: WorldView, object_type: str, *, shut_in: bool = False) -> tuple[str, ...]:
    """The objects of the type that some reachable pose can see (`WorldView.unseeable` leaves out the rest);
    with `shut_in`, also those inside a closed receptacle that can be seen (and opened)."""
    hidden = view.unseeable()
    state = view.state
    return tuple(sorted(o for o in state.of_type(object_type) if o not in hidden
                        and (shut_in or enclosing_closed(state, o) is None)))


def _views(view: WorldView, oid: str, key: Key) -> list[tuple[float, AgentPose]]:
    """Poses at a grid point that may see the object: facing it (and the heading beside when it is off
    centre), the horizon that points at it and those 15 degrees either side; with a penalty for each."""
    lo, hi = view.aabb(oid)
    center = (lo + hi) / 2
    x, y = key[0] * GRID, key[1] * GRID
    d = math.hypot(center[0] - x, center[1] - y)
    yaw = math.degrees(math.atan2(center[0] - x, center[1] - y)) % 360
    rot = round(yaw / 90) % 4 * 90
    off = (yaw - rot + 180) % 360 - 180
    headings = [(rot, 0.0)] + ([((rot + (90 if off > 0 else -90)) % 360, 0.5)] if abs(off) > 20 else [])
    pitch = math.degrees(math.atan2(CAMERA_HEIGHT - center[2], max(d, 0.05)))
    base = int(np.clip(round(pitch / 15) * 15, HORIZON_MIN, HORIZON_MAX))
    out = []
    for r, penalty in headings:
        for h in dict.fromkeys([base, min(base + 15, HORIZON_MAX), max(base - 15, HORIZON_MIN)]):
            out.append((penalty + abs(h - base) / 100, AgentPose(x, y, r, h)))
    return out


class ObjectNavGoal:
    """Stop with an instance of a type visible within the success distance."""

    task_type = "objectnav"
    stop_to_succeed = True

    def __init__(self, object_type: str, success_distance: float = SUCCESS_DISTANCE):
        self.object_type = object_type
        self.success_distance = success_distance
        self.instruction = OBJECTNAV_TEMPLATE.format(obj=object_type.lower())
        self.name = f"sees({object_type}, {success_distance:g} m)"

    def weights(self) -> dict[str, int]:
        return {self.name: 1}

    def stages(self) -> dict[str, str]:
        return {self.name: "GotoLocation"}

    def scores(self, view: WorldView, visible: set[str]) -> dict[str, int]:
        state, agent = view.state, view.agent
        return {self.name: int(any(o in state.objects and state.objects[o].object_type == self.object_type
                                   and footprint_distance(agent, view.aabb(o)) <= self.success_distance + 1e-6
                                   for o in visible))}

    def subgoal(self, scores: dict[str, int]) -> str:
        return "" if scores[self.name] else self.name

    def instances(self, view: WorldView) -> tuple[str, ...]:
        return seeable_instances(view, self.object_type)

    def region(self, view: WorldView) -> frozenset[Key]:
        return region_of(view, self.instances(view), within=self.success_distance,
                         reach=view.config.visibility_distance)

    def expert_plan(self, world: World) -> ExpertPlan | None:
        from luminous_sim.env.actions import nav_api
        from luminous_sim.planning import NavGraph
        from luminous_sim.planning.navigation import look_steps

        view = world.view()
        start = view.agent
        target = self._nearest_view(world)
        if target is None:
            return None
        graph = NavGraph(view.nav)
        try:
            nodes = nx.dijkstra_path(graph.graph, graph.node(start), graph.node(target),
                                     weight=lambda u, v, e: MOVE_COST if e["action"] == "MoveAhead" else TURN_COST)
        except (nx.NetworkXNoPath, nx.NodeNotFound):
            return None
        walk = [graph.graph.edges[u, v]["action"] for u, v in pairwise(nodes)]
        actions = tuple(nav_api(a) for a in look_steps(start.horizon, target.horizon) + walk)
        for api in actions:
            if not world.step(api).success:
                return None
        met = self.scores(view, set(view.visible_objects()))[self.name]
        return ExpertPlan(actions) if met else None

    def _nearest_view(self, world: World) -> AgentPose | None:
        """The pose nearest the agent (fewest moves) that meets the goal: region points in order of their
        geodesic distance, each tried at the views that may see an instance (rendered, in a teleport that is
        undone), up to `MAX_VIEWS` renders."""
        view = world.view()
        start = view.agent
        from_here = grid_distances(view.nav.keys, [start.grid_key()])
        instances = self.instances(view)
        region = region_of(view, instances, within=self.success_distance, reach=view.config.visibility_distance)
        candidates: list[tuple[int, float, str, AgentPose]] = []
        for oid in instances:
            box = view.aabb(oid)
            for key in region:
                if key not in from_here:
                    continue
                pose = AgentPose(key[0] * GRID, key[1] * GRID)
                if footprint_distance(pose, box) > self.success_distance + 1e-6:
                    continue
                candidates += [(from_here[key], penalty, oid, p) for penalty, p in _views(view, oid, key)]
        candidates.sort(key=lambda c: (c[0], c[1], c[3].x, c[3].y, c[3].rotation, c[3].horizon, c[2]))
        found = None
        try:
            for _, _, _, pose in candidates[:MAX_VIEWS]:
                if not world.step(pose.to_alfred()).success:
                    continue
                if self.scores(view, set(view.visible_objects()))[self.name]:
                    found = pose
                    break
        finally:
            world.step(start.to_alfred())
        return found

    def to_dict(self) -> dict[str, Any]:
        return {"kind": self.task_type, "object_type": self.object_type, "success_distance": self.success_distance}


def target_types(view: WorldView, worthy: Any, *, shut_in: bool = False) -> list[str]:
    """The `worthy` types that have an instance some reachable pose can see (`seeable_instances`), sorted."""
    hidden = view.unseeable()
    state = view.state
    return sorted({st.object_type for oid, st in state.objects.items()
                   if oid not in hidden and worthy(st.object_type)
                   and (shut_in or enclosing_closed(state, oid) is None)})


def _worth_finding(object_type: str) -> bool:
    ab = abilities(object_type)
    return ab.pickupable or ab.receptacle or ab.openable or ab.toggleable


class ObjectNav(TaskKind):
    """Find an object of a type and Stop where it is seen within the success distance."""

    templates = (OBJECTNAV_TEMPLATE,)

    def draw_goal(self, world: World, scene: Scene, rng: np.random.Generator) -> Goal:
        view = world.view()
        types = target_types(view, _worth_finding)
        for i in rng.permutation(len(types)) if len(types) > 1 else ():  # a target and distractors
            goal = ObjectNavGoal(types[int(i)], self.options["success_distance"])
            if start_keys(view, goal.region(view), self.options["min_start_distance"]):
                return goal
        raise TaskSamplingError(f"no objectnav target in {scene.room.name} (seed {scene.seed}) with a start "
                                f"{self.options['min_start_distance']:g} m from it")

    def draw_start(self, world: World, goal: Goal, rng: np.random.Generator) -> AgentPose | None:
        return nav_start(world, goal, rng, self.options["min_start_distance"], self.name)

    def goal_from_dict(self, data: dict[str, Any]) -> Goal:
        return ObjectNavGoal(data["object_type"], float(data.get("success_distance", SUCCESS_DISTANCE)))


def nav_start(world: World, goal: Goal, rng: np.random.Generator, min_distance: float, kind: str) -> AgentPose:
    """A start at least `min_distance` m from the goal's success region (`navscore.draw_start`).

    Raises:
        TaskSamplingError: no grid point is that far.
    """
    from luminous_sim.env.navscore import NavScored, draw_start

    if not isinstance(goal, NavScored):
        raise TypeError(f"{kind}: its goal has no success region")
    start = draw_start(world.view(), goal.region(world.view()), min_distance, rng)
    if start is None:
        raise TaskSamplingError(f"{kind}: no start {min_distance:g} m from the {goal.object_type}")
    return start
