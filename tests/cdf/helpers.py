"""Shared data of the CDF tests: the example files and a small valid document to mutate."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((REPO / "cdf" / "examples").glob("*.yaml"))

BASE: dict[str, Any] = {
    "cdf_version": 2,
    "scene": {
        "room_type": "Kitchen",
        "objects": [
            {"name": "fridge", "type": "Fridge"},
            {"name": "counter", "type": "CounterTop"},
            {"name": "apple", "type": "Apple"},
            {"name": "chair", "type": "Chair"},
        ],
        "relations": [
            {"subject": "apple", "relation": "on", "target": "counter"},
            {"subject": "counter", "relation": "against_wall"},
        ],
    },
    "task": {"goal": "(and (inReceptacle apple fridge) (isCool apple))"},
}


def base() -> dict[str, Any]:
    """A fresh copy of BASE."""
    return copy.deepcopy(BASE)


def rel(subject: str, relation: str, target: str | None = None) -> dict[str, Any]:
    """A relation entry."""
    out = {"subject": subject, "relation": relation}
    if target is not None:
        out["target"] = target
    return out
