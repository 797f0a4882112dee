"""Property-based tests: whatever is thrown at the loader, it answers with a ChallengeDefinition or a
CDFError, never another exception."""

from __future__ import annotations

import copy
import json
from typing import Any

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.cdf import CDFError, dumps, from_document, load, loads
from luminous_sim.cdf.reader import parse_text
from luminous_sim.vocab import ALL_TYPES
from tests.cdf.helpers import BASE, EXAMPLES

FUZZ = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])

EXAMPLE_DOCS = [parse_text(p.read_text(), source=str(p)) for p in EXAMPLES] + [BASE]

_words = st.sampled_from(
    [
        "cdf_version",
        "scene",
        "task",
        "execution",
        "room_type",
        "room",
        "objects",
        "relations",
        "name",
        "type",
        "count",
        "subject",
        "relation",
        "target",
        "goal",
        "initial",
        "on",
        "in",
        "Kitchen",
        "Apple",
        "apple",
        "fridge",
        "wall",
        "(isHot apple)",
        "action",
        "object",
        "PickupObject",
        "?x",
        "",
    ]
)
_scalars = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(-5, 5),
    st.integers(),
    st.floats(allow_nan=True),
    st.text(max_size=12),
    _words,
)
_keys = st.one_of(_words, st.text(max_size=3), st.integers(-2, 2))
_values = st.recursive(
    _scalars,
    lambda kids: st.one_of(st.lists(kids, max_size=3), st.dictionaries(_keys, kids, max_size=3)),
    max_leaves=10,
)


def _outcome(call: Any, *args: Any, **kwargs: Any) -> None:
    try:
        call(*args, **kwargs)
    except CDFError as exc:
        assert str(exc)


@FUZZ
@given(_values)
def test_random_values(doc: Any) -> None:
    _outcome(from_document, doc, "fuzz.yaml")


@FUZZ
@given(st.sampled_from([1, 2]), st.dictionaries(_words, _values, max_size=4))
def test_random_documents_with_a_version(version: int, body: dict[Any, Any]) -> None:
    _outcome(from_document, {**body, "cdf_version": version}, "fuzz.yaml")


@FUZZ
@given(st.dictionaries(_words, _values, max_size=3), st.lists(_values, max_size=3), _values)
def test_random_scenes(scene: dict[Any, Any], relations: list[Any], task: Any) -> None:
    scene = {"room_type": "Kitchen", **scene}
    if relations:
        scene["relations"] = relations
    _outcome(from_document, {"cdf_version": 2, "scene": scene, "task": task}, "fuzz.yaml")


def _paths(node: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    out = [prefix]
    if isinstance(node, dict):
        for k, v in node.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            out += _paths(v, prefix + (i,))
    return out


def _type_names() -> st.SearchStrategy[str]:
    return st.one_of(
        st.sampled_from(ALL_TYPES),
        st.text(max_size=10),
        st.sampled_from(ALL_TYPES).map(lambda t: t[:-1]),
    )


MUTATIONS = (
    "delete",
    "replace",
    "text",
    "type_name",
    "wrap_list",
    "wrap_dict",
    "duplicate",
    "empty",
)


@FUZZ
@given(st.data())
def test_mutated_examples(data: st.DataObject) -> None:
    doc = copy.deepcopy(data.draw(st.sampled_from(EXAMPLE_DOCS)))
    for _ in range(data.draw(st.integers(1, 3))):
        path = data.draw(st.sampled_from(_paths(doc)))
        kind = data.draw(st.sampled_from(MUTATIONS))
        if not path:
            doc = data.draw(_values) if kind == "replace" else doc
            continue
        parent: Any = doc
        for p in path[:-1]:
            parent = parent[p]
        key = path[-1]
        value = parent[key]
        if kind == "delete":
            del parent[key]
        elif kind == "replace":
            parent[key] = data.draw(_values)
        elif kind == "text":
            parent[key] = data.draw(st.text(max_size=20))
        elif kind == "type_name":
            parent[key] = data.draw(_type_names())
        elif kind == "wrap_list":
            parent[key] = [value]
        elif kind == "wrap_dict":
            parent[key] = {"x": value}
        elif kind == "duplicate" and isinstance(parent, list):
            parent.append(copy.deepcopy(value))
        elif kind == "empty":
            parent[key] = type(value)() if isinstance(value, (dict, list, str)) else None
    _outcome(from_document, doc, "fuzz.yaml")


@FUZZ
@given(st.data())
def test_random_strings_in_name_and_type_fields(data: st.DataObject) -> None:
    doc = copy.deepcopy(BASE)
    field = data.draw(st.sampled_from(["type", "name", "subject", "target", "relation", "goal"]))
    text = data.draw(st.one_of(st.text(max_size=30), _type_names()))
    if field in ("type", "name"):
        doc["scene"]["objects"][data.draw(st.integers(0, 3))][field] = text
    elif field == "goal":
        doc["task"]["goal"] = text
    else:
        doc["scene"]["relations"][0][field] = text
    _outcome(from_document, doc, "fuzz.yaml")


@FUZZ
@given(st.text(max_size=300))
def test_random_yaml_text(text: str) -> None:
    _outcome(loads, text, "yaml", "fuzz.yaml")


@FUZZ
@given(st.binary(max_size=300))
def test_random_bytes(raw: bytes) -> None:
    _outcome(loads, raw, "yaml", "fuzz.yaml")
    _outcome(loads, raw, "json", "fuzz.json")


@FUZZ
@given(st.data())
def test_mutated_example_text(data: st.DataObject) -> None:
    text = data.draw(st.sampled_from(EXAMPLES)).read_text()
    for _ in range(data.draw(st.integers(1, 4))):
        i = data.draw(st.integers(0, len(text)))
        j = data.draw(st.integers(i, min(len(text), i + 20)))
        text = (
            text[:i] + data.draw(st.text(alphabet=":-[]{}&*!|>'\"#\n ab1?", max_size=6)) + text[j:]
        )
    _outcome(loads, text, "yaml", "fuzz.yaml")


@FUZZ
@given(_values)
def test_random_json_text(doc: Any) -> None:
    try:
        text = json.dumps(doc)
    except (TypeError, ValueError):
        return
    _outcome(loads, text, "json", "fuzz.json")


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(EXAMPLES))
def test_valid_documents_survive_dump_and_load(path: Any) -> None:
    cdf = load(path)
    assert loads(dumps(cdf)) == cdf
    assert loads(dumps(cdf, "json"), fmt="json") == cdf
    assert yaml.safe_load(dumps(cdf))["cdf_version"] == 2
