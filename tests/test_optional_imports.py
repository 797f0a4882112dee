"""The optional extras (torch, stable-baselines3, Minari, usd-core, MuJoCo, viser) load only when a command that
needs them runs: importing the package, its data layer, the export and viewer packages and the whole `luminous`
parser loads none of them."""

from __future__ import annotations

import subprocess
import sys

from tests.conftest import REPO

OPTIONAL = ("torch", "stable_baselines3", "minari", "h5py", "pxr", "mujoco", "viser", "playwright")


def test_the_package_and_the_cli_load_no_optional_extra():
    code = ("import sys, luminous_sim, luminous_sim.data, luminous_sim.env, luminous_sim.export, luminous_sim.viewer; "
            "from luminous_sim.cli.main import build_parser; build_parser(); "
            f"print(sorted(m for m in {OPTIONAL!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "[]"
