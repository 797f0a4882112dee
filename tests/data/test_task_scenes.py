"""Rooms generated to support a task type: some task of the type is feasible and fits physically."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.data import scene_for_task, task_scenes
from luminous_sim.planning import draw_task
from luminous_sim.tasks import TaskSamplingError, feasible_params, state_from_scene
from luminous_sim.world import World


def _fits(scene, task_type: str) -> None:
    """The episode's own test finds a task, whatever the draw's seed."""
    with World(scene) as world:
        for seed in (1, 7):
            task = draw_task(scene, world.view(), task_type, np.random.default_rng(seed))
            assert task.task_type == task_type


@pytest.mark.parametrize(("task_type", "room"), [("pick_two_obj_and_place", "Bedroom"),
                                                  ("pick_two_obj_and_place", "Bathroom"),
                                                  ("pick_heat_then_place_in_recep", "Kitchen")])
def test_scene_for_task_supports_the_task(task_type, room):
    scene = scene_for_task(task_type, room, seed=5)
    assert scene.room.room_type == room
    assert feasible_params(scene, state_from_scene(scene), task_type)
    _fits(scene, task_type)
    again = scene_for_task(task_type, room, seed=5)
    assert again.model_dump_json() == scene.model_dump_json()


@pytest.mark.parametrize(("task_type", "room", "seed"), [("pick_and_place_with_movable_recep", "Bedroom", 0),
                                                          ("pick_two_obj_and_place", "LivingRoom", 0)])
def test_a_task_fits_physically_where_only_a_symbolic_one_did(task_type, room, seed):
    """The first default Bedroom of seed 0 holds movable-receptacle tasks only symbolically (a bowl or
    a mug on a side table with room for neither): that room is passed over for one where a task fits."""
    scene = scene_for_task(task_type, room, seed)
    _fits(scene, task_type)
    assert scene_for_task(task_type, room, seed).model_dump_json() == scene.model_dump_json()


def test_default_rooms_that_do_not_fit_give_way_to_a_room_generated_for_a_task(monkeypatch):
    real = task_scenes.physical_misfit
    tried = []

    def only_generated(scene, task_type, catalog=None):
        tried.append(scene.source)
        return "no room (default rooms refused by the test)" if not scene.source else real(scene, task_type, catalog)

    monkeypatch.setattr(task_scenes, "physical_misfit", only_generated)
    scene = scene_for_task("pick_and_place_simple", "Bedroom", seed=3)
    assert scene.source and tried[:task_scenes.DEFAULT_ROOM_TRIES] == [""] * task_scenes.DEFAULT_ROOM_TRIES
    monkeypatch.undo()
    _fits(scene, "pick_and_place_simple")
    monkeypatch.setattr(task_scenes, "physical_misfit", only_generated)
    assert scene_for_task("pick_and_place_simple", "Bedroom", seed=3).model_dump_json() == scene.model_dump_json()


def test_a_room_where_nothing_fits_physically_is_rejected(monkeypatch):
    tried = []

    def nothing_fits(scene, task_type, catalog=None):
        tried.append(scene)
        return "no free spot (test)"

    monkeypatch.setattr(task_scenes, "physical_misfit", nothing_fits)
    with pytest.raises(TaskSamplingError) as info:
        scene_for_task("pick_and_place_simple", "Bedroom", seed=4)
    message = str(info.value)
    for part in ("pick_and_place_simple", "Bedroom", "seed 4", "no free spot (test)", "default room 0"):
        assert part in message
    assert len(tried) <= task_scenes.DEFAULT_ROOM_TRIES + task_scenes.TASK_DRAWS  # bounded
    assert sum(bool(s.source) for s in tried) > 0  # rooms generated for drawn tasks were tried too


def test_scene_for_task_refuses_a_room_type_the_task_excludes():
    with pytest.raises(TaskSamplingError, match="Bathroom"):
        scene_for_task("pick_heat_then_place_in_recep", "Bathroom", seed=1)


# issue 14: a named room and a given task
def test_scene_for_task_in_a_named_room():
    scene = scene_for_task("pick_and_place_simple", "Kitchen", seed=2, room="FloorPlan1")
    assert scene.room.name == "FloorPlan1"
    _fits(scene, "pick_and_place_simple")
    again = scene_for_task("pick_and_place_simple", "Kitchen", seed=2, room="FloorPlan1")
    assert again.model_dump_json() == scene.model_dump_json()


def test_scene_for_a_given_task_in_a_named_room_fits_that_task():
    """A task whose object FloorPlan1's default room lacks: a room is generated for that very task."""
    from luminous_sim.data import task_misfit
    from luminous_sim.tasks import PddlParams

    default = scene_for_task("pick_and_place_simple", "Kitchen", seed=2, room="FloorPlan1")
    present = {o.type for o in default.objects}
    missing = next(t for t in ("Kettle", "Ladle", "Spatula", "SaltShaker", "PepperShaker", "WineBottle", "Potato",
                               "Egg", "Lettuce", "Bread") if t not in present)
    params = PddlParams(missing, "CounterTop")
    assert "is not feasible here" in task_misfit(default, "pick_and_place_simple", params)
    scene = scene_for_task("pick_and_place_simple", "Kitchen", seed=2, room="FloorPlan1", params=params)
    assert scene.room.name == "FloorPlan1" and scene.source == f"pick_and_place_simple-{missing}-None-CounterTop"
    assert params in feasible_params(scene, state_from_scene(scene), "pick_and_place_simple")
    assert task_misfit(scene, "pick_and_place_simple", params) is None


def test_scene_for_task_refuses_a_room_of_another_type_and_bad_parameters():
    from luminous_sim.tasks import PddlParams, TaskError

    with pytest.raises(TaskError, match="FloorPlan301 is a Bedroom, not a Kitchen"):
        scene_for_task("pick_and_place_simple", "Kitchen", seed=0, room="FloorPlan301")
    with pytest.raises(TaskError, match="Apple"):
        scene_for_task("pick_and_place_simple", "Kitchen", seed=0, params=PddlParams("Apple", "Apple"))


def test_no_room_for_a_given_task_names_the_task_and_the_room(monkeypatch):
    from luminous_sim.tasks import PddlParams

    monkeypatch.setattr(task_scenes, "task_misfit", lambda scene, task_type, params, catalog=None: "no spot (test)")
    with pytest.raises(TaskSamplingError) as info:
        scene_for_task("pick_and_place_simple", "Kitchen", seed=0, room="FloorPlan1",
                       params=PddlParams("Apple", "Fridge"))
    for part in ("Kitchen in room FloorPlan1", "the task pick_and_place_simple-Apple-None-Fridge", "no spot (test)"):
        assert part in str(info.value)
