"""Imports point down only: pybullet lives in luminous_sim/world/ and nowhere else in the package."""

from __future__ import annotations

import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "luminous_sim"


def _imports(path: Path) -> set[str]:
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name.split(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module.split(".")[0] if node.level == 0 else "")
    return names


def test_pybullet_only_in_world():
    offenders = [
        str(p.relative_to(PKG)) for p in PKG.rglob("*.py")
        if "world" not in p.relative_to(PKG).parts[:1] and {"pybullet", "pybullet_utils"} & _imports(p)
    ]
    assert not offenders, f"pybullet imported outside world/: {offenders}"


def test_pure_layers_do_not_import_upper_layers():
    lower = {"vocab", "assets", "cdf"}
    upper = ("luminous_sim.world", "luminous_sim.env", "luminous_sim.cli", "luminous_sim.data")
    for sub in lower:
        for p in (PKG / sub).rglob("*.py"):
            text = p.read_text()
            assert not any(f"import {u}" in text or f"from {u}" in text for u in upper), p
