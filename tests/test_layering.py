"""Imports point down (or sideways) only, as DESIGN.md's layer table says, pybullet lives in
luminous_sim/world/ alone, and the scene generator (cssg/) is a producer that only layers L4 and L5 import.
Function-level (lazy) imports count too."""

from __future__ import annotations

import ast
from pathlib import Path

PKG = Path(__file__).resolve().parents[1] / "luminous_sim"

LAYER = {
    "errors": 0, "fileio": 0, "lazy": 0, "limits": 0, "resources": 0, "vocab": 0, "assets": 0, "cdf": 0,
    "scene": 1, "rooms": 1, "cssg": 1, "states": 1,
    "world": 2,
    "tasks": 3, "planning": 3, "language": 3, "splits": 3, "text": 3,
    "env": 4, "benchmark": 4, "episodes": 4,
    "data": 5, "eval": 5, "export": 5, "thor": 5, "viewer": 5, "bc": 5, "cli": 5, "layouts": 5, "demo": 5, "episode": 5,
    "cdf_episode": 5, "agents": 5,
    "scene_outputs": 5,
}
LAYER_4_ORDER = ("benchmark", "episodes", "env")
"""Layer L4 in order: a package imports only those before it. The splits as data (benchmark), the episodes
drawn from them and elsewhere (episodes), the env that plays episodes (env: its task kinds reach the episodes'
sources through `episodes.Drawing`, so episodes need nothing of the env)."""
PYBULLET = {"pybullet", "pybullet_utils", "pybullet_data"}
GENERATOR = "cssg"
"""Imported by layers L4 and L5 only: the environments (L4) generate their scenes on the fly, and task-driven
generation and the command line (L5) produce scenes; the simulator, the planner and the task layer (L1-L3)
use the scene geometry in scene/, never the generator's insides."""
GENERATOR_USERS = 4
"""The lowest layer that may import the generator."""


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            names.add(node.module)
            if node.module == "luminous_sim":  # `from luminous_sim import cssg`
                names |= {f"luminous_sim.{a.name}" for a in node.names}
        elif (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "import_module"
              and node.args and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)):
            names.add(node.args[0].value)
    return names


def _package(path: Path) -> str:
    rel = path.relative_to(PKG).parts
    return rel[0].removesuffix(".py")


def test_every_package_has_a_layer():
    packages = {_package(p) for p in PKG.rglob("*.py") if p.name != "__init__.py" or p.parent != PKG}
    assert packages <= set(LAYER), f"add to LAYER: {sorted(packages - set(LAYER))}"


def test_imports_point_down_and_pybullet_stays_in_world():
    problems = []
    for path in sorted(PKG.rglob("*.py")):
        if path.parent == PKG and path.name == "__init__.py":
            continue
        own = _package(path)
        for name in _imports(path):
            parts = name.split(".")
            if parts[0] in PYBULLET and own != "world":
                problems.append(f"{path.relative_to(PKG)} imports {name} (pybullet belongs to world/)")
            if parts[0] == "luminous_sim" and len(parts) > 1 and parts[1] in LAYER:
                target = parts[1]
                if LAYER[target] > LAYER[own]:
                    problems.append(f"{path.relative_to(PKG)} (L{LAYER[own]}) imports {name} (L{LAYER[target]})")
    assert not problems, "\n".join(problems)


def test_nothing_below_layer_4_imports_the_generator():
    problems = []
    for path in sorted(PKG.rglob("*.py")):
        if path.parent == PKG and path.name == "__init__.py":
            continue
        own = _package(path)
        if own == GENERATOR or LAYER[own] >= GENERATOR_USERS:
            continue
        problems += [f"{path.relative_to(PKG)} (L{LAYER[own]}) imports {name}" for name in sorted(_imports(path))
                     if name.split(".")[:2] == ["luminous_sim", GENERATOR]]
    assert not problems, "the generator is a producer (DESIGN.md, Layers):\n" + "\n".join(problems)


def test_layer_4_imports_point_back_in_its_order():
    problems = []
    for path in sorted(PKG.rglob("*.py")):
        own = _package(path) if not (path.parent == PKG and path.name == "__init__.py") else ""
        if own not in LAYER_4_ORDER:
            continue
        later = LAYER_4_ORDER[LAYER_4_ORDER.index(own) + 1:]
        problems += [f"{path.relative_to(PKG)} ({own}) imports {name}" for name in sorted(_imports(path))
                     if name.split(".")[0] == "luminous_sim" and len(name.split(".")) > 1
                     and name.split(".")[1] in later]
    assert not problems, f"L4 is ordered {' < '.join(LAYER_4_ORDER)}:\n" + "\n".join(problems)


AGENT_BLIND = ("luminous_sim.world", "luminous_sim.planning", "luminous_sim.episodes", "luminous_sim.scene",
               "luminous_sim.env.expert", "luminous_sim.env.oracle_policy", "luminous_sim.env.alfred_env")
"""What the agents may never see: the world, the planner, the episode's spec and scene, the expert (an agent
sees only what the env gives an agent: observations, the action's feedback, the instructions)."""


def test_the_agents_import_no_world_no_planner_and_no_expert():
    problems = [f"{path.relative_to(PKG)} imports {name}" for path in sorted((PKG / "agents").rglob("*.py"))
                for name in sorted(_imports(path)) if name.startswith(AGENT_BLIND)]
    assert not problems, "\n".join(problems)


def test_no_module_takes_another_modules_private_names():
    """A name with a leading underscore is its module's own: no other module imports it (issue 42)."""
    taken = []
    for path in PKG.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("luminous_sim"):
                taken += [f"{path.relative_to(PKG)}:{node.lineno} {node.module}.{a.name}" for a in node.names
                          if a.name.startswith("_") and not a.name.startswith("__")]
    assert not taken, "private names imported across modules:\n" + "\n".join(taken)
