"""`luminous_sim.tasks` is layer L3 and pure: no PyBullet, nothing from the world or upper layers."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

TASKS = Path(__file__).resolve().parents[2] / "luminous_sim" / "tasks"
ALLOWED_OWN = (
    "luminous_sim.errors",
    "luminous_sim.vocab",
    "luminous_sim.cdf",
    "luminous_sim.scene",
    "luminous_sim.states",
    "luminous_sim.tasks",
)
ALLOWED_THIRD_PARTY = {"numpy", "yaml"}


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
    return names


def test_tasks_import_only_pure_modules():
    files = sorted(TASKS.glob("*.py"))
    assert files
    for path in files:
        for name in _imports(path):
            top = name.split(".")[0]
            if top == "luminous_sim":
                assert name.startswith(ALLOWED_OWN), f"{path.name} imports {name}"
            else:
                assert top in sys.stdlib_module_names or top in ALLOWED_THIRD_PARTY, (
                    f"{path.name} imports {name}"
                )


def test_modules_stay_small():
    for path in TASKS.glob("*.py"):
        assert len(path.read_text().splitlines()) <= 300, path.name
