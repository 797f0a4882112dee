"""Rooms generated to support a task type."""

from __future__ import annotations

import pytest

from luminous_sim.data import scene_for_task
from luminous_sim.tasks import TaskSamplingError, feasible_params, state_from_scene


@pytest.mark.parametrize(("task_type", "room"), [("pick_two_obj_and_place", "Bedroom"),
                                                  ("pick_two_obj_and_place", "Bathroom"),
                                                  ("pick_heat_then_place_in_recep", "Kitchen")])
def test_scene_for_task_supports_the_task(task_type, room):
    scene = scene_for_task(task_type, room, seed=5)
    assert scene.room.room_type == room
    assert feasible_params(scene, state_from_scene(scene), task_type)
    again = scene_for_task(task_type, room, seed=5)
    assert again.model_dump_json() == scene.model_dump_json()


def test_scene_for_task_refuses_a_room_type_the_task_excludes():
    with pytest.raises(TaskSamplingError, match="Bathroom"):
        scene_for_task("pick_heat_then_place_in_recep", "Bathroom", seed=1)
