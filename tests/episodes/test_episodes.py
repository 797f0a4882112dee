"""The episodes package: one spec, ALFRED's set-up in one place, one expert check, and the old paths of moved
names still working (with a warning) for one release."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

from luminous_sim.benchmark import benchmark_entry
from luminous_sim.episodes import (
    EpisodeSpec,
    FreshWorlds,
    TaskGoal,
    alfred_set_up,
    entry_spec,
    keyed,
    prepare,
    solve,
)
from luminous_sim.errors import LuminousError
from luminous_sim.world import AgentPose, World

PKG = Path(__file__).resolve().parents[2] / "luminous_sim"
CLEANING = "pick_clean_then_place_in_recep"


@pytest.fixture(scope="module")
def spec() -> EpisodeSpec:
    """U+ entry 0 (a pick-and-place in a kitchen layout)."""
    return entry_spec(benchmark_entry("U+", 0))


class CountingWorlds(FreshWorlds):
    def __init__(self):
        super().__init__()
        self.out = 0

    def get(self, scene, dirty=(), start=None):
        self.out += 1
        return super().get(scene, dirty, start)

    def put(self, world):
        self.out -= 1
        super().put(world)


def test_a_split_entry_is_a_keyed_spec_of_its_task(spec):
    entry = benchmark_entry("U+", 0)
    assert spec.key == entry.episode_key and spec.start == entry.start
    assert spec.task.params.to_json() == entry.pddl_params
    assert keyed(spec, AgentPose(0, 0, 0, 0)) is spec  # a keyed spec keeps its key


def test_alfred_set_up_makes_dirty_only_for_cleaning_and_prepare_applies_the_spec(spec):
    world = World(spec.scene)
    try:
        assert alfred_set_up(world, "pick_and_place_simple") == ()
        dirty = alfred_set_up(world, CLEANING)
        state = world.view().state
        assert dirty and all(state.objects[o].isDirty for o in dirty)
    finally:
        world.close()
    world = prepare(World(spec.scene), spec)
    try:
        assert world.agent == spec.start
    finally:
        world.close()


def test_solve_proves_a_solvable_spec_and_gives_every_world_back(spec):
    worlds = CountingWorlds()
    solution = solve(spec, worlds)
    assert solution.cause == "" and solution.plan is not None and solution.plan.exact
    assert solution.plan.steps and worlds.out == 0


def test_solve_names_why_the_expert_fails(spec):
    """Negative control: the task's object removed from the scene, the oracle fails and says why."""
    target = spec.task.params.object_target
    scene = spec.scene.model_copy(update={"objects": [o for o in spec.scene.objects if o.type != target]})
    worlds = CountingWorlds()
    solution = solve(EpisodeSpec(scene, spec.goal, spec.dirty, start=spec.start), worlds)
    assert solution.plan is None and solution.cause and worlds.out == 0


def test_a_goal_that_is_no_task_has_no_task():
    class Nav:
        task_type = "objectnav"

    with pytest.raises(LuminousError, match="objectnav episode's goal is not a task"):
        _ = EpisodeSpec(None, Nav()).task  # type: ignore[arg-type]


def test_alfreds_set_up_is_written_once():
    """Only `episodes.initial_state` makes objects dirty for an episode (the world defines how)."""
    callers = []
    for path in sorted(PKG.rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr in ("set_up_dirty", "alfred_dirty")):
                callers.append(path.relative_to(PKG).as_posix())
    assert sorted(set(callers)) == ["episodes/initial_state.py"]


@pytest.mark.parametrize(("old", "name", "new"), [
    ("luminous_sim.env.goals", "TaskGoal", "luminous_sim.episodes"),
    ("luminous_sim.env.goals", "ExpertPlan", "luminous_sim.episodes"),
    ("luminous_sim.benchmark", "entry_episode", "luminous_sim.episodes.split"),
    ("luminous_sim.benchmark", "SplitVersionError", "luminous_sim.episodes"),
    ("luminous_sim.benchmark", "BenchmarkEpisode", "luminous_sim.episodes"),
    ("luminous_sim.env.cdf_scenes", "cdf_scene", "luminous_sim.episodes"),
    ("luminous_sim.env.cdf_scenes", "cdf_paths", "luminous_sim.env.episodes"),
    ("luminous_sim.env.episodes", "UNAVAILABLE_CAUSES", "luminous_sim.episodes"),
    ("luminous_sim.env.episodes", "EpisodeUnavailable", "luminous_sim.episodes"),
])
def test_an_old_path_warns_and_gives_the_moved_name(old, name, new):
    import importlib

    with pytest.warns(DeprecationWarning, match=f"{old}.{name} moved to {new}.{name}"):
        got = getattr(importlib.import_module(old), name)
    assert got is getattr(importlib.import_module(new), name)


def test_the_old_freeze_command_warns_and_runs():
    done = subprocess.run([sys.executable, "-W", "always::DeprecationWarning", "-m", "luminous_sim.benchmark.freeze",
                           "--help"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "moved to python -m luminous_sim.episodes.freeze" in done.stderr
    assert "usage: python -m luminous_sim.episodes.freeze" in done.stdout


def test_the_entry_spec_goal_is_a_task_goal(spec):
    assert isinstance(spec.goal, TaskGoal)
