"""Drawing feasible ALFRED tasks for a scene (A `gen/scripts/generate_trajectories.py` constraints).

Candidates are enumerated stage by stage (object, slicing, state-change ability, movable
receptacle, receptacle or lamp), each stage applying ALFRED's constraints to what the scene holds;
the first stage that leaves nothing names the reason in a `TaskSamplingError`. A task is then
drawn hierarchically: the object type uniformly among the feasible ones, then whether it is
sliced, then the movable receptacle, the receptacle and the lamp, each uniformly among the values
still feasible.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import replace

import numpy as np

from luminous_sim.scene.model import Scene
from luminous_sim.states import ObjectState, WorldState
from luminous_sim.states.tables import DEFAULT_SLICE_COUNTS
from luminous_sim.tasks.cdf_bridge import cdf_for_task, required_objects, task_from_cdf
from luminous_sim.tasks.constraints import ABILITY, DEVICES, NEVER_PARENT, PICKUP_TYPES, params_problems
from luminous_sim.tasks.errors import TaskSamplingError
from luminous_sim.tasks.evaluate import goal_conditions, goal_satisfied, parents
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.templates import task_description
from luminous_sim.tasks.types import (
    LAMPS,
    MOVABLE_RECEPTACLES,
    SLICED_PARENTS,
    SLICING_TOOLS,
    TASK_TYPES,
    goal_for,
    task_info,
)
from luminous_sim.vocab import SLICED_TYPES, abilities, can_contain

__all__ = [
    "DRAW_ORDER",
    "cdf_for_task",
    "feasible_params",
    "feasible_task_types",
    "required_objects",
    "sample_task",
    "state_from_scene",
    "task_from_cdf",
]

DRAW_ORDER: tuple[str, ...] = ("object_target", "object_sliced", "mrecep_target", "parent_target", "toggle_target")
"""The order in which parameters are drawn, each uniformly among the values still feasible."""


def state_from_scene(scene: Scene) -> WorldState:
    """The pure initial state of a generated scene (what a `World` starts from, without physics)."""
    objs = [
        ObjectState(
            o.id,
            o.type,
            isOpen=bool(o.states.get("isOpen", False)),
            isToggled=bool(o.states.get("isToggled", False)),
            isDirty=bool(o.states.get("isDirty", False)),
            parent=o.parent,
        )
        for o in scene.objects
    ]
    return WorldState.of(objs)


class _Holdings:
    """What a state holds, by type."""

    def __init__(self, state: WorldState):
        self.state = state
        self.count: dict[str, int] = {}
        for o in state.objects.values():
            self.count[o.object_type] = self.count.get(o.object_type, 0) + 1

    def has(self, object_type: str) -> bool:
        return self.count.get(object_type, 0) > 0

    def present(self, types: Iterable[str]) -> list[str]:
        return sorted(t for t in set(types) if self.has(t))

    def pieces(self, parent: str) -> int:
        """Slices there are or could be of a sliceable type (existing ones plus whole ones cut)."""
        whole = [k for k in self.state.of_type(parent) if not self.state[k].isSliced]
        made = sum(self.state.slice_counts.get(k, DEFAULT_SLICE_COUNTS.get(parent, 1)) for k in whole)
        return self.count.get(parent + "Sliced", 0) + made

    def holds_type(self, receptacle_type: str, object_type: str) -> bool:
        """Whether an object of the type (or a slice of it) is already in a `receptacle_type`."""
        s = self.state
        return any(
            object_type in (o.object_type, SLICED_TYPES.get(o.object_type))
            and any(s[r].object_type == receptacle_type for r in parents(s, k))
            for k, o in s.objects.items()
        )


_Expand = Callable[[_Holdings, PddlParams], list[PddlParams]]


def _stages(task_type: str, sliced: bool | None) -> list[tuple[_Expand, str]]:
    """(expand, why-empty) per stage; each maps a partial candidate to its feasible extensions."""

    def objects(h: _Holdings, p: PddlParams) -> list[PddlParams]:
        banned = MOVABLE_RECEPTACLES if task_type == "pick_and_place_with_movable_recep" else ()
        return [replace(p, object_target=t) for t in h.present(PICKUP_TYPES) if t not in banned]

    def slicing(h: _Holdings, p: PddlParams) -> list[PddlParams]:
        can = task_info(task_type).sliced and p.object_target in SLICED_PARENTS and bool(h.present(SLICING_TOOLS))
        options = {None: [False, True] if can else [False], False: [False], True: [True] if can else []}[sliced]
        return [replace(p, object_sliced=s) for s in options]

    no_slice = (f"{task_type} is never sliced in ALFRED" if sliced and not task_info(task_type).sliced
                else f"a sliced {task_type} needs one of {', '.join(SLICED_PARENTS)} and a "
                     f"{' or '.join(SLICING_TOOLS)} in the scene")
    stages: list[tuple[_Expand, str]] = [
        (objects, "the scene holds no object type ALFRED picks up"
                  + (" other than a movable receptacle" if task_type == "pick_and_place_with_movable_recep"
                     else "")),
        (slicing, no_slice),
    ]
    if task_type in DEVICES:
        device, ability = DEVICES[task_type][0], ABILITY[task_type]
        stages += [
            (lambda h, p: [p] if getattr(abilities(p.object_type), ability) else [],
             f"no object in the scene is {ability}"),
            (lambda h, p: [] if h.holds_type(device, p.object_target) else [p],
             f"every {ability} object type present already has an instance inside the {device}"),
        ]
    if task_type == "pick_two_obj_and_place":
        stages.append((
            lambda h, p: [p] if (h.pieces(p.object_target) if p.object_sliced
                                 else h.count.get(p.object_target, 0)) >= 2 else [],
            "pick_two_obj_and_place needs two instances of one object type",
        ))
    if task_type == "pick_and_place_with_movable_recep":
        stages.append((
            lambda h, p: [replace(p, mrecep_target=m) for m in h.present(MOVABLE_RECEPTACLES)
                          if can_contain(m, p.object_type)],
            f"no movable receptacle ({', '.join(MOVABLE_RECEPTACLES)}) in the scene accepts an object present",
        ))
    if task_type == "look_at_obj_in_light":
        stages.append((lambda h, p: [replace(p, toggle_target=t) for t in h.present(LAMPS)],
                       f"the scene has no {' or '.join(LAMPS)}"))
        return stages

    def receptacles(h: _Holdings, p: PddlParams) -> list[PddlParams]:
        out = []
        for r in h.present(t for t in h.count if abilities(t).receptacle and t not in NEVER_PARENT):
            q = replace(p, parent_target=r)
            if params_problems(task_type, q):
                continue
            if task_type == "pick_two_obj_and_place" and h.holds_type(r, q.object_type):
                continue
            if q.mrecep_target and h.holds_type(r, q.mrecep_target):
                continue
            out.append(q)
        return out

    why = "no receptacle in the scene may take the object (ALFRED's receptacle table and exclusions"
    if task_type == "pick_two_obj_and_place":
        why += "; pick_two: not CoffeeMachine/ToiletPaperHanger/HandTowelHolder, none already holding the type"
    if task_type == "pick_and_place_with_movable_recep":
        why += "; it must accept the movable receptacle and not already hold one of its type"
    stages.append((receptacles, why + ")"))
    return stages


def _where(scene: Scene) -> str:
    return f"scene {scene.room.name!r} (seed {scene.seed})"


def feasible_params(
    scene: Scene, state: WorldState, task_type: str, sliced: bool | None = None
) -> list[PddlParams]:
    """Every parameter set ALFRED's constraints allow for a task type in a scene, in sorted order.

    Args:
        scene: the scene (its room type decides which task types are allowed).
        state: the scene's current object states (what is where, what is held).
        task_type: one of the seven ALFRED task types.
        sliced: True for sliced variants only, False for unsliced only, None for both.

    Raises:
        TaskSamplingError: none is feasible; the message names the scene and the reason.
        TaskError: an unknown task type.
    """
    info = task_info(task_type)
    where = f"no {task_type} task in {_where(scene)}"
    room = scene.room.room_type
    if room not in info.rooms:
        raise TaskSamplingError(f"{where}: ALFRED generates it only in {', '.join(sorted(info.rooms))}, "
                                f"and this is a {room}")
    h = _Holdings(state)
    missing = [d for d in DEVICES.get(task_type, ()) if not h.has(d)]
    if missing:
        raise TaskSamplingError(f"{where}: the scene has no {' and no '.join(missing)}")
    cands = [PddlParams(object_target="")]
    for expand, why in _stages(task_type, sliced):
        cands = [q for p in cands for q in expand(h, p)]
        if not cands:
            raise TaskSamplingError(f"{where}: {why}")
    open_goals = [p for p in cands if not _already_met(task_type, p, state)]
    if not open_goals:
        raise TaskSamplingError(f"{where}: every candidate goal already holds in the initial state")
    return sorted(open_goals, key=lambda p: tuple(str(getattr(p, k)) for k in DRAW_ORDER))


def _already_met(task_type: str, params: PddlParams, state: WorldState) -> bool:
    goal = goal_for(params, task_type)
    if goal_satisfied(goal, state):
        return True
    done, total = goal_conditions(TaskInstance(task_type, params, goal, 0), state)
    return done == total


def _draw(cands: list[PddlParams], rng: np.random.Generator) -> PddlParams:
    for key in DRAW_ORDER:
        values = sorted({getattr(p, key) for p in cands})
        pick = values[int(rng.integers(len(values)))]
        cands = [p for p in cands if getattr(p, key) == pick]
    return cands[0]


def sample_task(
    scene: Scene,
    state: WorldState,
    task_type: str,
    rng: np.random.Generator,
    *,
    sliced: bool | None = None,
    closed_receptacles: bool = False,
) -> TaskInstance:
    """Draw a feasible ALFRED task of a type for a scene, with a templated instruction.

    Args:
        scene: the scene (room type, seed).
        state: its object states (see `state_from_scene`).
        task_type: one of the seven ALFRED task types.
        rng: every draw comes from it (same seed, same task).
        sliced: force the sliced (True) or unsliced (False) variant; None lets the draw decide.
        closed_receptacles: add ALFRED's "every receptacle closed" conjunct to the goal.

    Raises:
        TaskSamplingError: no task of the type is feasible; the message says why.
    """
    params = _draw(feasible_params(scene, state, task_type, sliced), rng)
    task = TaskInstance(task_type, params, goal_for(params, task_type, closed_receptacles), scene.seed)
    return replace(task, instruction=task_description(task, rng))


def feasible_task_types(scene: Scene, state: WorldState) -> list[str]:
    """The ALFRED task types with at least one feasible task in the scene, in ALFRED's order."""
    out = []
    for name in TASK_TYPES:
        try:
            feasible_params(scene, state, name)
        except TaskSamplingError:
            continue
        out.append(name)
    return out
