"""The `goal_mask` observation: 255 exactly on the pixels of the goal type's objects, for navigation and ALFRED
goals, through a whole oracle episode."""

from __future__ import annotations

import gymnasium
import numpy as np

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env.alfred_env import LuminousEnv
from luminous_sim.env.goal_mask import goal_type


def _expected(env: LuminousEnv) -> np.ndarray:
    """The mask from the segmentation and the objects' types, the long way."""
    assert env.world is not None
    state = env.world.view().state
    ids = env.world.instance_ids()
    out = np.zeros(ids.shape, dtype=np.uint8)
    for body, oid in env.world.body_to_object().items():
        if oid in state.objects and state.objects[oid].object_type == env._goal_type:
            out[ids == body] = 255
    return out[..., None]


def test_goal_mask_follows_the_target_through_an_objectnav_episode():
    env = gymnasium.make("Luminous-ObjectNav-64-v2", goal_mask=True).unwrapped
    assert isinstance(env, LuminousEnv)
    obs, _ = env.reset(seed=1_000_000)
    assert env.observation_space["goal_mask"].contains(obs["goal_mask"])
    assert goal_type(env.episode.goal) == env.episode.goal.object_type  # type: ignore[union-attr]
    shown = []
    done = False
    while not done:
        np.testing.assert_array_equal(obs["goal_mask"], _expected(env))
        shown.append(int((obs["goal_mask"] > 0).sum()))
        obs, _, terminated, truncated, info = env.step(env.expert_action())
        done = terminated or truncated
    assert info["success"]
    assert shown[-1] > 0  # the oracle stops with the target in view, so the mask shows it
    assert min(shown) < shown[-1]
    env.close()


def test_goal_mask_of_an_alfred_task_is_its_object_target():
    env = gymnasium.make("Luminous-ALFRED-PickPlace-v2", goal_mask=True, width=64, height=64).unwrapped
    assert isinstance(env, LuminousEnv)
    env.reset(seed=3)
    task = env.episode.goal.task  # type: ignore[union-attr]
    assert goal_type(env.episode.goal) == task.params.object_type != ""  # type: ignore[union-attr]
    for _ in range(60):
        obs, _, terminated, truncated, _ = env.step(env.expert_action())
        np.testing.assert_array_equal(obs["goal_mask"], _expected(env))
        if terminated or truncated:
            break
    env.close()
