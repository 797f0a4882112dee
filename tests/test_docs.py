"""docs/architecture.md's package map tells the truth: every package (and top-level module) of
luminous_sim/ has a row with the layer tests/test_layering.py gives it, every public name a row lists is
exported, and the imports a row lists are the package's imports now."""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from pathlib import Path

from tests.test_layering import LAYER, PKG, _imports, _package

DOC = PKG.parent / "docs" / "architecture.md"
START, END = "<!-- package-map:start -->", "<!-- package-map:end -->"
HEADER = ["package", "layer", "job", "public names", "imports (now)"]
SHORTENED = re.compile(r"\.\.\.\s*\((\d+)\)")
"""A shortened list of public names ends in `... (N)`, N the length of the package's `__all__`."""


@dataclass(frozen=True)
class Row:
    package: str
    layer: int
    job: str
    public: tuple[str, ...]
    total: int | None
    """N of a shortened list, None for a complete one."""
    imports: frozenset[str]


def _cells(line: str) -> list[str]:
    return [c.strip() for c in line.strip().strip("|").split("|")]


def _ticked(cell: str) -> list[str]:
    return re.findall(r"`([^`]+)`", cell)


def _key(cell: str) -> str:
    """`vocab/` -> vocab, `errors.py` -> errors."""
    name = cell.strip("`").removesuffix("/").removesuffix(".py")
    assert name and "/" not in name and "." not in name, f"not a package or module name: {cell!r}"
    return name


def _layer(cell: str) -> int:
    assert re.fullmatch(r"L\d", cell), f"a layer is L0..L5, not {cell!r}"
    return int(cell[1])


def _map() -> dict[str, Row]:
    text = DOC.read_text()
    assert text.count(START) == 1 and text.count(END) == 1, f"{DOC.name} needs one {START} ... {END} block"
    lines = [ln for ln in text.split(START)[1].split(END)[0].splitlines() if ln.startswith("|")]
    assert _cells(lines[0]) == HEADER, f"the package map's columns are {HEADER}"
    rows: dict[str, Row] = {}
    for line in lines[2:]:
        package, layer, job, public, imports = _cells(line)
        key = _key(package)
        assert key not in rows, f"two rows for {key}"
        total = SHORTENED.search(public)
        rows[key] = Row(key, _layer(layer), job, tuple(_ticked(public)), int(total[1]) if total else None,
                        frozenset(_ticked(imports)))
    return rows


def _on_disk() -> set[str]:
    """Every sub-package (a folder holding Python files) and top-level module of luminous_sim/."""
    packages = {p.name for p in PKG.iterdir() if p.is_dir() and any(p.rglob("*.py"))}
    return packages | {p.stem for p in PKG.glob("*.py") if p.name != "__init__.py"}


def _module_names(path: Path) -> set[str]:
    """The public names a module defines or imports at its top level."""
    names: set[str] = set()
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef):
            names.add(node.name)
        elif isinstance(node, ast.Assign):
            names |= {t.id for t in node.targets if isinstance(t, ast.Name)}
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Import | ast.ImportFrom):
            names |= {(a.asname or a.name).split(".")[0] for a in node.names}
    return {n for n in names if not n.startswith("_")}


def _all(path: Path) -> list[str] | None:
    """A module's `__all__` (a literal list), or None when it has none."""
    for node in ast.parse(path.read_text()).body:
        if isinstance(node, ast.Assign):
            targets, value = node.targets, node.value
        elif isinstance(node, ast.AnnAssign) and node.value is not None:
            targets, value = [node.target], node.value
        else:
            continue
        if any(isinstance(t, ast.Name) and t.id == "__all__" for t in targets):
            return list(ast.literal_eval(value))
    return None


def _resolves(package: Path, dotted: str) -> bool:
    """Whether `module.name` (or `subpackage.module`, or `module`) exists inside a package folder."""
    path, parts = package, dotted.split(".")
    for i, part in enumerate(parts):
        if (path / part).is_dir():
            path = path / part
        elif (path / f"{part}.py").is_file():
            rest = parts[i + 1:]
            return not rest or (len(rest) == 1 and rest[0] in _module_names(path / f"{part}.py"))
        else:
            return False
    return True


def _import_graph() -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {name: set() for name in _on_disk()}
    for path in PKG.rglob("*.py"):
        if path.parent == PKG and path.name == "__init__.py":
            continue
        own = _package(path)
        for name in _imports(path):
            parts = name.split(".")
            if parts[0] == "luminous_sim" and len(parts) > 1 and parts[1] in LAYER and parts[1] != own:
                graph[own].add(parts[1])
    return graph


def test_every_package_has_a_row_with_its_layer():
    rows = _map()
    missing = sorted(_on_disk() - set(rows))
    assert not missing, f"add a row to the package map in {DOC.name} for: {missing}"
    assert set(rows) == set(LAYER), (
        f"the package map and tests/test_layering.py's LAYER differ: only in the map {sorted(set(rows) - set(LAYER))}, "
        f"only in LAYER {sorted(set(LAYER) - set(rows))}")
    wrong = [f"{k}: L{r.layer} in {DOC.name}, L{LAYER[k]} in LAYER" for k, r in rows.items() if r.layer != LAYER[k]]
    assert not wrong, "\n".join(wrong)


def test_the_layers_table_agrees_with_layer():
    text = DOC.read_text().split("## Layers", 1)[1].split("\n## ", 1)[0]
    listed: dict[str, int] = {}
    for line in text.splitlines():
        cells = _cells(line) if line.startswith("| L") else []
        if cells:
            listed |= {_key(name): _layer(cells[0]) for name in _ticked(cells[1])}
    wrong = sorted(f"{k}: L{listed.get(k, '-')} in the table, L{LAYER.get(k, '-')} in LAYER"
                   for k in set(listed) | set(LAYER) if listed.get(k) != LAYER.get(k))
    assert not wrong, f"the layers table in {DOC.name} must list LAYER's packages at their layers:\n" + "\n".join(wrong)


def test_listed_public_names_are_exported():
    problems = []
    for key, row in _map().items():
        folder, module = PKG / key, PKG / f"{key}.py"
        if not folder.is_dir() and not module.is_file():
            if row.public or "not yet written" not in row.job:
                problems.append(f"{key}: not in luminous_sim/, so its row says 'not yet written' and lists no names")
            continue
        init = folder / "__init__.py"
        exported = _all(init) if init.is_file() else _all(module) if module.is_file() else None
        if exported is None:
            defined = _module_names(module) if module.is_file() else set()
            problems += [f"{key}: {name} is not defined there" for name in row.public
                         if not (name in defined if module.is_file() else _resolves(folder, name))]
            continue
        problems += [f"{key}: {name} is not in its __all__" for name in row.public if name not in exported]
        left_out = sorted(set(exported) - set(row.public))
        if row.total is None and left_out:
            problems.append(f"{key}: the list is not shortened ('... (N)') but leaves out {left_out}")
        if row.total is not None and row.total != len(exported):
            problems.append(f"{key}: '... ({row.total})' but its __all__ has {len(exported)} names")
    assert not problems, "\n".join(problems)


def test_listed_imports_are_the_imports_now():
    graph = _import_graph()
    wrong = [f"{k}: the map lists {sorted(r.imports)}, the code imports {sorted(graph.get(k, set()))}"
             for k, r in _map().items() if set(r.imports) != graph.get(k, set())]
    assert not wrong, f"update the 'imports (now)' column in {DOC.name}:\n" + "\n".join(wrong)
