"""Cross-field checks of a CDF: names, receptacle compatibility, impossible combinations, cycles.

Each check returns Issues with the key path of the offending value; `raise_for_issues` raises one
CDFValidationError listing them all.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

from luminous_sim.cdf.affordances import (
    STANDS_ON,
    accepted_by,
    can_support,
    has_ability,
    is_receptacle,
)
from luminous_sim.cdf.bounds import size_issues
from luminous_sim.cdf.contradictions import find_conflicts
from luminous_sim.cdf.graph import find_axis_contradiction, find_fixed_cycle
from luminous_sim.cdf.house import check_house, house_names
from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cdf.predicates import (
    PREDICATES,
    Expr,
    Param,
    atoms,
    is_ground_conjunction,
    is_variable,
    to_sexpr,
)
from luminous_sim.cdf.refs import asset_type, room_type_of
from luminous_sim.cdf.relations import (
    EXCLUSIVE_BINARY,
    EXCLUSIVE_UNARY,
    RELATIONS,
    STRUCTURE_ELEMENTS,
)
from luminous_sim.vocab import ALFRED_TASK_ROOMS, ALL_TYPES

if TYPE_CHECKING:
    from luminous_sim.cdf.schema import ChallengeDefinition, HighLevelStep, LowLevelStep, ObjectSpec

STATE_ABILITY: dict[str, str] = {
    "isOpen": "openable",
    "isToggled": "toggleable",
    "isDirty": "dirtyable",
    "isSliced": "sliceable",
    "isHot": "heatable",
    "isCold": "coolable",
    "isFilled": "fillable",
}
"""Initial-state flag -> the ability an object type needs for the flag to be true."""

ACTION_ABILITY: dict[str, str | None] = {
    "GotoLocation": None,
    "PickupObject": "pickupable",
    "PutObject": None,
    "OpenObject": "openable",
    "CloseObject": "openable",
    "ToggleObject": "toggleable",
    "ToggleObjectOn": "toggleable",
    "ToggleObjectOff": "toggleable",
    "SliceObject": "sliceable",
    "HeatObject": "heatable",
    "CoolObject": "coolable",
    "CleanObject": "cleanable",
}
"""Execution action -> the ability its object's type needs (receptacles need `receptacle`)."""


_RECEPTACLES = tuple(t for t in ALL_TYPES if is_receptacle(t))


def raise_for_issues(cdf: ChallengeDefinition, source: str = "<cdf>", note: str = "") -> None:
    """Raise CDFValidationError if `check(cdf)` finds anything.

    Args:
        cdf: The document.
        source: File name for the messages.
        note: Appended to each message.
    """
    issues = check(cdf)
    if issues:
        raise CDFValidationError(source, [Issue(i.path, i.message + note) for i in issues])


def check(cdf: ChallengeDefinition) -> list[Issue]:
    """Every cross-field problem of a structurally valid document (empty when it is consistent).

    A document over the size limits (`bounds.size_issues`) gets only those issues: nothing else is checked.
    """
    rooms = cdf.scene.house.rooms if cdf.scene.house is not None else ()
    too_large = size_issues((o.count for o in cdf.all_objects()),
                            len(cdf.scene.relations) + sum(len(r.relations) for r in rooms), len(cdf.execution or ()))
    if too_large:
        return too_large
    names, issues = _check_objects(cdf.scene.objects)
    names.update(house_names(cdf))
    issues += _check_room(cdf)
    issues += check_house(cdf)
    issues += _check_relations(cdf, names)
    issues += _check_cycles(cdf)
    if cdf.task is not None:
        issues += _check_task(cdf, names)
    for i, step in enumerate(cdf.execution or ()):
        issues += _check_step(step, f"execution[{i}]", names)
    return issues


# -- messages ---------------------------------------------------------------------------------


def _listing(items: Sequence[str], limit: int = 10) -> str:
    shown = ", ".join(items[:limit])
    return shown + (f", ... ({len(items)} in all)" if len(items) > limit else "")


