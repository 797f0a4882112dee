"""Reading CDF text safely: YAML (a restricted safe subset) or JSON, never executing anything.

* Only plain data tags are constructed (null, bool, int, float, str, list, map); anything else,
  including !!python/*, !!binary, !!timestamp and !!set, is an error. Booleans are YAML 1.2's
  true/false only, so `relation: on` stays the string "on".
* Duplicate keys are errors. Anchors and aliases are allowed, but the expanded document must stay
  under MAX_NODES values and MAX_DEPTH levels, and may not refer to itself.
* Text over MAX_BYTES is rejected before parsing.
"""

from __future__ import annotations

import json
import re
from typing import Any

import yaml

from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.limits import MAX_CDF_BYTES

MAX_BYTES = MAX_CDF_BYTES
"""`limits.MAX_CDF_BYTES`, under its older name."""
MAX_NODES = 100_000
MAX_DEPTH = 48
FORMATS = ("yaml", "json")

_PLAIN_TAGS = {
    f"tag:yaml.org,2002:{t}" for t in ("null", "bool", "int", "float", "str", "seq", "map")
}
_MERGE = "tag:yaml.org,2002:merge"


class _Loader(yaml.SafeLoader):
    """SafeLoader restricted to plain data, YAML 1.2 booleans, no duplicate keys."""

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
        seen: set[tuple[str, str]] = set()
        for key_node, _ in node.value:
            if isinstance(key_node, yaml.ScalarNode) and key_node.tag != _MERGE:
                key = (key_node.tag, key_node.value)
                if key in seen:
                    raise yaml.constructor.ConstructorError(
                        None,
                        None,
                        f"duplicate key {key_node.value!r}; expected each key once",
                        key_node.start_mark,
                    )
                seen.add(key)
        return super().construct_mapping(node, deep=deep)


_Loader.yaml_constructors = {
    tag: f
    for tag, f in yaml.SafeLoader.yaml_constructors.items()
    if tag in _PLAIN_TAGS or tag is None
}
_Loader.yaml_implicit_resolvers = {
    first: [
        (tag, rx)
        for tag, rx in resolvers
        if tag not in ("tag:yaml.org,2002:bool", "tag:yaml.org,2002:timestamp")
    ]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
_Loader.add_implicit_resolver(
    "tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"), list("tTfF")
)


def _error(source: str, message: str) -> CDFValidationError:
    return CDFValidationError(source, [Issue("", message)])


def check_tree(data: Any, source: str) -> None:
    """Reject self-referencing, too deep or (once aliases are expanded) too large documents.

    Raises:
        CDFValidationError: The data is not a finite tree within MAX_DEPTH and MAX_NODES.
    """
    memo: dict[int, tuple[int, int]] = {}
    active: set[int] = set()

    def walk(node: Any) -> tuple[int, int]:  # (expanded size, height)
        if not isinstance(node, (dict, list)):
            return 1, 0
        key = id(node)
        if key in memo:
            return memo[key]
        if key in active:
            raise _error(source, "the document refers to itself through an alias; expected a tree")
        if len(active) > MAX_DEPTH:
            raise _error(source, f"nested deeper than {MAX_DEPTH} levels")
        active.add(key)
        children = list(node.keys()) + list(node.values()) if isinstance(node, dict) else node
        size, height = 1, 0
        for child in children:
            s, h = walk(child)
            size, height = size + s, max(height, h + 1)
            if size > MAX_NODES:
                raise _error(source, f"more than {MAX_NODES} values once aliases are expanded")
        active.discard(key)
        if height > MAX_DEPTH:
            raise _error(source, f"nested deeper than {MAX_DEPTH} levels")
        memo[key] = (size, height)
        return size, height

    walk(data)


def _no_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise ValueError(f"duplicate key {key!r}; expected each key once")
        out[key] = value
    return out


def _load_yaml(text: str, source: str) -> Any:
    """yaml.load with `source` as the name in error marks (PyYAML would say "<unicode string>")."""
    loader = _Loader(text)
    loader.name = source
    try:
        return loader.get_single_data()
    finally:
        loader.dispose()


def parse_text(text: str | bytes, fmt: str = "yaml", source: str = "<string>") -> Any:
    """Parse CDF text into plain data (dicts, lists, scalars), safely.

    Args:
        text: The document (bytes are decoded as UTF-8).
        fmt: "yaml" or "json".
        source: Name for error messages.

    Raises:
        CDFValidationError: Too large, not UTF-8, malformed, unsafe tags, duplicate keys, too deep.
    """
    if fmt not in FORMATS:
        raise _error(source, f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")
    size = len(text) if isinstance(text, bytes) else len(text.encode("utf-8", "surrogatepass"))
    if size > MAX_BYTES:
        raise _error(source, f"document is {size} bytes; expected at most {MAX_BYTES} "
                               "(luminous_sim.limits.MAX_CDF_BYTES)")
    if isinstance(text, bytes):
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise _error(source, f"not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    try:
        if fmt == "json":
            data = json.loads(text, object_pairs_hook=_no_duplicates)
        else:
            data = _load_yaml(text, source)
    except yaml.YAMLError as exc:
        raise _error(source, f"invalid YAML: {' '.join(str(exc).split())}") from None
    except (ValueError, RecursionError) as exc:  # json.JSONDecodeError is a ValueError
        raise _error(source, f"invalid {fmt.upper()}: {exc or 'nested too deeply'}") from None
    check_tree(data, source)
    return data
