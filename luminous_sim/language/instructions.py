"""Template instructions for a trajectory: one step-by-step sentence per high-level subgoal and a goal
directive. Navigation is described with turns, distances and a landmark near where the agent stops
("turn left and walk about 2 metres to the counter by the window"), not only "go to X"."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.language.names import preposition, spoken, type_from_word
from luminous_sim.language.verbs import VERBS, colour_word
from luminous_sim.scene.ids import type_of_id as type_of

if TYPE_CHECKING:
    from luminous_sim.planning.trajectory import Trajectory
    from luminous_sim.world import WorldView

LANDMARK_TYPES = ("CounterTop", "Fridge", "Sink", "DiningTable", "Sofa", "Bed", "Desk", "Dresser", "Shelf",
                  "TVStand", "CoffeeTable", "SideTable", "Toilet", "Bathtub", "Cabinet", "Microwave", "Window",
                  "ArmChair", "GarbageCan", "StoveBurner", "Television")
"""Things big or distinctive enough to steer by."""
NEAR = 1.5


@dataclass(frozen=True)
class Instructions:
    task_desc: str
    high_descs: list[str]


def _metres(steps: int) -> str:
    m = steps * 0.25
    if m <= 0.5:
        return "a step" if m <= 0.25 else "a couple of steps"
    if m < 1.5:
        return "about a metre"
    return f"about {round(m)} metres"


def _segments(actions: list[str]) -> list[tuple[str, int]]:
    """Navigation as turns and straight walks: [("left", 1), ("walk", 8), ("right", 1), ...]."""
    out: list[tuple[str, int]] = []
    for a in actions:
        kind = {"MoveAhead_25": "walk", "RotateLeft_90": "left", "RotateRight_90": "right"}.get(a)
        if kind is None:
            continue
        if out and out[-1][0] == kind:
            out[-1] = (kind, out[-1][1] + 1)
        else:
            out.append((kind, 1))
    return [("around", 1) if k in ("left", "right") and n == 2 else (k, n) for k, n in out]


class Describer:
    """Writes instructions for trajectories recorded in one world (read through its view)."""

    def __init__(self, view: WorldView, rng: np.random.Generator):
        self.view = view
        self.rng = rng

    def _pick(self, options) -> str:
        return options[int(self.rng.integers(len(options)))]

    def _position(self, object_id: str) -> np.ndarray | None:
        o = next((x for x in self.view.scene.objects if x.id == object_id), None)
        return None if o is None else np.array(o.position[:2])

    def landmark(self, object_id: str) -> str:
        """The object named with a landmark next to it: "the counter by the window". The landmark is never the
        object itself, one of its kind or anything named as it is (a sink basin's sink)."""
        if "|" not in object_id:  # only a type name is known ("apple", or ALFRED's "countertop")
            return f"the {spoken(type_from_word(object_id))}" if object_id else "the next spot"
        t = type_of(object_id)
        here = self._position(object_id)
        name = f"the {spoken(t)}"
        if here is None:
            return name
        near = []
        for o in self.view.scene.objects:
            if (o.type in LANDMARK_TYPES and o.type != t and spoken(o.type) != spoken(t) and o.id != object_id
                    and o.parent != object_id):
                d = float(np.linalg.norm(np.array(o.position[:2]) - here))
                if d < NEAR:
                    near.append((d, o.type))
        if near and self.rng.random() < 0.7:
            near.sort()
            by = spoken(near[0][1])
            return f"{name} {self._pick(('by', 'next to', 'near'))} the {by}"
        return name

    def attribute(self, object_id: str) -> str:
        """A colour word for the object, sometimes (the paper's [verb] + [object] + [attribute])."""
        if object_id not in self.view.body_ids() or self.rng.random() < 0.5:
            return ""
        colour = self.view.main_colour(object_id)
        return f"{colour_word(colour)} " if colour else ""

    def goto(self, nav: list[str], target: str) -> str:
        segs = _segments(nav)
        dest = self.landmark(target)
        parts = []
        for k, n in segs:
            if k == "walk":
                parts.append(f"{self._pick(('walk', 'go', 'move'))} forward {_metres(n)}")
            elif k == "around":
                parts.append("turn around")
            else:
                parts.append(f"turn {k}")
        verb = self._pick(VERBS["GotoLocation"])
        if not parts:
            return f"{verb.capitalize()} {dest}."
        if len(parts) > 3:  # long routes: the first move, how far in all, and the last move
            total = sum(n for k, n in segs if k == "walk")
            parts = [parts[0], f"{self._pick(('walk', 'go'))} {_metres(total)} in all", parts[-1]]
        route = ", ".join(parts[:-1]) + (" and " if len(parts) > 1 else "") + parts[-1]
        return f"{route[0].upper()}{route[1:]} to {dest}."

    def interaction(self, action: str, args: dict) -> str:
        o = args.get("objectId", "")
        obj = f"the {self.attribute(o)}{spoken(type_of(o))}"
        if action == "PutObject":
            r = args["receptacleObjectId"]
            return f"{self._pick(VERBS['PutObject']).capitalize()} {obj} {preposition(type_of(r))} " \
                   f"the {spoken(type_of(r))}."
        if action in ("HeatObject", "CoolObject", "CleanObject"):
            device = spoken(type_of(args.get("receptacleObjectId", "")))
            return f"{self._pick(VERBS[action]).capitalize()} {obj} in the {device}."
        if action == "ToggleObject":
            on = not self.view.state.objects.get(o) or self.view.state.objects[o].isToggled
            return f"{self._pick(VERBS['ToggleObjectOn' if on else 'ToggleObjectOff']).capitalize()} {obj}."
        verbs = VERBS.get(action, (action.replace("Object", "").lower(),))
        return f"{self._pick(verbs).capitalize()} {obj}."

    def describe(self, traj: Trajectory, task_desc: str) -> Instructions:
        """One sentence per non-End subgoal, aligned with `high_idx`."""
        highs = []
        for h in traj.high_pddl:
            pa = h["planner_action"]
            if pa["action"] == "End":
                continue
            if pa["action"] == "GotoLocation":
                nav = [a["discrete_action"]["action"] for a in traj.low_actions if a["high_idx"] == h["high_idx"]]
                target = next((x["planner_action"].get("receptacleObjectId") or x["planner_action"].get("objectId")
                               for x in traj.high_pddl if x["high_idx"] == h["high_idx"] + 1
                               and x["planner_action"]["action"] not in ("GotoLocation", "End")), None)
                named = (h["discrete_action"].get("args") or [""])[0]
                highs.append(self.goto(nav, target or named))
            else:
                highs.append(self.interaction(pa["action"], pa))
        return Instructions(task_desc, highs)
