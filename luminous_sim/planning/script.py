"""Executing a given script instead of a plan: a CDF's `execution` section, its high-level steps through
ALFRED's expansions and the oracle's navigation, its low-level steps as written.

A run of low-level navigation steps is recorded as one GotoLocation subgoal (ALFRED's subgoal for a
walk), each low-level interaction as a subgoal of its own. The script stops at its first failure: no
replanning, the point of a script being that it is followed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any

from luminous_sim.cdf.schema import HighLevelStep, LowLevelStep
from luminous_sim.errors import Failure, FailureCode, PlanningError
from luminous_sim.planning.alfred_actions import interaction_api, nav_api, type_name
from luminous_sim.planning.oracle import ExecutionError, Oracle
from luminous_sim.planning.symbolic import HighLevelAction
from luminous_sim.planning.trajectory import Trajectory
from luminous_sim.states import WorldState
from luminous_sim.tasks.meanings import MEANINGS
from luminous_sim.vocab import BASINS, DISCRETE_NAVIGATION, NAVIGATION_ACTIONS
from luminous_sim.world import interaction_args

DEVICES: dict[str, tuple[str, ...]] = {
    m.achieved_by: (m.device,) + (tuple(b for b in BASINS if b != m.device) if m.achieved_by == "CleanObject" else ())
    for m in MEANINGS.values() if m.device and m.achieved_by
}
"""Heat/Cool/Clean -> the device types that do it (a CDF step names only the object)."""


@dataclass(frozen=True)
class LowLevelAction:
    """A script's low-level action, run as written (no navigation or door handling around it).

    Attributes:
        action: an ALFRED low-level action (`MoveAhead`, `PickupObject`, ...).
        args: `objectId` and, for PutObject, `receptacleObjectId` (object ids), as in ALFRED's api_action.
    """

    action: str
    args: Mapping[str, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        object.__setattr__(self, "args", MappingProxyType(dict(self.args)))

    @property
    def is_navigation(self) -> bool:
        return self.action in NAVIGATION_ACTIONS


ScriptAction = HighLevelAction | LowLevelAction


def script_from_cdf(steps: Sequence[HighLevelStep | LowLevelStep], names: Mapping[str, str],
                    state: WorldState) -> list[ScriptAction]:
    """A CDF's `execution` steps as actions on object ids.

    CDF names become ids through `names`; a PutObject that names no object puts what the script holds by
    then; Heat/Cool/Clean use the device the script last went to, else the first of its type in `state`;
    NoOp steps are dropped.

    Raises:
        PlanningError: a step names an object the scene does not have, puts with nothing held, or needs a
            device the scene lacks; the message names the step (`execution[3]`).
    """
    out: list[ScriptAction] = []
    held, at = state.held, None
    for i, step in enumerate(steps):
        where = f"execution[{i}] ({step.action})"
        if isinstance(step, HighLevelStep):
            if step.action == "NoOp":
                continue
            o, r = _id(step.object, names, f"{where}.object"), _id(step.receptacle, names, f"{where}.receptacle")
        else:
            o = _id(step.objectId, names, f"{where}.objectId")
            r = _id(step.receptacleObjectId, names, f"{where}.receptacleObjectId")
        if step.action == "PutObject" and o is None:
            if held is None:
                raise PlanningError(f"{where}: puts into {r} but the script holds nothing by then")
            o = held
        if step.action in DEVICES:
            r = _device(step.action, at, state, where)
        args = {k: v for k, v in (("objectId", o), ("receptacleObjectId", r)) if v is not None}
        out.append(HighLevelAction(step.action, args) if isinstance(step, HighLevelStep)
                   else LowLevelAction(step.action, args))
        if step.action == "GotoLocation":
            at = o
        elif step.action == "PickupObject":
            held = o
        elif step.action == "PutObject":
            held = None
    return out


def _id(name: str | None, names: Mapping[str, str], where: str) -> str | None:
    if name is None:
        return None
    if name not in names:
        raise PlanningError(f"{where}: {name!r} is not an object of the scene "
                            f"(mapped: {', '.join(sorted(names)) or 'none'})")
    return names[name]


def _device(action: str, at: str | None, state: WorldState, where: str) -> str:
    kinds = DEVICES[action]
    if at is not None and at in state.objects and state.objects[at].object_type in kinds:
        return at
    found = sorted(i for i, o in state.objects.items() if o.object_type in kinds)
    if not found:
        raise PlanningError(f"{where}: needs a {' or '.join(kinds)}, and the scene has none",
                            FailureCode.GOAL_UNREACHABLE)
    return found[0]


class ScriptOracle(Oracle):
    """The oracle's executor, following a given script."""

    def execute(self, script: Sequence[ScriptAction]) -> Trajectory:
        """Run `script` from the world's current state; the trajectory ends at its first failure."""
        traj = Trajectory(init_action=self.view.agent.to_alfred())
        self._frame(traj, high_idx=0, low_idx=0)
        try:
            self._execute(list(script), traj)
            traj.success = True
        except PlanningError as exc:  # ExecutionError, or an expansion that does not apply
            traj.fail(Failure(exc.code, str(exc)))
        traj.high_pddl.append({"discrete_action": {"action": "NoOp", "args": []}, "high_idx": len(traj.high_pddl),
                               "planner_action": {"action": "End", "value": 1}})
        return traj

    def _execute_one(self, actions: list, k: int, hl, traj: Trajectory) -> None:
        if not isinstance(hl, LowLevelAction):
            super()._execute_one(actions, k, hl, traj)
        elif hl.is_navigation:
            self._walk(actions, k, hl, traj)
        else:
            self._touch(hl, traj)

    def _walk(self, actions: list, k: int, step: LowLevelAction, traj: Trajectory) -> None:
        """One navigation step; consecutive ones make up one GotoLocation subgoal."""
        prev = actions[k - 1] if k else None
        joined = isinstance(prev, LowLevelAction) and prev.is_navigation
        high_idx = len(traj.high_pddl) - 1 if joined else len(traj.high_pddl)
        self._low(nav_api(step.action), {"action": DISCRETE_NAVIGATION[step.action], "args": {}}, high_idx, traj)
        location = self.view.agent.location_string()
        if joined:
            traj.high_pddl[-1]["planner_action"]["location"] = location
            return
        end = next((j for j in range(k, len(actions))
                    if not (isinstance(actions[j], LowLevelAction) and actions[j].is_navigation)), len(actions))
        target = self._next_object(actions, end - 1)
        traj.high_pddl.append({"discrete_action": {"action": "GotoLocation", "args": [type_name(target)]},
                               "high_idx": high_idx, "planner_action": {"action": "GotoLocation",
                                                                         "location": location}})

    def _touch(self, step: LowLevelAction, traj: Trajectory) -> None:
        """One interaction, aimed at its object (a put: at its receptacle) where the agent stands."""
        o, r = step.args.get("objectId"), step.args.get("receptacleObjectId")
        look_at = r or o
        if look_at is None:
            raise ExecutionError(f"{step.action} names no object", FailureCode.NO_TARGET)
        mask = self._mask(look_at)
        if mask is None:  # its own few pixels in an open container in view, never the container's
            mask = self._mask(look_at, few_pixels=True)
        if mask is None:
            raise ExecutionError(f"{look_at} is not visible enough from here for {step.action} to point at it",
                                 FailureCode.NOT_VISIBLE)
        high_idx = len(traj.high_pddl)
        api: dict[str, Any] = interaction_api(step.action, o or "", r)
        self._low(api, {"action": step.action, "args": interaction_args(mask)}, high_idx, traj)
        discrete = [type_name(o)] + ([type_name(r)] if step.action == "PutObject" else [])
        traj.high_pddl.append({"discrete_action": {"action": step.action, "args": discrete},
                               "high_idx": high_idx, "planner_action": {"action": step.action, **step.args}})
