"""`luminous_sim.rooms` is a pure layer: geometry libraries and lower layers only, no PyBullet."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

ROOMS = Path(__file__).resolve().parents[2] / "luminous_sim" / "rooms"
ALLOWED_THIRD_PARTY = {"numpy", "shapely", "pydantic", "matplotlib"}
ALLOWED_OWN = ("luminous_sim.errors", "luminous_sim.vocab", "luminous_sim.rooms")


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
    return names


def test_rooms_imports_only_pure_modules():
    for path in sorted(ROOMS.glob("*.py")):
        for name in _imports(path):
            top = name.split(".")[0]
            if top == "luminous_sim":
                assert name.startswith(ALLOWED_OWN), f"{path.name} imports {name}"
            else:
                assert top in sys.stdlib_module_names or top in ALLOWED_THIRD_PARTY, (
                    f"{path.name} imports {name}"
                )
            if top == "matplotlib":
                assert path.name == "plot.py", f"{path.name} imports matplotlib"
