"""`Luminous-HouseNav-64-v1`: ObjectNav across the rooms of a house generated per episode (`house_objectnav`)."""

from __future__ import annotations

import gymnasium
import pytest
from gymnasium.utils.env_checker import check_env

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import eval_seeds
from luminous_sim.env.actions import STOP

HOUSE = "Luminous-HouseNav-64-v1"


def test_the_oracle_succeeds_in_houses_drawn_per_episode_with_starts_in_other_rooms():
    env = gymnasium.make(HOUSE).unwrapped
    try:
        plans, cross = set(), []
        for seed in (3, 4):
            _, start = env.reset(seed=seed)
            assert env.world.scene.room.house is not None and start["shortest_path_length"] >= 3.0
            assert start["start_room"] and start["target_rooms"]
            cross.append(start["cross_room"])
            plans.add(env.world.scene.room.polygon().wkt)
            while True:
                action = env.expert_action()
                _, _, terminated, truncated, info = env.step(action)
                if terminated or truncated:
                    break
            assert action == env.actions.index(STOP) and info["success"] and 0 < info["spl"] <= 1
        assert len(plans) == 2  # a house (and its floor plan) per episode
        assert any(cross)
    finally:
        env.close()
    assert eval_seeds(HOUSE)[0] == 1_000_000


@pytest.mark.slow
def test_check_env_is_clean_on_the_house_id():
    env = gymnasium.make(HOUSE)
    try:
        check_env(env.unwrapped, skip_render_check=True)
    finally:
        env.close()


def test_v2_houses_have_a_front_door_and_v1_keeps_its_houses_without_one():
    from luminous_sim.env.kinds import task_kind

    kind = task_kind("house_objectnav")
    v1 = kind.configured(dict(gymnasium.spec(HOUSE).kwargs["task_options"])).generate_scene("LivingRoom", 5)
    v2 = kind.configured(dict(gymnasium.spec("Luminous-HouseNav-64-v2").kwargs["task_options"])).generate_scene(
        "LivingRoom", 5)
    assert not v1.room.doors and len(v2.room.doors) == 1
    assert v1.to_json() != v2.to_json()
