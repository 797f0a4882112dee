"""Goal directives from ALFRED's goal templates (A `gen/goal_library.py` `templates`, spec/alfred.md section 7).

ALFRED fills `{obj}`, `{recep}`, `{toggle}` and `{mrecep}` with lower-cased type names ("put a spraybottle in
garbagecan"); those are kept verbatim in `ALFRED_TEMPLATES` (`alfred_description`). The directives the project
writes (`task_description`) use `TEMPLATES`, the same templates as people would write them ("put a spray
bottle in the garbage can"), with the names, articles, plurals and prepositions of `language.names`.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping

import numpy as np

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Or, is_variable
from luminous_sim.language.names import definite, indefinite, plural, preposition, spoken, type_from_word
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.model import TaskInstance
from luminous_sim.tasks.types import TASK_TYPES

ALFRED_TEMPLATES: dict[str, tuple[str, ...]] = {
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
"""Goal key (task type, `_slice` when sliced) -> ALFRED's templates verbatim, in its order (filled with
lower-cased type names by `alfred_description`)."""

TEMPLATES: dict[str, tuple[str, ...]] = {
    "pick_and_place_simple": ("put {a_obj} {in_recep}", "place {a_obj} {in_recep}"),
    "pick_clean_then_place_in_recep": ("put {a_clean_obj} {in_recep}", "clean {a_obj} and put it {in_recep}"),
    "pick_heat_then_place_in_recep": ("put {a_hot_obj} {in_recep}", "heat {a_obj} and put it {in_recep}"),
    "pick_cool_then_place_in_recep": ("put {a_cold_obj} {in_recep}", "cool {a_obj} and put it {in_recep}"),
    "pick_two_obj_and_place": ("put two {objs} {in_recep}", "find two {objs} and put them {in_recep}"),
    "look_at_obj_in_light": ("look at {a_obj} under {the_toggle}", "examine {the_obj} by the light of {the_toggle}"),
    "pick_and_place_with_movable_recep": (
        "put {a_obj} {in_a_mrecep} and then put {the_mrecep} {in_recep}",
        "put {a_mrecep} holding {a_obj} {in_recep}",
        "carry {a_obj} {in_a_mrecep} to {the_recep}",
    ),
    "pick_clean_then_place_in_recep_slice": (
        "put {a_clean_slice} {in_recep}",
        "clean {a_slice} and put it {in_recep}",
    ),
    "pick_heat_then_place_in_recep_slice": ("put {a_hot_slice} {in_recep}", "heat {a_slice} and put it {in_recep}"),
    "pick_cool_then_place_in_recep_slice": ("put {a_cold_slice} {in_recep}", "cool {a_slice} and put it {in_recep}"),
    "pick_two_obj_and_place_slice": ("put two {slices} {in_recep}", "find two {slices} and put them {in_recep}"),
    "look_at_obj_in_light_slice": (
        "look at {a_slice} under {the_toggle}",
        "examine {the_slice} by the light of {the_toggle}",
    ),
    "pick_and_place_with_movable_recep_slice": (
        "put {a_slice} {in_a_mrecep} and then put {the_mrecep} {in_recep}",
        "put {a_mrecep} holding {a_slice} {in_recep}",
        "carry {a_slice} {in_a_mrecep} to {the_recep}",
    ),
    "pick_and_place_simple_slice": ("slice {a_obj} and put a slice {in_recep}", "put {a_slice} {in_recep}"),
}
"""Goal key -> ALFRED's goal templates (`ALFRED_TEMPLATES`, one for one) as people would write them: the
objects named in words with articles, the receptacle with its preposition, plurals for two objects.

