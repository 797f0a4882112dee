"""Layer L3: symbolic planning, navigation and the oracle that turns tasks into trajectories.

Public names are loaded on first use, so that the pure symbolic planner (`planning.symbolic`) can be
imported without the simulator that the oracle drives.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.planning.navigation import NavGraph, goto_actions, look_steps
    from luminous_sim.planning.oracle import ExecutionError, Oracle, with_forbidden
    from luminous_sim.planning.script import LowLevelAction, ScriptOracle, script_from_cdf
    from luminous_sim.planning.task_fit import (
        distinct_tasks,
        draw_task,
        has_room,
        has_room_for_two,
        physically_feasible,
        unseeable,
    )
    from luminous_sim.planning.trajectory import Trajectory

_WHERE = {
    "ExecutionError": "oracle", "Oracle": "oracle", "with_forbidden": "oracle",
    "NavGraph": "navigation", "goto_actions": "navigation", "look_steps": "navigation",
    "Trajectory": "trajectory",
    "LowLevelAction": "script", "ScriptOracle": "script", "script_from_cdf": "script",
    "distinct_tasks": "task_fit", "draw_task": "task_fit", "has_room": "task_fit", "has_room_for_two": "task_fit",
    "physically_feasible": "task_fit", "unseeable": "task_fit",
}

__all__ = [
    "ExecutionError",
    "LowLevelAction",
    "NavGraph",
    "Oracle",
    "ScriptOracle",
    "Trajectory",
    "distinct_tasks",
    "draw_task",
    "goto_actions",
    "has_room",
    "has_room_for_two",
    "look_steps",
    "physically_feasible",
    "script_from_cdf",
    "unseeable",
    "with_forbidden",
]


__getattr__ = lazy_getattr(__name__, _WHERE)
