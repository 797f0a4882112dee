"""The wheel holds everything the package reads at run time: every data file of the source tree (each FloorPlan
room, every file the asset catalog lists, the schemas, the example CDFs, the frozen manifests, the shipped
checkpoints, the env specs), and its metadata is a release's (SPDX licence, version). No module finds data
relative to the source tree. (`.ci/run`'s release check installs the wheel and runs it from outside the
repository: scripts/release_check.sh.)"""

from __future__ import annotations

import json
import re
import subprocess
import sys
import zipfile
from email.parser import Parser
from pathlib import Path

import pytest

from luminous_sim import __version__
from luminous_sim.resources import examples_dir, room_library_dir, schema_dir, shipped_asset_library_dir
from tests.conftest import REPO

PKG = REPO / "luminous_sim"
NOT_DATA = {".py", ".pyc", ".lock"}


@pytest.fixture(scope="module")
def wheel(tmp_path_factory) -> zipfile.ZipFile:
    out = tmp_path_factory.mktemp("wheel")
    done = subprocess.run([sys.executable, "-m", "build", "--wheel", "--no-isolation", "--outdir", str(out), str(REPO)],
                          capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert "BuildBackendWarning" not in done.stdout + done.stderr, "the build warns"
    (path,) = out.glob("*.whl")
    return zipfile.ZipFile(path)


def _tracked_data() -> list[str]:
    """Every data file of the package's source tree (tracked by git), relative to the repository."""
    listed = subprocess.run(["git", "ls-files", "-z", "luminous_sim", "envs"], cwd=REPO, capture_output=True,
                            check=True).stdout.decode().split("\0")
    return sorted(p for p in listed if p and Path(p).suffix not in NOT_DATA)


def test_every_data_file_of_the_source_tree_is_in_the_wheel(wheel):
    names = set(wheel.namelist())
    wanted = [f"luminous_sim/env/specs/{Path(p).name}" if p.startswith("envs/") else p
              for p in _tracked_data() if not p.endswith(".md")]
    assert len(wanted) > 3600
    missing = [p for p in wanted if p not in names]
    assert not missing, f"{len(missing)} data files are not in the wheel, e.g. {missing[:5]}"


def test_the_wheel_holds_each_kind_of_data_by_name(wheel):
    names = set(wheel.namelist())

    def rel(path: Path) -> str:
        return path.resolve().relative_to(REPO.resolve()).as_posix()

    rooms = sorted(room_library_dir().rglob("FloorPlan*.json"))
    assert len(rooms) == 120 and all(rel(p) in names for p in rooms)
    library = shipped_asset_library_dir()
    catalog = json.loads((library / "catalog.json").read_text())
    listed = {f for a in catalog["assets"] for f in (*a["files"], a["urdf"], a["lod_urdf"]) if f}
    assert rel(library / "catalog.json") in names
    assert not [f for f in listed if rel(library / f) not in names]
    for folder in (schema_dir(), examples_dir()):
        files = [p for p in folder.rglob("*") if p.is_file()]
        assert files and all(rel(p) in names for p in files)
    for path in ("luminous_sim/benchmark/data/S+.jsonl", "luminous_sim/benchmark/data/U+.jsonl",
                 "luminous_sim/layouts/data/learned_layouts.pt", "luminous_sim/env/specs/alfred.toml",
                 "luminous_sim/agents/data/instruction_parser.pt"):
        assert path in names, path
    assert [p for p in names if p.endswith(".pt")], "the shipped checkpoints"


def test_the_metadata_is_a_releases(wheel):
    (meta,) = [n for n in wheel.namelist() if n.endswith(".dist-info/METADATA")]
    fields = Parser().parsestr(wheel.read(meta).decode())
    assert fields["Version"] == __version__ == "0.2.0"
    assert fields["License-Expression"] == "MIT"
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in wheel.namelist())
    assert fields["Requires-Python"]
    extras = set(fields.get_all("Provides-Extra") or [])
    assert {"export", "view", "test", "learn"} <= extras


def test_no_module_finds_data_relative_to_the_source_tree():
    """Data is found through luminous_sim.resources (package data), never `Path(__file__).parents[N]`; the two
    allowed: the env registration's fallback to `envs/` in a checkout, and the thor shim's package root."""
    allowed = {"env/registration.py", "thor/shim.py"}
    offenders = []
    for path in sorted(PKG.rglob("*.py")):
        rel = path.relative_to(PKG).as_posix()
        if rel in allowed:
            continue
        for i, line in enumerate(path.read_text().splitlines(), 1):
            if re.search(r"\.parents\[\d\]|\.parent\.parent\.parent", line):
                offenders.append(f"{rel}:{i}: {line.strip()}")
    assert not offenders, "\n".join(offenders)
