"""ALFRED's templated goal descriptions (A `gen/goal_library.py` `templates`, spec/alfred.md section 7).

`{obj}`, `{recep}`, `{toggle}` and `{mrecep}` are filled with lower-cased type names
("spraybottle"); for a sliced task `{obj}` is the parent type ("apple").
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping

import numpy as np

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Or, is_variable
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.model import TaskInstance
from luminous_sim.tasks.types import TASK_TYPES

TEMPLATES: dict[str, tuple[str, ...]] = {
    "pick_and_place_simple": ("put a {obj} in {recep}", "put some {obj} on {recep}"),
    "pick_clean_then_place_in_recep": (
        "put a clean {obj} in {recep}",
        "clean some {obj} and put it in {recep}",
    ),
    "pick_heat_then_place_in_recep": (
        "put a hot {obj} in {recep}",
        "heat some {obj} and put it in {recep}",
    ),
    "pick_cool_then_place_in_recep": (
        "put a cool {obj} in {recep}",
        "cool some {obj} and put it in {recep}",
    ),
    "pick_two_obj_and_place": (
        "put two {obj} in {recep}",
        "find two {obj} and put them in {recep}",
    ),
    "look_at_obj_in_light": (
        "look at {obj} under the {toggle}",
        "examine the {obj} with the {toggle}",
    ),
    "pick_and_place_with_movable_recep": (
        "put {obj} in a {mrecep} and then put them in {recep}",
        "put a {mrecep} of {obj} in {recep}",
        "put {obj} {mrecep} in {recep}",
    ),
    "pick_clean_then_place_in_recep_slice": (
        "put a clean slice of {obj} in {recep}",
        "clean some sliced {obj} and put it in {recep}",
    ),
    "pick_heat_then_place_in_recep_slice": (
        "put a hot slice of {obj} in {recep}",
        "heat some sliced {obj} and put it in {recep}",
    ),
    "pick_cool_then_place_in_recep_slice": (
        "put a cool slice of {obj} in {recep}",
        "cool some sliced {obj} and put it in {recep}",
    ),
    "pick_two_obj_and_place_slice": (
        "put two sliced {obj} in {recep}",
        "find two sliced {obj} and put them in {recep}",
    ),
    "look_at_obj_in_light_slice": (
        "look at sliced {obj} under the {toggle}",
        "examine the sliced {obj} with the {toggle}",
    ),
    "pick_and_place_with_movable_recep_slice": (
        "put sliced {obj} in a {mrecep} and then put them in {recep}",
        "put a {mrecep} of sliced {obj} in {recep}",
        "put sliced {obj} {mrecep} in {recep}",
    ),
    "pick_and_place_simple_slice": (
        "slice {obj} and put in {recep}",
        "put sliced {obj} in {recep}",
    ),
}
"""Goal key (task type, `_slice` when sliced) -> ALFRED's templates, in its order."""

_PHRASES: dict[str, str] = {
    "inReceptacle": "put the {0} in the {1}",
    "inReceptacleObject": "put the {0} in the {1}",
    "isHot": "heat the {0}",
    "isCool": "cool the {0}",
    "isClean": "clean the {0}",
    "isSliced": "slice the {0}",
    "isOn": "turn on the {0}",
    "isToggled": "turn on the {0}",
    "isOpen": "open the {0}",
    "isFilled": "fill the {0}",
    "holds": "hold the {0}",
}


def fill_template(template: str, task: TaskInstance) -> str:
    """A template with the task's lower-cased type names filled in."""
    p = task.params
    return template.format(
        obj=p.object_target.lower(),
        recep=p.parent_target.lower(),
        toggle=p.toggle_target.lower(),
        mrecep=p.mrecep_target.lower(),
    )


def _positive_atoms(
    expr: Expr, scope: Mapping[str, str | None]
) -> Iterator[tuple[Atom, Mapping[str, str | None]]]:
    if isinstance(expr, Atom):
        yield expr, scope
    elif isinstance(expr, (And, Or)):
        for e in expr.args:
            yield from _positive_atoms(e, scope)
    elif isinstance(expr, (Exists, ForAll)):
        yield from _positive_atoms(expr.body, {**scope, **{p.var: p.type for p in expr.params}})


def _spoken_goal(task: TaskInstance) -> str:
    """A plain reading of a custom goal's positive atoms ("heat the apple and put the apple in ...")."""
    phrases: list[str] = []
    for atom, scope in _positive_atoms(task.goal, {}):
        if atom.pred not in _PHRASES:
            continue
        words = [(scope.get(a) or "object") if is_variable(a) else a for a in atom.args]
        phrase = _PHRASES[atom.pred].format(*(w.replace("_", " ").lower() for w in words))
        if phrase not in phrases:
            phrases.append(phrase)
    return " and ".join(phrases)


def task_description(task: TaskInstance, rng: np.random.Generator) -> str:
    """ALFRED's templated goal description, a template drawn uniformly with `rng`.

    A custom task whose type and parameters are ALFRED's uses ALFRED's templates; any other custom
    goal is read out atom by atom (negations and quantifiers are not spoken).

    Raises:
        TaskError: an ALFRED task type without templates (an unknown type).
    """
    known = task.task_type in TASK_TYPES and bool(task.params.object_target)
    if task.custom and not known:
        return _spoken_goal(task)
    options = TEMPLATES.get(task.goal_key)
    if options is None:
        raise TaskError(
            f"no goal templates for {task.goal_key!r}; expected one of {', '.join(TEMPLATES)}"
        )
    return fill_template(options[int(rng.integers(len(options)))], task)
