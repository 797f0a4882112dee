from __future__ import annotations

import json
from pathlib import Path

import pytest

from luminous_sim.cdf import CDF_VERSION, export_schema, schema_dict, schema_filename, schema_text
from luminous_sim.cdf.reader import parse_text
from tests.cdf.helpers import EXAMPLES, REPO

COMMITTED = REPO / "cdf" / "schema" / schema_filename()


def test_committed_schema_equals_the_export() -> None:
    assert COMMITTED.exists(), "run `luminous cdf schema --out cdf/schema`"
    assert (
        COMMITTED.read_text(encoding="utf-8") == schema_text()
    ), "run `luminous cdf schema --out cdf/schema`"


def test_export_writes_the_versioned_file(tmp_path: Path) -> None:
    path = export_schema(tmp_path / "out")
    assert path.name == f"cdf-v{CDF_VERSION}.schema.json"
    assert json.loads(path.read_text()) == schema_dict()


def test_schema_shape() -> None:
    schema = schema_dict()
    assert schema["properties"]["cdf_version"]["const"] == CDF_VERSION
    assert schema["additionalProperties"] is False
    assert "Expression" in schema["$defs"]
    assert "cdf-expression" not in json.dumps(schema)


def test_schema_names_are_the_documents_not_the_classes() -> None:
    """`$defs` are keyed by title: the classes are `SceneSpec`, ... (the runtime owns `Scene`, ...)."""
    from luminous_sim.cdf import AgentPoseSpec, ObjectStateSpec, SceneSpec

    defs = schema_dict()["$defs"]
    for cls, name in ((SceneSpec, "Scene"), (AgentPoseSpec, "AgentPose"), (ObjectStateSpec, "ObjectState")):
        assert defs[name]["title"] == name and cls.__name__ not in defs
    assert '"#/$defs/SceneSpec"' not in schema_text()


@pytest.mark.parametrize("path", [p for p in EXAMPLES if "v1" not in p.stem], ids=lambda p: p.stem)
def test_current_examples_satisfy_the_json_schema(path: Path) -> None:
    jsonschema = pytest.importorskip("jsonschema")
    validator = jsonschema.Draft202012Validator(schema_dict())
    validator.check_schema(schema_dict())
    errors = [e.message for e in validator.iter_errors(parse_text(path.read_text()))]
    assert not errors


def test_json_schema_rejects_unknown_keys() -> None:
    jsonschema = pytest.importorskip("jsonschema")
    doc = {"cdf_version": CDF_VERSION, "scene": {"room_type": "Kitchen", "objekts": []}}
    assert list(jsonschema.Draft202012Validator(schema_dict()).iter_errors(doc))
