"""A build hook only: the metadata lives in pyproject.toml.

The environment specs have one copy, the top-level `envs/*.toml` (see envs/README.md). A wheel ships them
as package data, `luminous_sim/env/specs/`, copied there at build time; an editable install reads `envs/`
in place (`luminous_sim/env/registration.py`).
"""

from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

ROOT = Path(__file__).resolve().parent
SPECS_SOURCE = ROOT / "envs"
SPECS_TARGET = ("luminous_sim", "env", "specs")


class BuildPyWithSpecs(build_py):
    """`build_py` that also copies `envs/*.toml` into the built package."""

    def run(self) -> None:
        super().run()
        if getattr(self, "editable_mode", False):
            return
        sources = sorted(SPECS_SOURCE.glob("*.toml"))
        if not sources:
            raise SystemExit(f"no environment specs in {SPECS_SOURCE}: the wheel would register no ids")
        target = Path(self.build_lib, *SPECS_TARGET)
        self.mkpath(str(target))
        for src in sources:
            self.copy_file(str(src), str(target / src.name))


setup(cmdclass={"build_py": BuildPyWithSpecs})
