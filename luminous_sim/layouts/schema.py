"""The JSON Schema of the layout format, generated from its pydantic models; the shipped copy lives in
`luminous_sim/resources/cdf/schema/` (beside the CDF's), and a test checks it equals a fresh export."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from luminous_sim.layouts.model import LAYOUT_FORMAT, Layout
from luminous_sim.resources import schema_dir

SCHEMA_FILENAME = "luminous-layout-v1.schema.json"
SCHEMA_ID = f"https://luminous-sim.dev/schema/{SCHEMA_FILENAME}"
SCHEMA_DIR = schema_dir()
"""Where the shipped schema lives (package data; the repository's `cdf/schema/` links to it)."""


def schema_dict() -> dict[str, Any]:
    """The JSON Schema (draft 2020-12) of `luminous-layout/1`."""
    schema = Layout.model_json_schema(mode="validation")
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "$id": SCHEMA_ID,
        **{k: v for k, v in schema.items() if k != "title"},
        "title": f"Luminous-Sim layout ({LAYOUT_FORMAT})",
    }


def schema_text() -> str:
    """The schema as written to disk (sorted keys, two-space indent, final newline)."""
    return json.dumps(schema_dict(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def export_schema(out_dir: str | os.PathLike[str] = SCHEMA_DIR) -> Path:
    """Write the schema to `out_dir/luminous-layout-v1.schema.json` (making the folder); return the path."""
    from luminous_sim.fileio import write_atomic

    path = Path(out_dir) / SCHEMA_FILENAME
    write_atomic(path, schema_text())
    return path
