"""Goal evaluation on a pure `WorldState`: any goal expression (`goal_satisfied`, from
`expressions`) and ALFRED's evaluation-time goal-condition counts (`goal_conditions`; A
`env/tasks.py`, spec/alfred.md section 1.2).

Objects match a target name by type rather than ALFRED's substring of the object id: a target
`Apple` matches apples and their slices (whose ids contain "Apple"), `AppleSliced` only slices; we
do not reproduce the substring accidents (`Pot` matching `Potato`, `Pen` matching `Pencil`).
"""

from __future__ import annotations

from collections.abc import Callable, Collection

from luminous_sim.states import WorldState
from luminous_sim.tasks.expressions import (
    PREDICATE_FUNCTIONS,
    conjunct_progress,
    goal_satisfied,
    in_receptacle,
    is_clean,
    parents,
)
from luminous_sim.tasks.model import TaskInstance
from luminous_sim.tasks.types import task_info
from luminous_sim.vocab import SLICED_TYPES, abilities

__all__ = [
    "PREDICATE_FUNCTIONS",
    "conjunct_progress",
    "goal_conditions",
    "goal_satisfied",
    "in_receptacle",
    "is_clean",
    "matching",
    "parents",
    "task_satisfied",
]


def matching(state: WorldState, name: str, ability: str) -> list[str]:
    """Ids of objects that match a target name and have an ability (`receptacle`, `pickupable`, ...)."""
    if not name:
        return []
    return [
        k
        for k, o in state.objects.items()
        if name in (o.object_type, SLICED_TYPES.get(o.object_type))
        and getattr(abilities(o.object_type), ability)
    ]


def _inside(state: WorldState, objs: list[str], receptacles: list[str]) -> list[str]:
    return [o for o in objs if any(in_receptacle(state, o, r) for r in receptacles)]


_Count = Callable[[TaskInstance, WorldState, "Collection[str] | None"], tuple[int, int]]


def _targets(task: TaskInstance, state: WorldState) -> tuple[list[str], list[str], int, int]:
    """(object matches, parent matches, sliced total, sliced score) shared by every type."""
    objs = matching(state, task.params.object_type, "pickupable")
    recs = matching(state, task.params.parent_target, "receptacle")
    if not task.params.object_sliced:
        return objs, recs, 0, 0
    pieces = [o for o in objs if "Sliced" in state[o].object_type]
    if task.task_type == "pick_two_obj_and_place":
        return objs, recs, 2, min(len(pieces), 2)
    return objs, recs, 1, int(bool(pieces))


def _simple(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None
) -> tuple[int, int]:
    objs, recs, ts, s = _targets(task, state)
    return s + bool(_inside(state, objs, recs)), ts + 1


def _pick_two(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None
) -> tuple[int, int]:
    objs, recs, ts, s = _targets(task, state)
    best = max((len(_inside(state, objs, [r])) for r in recs), default=0)
    return s + min(best, 2), ts + 2


def _look_at(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None
) -> tuple[int, int]:
    objs, _, ts, s = _targets(task, state)
    lamps = matching(state, task.params.toggle_target, "toggleable")
    lit = any(state[t].isToggled and (visible is None or t in visible) for t in lamps)
    held = state.held is not None and state.held in objs
    return s + lit + held, ts + 2


def _changed(kind: str) -> _Count:
    def count(
        task: TaskInstance, state: WorldState, visible: Collection[str] | None
    ) -> tuple[int, int]:
        objs, recs, ts, s = _targets(task, state)
        in_place = set(_inside(state, objs, recs))
        changed = {o for o in objs if o in getattr(state, kind)}
        return s + bool(in_place) + bool(changed) + bool(in_place & changed), ts + 3

    return count


def _movable(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None
) -> tuple[int, int]:
    objs, recs, ts, s = _targets(task, state)
    movables = matching(state, task.params.mrecep_target, "pickupable")
    holding = [m for m in movables if _inside(state, objs, [m])]
    placed = _inside(state, movables, recs)
    stacked = [m for m in holding if m in placed]
    return s + bool(holding) + bool(placed) + bool(stacked), ts + 3


_COUNTS: dict[str, _Count] = {
    "pick_and_place_simple": _simple,
    "pick_two_obj_and_place": _pick_two,
    "look_at_obj_in_light": _look_at,
    "pick_clean_then_place_in_recep": _changed("cleaned"),
    "pick_heat_then_place_in_recep": _changed("heated"),
    "pick_cool_then_place_in_recep": _changed("cooled"),
    "pick_and_place_with_movable_recep": _movable,
}


def goal_conditions(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None = None
) -> tuple[int, int]:
    """(completed, total) goal conditions, as ALFRED's evaluator counts them.

    Args:
        task: the task; a custom (CDF) task is scored by the conjuncts of its own goal.
        state: the world state, with the heated/cooled/cleaned bookkeeping sets.
        visible: ids the agent sees now; look_at_obj_in_light needs its lamp on *and* visible.
            None skips the visibility check (a lamp that is on counts).

    Returns:
        The pair ALFRED's `goal_conditions_met` returns; the goal is met when they are equal.

    Raises:
        TaskError: an unknown task type.
    """
    if task.custom:
        return conjunct_progress(task.goal, state, task.names)
    task_info(task.task_type)
    return _COUNTS[task.task_type](task, state, visible)


def task_satisfied(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None = None
) -> bool:
    """ALFRED's `goal_satisfied`: every goal condition is met."""
    done, total = goal_conditions(task, state, visible)
    return done == total
