"""Worlds reused across episodes in one scene: the same observations, rewards and infos as in a new env, and
no new build where the world could be put back (`WorldPool`, `World.reset_to_start`)."""

from __future__ import annotations

import gymnasium
import numpy as np

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import LuminousEnv

OBS = {"depth": True, "segmentation": True, "pose": True, "inventory": True}


def make(env_id: str) -> LuminousEnv:
    return gymnasium.make(env_id, max_steps=40, **OBS).unwrapped


def same_obs(a: dict, b: dict) -> bool:
    return a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) if isinstance(a[k], np.ndarray) else a[k] == b[k]
                                        for k in a)


def play(env: LuminousEnv, actions: list) -> list:
    """Each step's observation, reward, terminated, truncated and info."""
    out = []
    for a in actions:
        obs, reward, terminated, truncated, info = env.step(a)
        out.append((obs, reward, terminated, truncated, info))
        if terminated or truncated:
            break
    return out


def episode_actions(env: LuminousEnv, seed: int) -> list:
    """The expert's actions, in the env's action form, with a few turns and looks there and back between them."""
    rng = np.random.default_rng(seed)
    detours = [("RotateLeft", "RotateRight"), ("LookUp", "LookDown"), ("RotateRight", "RotateLeft")]
    acts: list = []
    for api in env.episode.expert.actions:
        acts.append(env.action_for(api))
        if rng.random() < 0.3:
            acts += [env.actions.index(name) for name in detours[int(rng.integers(len(detours)))]]
    return acts


def check_reuse(env_id: str, first_seed: int, seed: int) -> tuple[LuminousEnv, int]:
    """Play an episode of navigation in a scene, then an episode drawn with `seed` in the same scene; compare
    it with the same episode in a new env. The used env and its builds before the second reset."""
    used = make(env_id)
    used.reset(seed=first_seed)
    scene = used.episode.scene
    play(used, [int(a) for a in np.random.default_rng(0).integers(5, size=8)])  # looks and walks only
    builds = used.worlds.builds
    new = make(env_id)
    obs_new, info_new = new.reset(seed=seed, options={"scene": scene})
    obs_used, info_used = used.reset(seed=seed, options={"scene": scene})
    assert same_obs(obs_new, obs_used) and info_new == info_used
    actions = episode_actions(new, seed)
    a, b = play(new, actions), play(used, actions)
    assert len(a) == len(b) and a[-1][4]["success"]
    for (oa, *rest_a), (ob, *rest_b) in zip(a, b, strict=True):
        assert same_obs(oa, ob) and rest_a == rest_b
    new.close()
    return used, builds


def test_a_reused_world_gives_the_same_episode_and_is_not_rebuilt():
    env, builds = check_reuse("Luminous-NavToObject-64-v1", 3, 11)
    assert env.worlds.builds == builds and env.worlds.reuses >= 2  # the agent's world and the expert's proof
    assert env.worlds.kept == 1  # the expert's world waits for the next episode beside the agent's
    env.close()


def test_a_touched_world_is_rebuilt_and_the_episode_is_still_the_same():
    env, builds = check_reuse("Luminous-PickUp-64-v1", 3, 11)
    assert env.worlds.reuses >= 1  # the agent's world (it only walked)
    assert env.worlds.builds == builds + 1  # the expert's proof picked something up: a new world
    assert env.worlds.kept == 0  # and that world could not be put back at its start
    env.close()


def test_the_expert_replans_in_kept_worlds_with_the_same_advice():
    a = gymnasium.make("Luminous-NavToObject-64-v1", expert_in_info=True).unwrapped
    b = gymnasium.make("Luminous-NavToObject-64-v1", expert_in_info=True).unwrapped
    a.reset(seed=5)
    scene = a.episode.scene
    first = a.reset(seed=6, options={"scene": scene})[1]
    assert first == b.reset(seed=6, options={"scene": scene})[1]
    for action in (1, 1, 0, 3, 2):  # off the expert's path: it replans in a shadow world
        step = a.step(action)
        assert step[1:] == b.step(action)[1:]
        if step[2] or step[3]:  # the goal came into view (a step after the end raises)
            break
    assert a.expert.replans == b.expert.replans >= 1
    a.close(), b.close()
