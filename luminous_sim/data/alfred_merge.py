"""The merge operator (paper section 3.6): the parsed CDFs of one floor plan's trajectories -> one scene.

ALFRED never moves large furniture, so the merged scene keeps every piece of furniture any trajectory
requires (matched across trajectories by its AI2-THOR instance). Small objects are respawned per
trajectory, so their placements may disagree ("Apple_1 on the countertop" in one, "in the fridge" in
another): for each the merge keeps the most common placement and the most common value of each initial
state flag, and reports each conflict and how it was resolved. Task sections and agent starts belong to
single trajectories and are left out of the merged scene (reported as notes).
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from luminous_sim.cdf import CDFValidationError, ChallengeDefinition, from_document
from luminous_sim.data.alfred_parser import (
    AlfredParse,
    AlfredParseError,
    ParseNote,
    match_instance,
    snake,
    thor_position,
)
from luminous_sim.rooms import load_room
from luminous_sim.vocab import abilities


@dataclass(frozen=True)
class MergeConflict:
    """Trajectories that disagree about one object, and what the merge kept.

    Attributes:
        object: the object's name in the merged CDF.
        key: the AI2-THOR instance it stands for.
        about: `placement`, or `state.<flag>`.
        options: each value the trajectories asked for, with how many asked for it (most first).
        chosen: the value kept (`unset` when none was).
        resolution: why that one.
    """

    object: str
    key: str
    about: str
    options: tuple[tuple[str, int], ...]
    chosen: str
    resolution: str

    def to_json(self) -> dict[str, Any]:
        return {"object": self.object, "key": self.key, "about": self.about,
                "options": [{"value": v, "trajectories": n} for v, n in self.options],
                "chosen": self.chosen, "resolution": self.resolution}


@dataclass(frozen=True)
class MergedCDF:
    """One floor plan's merged scene.

    Attributes:
        floor_plan: the room (`FloorPlan12`).
        cdf: the merged, validated CDF (scene only).
        sources: the trajectories merged, in the order read.
        conflicts: each disagreement and its resolution.
        notes: what the merge left out, and why.
        keys: merged CDF name -> AI2-THOR instance.
    """

    floor_plan: str
    cdf: ChallengeDefinition
    sources: tuple[str, ...]
    conflicts: tuple[MergeConflict, ...]
    notes: tuple[ParseNote, ...]
    keys: Mapping[str, str]

    def to_json(self) -> dict[str, Any]:
        return {"floor_plan": self.floor_plan, "sources": list(self.sources),
                "objects": {n: self.keys[n] for n in sorted(self.keys)},
                "conflicts": [c.to_json() for c in self.conflicts],
                "notes": [n.to_json() for n in self.notes]}


def is_large(object_type: str) -> bool:
    """Furniture and fixtures (what ALFRED never moves), as opposed to small pickupable objects."""
    return not abilities(object_type).pickupable


class _Identities:
    """Canonical instance keys across trajectories: one object recorded at slightly different positions
    (a coordinate rounded one way, an objectId the other; a basin by its own or its sink's position) is
    one object."""

    def __init__(self) -> None:
        self.concrete: list[str] = []

    def canonical(self, key: str, object_type: str) -> str | None:
        pos = thor_position(key)
        if pos is None:
            return None  # a placeholder ("any Knife"): matched by type, see _placeholders
        hit = match_instance(object_type, pos, self.concrete) if key not in self.concrete else key
        if hit is None:
            self.concrete.append(key)
            return key
        return hit


def _choose(counts: Counter[str], prefer: Iterable[str] = ()) -> tuple[str, str]:
    """The most common value, and why; ties go to a value in `prefer`, then to the first in sorted order."""
    ranked = sorted(counts.items(), key=lambda kv: (-kv[1], kv[0] not in set(prefer), kv[0]))
    (best, n), total = ranked[0], sum(counts.values())
    if len(ranked) > 1 and ranked[1][1] == n:
        why = ("tie; kept the one on large furniture" if best in set(prefer) and ranked[1][0] not in set(prefer)
               else "tie; kept the first in sorted order")
        return best, f"{why} ({n} of {total} trajectories that state it)"
    return best, f"most common ({n} of {total} trajectories that state it)"


def merge_parses(parses: Sequence[AlfredParse]) -> MergedCDF:
    """Merge the parsed trajectories of one floor plan into one scene description.

    Args:
        parses: parses of trajectories that share `floor_plan` (any order: they are sorted by source).

    Returns:
        The merged CDF with its conflicts and notes.

    Raises:
        AlfredParseError: no parses, or parses of different floor plans.
    """
    if not parses:
        raise AlfredParseError("merge: no parsed trajectories to merge")
    plans = sorted({p.floor_plan for p in parses})
    if len(plans) > 1:
        raise AlfredParseError(f"merge: trajectories of several floor plans ({', '.join(plans)}); expected one")
    floor_plan = plans[0]
    parses = sorted(parses, key=lambda p: (p.source, p.task_id))
    ids = _Identities()
    types: dict[str, str] = {}
    order: list[str] = []
    placements: dict[str, Counter[tuple[str, str]]] = {}
    states: dict[str, dict[str, Counter[bool]]] = {}
    per_parse_types: list[Counter[str]] = []
    for p in parses:
        local: dict[str, str] = {}
        per_parse_types.append(Counter(o.type for o in p.cdf.scene.objects))
        for o in p.cdf.scene.objects:
            key = ids.canonical(p.keys.get(o.name, o.name), o.type)
            if key is None:
                continue
            local[o.name] = key
            if key not in types:
                types[key] = o.type
                order.append(key)
            for flag, value in (o.state.model_dump(exclude_none=True) if o.state else {}).items():
                states.setdefault(key, {}).setdefault(flag, Counter())[value] += 1
        for r in p.cdf.scene.relations:
            if r.subject in local and r.target in local:
                placements.setdefault(local[r.subject], Counter())[(r.relation, local[r.target])] += 1
    names = _names(order, types)
    conflicts: list[MergeConflict] = []
    relations: list[tuple[str, str, str]] = []
    for key in order:
        counts = placements.get(key)
        if not counts:
            continue
        labelled = Counter({f"{rel} {names[t]}": n for (rel, t), n in counts.items()})
        back = {f"{rel} {names[t]}": (rel, t) for rel, t in counts}
        chosen, why = _choose(labelled, prefer=[v for v, (_, t) in back.items() if is_large(types[t])])
        relations.append((key, *back[chosen]))
        if len(labelled) > 1:
            conflicts.append(MergeConflict(names[key], key, "placement", _ranked(labelled), chosen, why))
    object_states: dict[str, dict[str, bool]] = {}
    for key in order:
        for flag, values in states.get(key, {}).items():
            if len(values) == 1:
                object_states.setdefault(key, {})[flag] = next(iter(values))
                continue
            (v1, n1), (_, n2) = values.most_common(2)
            options = _ranked(Counter({str(v).lower(): n for v, n in values.items()}))
            if n1 == n2:
                conflicts.append(MergeConflict(names[key], key, f"state.{flag}", options, "unset",
                                               "tie; left to the generator"))
            else:
                object_states.setdefault(key, {})[flag] = v1
                conflicts.append(MergeConflict(names[key], key, f"state.{flag}", options, str(v1).lower(),
                                               f"most common ({n1} of {n1 + n2} trajectories that state it)"))
    extra = _placeholders(order, types, per_parse_types)
    for key, object_type in extra:
        types[key] = object_type
        order.append(key)
    names = _names(order, types)
    notes = _notes(parses, extra)
    room_type = load_room(floor_plan).room_type
    cdf = _validated(floor_plan, room_type, order, types, names, object_states, relations, conflicts, notes,
                     len(parses))
    return MergedCDF(floor_plan, cdf, tuple(p.source for p in parses), tuple(conflicts), tuple(notes),
                     {names[k]: k for k in order})


def _ranked(counts: Counter[str]) -> tuple[tuple[str, int], ...]:
    return tuple(sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))


def _names(order: Sequence[str], types: Mapping[str, str]) -> dict[str, str]:
    seen: Counter[str] = Counter()
    out = {}
    for key in order:
        t = types[key]
        seen[t] += 1
        out[key] = snake(t) + (f"_{seen[t]}" if seen[t] > 1 else "")
    return out


def _placeholders(
    order: Sequence[str], types: Mapping[str, str], per_parse: Sequence[Counter[str]]
) -> list[tuple[str, str]]:
    """Objects a trajectory needs by type only (a task's knife, a GotoLocation target): enough instances
    of each type for the trajectory that needs the most."""
    have = Counter(types[k] for k in order)
    need: Counter[str] = Counter()
    for counts in per_parse:
        for t, n in counts.items():
            need[t] = max(need[t], n)
    return [(f"{t}|any|{i}", t) for t in sorted(need) for i in range(have[t], need[t])]


def _notes(parses: Sequence[AlfredParse], extra: Sequence[tuple[str, str]]) -> list[ParseNote]:
    tasks = Counter(p.task_type for p in parses)
    notes = [
        ParseNote("task", ", ".join(f"{t} x{n}" for t, n in sorted(tasks.items())),
                  "tasks belong to single trajectories; the merged CDF describes the scene only"),
        ParseNote("task.agent", f"{sum(1 for p in parses if p.cdf.task and p.cdf.task.agent)} agent starts",
                  "each trajectory starts the agent elsewhere; the merged scene has no start"),
    ]
    notes += [ParseNote("objects", f"{t} ({k})", "needed by type only; no instance of that type is named by "
                                                 "another trajectory") for k, t in extra]
    return notes


def _validated(
    floor_plan: str, room_type: str, order: Sequence[str], types: Mapping[str, str], names: Mapping[str, str],
    object_states: Mapping[str, Mapping[str, bool]], relations: list[tuple[str, str, str]],
    conflicts: list[MergeConflict], notes: list[ParseNote], count: int,
) -> ChallengeDefinition:
    """The merged CDF, validated; a relation the validation refuses (a cycle, a second support) is
    dropped and reported as a resolved conflict."""
    for _ in range(len(relations) + 1):
        doc = {
            "cdf_version": 2, "name": f"{floor_plan}-merged",
            "description": f"Merged from {count} ALFRED trajectories of {floor_plan}.",
            "scene": {
                "room_type": room_type, "room": floor_plan,
                "objects": [{"name": names[k], "type": types[k]}
                            | ({"state": dict(object_states[k])} if object_states.get(k) else {}) for k in order],
                "relations": [{"subject": names[s], "relation": r, "target": names[t]} for s, r, t in relations],
            },
        }
        try:
            return from_document(doc, f"<merge {floor_plan}>")
        except CDFValidationError as exc:
            bad = sorted({int(m.group(1)) for i in exc.issues if (m := re.match(r"scene\.relations\[(\d+)\]", i.path))})
            if not bad:
                raise AlfredParseError(f"merge {floor_plan}: the merged CDF does not validate: {exc}") from None
            for j in reversed(bad):
                s, r, t = relations.pop(j)
                message = next(i.message for i in exc.issues if i.path.startswith(f"scene.relations[{j}]"))
                conflicts.append(MergeConflict(names[s], s, "placement", ((f"{r} {names[t]}", 1),), "unset",
                                               f"dropped: CDF validation: {message}"))
    raise AlfredParseError(f"merge {floor_plan}: the merged CDF does not validate")


def merge_by_floor_plan(parses: Iterable[AlfredParse]) -> dict[str, MergedCDF]:
    """`merge_parses` per floor plan, keyed by floor plan in natural order (FloorPlan2 before FloorPlan10)."""
    groups: dict[str, list[AlfredParse]] = {}
    for p in parses:
        groups.setdefault(p.floor_plan, []).append(p)
    ordered = sorted(groups, key=lambda n: (len(n), n))
    return {plan: merge_parses(groups[plan]) for plan in ordered}
