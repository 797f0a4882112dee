"""The modular reference agent (FILM's and HLSM's design; the simulator's depth and segmentation in the
privileged track, learned ones from RGB in the rgb track: `Perception` and the `InstanceTracker`): the
instruction parser reads the task, the semantic map is built from the agent's own frames and pose, frontier
search with receptacle priors finds what is not yet seen, and the task type's subgoals are acted out with A*
over its own map and interactions on the target's pixels.

It sees only what the env gives an agent: the observation (`rgb`, and in the privileged track `depth`,
`segmentation`, `instance_types`), the last action's `failure_code`, and the instructions at reset
(docs/agents.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from luminous_sim.agents.camera import Intrinsics
from luminous_sim.agents.instances import InstanceTracker
from luminous_sim.agents.navigation import State, plan_path
from luminous_sim.agents.own_pose import HEADINGS, HORIZON_RANGE, STEP, OwnPose
from luminous_sim.agents.priors import SearchPriors, default_priors
from luminous_sim.agents.semantic_map import Instance, Node, SemanticMap
from luminous_sim.agents.subgoals import Subgoal, subgoals
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALL_TYPES, abilities
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT

NEEDS = ("depth", "segmentation", "instance_types")
"""The observations the agent maps with (the privileged track's)."""
REACH = 1.48
"""Metres from the eye to a pixel's point within which the agent interacts (ALFRED's 1.5 is measured to the
object's nearest point, which is never farther than a point seen on it)."""
POSE_TRIES = 4
"""Interaction poses tried for one instance before it counts as out of reach."""
OPEN_STANDOFF = 0.5
"""Metres on the floor to stand from what opens (a door swings towards the agent), at first."""
FRONTIER_AWAY = 3
"""Nodes a frontier must be from every node stood on (nearer floor is below the camera's view)."""
NEAREST_SLACK = 0.3
"""Metres beyond the nearest pose's eye distance a pose may be when the agent looks at a site (from close,
the eye sees over a sink's rim and a shelf's lip)."""
SEARCH_ROUNDS = 4096
"""Receptacles and sites one search decision may pass over (each is marked searched or acted on: a bound, not
a budget)."""
STOP = {"action": "Stop"}


class TrackError(LuminousError):
    """The agent was given an env without the observations its track needs."""


def type_index(name: str) -> int:
    return ALL_TYPES.index(name) + 1 if name in ALL_TYPES else 0


def type_name(index: int) -> str:
    return ALL_TYPES[index - 1] if 0 < index <= len(ALL_TYPES) else ""


@dataclass
class AgentSettings:
    """The agent's choices (the defaults are the reference agent's)."""

    use_steps: bool = True
    """Parse the step instructions with the directive (ALFRED's `high_descs`)."""
    given_task: dict[str, Any] | None = None
    """The task's type and `pddl_params` given instead of parsed (the parser ablation; None: parsed)."""


@dataclass
class _Episode:
    plan: list[Subgoal]
    map: SemanticMap
    pose: OwnPose = field(default_factory=OwnPose)
    index: int = 0
    queue: list[str] = field(default_factory=list)
    last: dict[str, Any] | None = None
    target: int | None = None
    roles: dict[str, int] = field(default_factory=dict)
    opened: set[int] = field(default_factory=set)
    tried: dict[int, set[Node]] = field(default_factory=dict)
    standoff: dict[int, float] = field(default_factory=dict)
    """Per instance, the least distance (metres, on the floor) to stand from it: raised each time opening it
    failed because its door would hit the agent."""
    out_of_reach: set[int] = field(default_factory=set)
    closed_points: dict[int, np.ndarray] = field(default_factory=dict)
    """Per instance opened, the points it was seen at before (restored when it is closed again)."""
    put_at: dict[int, OwnPose] = field(default_factory=dict)
    """Per instance put down, the pose it was put from (where to look for it again: in the fridge it cooled in)."""
    searched: set[int] = field(default_factory=set)
    """Receptacles that open, looked into."""
    searched_sites: set[tuple[int, tuple[int, int]]] = field(default_factory=set)
    """(receptacle, site) looked at from close: a receptacle that does not open is searched site by site."""
    started: bool = False
    """Whether it has looked around where it started."""
    held: int | None = None
    turn: str = "RotateRight"
    """Which way it looks around (drawn from the episode's seed: the search's randomness)."""
    seen_types: set[int] = field(default_factory=set)
    tracker: InstanceTracker | None = None
    """The rgb track's instances from predicted types (None: the simulator's segmentation)."""
    searching: bool = False
    """The last interaction opened a receptacle to look inside (search), not a subgoal's."""


class ModularAgent:
    """The agent (see the module docstring); `reset` and `act` are the evaluation's agent interface."""

    def __init__(self, width: int, height: int, parser: Any = None, priors: SearchPriors | None = None,
                 settings: AgentSettings | None = None, perception: Any = None):
        """`perception`: a `Perception` (the rgb track: depth and types predicted from RGB); None to map with the
        simulator's depth, segmentation and types (the privileged track)."""
        self.intrinsics = Intrinsics(width, height)
        self.perception = perception
        self.parser = parser
        self.priors = priors or default_priors()
        self.settings = settings or AgentSettings()
        self.task: dict[str, Any] = {}
        self.ep = _Episode([], SemanticMap(self.intrinsics))

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        given = self.settings.given_task
        if given is None:
            if self.parser is None:
                from luminous_sim.agents.parser import default_parser

                self.parser = default_parser()
            steps = list(info.get("high_descs") or []) if self.settings.use_steps else []
            directive = instruction.split("\n")[0]
            self.task = self.parser.parse(directive, steps).to_dict()
        else:
            self.task = {"task_type": given["task_type"], "pddl_params": dict(given["pddl_params"])}
        self.ep = _Episode(subgoals(self.task["task_type"], self.task["pddl_params"]), SemanticMap(self.intrinsics),
                           tracker=InstanceTracker(self.intrinsics) if self.perception is not None else None)
        rng = np.random.default_rng(int(info.get("episode_seed") or 0))
        self.ep.turn = "RotateRight" if rng.random() < 0.5 else "RotateLeft"

    def diagnosis(self) -> dict[str, Any]:
        """Where the episode stands, in the agent's own terms (for an error breakdown): the parsed task, the
        subgoal reached, and whether that subgoal's target was ever seen."""
        ep = self.ep
        current = ep.plan[ep.index] if ep.index < len(ep.plan) else None
        return {"task": self.task, "subgoal": ep.index, "subgoals": len(ep.plan),
                "action": current.action if current else "",
                "target_seen": current is not None and any(type_index(t) in ep.seen_types for t in current.types)}

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> dict[str, Any]:
        ep = self.ep
        self._feedback(info)
        if ep.tracker is not None:
            types, depth = self.perception.predict(np.asarray(observation["rgb"]))
            seg = ep.tracker.update(types, depth, ep.pose, ep.held)
        else:
            depth = np.asarray(observation["depth"], np.float32)[..., 0]
            seg = np.asarray(observation["segmentation"])
            types = np.asarray(observation["instance_types"])
        ep.map.update(depth, seg, types, ep.pose, ep.held)
        ep.seen_types.update(int(t) for t in np.unique(types) if t)
        action = self._decide(depth, seg)
        ep.last = action
        return action

    # --- feedback -------------------------------------------------------------------------------------------

    def _feedback(self, info: dict[str, Any]) -> None:
        ep, last = self.ep, self.ep.last
        if last is None:
            return
        ok = info.get("failure_code") in (None, "")
        name = last["action"]
        if name in ("MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown"):
            if ok:
                ep.pose = ep.pose.after(name)
            else:
                if name == "MoveAhead":
                    ep.map.blocked_moves.add((ep.pose.node, ep.pose.heading))
                ep.queue.clear()
            return
        ep.queue.clear()
        body = ep.target
        if body is None:
            return
        if not ok:
            if name == "OpenObject" and info.get("failure_code") == "blocked":
                target = ep.map.instances.get(body)
                if target is not None:
                    ep.standoff[body] = _flat_distance(ep.pose.node, target.points) + STEP
            ep.tried.setdefault(body, set()).add(ep.pose.node)
            if len(ep.tried[body]) >= POSE_TRIES:
                ep.out_of_reach.add(body)
                if ep.searching:
                    ep.searched.add(body)
            return
        seen = ep.map.instances.get(body)
        if name == "OpenObject":
            ep.opened.add(body)
            if seen is not None:  # its points as it stands closed (the door will be seen where it swings)
                ep.closed_points[body] = seen.points.copy()
        elif name == "CloseObject":
            ep.opened.discard(body)
            if seen is not None and body in ep.closed_points:
                seen.points = ep.closed_points.pop(body)
        if ep.searching:  # look inside at other horizons too
            ep.searched.add(body)
            ep.searching = False
            h = ep.pose.horizon
            ep.queue = (["LookDown", "LookUp"] if h + 15 <= HORIZON_RANGE[1] else []) + (
                ["LookUp", "LookDown"] if h - 15 >= HORIZON_RANGE[0] else [])
            return
        if ep.index >= len(ep.plan):
            return
        sg = ep.plan[ep.index]
        if sg.role:
            ep.roles[sg.role] = body
        if name in ("PickupObject", "SliceObject"):
            ep.map.forget_instance(body)
            if ep.tracker is not None:
                ep.tracker.forget(body)
        if name == "PickupObject":
            ep.held = body
        elif name == "PutObject":
            if ep.held is not None:
                ep.put_at[ep.held] = ep.pose
            ep.held = None
        ep.index += 1
        ep.tried.clear()
        ep.out_of_reach.clear()

    # --- decisions ------------------------------------------------------------------------------------------

    def _decide(self, depth: np.ndarray, seg: np.ndarray) -> dict[str, Any]:
        ep = self.ep
        for _ in range(len(ep.plan) + 4):
            if ep.index >= len(ep.plan):
                return STOP
            if not ep.started:  # look around where it starts
                ep.started = True
                ep.queue = [ep.turn] * 4
            if ep.queue:
                return self._nav(ep.queue.pop(0))
            sg = ep.plan[ep.index]
            if sg.action == "OpenObject" and ep.roles.get(sg.role) in ep.opened and sg.role:
                ep.index += 1
                continue
            target = self._choose(sg)
            ep.searching = False
            if target is None:
                return self._back_to_put(sg) or self._explore(sg, depth, seg)
            if sg.action == "OpenObject" and target.body in ep.opened:  # opened while searching
                if sg.role:
                    ep.roles[sg.role] = target.body
                ep.index += 1
                continue
            action = self._interact(sg.action, target, depth, seg)
            if action is not None:
                return action
            step = self._approach(target)
            if step is not None:
                return step
        return STOP

    def _nav(self, name: str) -> dict[str, Any]:
        self.ep.target = None
        return {"action": name}

    def _choose(self, sg: Subgoal) -> Instance | None:
        ep = self.ep
        wanted = {type_index(t) for t in sg.types}
        mine = ep.roles.get(sg.role) if sg.role and sg.role != "other" else None
        if mine is not None and mine in ep.map.instances and mine not in ep.out_of_reach:
            return ep.map.instances[mine]
        first = ep.roles.get("object")
        found = [i for i in ep.map.instances.values() if i.type_index in wanted and i.body not in ep.out_of_reach
                 and not (sg.role == "other" and i.body == first)]
        if not found:
            return None
        here = np.array([ep.pose.x, ep.pose.y])
        return min(found, key=lambda i: (float(np.linalg.norm(i.centre[:2] - here)), i.body))

    def _interact(self, name: str, target: Instance, depth: np.ndarray, seg: np.ndarray) -> dict[str, Any] | None:
        """The interaction with the target's mask (ALFRED's form) if it is in view and some of it within reach."""
        mask = seg == target.body
        rows, cols = np.nonzero(mask)
        if len(rows) == 0 or self.ep.pose.node in self.ep.tried.get(target.body, set()):
            return None
        right, up = self.intrinsics.rays(rows, cols)
        dist = depth[rows, cols] * np.sqrt(1 + right**2 + up**2)
        if not (dist < REACH).any():
            return None
        self.ep.target = target.body
        return {"action": name, "mask": mask}

    def _approach(self, target: Instance, looking: bool = False) -> dict[str, Any] | None:
        """The first move towards a pose from which the target is within reach (None: there is none left, or it
        is there). `looking`: the nearest such poses, and no reach bookkeeping (it looks, it does not act)."""
        ep = self.ep
        goals = self._poses(target, nearest=looking)
        path = plan_path(ep.map, (ep.pose.node, ep.pose.heading), goals)
        if path is None:
            if not looking:
                ep.out_of_reach.add(target.body)
            return None
        node = ep.pose.node if not path else _end(ep.pose, path)
        if not path and ep.pose.horizon == _horizon(node, target):
            if not looking:
                ep.tried.setdefault(target.body, set()).add(node)  # here, facing it, and still not in reach
                if len(ep.tried[target.body]) >= POSE_TRIES:
                    ep.out_of_reach.add(target.body)
            return None
        return self._walk(path, _horizon(node, target))

    def _back_to_put(self, sg: Subgoal) -> dict[str, Any] | None:
        """For a pick-up of the task's object, unseen since it was put down, the next move back to the pose it
        was put from (None: there is none, or it is there and the object is still unseen)."""
        ep = self.ep
        body = ep.roles.get(sg.role) if sg.action == "PickupObject" and sg.role == "object" else None
        if body is None or body not in ep.put_at:
            return None
        then = ep.put_at[body]
        path = plan_path(ep.map, (ep.pose.node, ep.pose.heading), [(then.node, then.heading)])
        looks = then.horizon - ep.pose.horizon
        if path is None or (not path and not looks):
            ep.put_at.pop(body)
            return None
        return self._walk(path, then.horizon)

    def _walk(self, path: list[str], horizon: int) -> dict[str, Any] | None:
        """The first of `path` then the tilts to `horizon` (None: nothing to do)."""
        looks = horizon - self.ep.pose.horizon
        self.ep.queue = path + ["LookDown" if looks > 0 else "LookUp"] * (abs(looks) // 15)
        return self._nav(self.ep.queue.pop(0)) if self.ep.queue else None

    def _poses(self, target: Instance, nearest: bool = False) -> list[State]:
        """Nodes (with the heading towards the target) from which its nearest seen point is within reach
        (`nearest`: only those within `NEAREST_SLACK` of the nearest)."""
        ep = self.ep
        c = target.centre
        cx, cy = round(c[0] / STEP), round(c[1] / STEP)
        found: list[tuple[float, State]] = []
        tried = ep.tried.get(target.body, set())
        standoff = ep.standoff.get(target.body, OPEN_STANDOFF if _opens(target) else 0.0)
        for dx in range(-6, 7):
            for dy in range(-6, 7):
                node = (cx + dx, cy + dy)
                if node in tried or ep.map.blocked(node) or _flat_distance(node, target.points) < standoff:
                    continue
                eye = ep.map.eye_distance(node, target.points)
                if 0.3 < eye < REACH - 0.05:
                    found.append((eye, (node, _facing(node, c))))
        if nearest and found:
            least = min(e for e, _ in found)
            found = [f for f in found if f[0] <= least + NEAREST_SLACK]
        return [state for _, state in found]

    def _explore(self, sg: Subgoal, depth: np.ndarray, seg: np.ndarray) -> dict[str, Any]:
        """A step of search for the subgoal's types: the nearest frontier; else, for what can be put away, the
        receptacles by the priors (`_search_receptacles`); else Stop."""
        ep = self.ep
        frontier = self._frontier()
        if frontier:
            path = plan_path(ep.map, (ep.pose.node, ep.pose.heading), [(n, h) for n in frontier for h in range(4)])
            if path:
                ep.queue = path + [ep.turn] * 3  # and look around there
                return self._nav(ep.queue.pop(0))
        if not any(abilities(t).pickupable for t in sg.types):
            return STOP  # what cannot be put away is found by exploring alone
        return self._search_receptacles(sg, depth, seg)

    def _search_receptacles(self, sg: Subgoal, depth: np.ndarray, seg: np.ndarray) -> dict[str, Any]:
        """Go to the receptacle likeliest to hold one of the subgoal's types (the priors, then nearness): open
        and look into one that opens; look at one that does not from close, site by site (`semantic_map.SITE`),
        and a step lower. Stop when every receptacle has been searched."""
        ep = self.ep
        here = np.array([ep.pose.x, ep.pose.y])

        def score(item: tuple[Instance, tuple[int, int] | None]) -> tuple[float, float, int]:
            i, site = item
            chance = max(self.priors.chance(t, type_name(i.type_index)) for t in sg.types)
            where = i.centre if site is None else i.site_point(site)
            return (chance, -float(np.linalg.norm(where[:2] - here)), -i.body)

        for _ in range(SEARCH_ROUNDS):
            left: list[tuple[Instance, tuple[int, int] | None]] = []
            for i in ep.map.instances.values():
                kind = abilities(type_name(i.type_index))
                if not kind.receptacle or i.body in ep.out_of_reach or i.body == ep.held:
                    continue
                if kind.openable:
                    left += [] if i.body in ep.searched else [(i, None)]
                else:
                    left += [(i, site) for site in sorted(i.sites) if (i.body, site) not in ep.searched_sites]
            if not left:
                return STOP
            likely, site = max(left, key=score)
            if site is not None:
                spot = Instance(likely.body, likely.type_index, likely.site_point(site)[None])
                step = self._approach(spot, looking=True)
                if step is not None:
                    return step
                ep.searched_sites.add((likely.body, site))
                if ep.pose.horizon + 15 <= HORIZON_RANGE[1] and self._poses(spot, nearest=True):
                    ep.queue = ["LookUp"]  # after one look a step lower
                    return self._nav("LookDown")
                continue
            closed = likely.body not in ep.opened
            if closed:
                action = self._interact("OpenObject", likely, depth, seg)
                if action is not None:
                    ep.searching = True
                    return action
            step = self._approach(likely)
            if step is not None:
                return step
            if not closed or likely.body in ep.out_of_reach:
                ep.searched.add(likely.body)  # looked at from within reach, or out of reach from everywhere
        return STOP

    def _frontier(self) -> list[Node]:
        ep = self.ep
        visited = ep.map.visited
        out: list[Node] = []
        known = [n for n in ep.map.known_nodes() if not ep.map.blocked(n)]
        for n in known:
            if min(max(abs(n[0] - v[0]), abs(n[1] - v[1])) for v in visited) < FRONTIER_AWAY:
                continue
            if any(not ep.map.known((n[0] + dx, n[1] + dy)) for dx, dy in HEADINGS):
                out.append(n)
        return out


def _flat_distance(node: Node, points: np.ndarray) -> float:
    """The least distance on the floor from a node to any of `points`."""
    return float(np.min(np.hypot(points[:, 0] - node[0] * STEP, points[:, 1] - node[1] * STEP)))


def _opens(target: Instance) -> bool:
    return abilities(type_name(target.type_index)).openable


def _end(pose: OwnPose, path: list[str]) -> Node:
    for name in path:
        pose = pose.after(name)
    return pose.node


def _facing(node: Node, point: np.ndarray) -> int:
    angle = math.degrees(math.atan2(point[0] - node[0] * STEP, point[1] - node[1] * STEP)) % 360
    return round(angle / 90) % 4


def _horizon(node: Node, target: Instance) -> int:
    c = target.centre
    flat = math.hypot(c[0] - node[0] * STEP, c[1] - node[1] * STEP)
    down = math.degrees(math.atan2(CAMERA_HEIGHT - c[2], max(flat, 0.05)))
    h = round(down / 15) * 15
    return min(max(h, HORIZON_RANGE[0]), HORIZON_RANGE[1])


def modular(context: Any) -> ModularAgent:
    """The evaluation's factory (`luminous eval --policy luminous_sim.agents:modular --track privileged`)."""
    obs = context.config.observations
    missing = [k for k in NEEDS if not getattr(obs, k)]
    if missing:
        raise TrackError(f"the modular agent maps with {', '.join(NEEDS)}, which this env does not observe "
                         f"({', '.join(missing)} off): evaluate it with --track privileged (its perception "
                         "for the rgb track: --policy luminous_sim.agents:modular_rgb)")
    return ModularAgent(obs.width, obs.height)


def modular_rgb(context: Any) -> ModularAgent:
    """The evaluation's factory for the rgb track (`luminous eval --policy luminous_sim.agents:modular_rgb`): depth
    and types predicted from RGB by `default_perception` (`LUMINOUS_PERCEPTION`'s checkpoint), instances tracked
    from them."""
    import torch

    from luminous_sim.agents.perception import default_perception

    torch.set_num_threads(1)  # the agent's own process, one an evaluation worker: a thread a core
    obs = context.config.observations
    return ModularAgent(obs.width, obs.height, perception=default_perception())


def modular_no_steps(context: Any) -> ModularAgent:
    """The modular agent parsing the goal directive alone (the step-instructions ablation)."""
    agent = modular(context)
    agent.settings = AgentSettings(use_steps=False)
    return agent
