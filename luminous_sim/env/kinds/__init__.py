"""The env's task kinds, registered in one place (`KINDS`): each is a `TaskKind` with fixed hooks (its room
types, its set-up before the episode, drawing its goal, reading a goal back). ALFRED's seven types share one
class parameterised by the type (`alfred`); `goto_object` and `pickup_object` are a module each. A new kind
is a module with a `TaskKind` subclass and a line in `KINDS`.

Kind modules are imported on first use (`task_kind`), so that the registry's names (`TASK_KINDS`, which
`EnvConfig` checks against) cost nothing at `import luminous_sim`.
"""

from __future__ import annotations

import importlib
from functools import cache
from typing import TYPE_CHECKING, Any

from luminous_sim.env.kinds.base import TaskKind
from luminous_sim.env.kinds.options import KIND_OPTIONS
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES

if TYPE_CHECKING:
    from luminous_sim.episodes import Goal
    from luminous_sim.world import World

KINDS: dict[str, str] = {
    **dict.fromkeys(ALFRED_TASK_TYPES, "alfred:AlfredKind"),
    "goto_object": "goto_object:GotoObject",
    "pickup_object": "pickup_object:PickupObject",
    "objectnav": "objectnav:ObjectNav",
    "objectnav_pickup": "objectnav_pickup:ObjectNavPickup",
    "house_objectnav": "house_objectnav:HouseObjectNav",
}
"""Kind name -> `module:Class` in this package (the class is made with the name)."""
TASK_KINDS: tuple[str, ...] = tuple(KINDS)

__all__ = ["KINDS", "KIND_OPTIONS", "TASK_KINDS", "TaskKind", "goal_from_dict", "kind_templates", "set_up", "task_kind"]


@cache
def task_kind(name: str) -> TaskKind:
    """The registered kind of this name.

    Raises:
        LuminousError: no kind has the name.
    """
    where = KINDS.get(name)
    if where is None:
        raise LuminousError(f"task kind {name!r}: expected one of {', '.join(TASK_KINDS)}")
    module, cls = where.split(":")
    kind = getattr(importlib.import_module(f"{__name__}.{module}"), cls)(name)
    if not isinstance(kind, TaskKind):
        raise LuminousError(f"task kind {name!r}: {where} is not a TaskKind")
    return kind


def set_up(world: World, task_type: str) -> tuple[str, ...]:
    """The objects to make dirty before an episode of `task_type` (none for a type no kind registers, e.g.
    a CDF's own task)."""
    return task_kind(task_type).set_up(world) if task_type in KINDS else ()


def goal_from_dict(data: dict[str, Any]) -> Goal:
    """A goal from `Goal.to_dict` data: a task (`kind` "task"), else a goal of the kind it names."""
    if data["kind"] == "task":
        from luminous_sim.episodes import TaskGoal
        from luminous_sim.tasks import TaskInstance

        return TaskGoal(TaskInstance.from_dict(data["task"]))
    return task_kind(data["kind"]).goal_from_dict(data)


@cache
def kind_templates() -> tuple[str, ...]:
    """The instruction templates of every kind's own goals (each once)."""
    return tuple(dict.fromkeys(t for name in TASK_KINDS for t in task_kind(name).templates))
