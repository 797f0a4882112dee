"""`luminous_sim.states` is a pure layer: the standard library and the lower layers only, no PyBullet."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

STATES = Path(__file__).resolve().parents[2] / "luminous_sim" / "states"
ALLOWED_OWN = ("luminous_sim.errors", "luminous_sim.vocab", "luminous_sim.states")


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
    return names


def test_states_imports_only_pure_modules():
    files = sorted(STATES.glob("*.py"))
    assert files
    for path in files:
        for name in _imports(path):
            top = name.split(".")[0]
            if top == "luminous_sim":
                assert name.startswith(ALLOWED_OWN), f"{path.name} imports {name}"
            else:
                assert top in sys.stdlib_module_names, f"{path.name} imports {name}"


def test_modules_stay_small():
    for path in STATES.glob("*.py"):
        assert len(path.read_text().splitlines()) <= 250, path.name