def _unknown_name(name: str, names: dict[str, ObjectSpec], room_elements: bool = False) -> str:
    candidates = list(names) + (list(STRUCTURE_ELEMENTS) if room_elements else [])
    hint = difflib.get_close_matches(name, candidates, n=1)
    extra = f"; did you mean {hint[0]!r}?" if hint else ""
    what = "a name declared in scene.objects"
    if room_elements:
        what += f" or a room element ({', '.join(STRUCTURE_ELEMENTS)})"
    declared = f": {_listing(list(names))}" if names else " (none are declared)"
    return f"unknown name {name!r}{extra} (expected {what}{declared})"


def _a(word: str) -> str:
    return ("an " if word[:1].lower() in "aeiou" else "a ") + word


def _lacks(name: str, obj_type: str, ability: str) -> str:
    return f"{name!r} is {_a(obj_type)}, which is not {ability.replace('_', ' ')}"


# -- checks -----------------------------------------------------------------------------------


def _check_objects(objects: Iterable[ObjectSpec]) -> tuple[dict[str, ObjectSpec], list[Issue]]:
    names: dict[str, ObjectSpec] = {}
    first: dict[str, int] = {}
    issues: list[Issue] = []
    for i, obj in enumerate(objects):
        path = f"scene.objects[{i}]"
        if obj.name in STRUCTURE_ELEMENTS:
            issues.append(
                Issue(
                    f"{path}.name",
                    f"{obj.name!r} is reserved for the room element; expected another name",
                )
            )
        elif obj.name in names:
            issues.append(
                Issue(
                    f"{path}.name",
                    f"duplicate name {obj.name!r} (first declared at "
                    f"scene.objects[{first[obj.name]}]); expected unique names",
                )
            )
        else:
            names[obj.name] = obj
            first[obj.name] = i
        implied = asset_type(obj.asset) if obj.asset else None
        if implied is not None and implied != obj.type:
            issues.append(
                Issue(
                    f"{path}.asset",
                    f"asset {obj.asset!r} is {_a(implied)}; expected an asset of type {obj.type}",
                )
            )
        if obj.state is not None:
            for flag, ability in STATE_ABILITY.items():
                if getattr(obj.state, flag) is True and not has_ability(obj.type, ability):
                    issues.append(
                        Issue(
                            f"{path}.state.{flag}",
                            f"{_lacks(obj.name, obj.type, ability)}; expected {flag} only on "
                            f"{ability} types",
                        )
                    )
    return names, issues


def _check_room(cdf: ChallengeDefinition) -> list[Issue]:
    room = cdf.scene.room
    if not isinstance(room, str):
        return []
    implied = room_type_of(room)
    if implied is not None and implied not in cdf.scene.room_type:
        return [
            Issue(
                "scene.room",
                f"room {room!r} is {_a(implied)}, but scene.room_type is "
                f"{_listing(list(cdf.scene.room_type))}; expected "
                f"{_a(' or '.join(cdf.scene.room_type))} room",
            )
        ]
    return []


