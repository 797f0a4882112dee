"""Layer L3: ALFRED's task types, their goals and evaluation, feasible sampling and templates.

Typical use::

    from luminous_sim import tasks
    state = tasks.state_from_scene(scene)
    task = tasks.sample_task(scene, state, "pick_heat_then_place_in_recep", rng)
    done, total = tasks.goal_conditions(task, state_after)
    goal = task.conditions()        # named conditions: .success, .alfred_counts, .progress, .subgoals

Pure: no PyBullet. Goals are `luminous_sim.cdf` expressions, so a CDF's own goal and ALFRED's
goal library are evaluated by the same code.
"""

from luminous_sim.tasks.cdf_bridge import (
    cdf_for_task,
    names_from_scene,
    params_from_goal,
    required_objects,
    task_from_cdf,
)
from luminous_sim.tasks.conditions import (
    PLAN_ORDER,
    Condition,
    GoalConditions,
    compile_goal,
    task_conditions,
)
from luminous_sim.tasks.constraints import params_problems
from luminous_sim.tasks.errors import TaskError, TaskSamplingError
from luminous_sim.tasks.evaluate import (
    conjunct_progress,
    goal_conditions,
    goal_satisfied,
    in_receptacle,
    matching,
    parents,
    task_satisfied,
)
from luminous_sim.tasks.initial import (
    DIRTY_FIRST,
    STATE_LITERALS,
    alfred_dirty,
    check_initial,
    initial_literals,
    scene_with_initial,
)
from luminous_sim.tasks.meanings import MEANINGS, PredicateMeaning
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.rooms import object_rooms, rooms_apart
from luminous_sim.tasks.sample import (
    SUBSTRING_CLASH,
    alfred_name_clash,
    draw_kept,
    draw_params,
    feasible_params,
    feasible_task_types,
    sample_task,
    state_from_scene,
)
from luminous_sim.tasks.templates import TEMPLATES, alfred_description, task_description
from luminous_sim.tasks.types import (
    TASK_TYPES,
    TaskType,
    closed_receptacles_goal,
    goal_for,
    task_info,
)

__all__ = [
    "DIRTY_FIRST",
    "MEANINGS",
    "PLAN_ORDER",
    "STATE_LITERALS",
    "SUBSTRING_CLASH",
    "TASK_TYPES",
    "TEMPLATES",
    "Condition",
    "GoalConditions",
    "PddlParams",
    "PredicateMeaning",
    "TaskError",
    "TaskInstance",
    "TaskSamplingError",
    "TaskType",
    "alfred_description",
    "alfred_dirty",
    "alfred_name_clash",
    "cdf_for_task",
    "check_initial",
    "closed_receptacles_goal",
    "compile_goal",
    "conjunct_progress",
    "draw_kept",
    "draw_params",
    "feasible_params",
    "feasible_task_types",
    "goal_conditions",
    "goal_for",
    "goal_satisfied",
    "in_receptacle",
    "initial_literals",
    "matching",
    "names_from_scene",
    "object_rooms",
    "params_from_goal",
    "params_problems",
    "parents",
    "required_objects",
    "rooms_apart",
    "sample_task",
    "scene_with_initial",
    "state_from_scene",
    "task_conditions",
    "task_description",
    "task_from_cdf",
    "task_info",
    "task_satisfied",
]
