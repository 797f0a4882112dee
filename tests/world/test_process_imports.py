"""A World process (generate a scene, build its World, render a frame) loads no scipy: scipy.ndimage alone
costs a process about 28 MB, and a World process has 150 MB (issue 16)."""

from __future__ import annotations

import subprocess
import sys

from tests.conftest import REPO


def test_a_world_process_loads_no_scipy():
    code = ("import sys\n"
            "from luminous_sim.cssg import empty_cdf, generate\n"
            "from luminous_sim.world import World, WorldConfig\n"
            "scene = generate(empty_cdf('Kitchen'), seed=0).scene\n"
            "with World(scene, WorldConfig(width=64, height=64)) as world:\n"
            "    world.frame(); world.visible_objects()\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('scipy', 'trimesh', 'torch')))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "[]"
