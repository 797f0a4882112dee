"""The JSON Schema of the current CDF version, for editors and other tools.

`schema_dict()` builds it from the pydantic model; `export_schema(out_dir)` writes
`cdf-v<N>.schema.json`. The shipped copy lives in `luminous_sim/resources/cdf/schema/` (the
repository's `cdf/schema/`), and a test checks it equals a fresh export. The loader is a little more
forgiving than the schema (aliases such as `color`, case-insensitive predicate names, version-1 documents).
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from luminous_sim.cdf.predicates import KEYWORDS, PREDICATES
from luminous_sim.cdf.schema import CDF_VERSION, EXPRESSION_MARKER, ChallengeDefinition
from luminous_sim.resources import schema_dir

SCHEMA_ID = f"https://luminous-sim.dev/schema/cdf-v{CDF_VERSION}.schema.json"
SCHEMA_DIR = schema_dir()
"""Where the shipped schema lives (package data; the repository's `cdf/schema/` links to it)."""

_REF = {"$ref": "#/$defs/Expression"}
_NAMES = {"type": "array", "items": {"type": "string"}}


def _expression_schema() -> dict[str, Any]:
    props: dict[str, Any] = {
        "and": {"type": "array", "items": _REF},
        "or": {"type": "array", "items": _REF, "minItems": 1},
        "not": _REF,
    }
    quantified = {
        "type": "object",
        "required": ["vars", "body"],
        "additionalProperties": False,
        "properties": {
            "vars": {
                "anyOf": [
                    {"type": "object", "additionalProperties": {"type": ["string", "null"]}},
                    {
                        "type": "array",
                        "items": {"type": "string", "pattern": r"^\?[A-Za-z][A-Za-z0-9_]*$"},
                    },
                ]
            },
            "body": _REF,
        },
    }
    for q in ("exists", "forall"):
        props[q] = quantified
    for name, info in PREDICATES.items():
        args = {**_NAMES, "minItems": info.arity, "maxItems": info.arity}
        props[name] = {"anyOf": [{"type": "string"}, args]} if info.arity == 1 else args
    return {
        "description": "A PDDL-like condition: an s-expression string such as "
        "'(and (inReceptacle apple fridge) (isCool apple))', a list (conjunction), or a one-key "
        f"mapping ({', '.join(KEYWORDS)} or a predicate).",
        "anyOf": [
            {"type": "string"},
            {"type": "array", "items": _REF},
            {
                "type": "object",
                "minProperties": 1,
                "maxProperties": 1,
                "additionalProperties": False,
                "properties": props,
            },
        ],
    }


def _replace_marker(node: Any) -> Any:
    if isinstance(node, dict) and node.get("$comment") == EXPRESSION_MARKER["$comment"]:
        return {k: v for k, v in node.items() if k != "$comment"} | _REF
    if isinstance(node, dict):
        return {k: _replace_marker(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_replace_marker(v) for v in node]
    return node


def _defs_by_title(schema: dict[str, Any]) -> dict[str, Any]:
    """Key each `$defs` entry by its title rather than by its Python class name.

    The CDF's document names (`Scene`, `AgentPose`, `ObjectState`) are the titles; the classes carry a
    `Spec` suffix so as not to clash with the runtime `scene.Scene`, `world.agent.AgentPose` and
    `states.ObjectState`.
    """
    defs = schema.get("$defs", {})
    renames = {k: v["title"] for k, v in defs.items() if v.get("title", k) != k}
    if not renames:
        return schema
    taken = set(defs) - set(renames)
    for title in renames.values():
        if title in taken:
            raise ValueError(f"two schema definitions would share the title {title!r}")
        taken.add(title)
    refs = {f"#/$defs/{old}": f"#/$defs/{new}" for old, new in renames.items()}

    def walk(node: Any) -> Any:
        if isinstance(node, dict):
            return {k: refs.get(v, v) if k == "$ref" else walk(v) for k, v in node.items()}
        if isinstance(node, list):
            return [walk(v) for v in node]
        return node

    out = walk({k: v for k, v in schema.items() if k != "$defs"})
    out["$defs"] = {renames.get(k, k): walk(v) for k, v in defs.items()}
    return out


def schema_dict() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of the current CDF version."""
    schema = _defs_by_title(ChallengeDefinition.model_json_schema(mode="validation"))
    schema = _replace_marker(schema)
    schema.setdefault("$defs", {})["Expression"] = _expression_schema()
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        "title": f"Luminous-Sim Challenge Definition Format, version {CDF_VERSION}",
        **{k: v for k, v in schema.items() if k != "title"},
    }


def schema_text() -> str:
    """The schema as it is written to disk (sorted keys, two-space indent, final newline)."""
    return json.dumps(schema_dict(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def schema_filename(version: int = CDF_VERSION) -> str:
    """`cdf-v<N>.schema.json`."""
    return f"cdf-v{version}.schema.json"


def export_schema(out_dir: str | os.PathLike[str] = SCHEMA_DIR) -> Path:
    """Write the schema to `out_dir/cdf-v<N>.schema.json` (making the folder); return the path."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    path = out / schema_filename()
    path.write_text(schema_text(), encoding="utf-8")
    return path