A field is a role (`obj`: the object, for a sliced task its parent "apple"; `slice`: one slice of it; `objs`,
`slices`: their plurals; `recep`, `toggle`, `mrecep`), after an optional `in` (the receptacle's preposition,
and "the" unless `a` follows), `a` or `the`, and adjectives: `{a_hot_slice}` -> "a hot slice of apple",
`{in_recep}` -> "on the counter", `{in_a_mrecep}` -> "in a bowl", `{obj}` -> "apple"."""

_PHRASES: dict[str, str] = {
    "inReceptacle": "put the {0} {in1} the {1}",
    "inReceptacleObject": "put the {0} {in1} the {1}",
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


_ROLES = ("obj", "objs", "slice", "slices", "recep", "toggle", "mrecep")


class _Fields(dict[str, str]):
    """A template's fields for a task, made on demand from their names (see `TEMPLATES`)."""

    def __init__(self, task: TaskInstance):
        super().__init__()
        p = task.params
        sliced = f"{p.object_target}Sliced"
        self.types = {"obj": p.object_target, "objs": p.object_target, "slice": sliced, "slices": sliced,
                      "recep": p.parent_target, "toggle": p.toggle_target, "mrecep": p.mrecep_target}

    def __missing__(self, key: str) -> str:
        *mods, role = key.split("_")
        if role not in self.types:
            raise KeyError(key)
        t = self.types[role]
        if role in ("objs", "slices"):
            return plural(t)
        where = ""
        if mods and mods[0] == "in":
            where, mods = preposition(t) + " ", mods[1:]
            if not mods or mods[0] not in ("a", "the"):
                mods = ["the", *mods]
        if not mods:
            return spoken(t)
        article, adjective = mods[0], " ".join(mods[1:])
        if article == "a":
            return where + indefinite(t, adjective)
        if article == "the":
            return where + definite(t, adjective)
        raise KeyError(key)


def directive_words() -> set[str]:
    """Every word a directive can use besides the objects' names (`language.names.words_of`): the templates'
    own words and the articles, prepositions and adjectives their fields add, lower-cased."""
    found = {"a", "an", "the", "some", "in", "on"}
    for options in TEMPLATES.values():
        for template in options:
            for field in re.findall(r"\{(\w+)\}", template):
                found |= {w for w in field.split("_") if w not in _ROLES}
            found |= set(re.findall(r"[a-z]+", re.sub(r"\{\w+\}", " ", template)))
    return found


def fill_template(template: str, task: TaskInstance) -> str:
    """One of `TEMPLATES` with the task's objects named in words: "put a hot slice of apple on the counter"."""
    return template.format_map(_Fields(task))


def alfred_description(task: TaskInstance, rng: np.random.Generator) -> str:
    """ALFRED's own templated goal description: one of `ALFRED_TEMPLATES` drawn uniformly with `rng`, filled with
    lower-cased type names as ALFRED does ("put a spraybottle in garbagecan")."""
    options = _options(ALFRED_TEMPLATES, task)
    p = task.params
    return options[int(rng.integers(len(options)))].format(
        obj=p.object_target.lower(),
        recep=p.parent_target.lower(),
        toggle=p.toggle_target.lower(),
        mrecep=p.mrecep_target.lower(),
    )


def _options(table: Mapping[str, tuple[str, ...]], task: TaskInstance) -> tuple[str, ...]:
    options = table.get(task.goal_key)
    if options is None:
        raise TaskError(f"no goal templates for {task.goal_key!r}; expected one of {', '.join(table)}")
    return options


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
        types = [type_from_word(w.split("|")[0].replace("_", "")) for w in words]
        names = [spoken(t) if t[:1].isupper() else w.replace("_", " ").lower() for w, t in zip(words, types)]
        in1 = preposition(types[1]) if len(types) > 1 and types[1][:1].isupper() else "in"
        phrase = _PHRASES[atom.pred].format(*names, in1=in1)
        if phrase not in phrases:
            phrases.append(phrase)
    return " and ".join(phrases)


def task_description(task: TaskInstance, rng: np.random.Generator) -> str:
    """The goal directive: one of the task's `TEMPLATES` (ALFRED's, in words) drawn uniformly with `rng`.

    A custom task whose type and parameters are ALFRED's uses ALFRED's templates; any other custom
    goal is read out atom by atom (negations and quantifiers are not spoken).

    Raises:
        TaskError: an ALFRED task type without templates (an unknown type).
    """
    known = task.task_type in TASK_TYPES and bool(task.params.object_target)
    if task.custom and not known:
        return _spoken_goal(task)
    options = _options(TEMPLATES, task)
    return fill_template(options[int(rng.integers(len(options)))], task)
