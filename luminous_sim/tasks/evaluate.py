"""Goal evaluation on a pure `WorldState`: any goal expression (`goal_satisfied`) and ALFRED's
evaluation-time goal-condition counts (`goal_conditions`; A `env/tasks.py`, spec/alfred.md section
1.2), both thin calls to the goal's compiled conditions (`tasks.conditions`).

Objects match a target name by type rather than ALFRED's substring of the object id: a target
`Apple` matches apples and their slices (whose ids contain "Apple"), `AppleSliced` only slices; we
do not reproduce the substring accidents (`Pot` matching `Potato`, `Pen` matching `Pencil`).
"""

from __future__ import annotations

from collections.abc import Collection

from luminous_sim.states import WorldState
from luminous_sim.tasks.conditions import conjunct_progress, matching, task_conditions
from luminous_sim.tasks.expressions import goal_satisfied, in_receptacle, is_clean, parents
from luminous_sim.tasks.model import TaskInstance

__all__ = [
    "conjunct_progress",
    "goal_conditions",
    "goal_satisfied",
    "in_receptacle",
    "is_clean",
    "matching",
    "parents",
    "task_satisfied",
]


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
    return task_conditions(task).alfred_counts(state, visible)


def task_satisfied(
    task: TaskInstance, state: WorldState, visible: Collection[str] | None = None
) -> bool:
    """ALFRED's `goal_satisfied`: every goal condition is met."""
    return task_conditions(task).success(state, visible)
