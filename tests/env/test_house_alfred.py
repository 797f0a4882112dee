"""`Luminous-HouseALFRED-v1`: ALFRED's task types in a house generated per episode, crossing rooms for a share."""

from __future__ import annotations

import gymnasium
import pytest
from gymnasium.utils.env_checker import check_env

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env import LuminousEnv
from luminous_sim.tasks import object_rooms

HOUSE_ALFRED = "Luminous-HouseALFRED-v1"


def _small(**over) -> LuminousEnv:
    return gymnasium.make(HOUSE_ALFRED, width=96, height=96, **over).unwrapped


def test_the_expert_solves_alfred_tasks_in_houses_some_across_rooms():
    env = _small(task_types=["pick_and_place_simple"], task_options={"house": 1.0, "cross_room_share": 1.0})
    try:
        for seed in (1, 2):
            _, info = env.reset(seed=seed)
            scene = env.episode.scene
            assert scene.room.house is not None and len(scene.room.house.rooms) == 4
            params = env.episode.goal.task.params
            rooms = object_rooms(scene)
            state = env.world.view().state
            here = {rooms[o] for o, s in state.objects.items() if s.object_type == params.object_target and o in rooms}
            there = {rooms[o] for o, s in state.objects.items() if s.object_type == params.parent_target and o in rooms}
            assert here and there and not here & there, "cross_room_share 1: the object is in another room"
            done = False
            while not done:
                _, _, terminated, truncated, info = env.step(env.expert_action())
                done = terminated or truncated
            assert info["success"]
    finally:
        env.close()


def test_the_id_plays_alfreds_types_in_houses_at_alfreds_camera():
    spec = gymnasium.spec(HOUSE_ALFRED)
    assert spec.kwargs["task_options"] == {"house": 1.0, "cross_room_share": 0.5}
    assert (spec.kwargs["width"], spec.kwargs["max_steps"], spec.kwargs["max_failures"]) == (300, 1000, 10)
    assert len(spec.kwargs["task_types"]) == 7


@pytest.mark.slow
def test_check_env_is_clean_on_the_house_alfred_id():
    env = _small()
    try:
        check_env(env, skip_render_check=True)
    finally:
        env.close()
