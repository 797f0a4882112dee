"""Drawing feasible ALFRED tasks for a scene (A `gen/scripts/generate_trajectories.py` constraints).

Candidates are enumerated stage by stage (object, slicing, state-change ability, movable
receptacle, receptacle or lamp), each stage applying ALFRED's constraints to what the scene holds;
the first stage that leaves nothing names the reason in a `TaskSamplingError`. A task is then
drawn hierarchically: the object type uniformly among the feasible ones, then whether it is
sliced, then the movable receptacle, the receptacle and the lamp, each uniformly among the values
still feasible.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np

from luminous_sim.errors import LuminousError
from luminous_sim.scene.model import Scene
from luminous_sim.states import ObjectState, WorldState
from luminous_sim.tasks.candidates import candidates
from luminous_sim.tasks.cdf_bridge import cdf_for_task, required_objects, task_from_cdf
from luminous_sim.tasks.errors import TaskSamplingError
from luminous_sim.tasks.evaluate import goal_conditions, goal_satisfied
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.templates import task_description
from luminous_sim.tasks.types import (
    TASK_TYPES,
    goal_for,
    task_info,
)
from luminous_sim.vocab import abilities

__all__ = [
    "DRAW_ORDER",
    "SUBSTRING_CLASH",
    "alfred_name_clash",
    "cdf_for_task",
    "draw_kept",
    "draw_params",
    "feasible_params",
    "feasible_task_types",
    "required_objects",
    "sample_task",
    "state_from_scene",
    "task_from_cdf",
]

DRAW_ORDER: tuple[str, ...] = (
    "object_target",
    "object_sliced",
    "mrecep_target",
    "parent_target",
    "toggle_target",
)
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


def _where(scene: Scene) -> str:
    return f"scene {scene.room.name!r} (seed {scene.seed})"


def feasible_params(
    scene: Scene, state: WorldState, task_type: str, sliced: bool | None = None, *, judged_alike: bool = True
) -> list[PddlParams]:
    """Every parameter set ALFRED's constraints allow for a task type in a scene, in sorted order.

    Args:
        scene: the scene (its room type decides which task types are allowed).
        state: the scene's current object states (what is where, what is held).
        task_type: one of the seven ALFRED task types.
        sliced: True for sliced variants only, False for unsliced only, None for both.
        judged_alike: leave out tasks ALFRED's objectId substring matching would judge differently from
            ours (`alfred_name_clash`); False keeps them (ALFRED's own tasks, reproduced by `--from-alfred`).

    Raises:
        TaskSamplingError: none is feasible; the message names the scene and the reason.
        TaskError: an unknown task type.
    """
    info = task_info(task_type)
    where = f"no {task_type} task in {_where(scene)}"
    rooms = scene.room.room_types
    if not info.rooms.intersection(rooms):
        raise TaskSamplingError(
            f"{where}: ALFRED generates it only in {', '.join(sorted(info.rooms))}, "
            f"and this is a {' and '.join(rooms)}"
        )
    cands, why = candidates(state, task_type, sliced)
    if not cands:
        raise TaskSamplingError(f"{where}: {why}")
    open_goals = [p for p in cands if not _already_met(task_type, p, state)]
    if not open_goals:
        raise TaskSamplingError(f"{where}: every candidate goal already holds in the initial state")
    clashes = {p: alfred_name_clash(p, state) if judged_alike else None for p in open_goals}
    alike = [p for p in open_goals if clashes[p] is None]
    if not alike:
        example = next(c for c in clashes.values() if c is not None)
        raise TaskSamplingError(f"{where}: {SUBSTRING_CLASH}: all {len(open_goals)} open candidate goals "
                                f"(e.g. {example})")
    return sorted(alike, key=lambda p: tuple(str(getattr(p, k)) for k in DRAW_ORDER))


SUBSTRING_CLASH = "ALFRED's objectId substring matching would judge the goal differently"
"""The rejection reason of `alfred_name_clash` (a `TaskSamplingError` names it when it leaves no candidate)."""

ROLE_ABILITY: tuple[tuple[str, str], ...] = (
    ("object_type", "pickupable"),
    ("parent_target", "receptacle"),
    ("mrecep_target", "pickupable"),
    ("toggle_target", "toggleable"),
)
"""Each task parameter and the ability ALFRED's `env/tasks.py` asks of the objects it matches."""


def alfred_name_clash(params: PddlParams, state: WorldState) -> str | None:
    """Why ALFRED's evaluator would judge this task differently from ours in this scene, or None.

    ALFRED's `env/tasks.py` matches a target by substring of the objectId (`get_objects_with_name_and_prop`):
    `Knife` also matches `ButterKnife|...`, `Pot` a `Potato|...`, `Pen` a `Pencil|...`, `Toilet` a
    `ToiletPaperHanger|...`; we match by type (a parent type also matching its slices). Where the scene holds
    an object with the ability ALFRED asks that matches a target's name by substring but not by type, some
    state (a butter knife in the sink basin, perhaps from the start) is a success for one judge and not the
    other: such a task is rejected, as ALFRED's generator never meets it (its floor plans are fixed).
    """
    for key, ability in ROLE_ABILITY:
        name: str = getattr(params, key)
        if not name:
            continue
        base = name.removesuffix("Sliced")
        ours = {base, f"{base}Sliced"}
        for oid, obj in state.objects.items():
            if name in oid and obj.object_type not in ours and _has(obj.object_type, ability):
                return f"{key} {name!r} also matches {oid} ({obj.object_type})"
    return None


def _has(object_type: str, ability: str) -> bool:
    try:
        return bool(getattr(abilities(object_type), ability))
    except LuminousError:  # a type outside ALFRED's vocabulary: no ability ALFRED's checks ask about
        return False


def _already_met(task_type: str, params: PddlParams, state: WorldState) -> bool:
    goal = goal_for(params, task_type)
    if goal_satisfied(goal, state):
        return True
    done, total = goal_conditions(TaskInstance(task_type, params, goal, 0), state)
    return done == total


def draw_params(cands: list[PddlParams], rng: np.random.Generator) -> PddlParams:
    """Draw from feasible parameters hierarchically, in `DRAW_ORDER`, each value uniformly.

    Callers that draw many tasks in one scene may keep `feasible_params` and call this per draw.

    Raises:
        TaskSamplingError: `cands` is empty.
    """
    if not cands:
        raise TaskSamplingError("no feasible parameters to draw from")
    for key in DRAW_ORDER:
        values = sorted({getattr(p, key) for p in cands})
        pick = values[int(rng.integers(len(values)))]
        cands = [p for p in cands if getattr(p, key) == pick]
    return cands[0]


def draw_kept(cands: list[PddlParams], rng: np.random.Generator, keep: Callable[[PddlParams], bool]) -> PddlParams:
    """`draw_params([p for p in cands if keep(p)], rng)`, asking `keep` only what the draw needs to know.

    At each level of `DRAW_ORDER` the draw needs the values that some kept candidate still has; a value's
    candidates are asked in order until one is kept, so an expensive `keep` (a physical check in a built
    world) runs on a fraction of the candidates. `keep` must be a pure function of its argument: then the
    draw, and `rng`'s state after it, are those of filtering everything first.

    Raises:
        TaskSamplingError: no candidate is kept; the message counts the candidates.
    """
    verdict: dict[int, bool] = {}

    def kept(i: int) -> bool:
        if i not in verdict:
            verdict[i] = bool(keep(cands[i]))
        return verdict[i]

    pool = list(range(len(cands)))
    for key in DRAW_ORDER:
        groups: dict[object, list[int]] = {}
        for i in pool:
            groups.setdefault(getattr(cands[i], key), []).append(i)
        values = sorted(v for v, members in groups.items() if any(kept(i) for i in members))  # type: ignore[type-var]
        if not values:
            raise TaskSamplingError(f"none of the {len(cands)} candidates passes the filter "
                                    "(e.g. no free spot in the receptacle)")
        pick = values[int(rng.integers(len(values)))]
        pool = groups[pick]
    return cands[next(i for i in pool if kept(i))]


def sample_task(
    scene: Scene,
    state: WorldState,
    task_type: str,
    rng: np.random.Generator,
    *,
    sliced: bool | None = None,
    closed_receptacles: bool = False,
    keep: Callable[[PddlParams], bool] | None = None,
) -> TaskInstance:
    """Draw a feasible ALFRED task of a type for a scene, with a templated instruction.

    Args:
        scene: the scene (room type, seed).
        state: its object states (see `state_from_scene`).
        task_type: one of the seven ALFRED task types.
        rng: every draw comes from it (same seed, same task).
        sliced: force the sliced (True) or unsliced (False) variant; None lets the draw decide.
        closed_receptacles: add ALFRED's "every receptacle closed" conjunct to the goal.
        keep: a further filter on the candidates (e.g. what the physical world can support); a pure
            function, asked only about the candidates the draw needs (`draw_kept`).

    Raises:
        TaskSamplingError: no task of the type is feasible; the message says why.
    """
    cands = feasible_params(scene, state, task_type, sliced)
    if keep is None:
        params = draw_params(cands, rng)
    else:
        try:
            params = draw_kept(cands, rng, keep)
        except TaskSamplingError as exc:
            raise TaskSamplingError(f"no {task_type} task in {_where(scene)}: {exc}") from None
    task = TaskInstance(
        task_type, params, goal_for(params, task_type, closed_receptacles), scene.seed
    )
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
