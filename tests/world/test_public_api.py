"""The world's public face: the names `luminous_sim.world` exports, the read-only view, scene set-up
before the first step, and no import circle between the World and its interaction modules."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import luminous_sim.language
import luminous_sim.planning
import luminous_sim.world
from luminous_sim.errors import LuminousError
from luminous_sim.world import WorldView
from tests.world.conftest import obj

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("package", [luminous_sim.world, luminous_sim.planning, luminous_sim.language])
def test_every_exported_name_resolves(package):
    assert package.__all__ and all(getattr(package, name) is not None for name in package.__all__)


def test_the_interaction_modules_do_not_import_the_world_module():
    code = ("import sys, luminous_sim.world.interaction, luminous_sim.world.placement, luminous_sim.world.view; "
            "sys.exit('luminous_sim.world.world' in sys.modules)")
    assert subprocess.run([sys.executable, "-c", code], check=False, cwd=REPO).returncode == 0


def test_the_view_is_a_world_view_and_queries_leave_the_world_as_it_was(world, kitchen_scene):
    view = world.view()
    assert isinstance(view, WorldView) and world.view() is view
    apple = obj(kitchen_scene, "apple")
    agent, state = view.agent, view.state
    poses = {k: view.pose(k)[0].tolist() for k in view.body_ids()}
    pose = view.interaction_pose(apple)
    assert pose is not None and apple not in view.unseeable()
    assert view.agent == agent and view.state == state
    assert {k: view.pose(k)[0].tolist() for k in view.body_ids()} == poses


def test_set_up_dirty_is_scene_set_up_before_the_first_step(world, kitchen_scene):
    apple, plate = obj(kitchen_scene, "apple"), obj(kitchen_scene, "plate")
    world.set_up_dirty([plate, "Nope|1"])  # ids that are not objects are skipped
    assert world.view().state.objects[plate].isDirty and not world.view().state.objects[apple].isDirty
    world.step("Pass")
    with pytest.raises(LuminousError, match="before the first"):
        world.set_up_dirty([apple])
    assert not world.view().state.objects[apple].isDirty


def test_set_start_is_scene_set_up_before_the_first_step(world):
    from luminous_sim.world import AgentPose

    default = world.agent
    x, y = (float(v) for v in world.nav.points()[0])
    start = AgentPose(x, y, 90, 0)
    before = world.frame().rgb.copy()
    world.set_start(start)
    assert world.agent == world.view().agent == start
    assert not np.array_equal(world.frame().rgb, before)  # rendered anew from the start, not the old frame
    world.step("RotateLeft")
    with pytest.raises(LuminousError, match="before the first World.step"):
        world.set_start(start)
    assert world.agent == start.rotated(-1)
    assert world.reset_to_start() and world.agent == default  # the start as built; set-up allowed again
    world.set_start(start)
    assert world.agent == start
