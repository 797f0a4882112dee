"""Version upgrades: `upgrade(doc)` lifts a raw document of an old version to the current one.

Version 1 (legacy) kept everything at the top level and wrote relations as sentences::

    cdf_version: 1
    room_type: Kitchen                 # or a list
    room: FloorPlan12                  # optional
    objects:
      - Fridge                         # a bare type: the name is the type
      - {type: Apple, name: apple, color: red, material: wax, size: 1.2, isCold: true}
    relations:
      - "apple in Fridge"
      - "Chair in front of Desk"       # multi-word relations, spaces for underscores
      - "Bed against wall"             # unary
    goal: "(isCool apple)"             # optional
    initial: "(isOpen Fridge)"         # optional

Version 2 (current) is described in schema.py. Each step `UPGRADES[n]` maps a version-n document to
version n+1; steps never mutate their input.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from typing import Any

from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cdf.relations import ALIASES, RELATIONS
from luminous_sim.cdf.schema import CDF_VERSION

_V1_STATE_FLAGS = (
    "isOpen",
    "isToggled",
    "isOn",
    "isDirty",
    "isSliced",
    "isHot",
    "isCold",
    "isFilled",
)
_V1_ATTRIBUTES = {"color": "colour", "colour": "colour", "material": "material", "size": "size"}
_V1_TOP_KEYS = {
    "cdf_version",
    "name",
    "description",
    "room_type",
    "room",
    "objects",
    "relations",
    "goal",
    "initial",
}
_ARTICLES = {"the", "a", "an"}


def _phrases() -> list[tuple[tuple[str, ...], str]]:
    names = {n: n for n in RELATIONS} | dict(ALIASES)
    table = {tuple(k.split("_")): v for k, v in names.items()}
    table[("on", "top", "of")] = "on"
    table[("inside",)] = "in"
    table[("against",)] = "against_wall"
    return sorted(table.items(), key=lambda kv: -len(kv[0]))


_PHRASES = _phrases()


def _fail(path: str, message: str, source: str) -> CDFValidationError:
    return CDFValidationError(source, [Issue(path, message + " (cdf_version 1 document)")])


def parse_v1_relation(
    text: str, path: str = "relations[0]", source: str = "<cdf>"
) -> dict[str, Any]:
    """Read a version-1 relation sentence ("Mug on DiningTable", "Bed against wall") into a mapping.

    Raises:
        CDFValidationError: The sentence is not `<subject> <relation words> [<target>]`.
    """
    words = [w for w in text.split() if w.lower() not in _ARTICLES]
    lowered = [w.lower() for w in words]
    for phrase, relation in _PHRASES:
        n = len(phrase)
        if len(words) >= 1 + n and tuple(lowered[1 : 1 + n]) == phrase:
            rest = words[1 + n :]
            if relation == "against_wall" and [w.lower() for w in rest] == ["wall"]:
                rest = []
            if len(rest) > 1:
                break
            out: dict[str, Any] = {"subject": words[0], "relation": relation}
            if rest:
                out["target"] = rest[0]
            return out
    raise _fail(
        path,
        f"cannot read relation {text!r}; expected '<subject> <relation> [<target>]', e.g. 'Mug on "
        "DiningTable'",
        source,
    )


def _v1_object(entry: Any, path: str, source: str) -> dict[str, Any]:
    if isinstance(entry, str):
        return {"name": entry, "type": entry}
    if not isinstance(entry, dict):
        raise _fail(
            path, f"expected an object type or a mapping, got {type(entry).__name__}", source
        )
    obj: dict[str, Any] = {}
    attributes: dict[str, Any] = {}
    state: dict[str, Any] = {}
    for key, value in entry.items():
        if key in _V1_ATTRIBUTES:
            attributes[_V1_ATTRIBUTES[key]] = value
        elif key in _V1_STATE_FLAGS:
            state["isToggled" if key == "isOn" else key] = value
        else:
            obj[key] = value
    if "name" not in obj and isinstance(obj.get("type"), str):
        obj["name"] = obj["type"]
    if attributes:
        obj["attributes"] = attributes
    if state:
        obj["state"] = state
    return obj


def _v1_to_v2(doc: dict[str, Any], source: str) -> dict[str, Any]:
    unknown = sorted(str(k) for k in doc if k not in _V1_TOP_KEYS)
    if unknown:
        raise _fail(
            unknown[0], f"unknown key; expected one of {', '.join(sorted(_V1_TOP_KEYS))}", source
        )
    objects = doc.get("objects", [])
    relations = doc.get("relations", [])
    for key, value in (("objects", objects), ("relations", relations)):
        if not isinstance(value, list):
            raise _fail(key, f"expected a list, got {type(value).__name__}", source)
    new_objects = [_v1_object(o, f"objects[{i}]", source) for i, o in enumerate(objects)]
    taken: dict[str, int] = {}
    for obj in new_objects:  # v1 names defaulted to the type; repeated types get _2, _3, ...
        name = obj.get("name")
        if isinstance(name, str) and name in taken and name == obj.get("type"):
            taken[name] += 1
            obj["name"] = f"{name}_{taken[name]}"
        elif isinstance(name, str):
            taken.setdefault(name, 1)
    new_relations = []
    for i, rel in enumerate(relations):
        if isinstance(rel, str):
            new_relations.append(parse_v1_relation(rel, f"relations[{i}]", source))
        else:
            raise _fail(
                f"relations[{i}]",
                f"expected a sentence such as 'Mug on DiningTable', got {type(rel).__name__}",
                source,
            )
    scene: dict[str, Any] = {
        "room_type": doc.get("room_type"),
        "objects": new_objects,
        "relations": new_relations,
    }
    if "room" in doc:
        scene["room"] = doc["room"]
    out: dict[str, Any] = {"cdf_version": 2, "scene": scene}
    for key in ("name", "description"):
        if key in doc:
            out[key] = doc[key]
    if "goal" in doc or "initial" in doc:
        out["task"] = {k: doc[k] for k in ("initial", "goal") if k in doc}
    return out


UPGRADES: dict[int, Callable[[dict[str, Any], str], dict[str, Any]]] = {1: _v1_to_v2}
"""Version n -> the function that turns a version-n document into version n+1."""

SUPPORTED_VERSIONS: tuple[int, ...] = (*sorted(UPGRADES), CDF_VERSION)


def document_version(doc: Any, source: str = "<cdf>") -> int:
    """The `cdf_version` of a raw document.

    Raises:
        CDFValidationError: Not a mapping, or the version is missing, not an integer or unsupported.
    """
    if doc is None:
        raise CDFValidationError(
            source,
            [Issue("", "the document is empty; expected a mapping with cdf_version and scene")],
        )
    if not isinstance(doc, dict):
        raise CDFValidationError(
            source, [Issue("", f"expected a mapping at the top level, got {type(doc).__name__}")]
        )
    if "cdf_version" not in doc:
        raise CDFValidationError(
            source,
            [
                Issue(
                    "cdf_version",
                    "required key is missing; expected one of "
                    f"{', '.join(map(str, SUPPORTED_VERSIONS))}",
                )
            ],
        )
    version = doc["cdf_version"]
    if type(version) is not int or version not in SUPPORTED_VERSIONS:
        newer = type(version) is int and version > CDF_VERSION
        why = "newer than this library reads" if newer else "unsupported"
        raise CDFValidationError(
            source,
            [
                Issue(
                    "cdf_version",
                    f"{why} version {version!r}; expected an integer among "
                    f"{', '.join(map(str, SUPPORTED_VERSIONS))}",
                )
            ],
        )
    return version


def upgrade(doc: dict[str, Any], source: str = "<cdf>") -> dict[str, Any]:
    """Lift a raw document to the current version through the chain of UPGRADES (a new dict).

    Raises:
        CDFValidationError: The version is unsupported or an old document cannot be read.
    """
    version = document_version(doc, source)
    out = copy.deepcopy(doc)
    while version < CDF_VERSION:
        out = UPGRADES[version](out, source)
        version += 1
    return out
