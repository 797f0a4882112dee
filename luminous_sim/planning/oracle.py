"""The oracle: plan a goal symbolically, expand each high-level action into ALFRED's low-level actions,
navigate by shortest paths on the pose graph, execute everything in the World with a check after each
action, and replan from the reached state when something fails."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

import numpy as np

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, Not
from luminous_sim.errors import Failure, FailureCode, PlanningError
from luminous_sim.planning.alfred_actions import interaction_api, nav_api, type_name
from luminous_sim.planning.expand import Step, expand, gating_parent
from luminous_sim.planning.navigation import NavGraph, goto_actions
from luminous_sim.planning.trajectory import Trajectory
from luminous_sim.vocab import DISCRETE_NAVIGATION
from luminous_sim.world import World, interaction_args
from luminous_sim.world.agent import AgentPose
from luminous_sim.world.masks import resolve_target
from luminous_sim.world.reach import interactable

MAX_REPLANS = 3
PUT_CHECK_SEED = 7
"""Seed of the dry-run puts that judge standing poses (the world's own random stream is left alone)."""
PLAN_TIMEOUT = 8.0
"""Seconds one (re)planning call may take; plans take milliseconds when the goal is reachable."""
NO_ROOM = frozenset({FailureCode.RECEPTACLE_FULL, FailureCode.NO_SPOT_IN_REACH})
"""Put failures that say the object did not fit: the next plan leaves it elsewhere."""


class ExecutionError(PlanningError):
    """A low-level action failed while executing the plan (the oracle replans); `code` says why."""

    def __init__(self, message: str, code: FailureCode, unreachable: str | None = None,
                 full: tuple[str, str] | None = None, packed: bool = False):
        super().__init__(message, code)
        self.unreachable = unreachable
        """An object no pose can see: the next plan must do without it."""
        self.full = full
        """(object, receptacle) that did not fit: the next plan must leave the object elsewhere."""
        self.packed = packed
        """Whether the receptacle had no free spot at all (not merely none within reach from here)."""


def with_forbidden(goal: Expr, forbidden: list[Expr]) -> Expr:
    """The goal with ground conjuncts added inside its outer `exists` (equivalent, as they mention
    none of its variables), where the planner's estimate sees them next to the atoms they contradict:
    with one coffee table too full for the box, "box on a coffee table, box not on this one" is
    recognised as impossible at once instead of after a search that exhausts its budget."""
    if not forbidden:
        return goal
    if isinstance(goal, Exists):
        body = goal.body.args if isinstance(goal.body, And) else (goal.body,)
        return Exists(goal.params, And((*body, *forbidden)))
    if isinstance(goal, And):
        k = next((i for i, a in enumerate(goal.args) if isinstance(a, Exists)), None)
        if k is not None:
            return And(goal.args[:k] + (with_forbidden(goal.args[k], forbidden),) + goal.args[k + 1:])
    return And((goal, *forbidden))


class Oracle:
    """Runs goals in one World and records what it did."""

    def __init__(self, world: World, record_frames: bool = True, max_replans: int = MAX_REPLANS):
        self.world = world
        self.view = world.view()
        self.record_frames = record_frames
        self.max_replans = max_replans
        self.graph = NavGraph(self.view.nav)

    # ------------------------------------------------------------------ public

    def run(self, goal: Expr, names: dict[str, str] | None = None) -> Trajectory:
        """Achieve `goal` from the world's current state; the trajectory says whether it succeeded."""
        from luminous_sim.planning.symbolic import solve

        traj = Trajectory(init_action=self.view.agent.to_alfred())
        self._frame(traj, high_idx=0, low_idx=0)
        excluded: set[str] = set()
        forbidden: list[Expr] = []
        for attempt in range(self.max_replans + 1):
            t0 = time.perf_counter()
            target = with_forbidden(goal, forbidden)
            try:
                plan = solve(self.view.state.without(excluded), target, names=names, timeout=PLAN_TIMEOUT)
            except PlanningError as exc:
                traj.fail(Failure(exc.code, str(exc)))
                break
            finally:
                traj.planning_seconds += time.perf_counter() - t0
            try:
                self._execute(plan.actions, traj)
                traj.success = True
                break
            except ExecutionError as exc:
                traj.replans = attempt + 1
                traj.fail(Failure(exc.code, str(exc)))
                if exc.unreachable:
                    excluded.add(exc.unreachable)
                    traj.unreachable.append(exc.unreachable)
                if exc.full:
                    forbidden.append(Not(Atom("inReceptacle", exc.full)))
                    if exc.packed:
                        traj.full.append(exc.full[1])
        traj.high_pddl.append({"discrete_action": {"action": "NoOp", "args": []}, "high_idx": len(traj.high_pddl),
                               "planner_action": {"action": "End", "value": 1}})
        return traj

    # ------------------------------------------------------------------ execution

    def _execute(self, actions: list, traj: Trajectory) -> None:
        for k, hl in enumerate(actions):
            try:
                self._execute_one(actions, k, hl, traj)
            except ExecutionError:
                traj.failed_subgoals.append(hl.action)
                raise

    def _execute_one(self, actions: list, k: int, hl, traj: Trajectory) -> None:
        """Run high-level action `k`, recording its low-level actions and its high_pddl entry."""
        nxt = actions[k + 1].action if k + 1 < len(actions) else "End"
        high_idx = len(traj.high_pddl)
        if hl.action == "GotoLocation":
            target = hl.args.get("objectId") or hl.args.get("target")
            pose = self._goto(target, high_idx, traj, put=self._put_after(actions, k))
            discrete = [type_name(self._next_object(actions, k) or target)]
            planner = {"action": "GotoLocation", "location": pose.location_string()}
        else:
            state = self.view.state
            steps = expand(hl.action, hl.args, state, keep_open=nxt not in ("GotoLocation", "End"))
            for step in steps:
                self._interact(step, high_idx, traj)
            planner = {"action": hl.action, **{k2: v for k2, v in hl.args.items()}}
            discrete = [type_name(hl.args.get("objectId"))] + (
                [type_name(hl.args["receptacleObjectId"])] if hl.action == "PutObject" else [])
        traj.high_pddl.append({"discrete_action": {"action": hl.action, "args": discrete},
                               "high_idx": high_idx, "planner_action": planner})

    @staticmethod
    def _next_object(actions: list, k: int) -> str | None:
        """ALFRED names a GotoLocation by the next subgoal's receptacle, else its object."""
        if k + 1 >= len(actions):
            return None
        args = actions[k + 1].args
        return args.get("receptacleObjectId") or args.get("objectId")

    def _pose_target(self, object_id: str) -> str:
        """Where to stand for an object: the closed container it is in, if any."""
        state = self.view.state
        gate = gating_parent(state, object_id) if object_id in state.objects else None
        if gate is not None and not state.objects[gate].isOpen:
            return gate
        return object_id

    @staticmethod
    def _put_after(actions: list, k: int) -> tuple[str, str] | None:
        """(object, receptacle) of the PutObject right after GotoLocation `k`, if that is what follows."""
        if k + 1 < len(actions) and actions[k + 1].action == "PutObject":
            args = actions[k + 1].args
            return args["objectId"], args["receptacleObjectId"]
        return None

    def _goto(self, object_id: str, high_idx: int, traj: Trajectory, put: tuple[str, str] | None = None,
              prefer_pose: Callable[[AgentPose], bool] | None = None):
        """Walk to a pose that sees the object; before a put, preferably one from which the held thing
        has a free spot in reach (a crowded table may have room only on its far side); else one that
        passes `prefer_pose`, if any does."""
        prefer = prefer_pose
        if put is not None:
            view = self.view

            def prefer(pose) -> bool:
                rng = np.random.default_rng(PUT_CHECK_SEED)
                return not isinstance(view.free_spot(*put, rng, assume_open=True, eye=pose.eye()), Failure)
        pose = self.view.interaction_pose(self._pose_target(object_id), prefer=prefer)
        if pose is None:
            raise ExecutionError(f"no pose from which {object_id} is visible within reach", FailureCode.NO_POSE,
                                 unreachable=object_id)
        try:
            steps = goto_actions(self.graph, self.view.agent, pose)
        except PlanningError as exc:
            raise ExecutionError(f"no path to {object_id}: {exc}", exc.code) from exc
        for a in steps:
            self._low(nav_api(a), {"action": DISCRETE_NAVIGATION[a], "args": {}}, high_idx, traj)
        return pose

    def _interact(self, step: Step, high_idx: int, traj: Trajectory) -> None:
        look_at = step.receptacle_id or step.object_id
        mask = self._mask(look_at)
        if mask is None:  # e.g. an egg that the opened fridge's shelf hides, or one an opened door revealed elsewhere
            here = self.view.agent

            def stay(pose) -> bool:  # looking up or down, or turning, rather than walking
                return (pose.x, pose.y) == (here.x, here.y)
            try:
                self._goto(look_at, high_idx, traj, prefer_pose=stay)
                mask = self._mask(look_at)
            except ExecutionError:  # no pose shows it fully (an apple at the back of a microwave): as it is
                mask = self._mask(look_at, few_pixels=True)
                if mask is None:
                    raise
            if mask is None:
                mask = self._mask(look_at, few_pixels=True)
        if mask is None:
            raise ExecutionError(f"{look_at} is not visible enough for {step.action} to point at it",
                                 FailureCode.NOT_VISIBLE)
        api = interaction_api(step.action, step.object_id, step.receptacle_id)
        self._low(api, {"action": step.action, "args": interaction_args(mask)}, high_idx, traj)

    def _mask(self, look_at: str, few_pixels: bool = False) -> np.ndarray | None:
        """The object's own mask, if it is visible (`min_visible_pixels` within reach; with `few_pixels`, any
        pixel of it when it sits in an open container in view, which AI2-THOR lets the agent reach into) and
        ALFRED's mask-to-object lookup (`ThorEnv.va_interact`: the instance that best overlaps the mask,
        the held object excluded, interactable objects only) returns it for that mask; else None. Never
        another object's mask: ALFRED would act on that object."""
        view = self.view
        if look_at not in view.visible_objects() and not (few_pixels and view.open_container_in_view(look_at)):
            return None
        mask = view.instance_masks().get(look_at)
        if mask is None or not mask.any():
            return None
        world = self.world
        state = view.state
        found = resolve_target(mask, world.instance_ids(), world.body_to_object(), state.held,
                               lambda oid: interactable(state, oid))
        return mask if found == look_at else None

    def _low(self, api: dict[str, Any], discrete: dict[str, Any], high_idx: int, traj: Trajectory) -> None:
        result = self.world.step(api)
        if not result.success:
            assert result.code is not None  # every failed StepResult has one
            full = (api["objectId"], api["receptacleObjectId"]) if api["action"] == "PutObject" and (
                result.code in NO_ROOM) else None
            raise ExecutionError(f"{api['action']} failed: {result.error}", result.code, full=full,
                                 packed=full is not None and result.code == FailureCode.RECEPTACLE_FULL)
        traj.low_actions.append({"api_action": api, "discrete_action": discrete, "high_idx": high_idx})
        self._frame(traj, high_idx, len(traj.low_actions) - 1)

    def _frame(self, traj: Trajectory, high_idx: int, low_idx: int) -> None:
        if self.record_frames:
            traj.add_frame(self.view.frame().rgb.copy(), high_idx, low_idx)
