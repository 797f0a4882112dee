"""The key/type structure of ALFRED-style JSON, to compare our traj_data.json with real ones field by field.

A path names where a value sits: `plan.low_actions[].api_action<PutObject>.receptacleObjectId`. List
elements share one path (`[]`); an object with a string `action` key is qualified by it (`<PutObject>`),
so that each action's own key set is compared with the same action's in the reference files.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

JSON_TYPES = {bool: "boolean", int: "integer", float: "number", str: "string", list: "array", dict: "object"}


def json_type(value: Any) -> str:
    """The JSON type name of a parsed value (`null` for None; bool before int)."""
    return "null" if value is None else JSON_TYPES[type(value)]


@dataclass
class Structure:
    """Which JSON types occur at each path, and which key sets each object path has."""

    types: dict[str, set[str]] = field(default_factory=dict)
    keys: dict[str, set[tuple[str, ...]]] = field(default_factory=dict)

    def add(self, value: Any, path: str = "") -> None:
        """Record `value` (and everything under it) at `path`."""
        if isinstance(value, dict) and isinstance(value.get("action"), str):
            path = f"{path}<{value['action']}>"
        self.types.setdefault(path, set()).add(json_type(value))
        if isinstance(value, dict):
            self.keys.setdefault(path, set()).add(tuple(sorted(value)))
            for k, v in value.items():
                self.add(v, f"{path}.{k}" if path else k)
        elif isinstance(value, list):
            for v in value:
                self.add(v, f"{path}[]")

    def merge(self, other: Structure) -> None:
        for p, ts in other.types.items():
            self.types.setdefault(p, set()).update(ts)
        for p, ks in other.keys.items():
            self.keys.setdefault(p, set()).update(ks)


def structure(value: Any) -> Structure:
    """The structure of one parsed JSON document."""
    out = Structure()
    out.add(value)
    return out


def _action_scope(path: str) -> str | None:
    """The innermost action-qualified object path above or at `path` (None if there is none)."""
    end = path.rfind(">")
    return path[:end + 1] if end >= 0 else None


def structure_differences(ours: Structure, references: Iterable[tuple[str, Structure]]) -> list[str]:
    """Every way `ours` departs from the reference files' structure, one line each.

    - a path of ours that no reference has, or a JSON type there that no reference uses;
    - an object whose key set no reference has at that path (per action for qualified paths);
    - an unqualified object whose key set differs from that of a reference file having it (checked
      against every file, named in the line);
    - a path every reference has but ours lacks, unless it belongs to an action ours never does.
    """
    refs = list(references)
    union = Structure()
    required: set[str] | None = None
    problems: list[str] = []
    for name, ref in refs:
        union.merge(ref)
        required = set(ref.types) if required is None else required & set(ref.types)
        for p, ks in ours.keys.items():
            if "<" not in p and p in ref.keys and ks != ref.keys[p]:
                problems.append(f"{name}: keys at {p or '(top)'}: ours {sorted(ks)}, ALFRED {sorted(ref.keys[p])}")
    for p, ts in sorted(ours.types.items()):
        if p not in union.types:
            problems.append(f"extra path {p}: no reference file has it")
        elif not ts <= union.types[p]:
            problems.append(f"type at {p}: ours {sorted(ts)}, ALFRED {sorted(union.types[p])}")
    for p, ks in sorted(ours.keys.items()):
        if p in union.keys and not ks <= union.keys[p]:
            problems.append(f"keys at {p}: ours {sorted(ks - union.keys[p])} not among ALFRED's "
                            f"{sorted(union.keys[p])}")
    for p in sorted(required or ()):
        scope = _action_scope(p)
        if p not in ours.types and (scope is None or scope in ours.types):
            problems.append(f"missing path {p}: every reference file has it")
    return problems
