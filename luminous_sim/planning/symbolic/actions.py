"""The planner's output: high-level actions in ALFRED's vocabulary and the plan that lists them.

A `HighLevelAction` keeps its arguments under ALFRED's planner keys: `objectId` (the object acted
on, or the place a GotoLocation goes to) and `receptacleObjectId` (PutObject's receptacle and the
device of HeatObject/CoolObject/CleanObject). `to_planner_action` and `to_discrete_action` give
ALFRED's two records of it (`plan.high_pddl[i].planner_action` / `.discrete_action`, spec 2.3).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from luminous_sim.errors import PlanningError
from luminous_sim.scene.ids import type_of_id
from luminous_sim.vocab import HIGH_LEVEL_ACTIONS, SLICED_TYPES

ACTIONS: tuple[str, ...] = HIGH_LEVEL_ACTIONS
"""ALFRED's high-level planner actions (End is added by `Plan.high_pddl`)."""

COSTS: dict[str, float] = {
    "GotoLocation": 1.0,
    "PickupObject": 1.0,
    "PutObject": 1.0,
    "OpenObject": 1.0,
    "CloseObject": 1.0,
    "ToggleObject": 5.0,
    "SliceObject": 5.0,
    "HeatObject": 3.0,
    "CoolObject": 3.0,
    "CleanObject": 3.0,
}
"""Action costs of ALFRED's put_task domain (spec 6.1), except Heat/Cool/Clean: ALFRED's domain sets
isHot/isCool/isClean only through those macros, while our simulator also cools on closing the fridge
(and so on), so the macros cost less than their primitive equivalents to keep ALFRED's expert plans
(Goto, Pickup, Goto, CoolObject, Goto, Put). GotoLocation costs 1 per move (no geometry)."""

_DEVICE_ACTIONS = ("PutObject", "HeatObject", "CoolObject", "CleanObject")


def _discrete_name(object_id: str) -> str:
    """ALFRED's lower-cased name of an object in `discrete_action.args` (slices by their parent)."""
    kind = type_of_id(object_id)
    return SLICED_TYPES.get(kind, kind).lower()


@dataclass(frozen=True)
class HighLevelAction:
    """One high-level planner action.

    Attributes:
        action: one of `ACTIONS`.
        args: `objectId` (and `receptacleObjectId` for PutObject and the Heat/Cool/Clean device);
            a GotoLocation may also carry the `location` string the navigation layer chose.
    """

    action: str
    args: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        if self.action not in ACTIONS:
            raise PlanningError(
                f"unknown high-level action {self.action!r}; expected one of {', '.join(ACTIONS)}"
            )
        object.__setattr__(self, "args", MappingProxyType(dict(self.args)))
        if "objectId" not in self.args:
            raise PlanningError(f"{self.action} needs an objectId")
        if self.action in _DEVICE_ACTIONS and "receptacleObjectId" not in self.args:
            raise PlanningError(f"{self.action} needs a receptacleObjectId")

    def __hash__(self) -> int:
        return hash((self.action, tuple(sorted(self.args.items()))))

    def __repr__(self) -> str:
        inner = ", ".join(str(v) for v in self.args.values())
        return f"{self.action}({inner})"

    @property
    def object_id(self) -> str:
        """The object acted on (for GotoLocation: the place gone to)."""
        return self.args["objectId"]

    @property
    def receptacle_id(self) -> str | None:
        """PutObject's receptacle, or the device of HeatObject/CoolObject/CleanObject."""
        return self.args.get("receptacleObjectId")

    @property
    def cost(self) -> float:
        """The action's cost in the planning domain."""
        return COSTS[self.action]

    def to_planner_action(self) -> dict[str, Any]:
        """ALFRED's `planner_action` dict.

        Heat/Cool name the device as `objectId`; Clean names the basin as `objectId` and the object
        as `cleanObjectId`; GotoLocation keeps the target as `objectId` (a Luminous addition) and
        ALFRED's `location` when the navigation layer has set one.
        """
        a, o, r = self.action, self.object_id, self.receptacle_id
        if a == "GotoLocation":
            out: dict[str, Any] = {"action": a, "objectId": o}
            if "location" in self.args:
                out["location"] = self.args["location"]
            return out
        if a in ("HeatObject", "CoolObject"):
            return {"action": a, "objectId": r, "forceVisible": True}
        if a == "CleanObject":
            return {"action": a, "objectId": r, "cleanObjectId": o, "forceVisible": True}
        if a == "PutObject":
            return {"action": a, "objectId": o, "receptacleObjectId": r, "forceVisible": True}
        return {"action": a, "objectId": o, "forceVisible": True}

    def to_discrete_action(self, next_action: HighLevelAction | None = None) -> dict[str, Any]:
        """ALFRED's `discrete_action` dict: the action and lower-cased type names.

        Args:
            next_action: for a GotoLocation, the following action: ALFRED names a GotoLocation by
                the next subgoal's receptacle, else its object. Without it, the place gone to.
        """
        if self.action == "GotoLocation":
            nxt = next_action
            target = (nxt.receptacle_id or nxt.object_id) if nxt is not None else self.object_id
            return {"action": "GotoLocation", "args": [_discrete_name(target)]}
        names = [_discrete_name(self.object_id)]
        if self.action == "PutObject" and self.receptacle_id is not None:
            names.append(_discrete_name(self.receptacle_id))
        return {"action": self.action, "args": names}


@dataclass(frozen=True)
class Plan:
    """A high-level plan and how it was found.

    Attributes:
        actions: the high-level actions, GotoLocation included.
        cost: their summed cost (`COSTS`).
        expanded: search nodes expanded (0 for external planners that do not say).
        seconds: wall time spent planning.
        backend: the solver that found it.
    """

    actions: list[HighLevelAction]
    cost: float
    expanded: int
    seconds: float
    backend: str = "astar"

    def __len__(self) -> int:
        return len(self.actions)

    def high_pddl(self) -> list[dict[str, Any]]:
        """ALFRED's `plan.high_pddl` list (with `high_idx`), ending with End."""
        out = []
        for i, a in enumerate(self.actions):
            nxt = self.actions[i + 1] if i + 1 < len(self.actions) else None
            out.append(
                {
                    "high_idx": i,
                    "planner_action": a.to_planner_action(),
                    "discrete_action": a.to_discrete_action(nxt),
                }
            )
        out.append(
            {
                "high_idx": len(self.actions),
                "planner_action": {"action": "End", "value": 1},
                "discrete_action": {"action": "NoOp", "args": []},
            }
        )
        return out

    def summary(self) -> str:
        """The actions on one line, e.g. `GotoLocation(CounterTop|1) PickupObject(Apple|1) ...`."""
        return " ".join(map(repr, self.actions))


def goto(place: str) -> HighLevelAction:
    """GotoLocation to the place of an object (its interaction location)."""
    return HighLevelAction("GotoLocation", {"objectId": place})


def act(action: str, object_id: str, receptacle_id: str | None = None) -> HighLevelAction:
    """A high-level interaction; `receptacle_id` for PutObject and the Heat/Cool/Clean device."""
    args = {"objectId": object_id}
    if receptacle_id is not None:
        args["receptacleObjectId"] = receptacle_id
    return HighLevelAction(action, args)
