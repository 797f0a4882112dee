"""ALFRED's seven task types as data, and their goals as expressions over the CDF predicates.

Goals follow ALFRED's goal library (spec/alfred.md section 1.1): existentially quantified over
instances of the parameter types, e.g. pick_and_place_simple with Apple and Fridge is
``(exists (?o - Apple ?r - Fridge) (inReceptacle ?o ?r))``. A sliced task is about the sliced
type (`AppleSliced`) and adds ``(isSliced ?o)``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Param
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.model import PddlParams
from luminous_sim.vocab import ALFRED_TASK_ROOMS, vocab_data

SLICED_PARENTS: tuple[str, ...] = ("Apple", "Bread", "Lettuce", "Potato", "Tomato")
"""Types that can be the object of a sliced task (sliceable with a `<X>Sliced` type; not Egg)."""
CLOSABLE_RECEPTACLES: tuple[str, ...] = tuple(
    t for t in vocab_data()["openable"] if t in vocab_data()["receptacles"]
)
"""Openable receptacle types: the ones ALFRED's "every receptacle closed" conjunct is about."""


def _v(name: str, type_: str) -> Param:
    return Param(name, type_)


def _simple(p: PddlParams) -> tuple[tuple[Param, ...], list[Expr]]:
    return (_v("?o", p.object_type), _v("?r", p.parent_target)), [
        Atom("inReceptacle", ("?o", "?r"))
    ]


def _pick_two(p: PddlParams) -> tuple[tuple[Param, ...], list[Expr]]:
    params = (_v("?r", p.parent_target), _v("?o1", p.object_type), _v("?o2", p.object_type))
    body: list[Expr] = [
        Not(Atom("=", ("?o1", "?o2"))),
        Atom("inReceptacle", ("?o1", "?r")),
        Atom("inReceptacle", ("?o2", "?r")),
    ]
    return params, body


def _look_at(p: PddlParams) -> tuple[tuple[Param, ...], list[Expr]]:
    params = (_v("?t", p.toggle_target), _v("?o", p.object_type))
    return params, [Atom("isToggled", ("?t",)), Atom("holds", ("?o",))]


def _changed(pred: str) -> Callable[[PddlParams], tuple[tuple[Param, ...], list[Expr]]]:
    def build(p: PddlParams) -> tuple[tuple[Param, ...], list[Expr]]:
        params = (_v("?o", p.object_type), _v("?r", p.parent_target))
        return params, [Atom(pred, ("?o",)), Atom("inReceptacle", ("?o", "?r"))]

    return build


def _movable(p: PddlParams) -> tuple[tuple[Param, ...], list[Expr]]:
    params = (_v("?r", p.parent_target), _v("?o", p.object_type), _v("?m", p.mrecep_target))
    body: list[Expr] = [
        Atom("inReceptacleObject", ("?o", "?m")),
        Atom("inReceptacle", ("?m", "?r")),
    ]
    return params, body


@dataclass(frozen=True)
class TaskType:
    """One ALFRED task type.

    Attributes:
        name: ALFRED's `task_type`.
        rooms: room types ALFRED generates it in.
        sliced: whether the generator draws sliced variants (look_at has a template but no data).
        needs: parameter slots besides object_target that must be set.
        build: (params) -> (quantified variables, goal conjuncts), the goal-library entry.
    """

    name: str
    rooms: frozenset[str]
    sliced: bool
    needs: tuple[str, ...]
    build: Callable[[PddlParams], tuple[tuple[Param, ...], list[Expr]]]




def _rooms(task_type: str) -> frozenset[str]:
    return ALFRED_TASK_ROOMS[task_type]


_TABLE: tuple[TaskType, ...] = (
    TaskType("pick_and_place_simple", _rooms("pick_and_place_simple"), True, ("parent_target",), _simple),
    TaskType("pick_two_obj_and_place", _rooms("pick_two_obj_and_place"), True, ("parent_target",), _pick_two),
    TaskType(
        "look_at_obj_in_light",
        _rooms("look_at_obj_in_light"),
        False,
        ("toggle_target",),
        _look_at,
    ),
    TaskType(
        "pick_clean_then_place_in_recep",
        _rooms("pick_clean_then_place_in_recep"),
        True,
        ("parent_target",),
        _changed("isClean"),
    ),
    TaskType(
        "pick_heat_then_place_in_recep",
        _rooms("pick_heat_then_place_in_recep"),
        True,
        ("parent_target",),
        _changed("isHot"),
    ),
    TaskType(
        "pick_cool_then_place_in_recep",
        _rooms("pick_cool_then_place_in_recep"),
        True,
        ("parent_target",),
        _changed("isCool"),
    ),
    TaskType(
        "pick_and_place_with_movable_recep",
        _rooms("pick_and_place_with_movable_recep"),
        True,
        ("parent_target", "mrecep_target"),
        _movable,
    ),
)
TASK_TYPES: dict[str, TaskType] = {t.name: t for t in _TABLE}
"""ALFRED task type name -> its data, in ALFRED's order."""


def task_info(name: str) -> TaskType:
    """The data of a task type.

    Raises:
        TaskError: an unknown name (the message lists the seven).
    """
    try:
        return TASK_TYPES[name]
    except KeyError:
        raise TaskError(
            f"unknown task type {name!r}; expected one of {', '.join(TASK_TYPES)}"
        ) from None


def closed_receptacles_goal() -> Expr:
    """ALFRED's extra conjunct "every receptacle is closed", over the openable receptacle types."""
    return And(
        tuple(ForAll((Param("?c", t),), Not(Atom("isOpen", ("?c",)))) for t in CLOSABLE_RECEPTACLES)
    )


def goal_for(params: PddlParams, task_type: str, closed_receptacles: bool = False) -> Expr:
    """The goal of an ALFRED task as an expression (spec/alfred.md section 1.1).

    Args:
        params: the task's parameters.
        task_type: one of the seven ALFRED task types.
        closed_receptacles: add ALFRED's "every (openable) receptacle is closed" conjunct, which the
            planner's goal has and ALFRED's evaluator does not check.

    Returns:
        ``(exists (vars) (and conjuncts...))``, plus the closed-receptacle conjunct if asked for.

    Raises:
        TaskError: an unknown task type or a parameter slot it needs is empty.
    """
    info = task_info(task_type)
    missing = [k for k in ("object_target", *info.needs) if not getattr(params, k)]
    if missing:
        raise TaskError(f"{task_type} needs {', '.join(missing)}; got {params.to_json()}")
    variables, body = info.build(params)
    if params.object_sliced:  # sliceable(o) and isSliced(o) for each object variable
        body += [Atom("isSliced", (v.var,)) for v in variables if v.type == params.object_type]
    goal: Expr = Exists(variables, And(tuple(body)))
    if closed_receptacles:
        goal = And((goal, closed_receptacles_goal()))
    return goal
