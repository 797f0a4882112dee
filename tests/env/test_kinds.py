"""Task kinds: one registry (`env.kinds.KINDS`) that `EnvConfig` checks against, one `TaskKind` per kind with
fixed hooks (rooms, set-up, goal drawing, reading a goal back)."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from luminous_sim.env import EnvConfig
from luminous_sim.env.kinds import KINDS, TASK_KINDS, TaskKind, goal_from_dict, kind_templates, task_kind
from luminous_sim.errors import LuminousError
from luminous_sim.tasks import task_info
from luminous_sim.vocab import ALFRED_TASK_TYPES, ROOM_TYPES
from tests.conftest import REPO


def test_every_registered_kind_is_a_task_kind_and_the_config_accepts_exactly_those():
    assert TASK_KINDS == tuple(KINDS) == ALFRED_TASK_TYPES + ("goto_object", "pickup_object", "objectnav",
                                                              "objectnav_pickup", "house_objectnav")
    for name in TASK_KINDS:
        kind = task_kind(name)
        assert isinstance(kind, TaskKind) and kind.name == name and task_kind(name) is kind
        assert set(kind.rooms()) <= set(ROOM_TYPES) and kind.rooms()
    assert EnvConfig(task_types=TASK_KINDS).task_types == TASK_KINDS
    with pytest.raises(LuminousError, match="task_types"):
        EnvConfig(task_types=("sweep_floor",))
    with pytest.raises(LuminousError, match="sweep_floor"):
        task_kind("sweep_floor")


def test_alfred_kinds_keep_alfreds_room_table_and_the_small_kinds_play_everywhere():
    for name in ALFRED_TASK_TYPES:
        assert task_kind(name).rooms() == tuple(sorted(task_info(name).rooms))
    for name in ("goto_object", "pickup_object", "objectnav", "objectnav_pickup"):
        assert task_kind(name).rooms() == ROOM_TYPES
    assert kind_templates() == ("go to the {obj}", "pick up the {obj}", "find the {obj}")


def test_goals_read_back_from_their_data():
    from luminous_sim.env.kinds.goto_object import GotoGoal
    from luminous_sim.env.kinds.pickup_object import pickup_task

    goto = goal_from_dict(GotoGoal("Mug").to_dict())
    assert isinstance(goto, GotoGoal) and goto.object_type == "Mug" and goto.instruction == "go to the mug"
    from luminous_sim.episodes import TaskGoal

    task = goal_from_dict(TaskGoal(pickup_task("Apple", 3)).to_dict())
    assert task.task_type == "pickup_object" and task.instruction == "pick up the apple"


def test_the_registry_loads_no_kind_module_nor_the_simulator():
    code = ("import sys, luminous_sim.env.config; "
            "print(sorted(m for m in sys.modules if m.startswith('luminous_sim.env.kinds.') "
            "or m in ('luminous_sim.world', 'pybullet')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "['luminous_sim.env.kinds.base', 'luminous_sim.env.kinds.options']"  # declarations


def test_the_cleaning_kind_makes_what_it_cleans_dirty_first():
    from luminous_sim.cssg import empty_cdf, generate
    from luminous_sim.env.worlds import WorldPool

    scene = generate(empty_cdf("Kitchen"), seed=0).scene
    pool = WorldPool(EnvConfig(width=64, height=64))
    world = pool.get(scene)
    try:
        dirty = task_kind("pick_clean_then_place_in_recep").set_up(world)
        assert dirty and task_kind("pick_and_place_simple").set_up(world) == ()
        state = world.view().state
        assert all(state.objects[o].object_type for o in dirty)
        goal = task_kind("pickup_object").draw_goal(world, scene, np.random.default_rng(0))
        assert goal.task_type == "pickup_object"
    finally:
        world.close()
