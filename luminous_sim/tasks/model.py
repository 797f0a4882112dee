"""Task values: ALFRED's `pddl_params` and a task instance (type, parameters, goal, instruction)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from luminous_sim.cdf.predicates import Expr, ExprError, parse_expr, to_sexpr
from luminous_sim.tasks.errors import TaskError
from luminous_sim.vocab import SLICED_TYPES

if TYPE_CHECKING:
    from luminous_sim.tasks.conditions import GoalConditions

PDDL_KEYS: tuple[str, ...] = (
    "mrecep_target",
    "object_sliced",
    "object_target",
    "parent_target",
    "toggle_target",
)
"""The keys of `traj_data['pddl_params']`, in the (sorted) order ALFRED's files have them."""


@dataclass(frozen=True)
class PddlParams:
    """ALFRED's task parameters (`traj_data['pddl_params']`).

    Attributes:
        object_target: the object type; for a sliced task the *parent* type (`Apple`).
        parent_target: the final receptacle type; "" for look_at_obj_in_light.
        toggle_target: `DeskLamp` or `FloorLamp` for look_at_obj_in_light, else "".
        mrecep_target: the movable receptacle type for pick_and_place_with_movable_recep, else "".
        object_sliced: whether the object must be sliced (the goal is about `<object>Sliced`).
    """

    object_target: str
    parent_target: str = ""
    toggle_target: str = ""
    mrecep_target: str = ""
    object_sliced: bool = False

    @property
    def object_type(self) -> str:
        """The type the goal is about: `AppleSliced` for a sliced apple task, else `object_target`."""
        return f"{self.object_target}Sliced" if self.object_sliced else self.object_target

    def to_json(self) -> dict[str, Any]:
        """The exact `pddl_params` dict of an ALFRED traj_data.json (keys sorted as there)."""
        return {
            "mrecep_target": self.mrecep_target,
            "object_sliced": self.object_sliced,
            "object_target": self.object_target,
            "parent_target": self.parent_target,
            "toggle_target": self.toggle_target,
        }

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> PddlParams:
        """Read a `pddl_params` dict (missing keys take their defaults; a sliced type is folded).

        Raises:
            TaskError: an unknown key or a value of the wrong type.
        """
        unknown = sorted(set(data) - set(PDDL_KEYS))
        if unknown:
            raise TaskError(
                f"pddl_params: unknown key(s) {', '.join(unknown)}; expected {', '.join(PDDL_KEYS)}"
            )
        values = {k: data.get(k, "") for k in PDDL_KEYS if k != "object_sliced"}
        for k, v in values.items():
            if not isinstance(v, str):
                raise TaskError(f"pddl_params.{k}: expected a string, got {v!r}")
        sliced = data.get("object_sliced", False)
        if not isinstance(sliced, bool):
            raise TaskError(f"pddl_params.object_sliced: expected true or false, got {sliced!r}")
        obj = values.pop("object_target")
        if obj in SLICED_TYPES:  # some tools write the sliced type; ALFRED stores the parent
            obj, sliced = SLICED_TYPES[obj], True
        return cls(object_target=obj, object_sliced=sliced, **values)


@dataclass(frozen=True)
class TaskInstance:
    """A task to solve in one scene.

    Attributes:
        task_type: one of ALFRED's seven types, or "custom" for a CDF goal without a type.
        params: ALFRED's parameters (best effort for a custom goal).
        goal: the goal as an expression over the CDF predicates.
        scene_seed: the seed of the scene the task was drawn for.
        instruction: a natural-language goal description.
        custom: True when the goal comes from a CDF rather than ALFRED's goal library; such a goal
            is scored by its own conjuncts rather than ALFRED's per-type conditions.
        names: CDF object name -> object id, for goals that name objects.
    """

    task_type: str
    params: PddlParams
    goal: Expr
    scene_seed: int
    instruction: str = ""
    custom: bool = False
    names: Mapping[str, str] = field(default_factory=dict, hash=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "names", MappingProxyType(dict(self.names)))

    def conditions(self) -> GoalConditions:
        """The goal compiled into named conditions: success, ALFRED's counts, progress, subgoals.

        Raises:
            TaskError: an unknown task type.
        """
        from luminous_sim.tasks.conditions import task_conditions  # it builds on this module

        return task_conditions(self)

    @property
    def goal_key(self) -> str:
        """ALFRED's goal-library key: the task type, plus `_slice` for a sliced object."""
        return self.task_type + ("_slice" if self.params.object_sliced else "")

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON data (the goal as an s-expression); `from_dict` reads it back."""
        return {
            "task_type": self.task_type,
            "goal_key": self.goal_key,
            "pddl_params": self.params.to_json(),
            "goal": to_sexpr(self.goal),
            "scene_seed": self.scene_seed,
            "instruction": self.instruction,
            "custom": self.custom,
            "names": dict(sorted(self.names.items())),
        }

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> TaskInstance:
        """Rebuild a task from `to_dict` data.

        Raises:
            TaskError: a missing key or a goal that does not parse.
        """
        try:
            goal = parse_expr(data["goal"])
            return cls(
                task_type=str(data["task_type"]),
                params=PddlParams.from_json(data["pddl_params"]),
                goal=goal,
                scene_seed=int(data["scene_seed"]),
                instruction=str(data.get("instruction", "")),
                custom=bool(data.get("custom", False)),
                names=dict(data.get("names", {})),
            )
        except KeyError as exc:
            raise TaskError(f"task data: missing key {exc.args[0]!r}") from None
        except ExprError as exc:
            raise TaskError(f"task data: goal: {exc}") from None