def _check_relations(cdf: ChallengeDefinition, names: dict[str, ObjectSpec]) -> list[Issue]:
    issues: list[Issue] = []
    support: dict[str, tuple[int, str, str]] = {}
    unary: dict[str, dict[str, int]] = {}
    pairs: dict[frozenset[str], dict[str, int]] = {}
    for i, rel in enumerate(cdf.scene.relations):
        path = f"scene.relations[{i}]"
        info = RELATIONS[rel.relation]
        if rel.subject in STRUCTURE_ELEMENTS:
            issues.append(
                Issue(
                    f"{path}.subject",
                    f"room element {rel.subject!r} cannot be a subject; expected a name declared "
                    "in scene.objects (room elements may only be targets)",
                )
            )
            continue
        if rel.subject not in names:
            issues.append(Issue(f"{path}.subject", _unknown_name(rel.subject, names)))
            continue
        if info.arity == 1:
            if rel.target is not None:
                issues.append(
                    Issue(
                        f"{path}.target",
                        f"'{rel.relation}' is unary and takes no target; expected no 'target' key",
                    )
                )
                continue
            seen = unary.setdefault(rel.subject, {})
            for pair in EXCLUSIVE_UNARY:
                if rel.relation in pair:
                    (other,) = pair - {rel.relation}
                    if other in seen:
                        issues.append(
                            Issue(
                                f"{path}.relation",
                                f"{rel.subject!r} cannot be both {other} "
                                f"(scene.relations[{seen[other]}]) and {rel.relation}",
                            )
                        )
            seen.setdefault(rel.relation, i)
            continue
        if rel.target is None:
            issues.append(
                Issue(
                    f"{path}.target",
                    f"'{rel.relation}' needs a target; expected a declared name or a room element",
                )
            )
            continue
        if rel.target == rel.subject:
            issues.append(
                Issue(
                    f"{path}.target",
                    f"{rel.subject!r} cannot be related to itself; expected another object",
                )
            )
            continue
        is_element = rel.target in STRUCTURE_ELEMENTS
        if not is_element and rel.target not in names:
            issues.append(
                Issue(f"{path}.target", _unknown_name(rel.target, names, room_elements=True))
            )
            continue
        if info.category == "support":
            problem = _support_problem(rel.relation, names[rel.subject], rel.target, names)
            if problem:
                issues.append(Issue(f"{path}.target", problem))
            elif rel.subject in support:
                j, how, where = support[rel.subject]
                issues.append(
                    Issue(
                        path,
                        f"{rel.subject!r} is already {how} {where!r} (scene.relations[{j}]); "
                        "expected one supporting receptacle per object",
                    )
                )
            else:
                support[rel.subject] = (i, rel.relation, rel.target)
        seen_pair = pairs.setdefault(frozenset({rel.subject, rel.target}), {})
        for pair in EXCLUSIVE_BINARY:
            if rel.relation in pair:
                (other,) = pair - {rel.relation}
                if other in seen_pair:
                    issues.append(
                        Issue(
                            f"{path}.relation",
                            f"{rel.subject!r} and {rel.target!r} cannot be both {other} "
                            f"(scene.relations[{seen_pair[other]}]) and {rel.relation}",
                        )
                    )
        seen_pair.setdefault(rel.relation, i)
    return issues


def _support_problem(
    relation: str, subject: ObjectSpec, target: str, names: dict[str, ObjectSpec]
) -> str | None:
    if target in STRUCTURE_ELEMENTS:
        return (
            f"'{relation}' needs a receptacle object as target, not the room element {target!r} "
            "(use against_wall, near, beside, ... for room elements)"
        )
    t_type = names[target].type
    if not is_receptacle(t_type):
        return (
            f"{target!r} is {_a(t_type)}, not a receptacle; expected a receptacle "
            f"({_listing(list(_RECEPTACLES), 8)})"
        )
    if can_support(t_type, subject.type):
        return None
    if not has_ability(subject.type, "pickupable") and subject.type not in STANDS_ON:
        return (
            f"{subject.name!r} is {_a(subject.type)}, a piece of furniture that stands on the "
            f"floor; it cannot be {relation} {target!r}"
        )
    fits = [r for r in _RECEPTACLES if can_support(r, subject.type)]
    return (
        f"{_a(subject.type)} cannot be {relation} {_a(t_type)} (ALFRED's receptacle table; "
        f"{t_type} accepts "
        f"{_listing(accepted_by(t_type), 6) or 'nothing'}); expected a receptacle that accepts "
        f"{subject.type}: "
        f"{_listing(fits, 6) or 'none'}"
    )


