"""Scenes from CDF files: `gymnasium.make(id, cdf=path)` or `reset(options={"cdf": path})`; a CDF's own task is
the goal (with its initial states and agent start), else a task of the env's types is drawn."""

from __future__ import annotations

from pathlib import Path

import gymnasium
import numpy as np
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim import cdf
from luminous_sim.episodes import cdf_scene
from luminous_sim.errors import LuminousError
from luminous_sim.tasks import names_from_scene, task_from_cdf

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples"
APPLE = str(EXAMPLES / "kitchen_apple_fridge.yaml")
SOAP = EXAMPLES / "bathroom_soap.yaml"
SMALL = {"width": 64, "height": 64, "grid": 3}


def no_task(tmp_path: Path) -> str:
    """The bathroom of the soap example without its task section."""
    text = SOAP.read_text()
    path = tmp_path / "bathroom_no_task.yaml"
    path.write_text(text[: text.index("task:")])
    return str(path)


def test_a_cdf_task_is_the_goal_with_its_initial_state_and_agent_start():
    env = gymnasium.make("Luminous-ALFRED-v1", cdf=APPLE, **SMALL).unwrapped
    _, info = env.reset(seed=0)
    scene, goal = env.episode.scene, env.episode.goal
    doc = cdf.load(APPLE)
    assert {o.name for o in scene.objects} >= {"counter", "fridge", "apple"}
    expected = task_from_cdf(doc, names_from_scene(scene), scene_seed=scene.seed)
    assert goal.task.goal == expected.goal and goal.task.custom
    assert (env.world.agent.rotation, env.world.agent.horizon) == (90, 30)  # task.agent
    fridge = names_from_scene(scene)["fridge"]
    assert not env.world.view().state.objects[fridge].isOpen  # task.initial
    assert info["redraws"] >= 0 and env.episode.expert is not None
    for action in env.episode.expert.actions:  # the proved plan reaches the CDF's goal
        _, _, terminated, _, info = env.step(env.action_for(action))
        if terminated:  # the goal may hold before the plan's last action (a step after the end raises)
            break
    assert terminated and info["success"]
    env.close()


def test_a_cdf_without_a_task_gets_a_task_of_the_env_and_a_fixed_scene_seed_reuses_the_world(tmp_path):
    path = no_task(tmp_path)
    env = gymnasium.make("Luminous-PickUp-64-v1").unwrapped
    env.reset(seed=1, options={"cdf": path, "scene_seed": 3})
    assert env.episode.scene is cdf_scene(path, 3) and env.episode.goal.task_type == "pickup_object"
    assert {o.name for o in env.episode.scene.objects} >= {"soap", "towel", "toilet"}
    builds = env.worlds.builds
    other = gymnasium.make("Luminous-PickUp-64-v1").unwrapped
    obs_a, info_a = env.reset(seed=2, options={"cdf": path, "scene_seed": 3})
    obs_b, info_b = other.reset(seed=2, options={"cdf": path, "scene_seed": 3})
    assert env.worlds.reuses >= 1 and env.worlds.builds <= builds + 1  # the agent's world at least
    assert np.array_equal(obs_a["rgb"], obs_b["rgb"]) and info_a == info_b
    env.close(), other.close()


def test_bad_cdf_input_is_a_clear_error(tmp_path):
    with pytest.raises(LuminousError, match="nope.yaml: no such CDF file"):
        gymnasium.make("Luminous-PickUp-64-v1", cdf="nope.yaml")
    with pytest.raises(LuminousError, match="split or cdf"):
        gymnasium.make("Luminous-PickUp-64-v1", cdf=APPLE, split="S+")
    bad = tmp_path / "bad.yaml"
    bad.write_text("cdf_version: 2\nname: bad\nscene: {room_type: Kitchen, objects: [{name: a, type: Unicorn}]}\n")
    env = gymnasium.make("Luminous-PickUp-64-v1").unwrapped
    with pytest.raises(LuminousError, match="bad.yaml"):
        env.reset(seed=0, options={"cdf": str(bad)})
    with pytest.raises(LuminousError, match="one of 'scene'"):
        env.reset(seed=0, options={"cdf": APPLE, "scene": object()})
    env.close()
