"""Shared fixtures and helpers for the test suite."""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

import pytest

REPO = Path(__file__).resolve().parents[1]
SHARED_ALFRED = REPO.parent / "shared" / "alfred"


@pytest.fixture(autouse=True, scope="session")
def _own_cache(tmp_path_factory) -> Iterator[None]:
    """Canonical builds made by tests go to a temporary cache, never the user's `~/.cache/luminous`."""
    old = os.environ.get("LUMINOUS_CACHE")
    os.environ["LUMINOUS_CACHE"] = str(tmp_path_factory.mktemp("cache"))
    yield
    if old is None:
        os.environ.pop("LUMINOUS_CACHE", None)
    else:
        os.environ["LUMINOUS_CACHE"] = old


@pytest.fixture(scope="session")
def shared_alfred() -> Path:
    """The real ALFRED data beside the repository; tests that need it skip with a reason when absent."""
    if not SHARED_ALFRED.exists():
        pytest.skip(f"ALFRED sample data not found at {SHARED_ALFRED}")
    return SHARED_ALFRED


UPLUS_BUILT = 7
"""U+ entries in the shared build (`uplus_build`): one of every task type."""


@pytest.fixture(scope="session")
def uplus_build(tmp_path_factory) -> Path:
    """A canonical U+ build of the first `UPLUS_BUILT` entries without frames, made once per test run and shared
    by every test (and xdist worker) that reads it; tests copy what they change, never edit it."""
    from filelock import FileLock

    from luminous_sim.data import BuildOptions, build_split

    base = tmp_path_factory.getbasetemp()
    root = base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base  # the run's folder, shared by its workers
    out, done = root / "uplus-build", root / "uplus-build.done"
    with FileLock(str(root / "uplus-build.lock")):
        if not done.is_file():
            report = build_split(out, "U+", UPLUS_BUILT, options=BuildOptions(frames=False, video=False),
                                 progress=False)
            assert report.built == UPLUS_BUILT, report.summary()
            done.write_text("")
    return out


def load_script(relative: str) -> Iterator[ModuleType]:
    """A script of the repository (`benchmarks/x.py`, `examples/x.py`) imported under its file's name for
    as long as the generator is suspended: `yield from load_script(...)` in a fixture."""
    path = REPO / relative
    spec = importlib.util.spec_from_file_location(path.stem, path)
    assert spec is not None and spec.loader is not None, f"cannot import {path}"
    module = importlib.util.module_from_spec(spec)
    sys.modules[path.stem] = module
    try:
        spec.loader.exec_module(module)
        yield module
    finally:
        del sys.modules[path.stem]


def file_tree(root: Path) -> dict[str, str]:
    """Every file and link under `root` (relative path -> sha256 of its content, or of the link's target)."""
    out = {}
    for p in sorted(root.rglob("*")):
        if p.is_symlink():
            out[p.relative_to(root).as_posix()] = "link:" + os.readlink(p)
        elif p.is_file():
            out[p.relative_to(root).as_posix()] = hashlib.sha256(p.read_bytes()).hexdigest()
    return out