def _check_cycles(cdf: ChallengeDefinition) -> list[Issue]:
    issues = []
    found = find_fixed_cycle(cdf)
    if found:
        names, idx = found
        issues.append(
            Issue(
                f"scene.relations[{idx[-1]}]",
                "relations form a cycle that no rewriting can resolve: "
                + " -> ".join(names)
                + " (on, in and face cannot be reversed); expected an acyclic set",
            )
        )
    found = find_axis_contradiction(cdf)
    if found:
        names, idx = found
        issues.append(
            Issue(
                f"scene.relations[{idx[-1]}]",
                "contradictory directions: "
                + " -> ".join(names)
                + " returns to its start; expected a consistent order",
            )
        )
    return issues


def _check_task(cdf: ChallengeDefinition, names: dict[str, ObjectSpec]) -> list[Issue]:
    task = cdf.task
    assert task is not None
    issues = []
    if task.type is not None and not ALFRED_TASK_ROOMS[task.type] & set(cdf.scene.room_type):
        issues.append(
            Issue(
                "task.type",
                f"ALFRED generates {task.type} only in {_listing(sorted(ALFRED_TASK_ROOMS[task.type]))}; "
                "expected a scene.room_type among them",
            )
        )
    if task.initial is not None:
        if not is_ground_conjunction(task.initial):
            issues.append(
                Issue(
                    "task.initial",
                    "expected ground literals joined by 'and' (no or, exists, forall or "
                    "?variables)",
                )
            )
        issues += _check_expr(task.initial, "task.initial", names)
        issues += _check_conflicts(task.initial, "task.initial", names)
    issues += _check_expr(task.goal, "task.goal", names)
    issues += _check_conflicts(task.goal, "task.goal", names)
    return issues


def _check_conflicts(expr: Expr, path: str, names: dict[str, ObjectSpec]) -> list[Issue]:
    def nonempty(param: Param) -> bool:
        return any(param.type is None or o.type == param.type for o in names.values())

    type_of = {n: o.type for n, o in names.items()}
    return [Issue(path, c.message()) for c in find_conflicts(expr, type_of, nonempty)]


def _check_expr(expr: Expr, path: str, names: dict[str, ObjectSpec]) -> list[Issue]:
    issues = []
    for atom, scope in atoms(expr):
        info = PREDICATES[atom.pred]
        types: list[str | None] = []
        for arg, ability in zip(atom.args, info.abilities):
            if is_variable(arg):
                types.append(scope.get(arg))
            elif arg not in names:
                issues.append(Issue(path, f"in {to_sexpr(atom)}: {_unknown_name(arg, names)}"))
                types.append(None)
                continue
            else:
                types.append(names[arg].type)
            t = types[-1]
            if ability and t and not has_ability(t, ability):
                issues.append(Issue(path, f"in {to_sexpr(atom)}: {_lacks(arg, t, ability)}"))
        if atom.pred == "inReceptacle" and len(types) == 2:
            obj_t, rec_t = types
            if obj_t and rec_t and is_receptacle(rec_t) and not can_support(rec_t, obj_t):
                issues.append(
                    Issue(
                        path,
                        f"in {to_sexpr(atom)}: {_a(obj_t)} cannot be in {_a(rec_t)} (ALFRED's "
                        "receptacle table)",
                    )
                )
    return issues


def _check_step(
    step: HighLevelStep | LowLevelStep, path: str, names: dict[str, ObjectSpec]
) -> list[Issue]:
    issues = []
    if hasattr(step, "receptacle"):
        obj_key, rec_key = "object", "receptacle"
    else:
        obj_key, rec_key = "objectId", "receptacleObjectId"
    for key, ability in ((obj_key, ACTION_ABILITY.get(step.action)), (rec_key, "receptacle")):
        name = getattr(step, key)
        if name is None:
            continue
        if name not in names:
            issues.append(Issue(f"{path}.{key}", _unknown_name(name, names)))
        elif ability and not has_ability(names[name].type, ability):
            issues.append(
                Issue(
                    f"{path}.{key}",
                    f"{_lacks(name, names[name].type, ability)}; expected "
                    f"{_a(ability.replace('_', ' '))} object for {step.action}",
                )
            )
    return issues
