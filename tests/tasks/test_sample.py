"""The sampler: ALFRED's constraints (one test each: rejected with a reason, accepted with valid
parameters), determinism, and feasible task types."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.tasks import (
    TASK_TYPES,
    PddlParams,
    TaskSamplingError,
    draw_params,
    feasible_params,
    feasible_task_types,
    goal_conditions,
    goal_satisfied,
    params_problems,
    sample_task,
    state_from_scene,
)
from tests.tasks.helpers import KITCHEN, LIVING, Layout, scene_of, state_of, with_, without


def feasible(layout: Layout, task_type: str, room: str = "Kitchen", **kw) -> list[PddlParams]:
    scene = scene_of(layout, room)
    return feasible_params(scene, state_from_scene(scene), task_type, **kw)


def rejected(layout: Layout, task_type: str, match: str, room: str = "Kitchen", **kw) -> None:
    with pytest.raises(TaskSamplingError, match=match) as info:
        feasible(layout, task_type, room, **kw)
    assert task_type in str(info.value) and "seed 7" in str(
        info.value
    )  # names the task and the scene


def test_state_from_scene_keeps_types_parents_and_states():
    scene = scene_of(KITCHEN)
    state = state_from_scene(scene)
    assert state == state_of(KITCHEN)
    on = scene.model_copy(
        update={
            "objects": tuple(
                o.model_copy(update={"states": {"isOpen": True}}) if o.type == "Fridge" else o
                for o in scene.objects
            )
        }
    )
    assert state_from_scene(on)["Fridge|1"].isOpen


# -- rooms and devices ------------------------------------------------------------------------


def test_room_type_must_allow_the_task():
    rejected(
        with_(KITCHEN, DeskLamp_1=("DeskLamp", "CounterTop|1")),
        "look_at_obj_in_light",
        "only in Bedroom, LivingRoom, and this is a Kitchen",
    )
    rejected(LIVING, "pick_heat_then_place_in_recep", "only in Kitchen", room="LivingRoom")
    assert feasible(LIVING, "look_at_obj_in_light", room="LivingRoom")


@pytest.mark.parametrize(
    ("task_type", "device"),
    [
        ("pick_heat_then_place_in_recep", "Microwave"),
        ("pick_cool_then_place_in_recep", "Fridge"),
        ("pick_clean_then_place_in_recep", "SinkBasin"),
        ("pick_clean_then_place_in_recep", "Faucet"),
    ],
)
def test_state_change_tasks_need_their_device(task_type, device):
    rejected(without(KITCHEN, device), task_type, f"the scene has no {device}")
    assert feasible(KITCHEN, task_type)


# -- objects ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("task_type", "ability", "bad", "good"),
    [
        ("pick_heat_then_place_in_recep", "heatable", "Lettuce", "Egg"),
        ("pick_cool_then_place_in_recep", "coolable", "Knife", "WineBottle"),
        ("pick_clean_then_place_in_recep", "cleanable", "Book", "Cloth"),
    ],
)
def test_object_must_have_the_ability(task_type, ability, bad, good):
    base: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Microwave|1": ("Microwave", "CounterTop|1"),
        "Fridge|1": ("Fridge", None),
        "SinkBasin|1": ("SinkBasin", None),
        "Faucet|1": ("Faucet", None),
    }
    rejected(
        with_(base, **{f"{bad}_1": (bad, None)}), task_type, f"no object in the scene is {ability}"
    )
    ok = feasible(with_(base, **{f"{good}_1": (good, None)}), task_type)
    assert {p.object_target for p in ok} == {good}


@pytest.mark.parametrize(
    ("task_type", "device"),
    [
        ("pick_heat_then_place_in_recep", "Microwave|1"),
        ("pick_cool_then_place_in_recep", "Fridge|1"),
        ("pick_clean_then_place_in_recep", "SinkBasin|1"),
    ],
)
def test_object_type_must_not_already_be_in_the_device(task_type, device):
    base: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Microwave|1": ("Microwave", "CounterTop|1"),
        "Fridge|1": ("Fridge", None),
        "SinkBasin|1": ("SinkBasin", None),
        "Faucet|1": ("Faucet", None),
        "Apple|1": ("Apple", device),
        "Apple|2": ("Apple", "CounterTop|1"),
    }
    rejected(base, task_type, "already has an instance inside the " + device.split("|")[0])
    ok = feasible(with_(base, Apple_1=("Apple", "CounterTop|1")), task_type)
    assert {p.object_target for p in ok} == {"Apple"}
    assert device.split("|")[0] not in {
        p.parent_target for p in ok
    }  # the device is never the receptacle


def test_pick_two_needs_two_instances():
    one: Layout = {"Cabinet|1": ("Cabinet", None), "Mug|1": ("Mug", None)}
    rejected(one, "pick_two_obj_and_place", "needs two instances of one object type")
    ok = feasible(with_(one, Mug_2=("Mug", None)), "pick_two_obj_and_place")
    assert ok == [PddlParams("Mug", "Cabinet")]


def test_pick_two_sliced_counts_the_pieces_of_one_parent():
    layout: Layout = {
        "Fridge|1": ("Fridge", None),
        "Apple|1": ("Apple", None),
        "Knife|1": ("Knife", None),
    }
    ok = feasible(layout, "pick_two_obj_and_place", sliced=True)
    assert ok == [PddlParams("Apple", "Fridge", object_sliced=True)]


def test_pick_two_receptacle_type_must_not_already_hold_the_type():
    layout: Layout = {
        "Cabinet|1": ("Cabinet", None),
        "Cabinet|2": ("Cabinet", None),
        "Mug|1": ("Mug", "Cabinet|1"),
        "Mug|2": ("Mug", None),
    }
    rejected(layout, "pick_two_obj_and_place", "none already holding the type")
    moved = with_(layout, Mug_1=("Mug", None))
    assert feasible(moved, "pick_two_obj_and_place") == [PddlParams("Mug", "Cabinet")]
    ok = feasible(with_(layout, Shelf_1=("Shelf", None)), "pick_two_obj_and_place")
    assert ok == [PddlParams("Mug", "Shelf")]


@pytest.mark.parametrize("excluded", ["CoffeeMachine"])
def test_pick_two_excluded_receptacles(excluded):
    layout: Layout = {
        f"{excluded}|1": (excluded, None),
        "Mug|1": ("Mug", None),
        "Mug|2": ("Mug", None),
    }
    rejected(
        layout, "pick_two_obj_and_place", "not CoffeeMachine/ToiletPaperHanger/HandTowelHolder"
    )
    assert feasible(layout, "pick_and_place_simple") == [PddlParams("Mug", excluded)]


def test_toaster_is_never_a_receptacle():
    layout: Layout = {
        "Toaster|1": ("Toaster", None),
        "Bread|1": ("Bread", None),
        "Knife|1": ("Knife", None),
    }
    rejected(
        layout,
        "pick_and_place_simple",
        "no receptacle in the scene may take the object",
        sliced=True,
    )


def test_receptacle_must_accept_the_object():
    layout: Layout = {"Bed|1": ("Bed", None), "Apple|1": ("Apple", None)}
    rejected(layout, "pick_and_place_simple", "ALFRED's receptacle table")
    assert feasible(with_(layout, Book_1=("Book", None)), "pick_and_place_simple") == [
        PddlParams("Book", "Bed")
    ]


def test_look_at_needs_a_lamp_and_a_pickupable_object():
    rejected(
        without(LIVING, "DeskLamp", "FloorLamp"),
        "look_at_obj_in_light",
        "no DeskLamp or FloorLamp",
        room="LivingRoom",
    )
    furniture = {k: v for k, v in LIVING.items() if v[0] in ("Sofa", "SideTable", "DeskLamp")}
    rejected(furniture, "look_at_obj_in_light", "no object type ALFRED picks up", room="LivingRoom")
    ok = feasible(LIVING, "look_at_obj_in_light", room="LivingRoom")
    assert {p.toggle_target for p in ok} == {"DeskLamp", "FloorLamp"}
    assert {p.object_target for p in ok} == {"Box", "KeyChain", "RemoteControl"}
    assert all(p.parent_target == "" and not params_problems("look_at_obj_in_light", p) for p in ok)


def test_look_at_is_never_sliced():
    layout = with_(LIVING, Apple_1=("Apple", "CoffeeTable|1"), Knife_1=("Knife", "CoffeeTable|1"))
    rejected(layout, "look_at_obj_in_light", "never sliced", room="LivingRoom", sliced=True)
    assert not any(
        p.object_sliced for p in feasible(layout, "look_at_obj_in_light", room="LivingRoom")
    )


# -- movable receptacles ----------------------------------------------------------------------

MOV = "pick_and_place_with_movable_recep"


def test_movable_receptacle_must_accept_the_object():
    layout: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Apple|1": ("Apple", None),
        "Mug|1": ("Mug", None),
    }
    rejected(layout, MOV, "no movable receptacle .* accepts an object present")
    ok = feasible(with_(layout, Plate_1=("Plate", None)), MOV)
    assert ok == [PddlParams("Apple", "CounterTop", mrecep_target="Plate")]


def test_receptacle_must_accept_the_movable_receptacle():
    layout: Layout = {
        "Drawer|1": ("Drawer", None),
        "Pencil|1": ("Pencil", None),
        "Mug|1": ("Mug", None),
    }
    rejected(layout, MOV, "must accept the movable receptacle")
    ok = feasible(with_(layout, Shelf_1=("Shelf", None)), MOV)
    assert ok == [PddlParams("Pencil", "Shelf", mrecep_target="Mug")]


def test_receptacle_must_not_already_hold_a_movable_receptacle_of_the_type():
    layout: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Apple|1": ("Apple", None),
        "Plate|1": ("Plate", "CounterTop|1"),
    }
    rejected(layout, MOV, "not already hold one of its type")
    ok = feasible(with_(layout, DiningTable_1=("DiningTable", None)), MOV)
    assert ok == [PddlParams("Apple", "DiningTable", mrecep_target="Plate")]


def test_object_may_not_be_a_movable_receptacle():
    layout: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Bowl|1": ("Bowl", None),
        "Plate|1": ("Plate", None),
    }
    rejected(layout, MOV, "other than a movable receptacle")


def test_movable_receptacle_is_never_the_final_receptacle():
    layout: Layout = {
        "Plate|1": ("Plate", None),
        "Bowl|1": ("Bowl", None),
        "Apple|1": ("Apple", None),
    }
    rejected(layout, MOV, "no receptacle in the scene may take the object")


# -- slicing ----------------------------------------------------------------------------------


def test_sliced_tasks_need_a_knife():
    layout: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Fridge|1": ("Fridge", None),
        "Apple|1": ("Apple", "CounterTop|1"),
    }
    rejected(
        layout,
        "pick_and_place_simple",
        "needs one of Apple, .* and a Knife or ButterKnife",
        sliced=True,
    )
    ok = feasible(
        with_(layout, ButterKnife_1=("ButterKnife", "CounterTop|1")),
        "pick_and_place_simple",
        sliced=True,
    )
    assert {(p.object_target, p.object_sliced) for p in ok} == {("Apple", True)}


def test_sliced_tasks_need_a_sliceable_parent_with_slices():
    layout: Layout = {
        "CounterTop|1": ("CounterTop", None),
        "Egg|1": ("Egg", None),
        "Knife|1": ("Knife", None),
    }
    rejected(
        layout,
        "pick_and_place_simple",
        "needs one of Apple, Bread, Lettuce, Potato, Tomato",
        sliced=True,
    )
    unsliced = feasible(layout, "pick_and_place_simple")
    assert {p.object_target for p in unsliced} == {"Egg", "Knife"} and not any(
        p.object_sliced for p in unsliced
    )


# -- initial state ----------------------------------------------------------------------------


def test_goal_must_not_already_hold():
    layout: Layout = {"Fridge|1": ("Fridge", None), "Apple|1": ("Apple", "Fridge|1")}
    rejected(
        layout, "pick_and_place_simple", "every candidate goal already holds in the initial state"
    )
    ok = feasible(with_(layout, CounterTop_1=("CounterTop", None)), "pick_and_place_simple")
    assert ok == [PddlParams("Apple", "CounterTop")]


def test_look_at_already_done_is_rejected():
    layout: Layout = {
        "SideTable|1": ("SideTable", None),
        "DeskLamp|1": ("DeskLamp", "SideTable|1"),
        "Book|1": ("Book", "SideTable|1"),
    }
    scene = scene_of(layout, "Bedroom")
    state = state_of(layout, {"DeskLamp|1": {"isToggled": True}}, held="Book|1")
    with pytest.raises(TaskSamplingError, match="already holds"):
        feasible_params(scene, state, "look_at_obj_in_light")
    assert feasible_params(
        scene, state.with_object("DeskLamp|1", isToggled=False), "look_at_obj_in_light"
    )


# -- drawing ----------------------------------------------------------------------------------

RICH = with_(
    KITCHEN,
    Bread_1=("Bread", "CounterTop|1"),
    Bowl_1=("Bowl", "Cabinet|1"),
    Egg_1=("Egg", "Fridge|1"),
    Lettuce_1=("Lettuce", "CounterTop|1"),
    Shelf_1=("Shelf", None),
)


def test_feasible_task_types():
    assert feasible_task_types(scene_of(RICH), state_of(RICH)) == [
        t for t in TASK_TYPES if t != "look_at_obj_in_light"
    ]
    living = scene_of(LIVING, "LivingRoom")
    assert feasible_task_types(living, state_of(LIVING)) == [
        "pick_and_place_simple",
        "pick_two_obj_and_place",
        "look_at_obj_in_light",
        "pick_and_place_with_movable_recep",
    ]  # a remote control or key chain in the box


@pytest.mark.parametrize("task_type", [t for t in TASK_TYPES if t != "look_at_obj_in_light"])
def test_sampled_tasks_are_valid_and_open(task_type):
    scene, state = scene_of(RICH), state_of(RICH)
    allowed = feasible_params(scene, state, task_type)
    drawn = set()
    for seed in range(25):
        task = sample_task(scene, state, task_type, np.random.default_rng(seed))
        assert task.params in allowed and not params_problems(task_type, task.params)
        assert not goal_satisfied(task.goal, state)
        done, total = goal_conditions(task, state)
        assert done < total
        assert task.scene_seed == scene.seed and task.instruction and not task.custom
        drawn.add(task.params)
    assert len(drawn) > 3
    assert any(p.object_sliced for p in drawn) == any(p.object_sliced for p in allowed)


def test_same_seed_same_task():
    scene, state = scene_of(RICH), state_of(RICH)
    for task_type in ("pick_and_place_simple", "pick_and_place_with_movable_recep"):
        a = [sample_task(scene, state, task_type, np.random.default_rng(s)) for s in range(10)]
        b = [sample_task(scene, state, task_type, np.random.default_rng(s)) for s in range(10)]
        assert a == b and [t.to_dict() for t in a] == [t.to_dict() for t in b]
        assert len({t.params for t in a}) > 1


def test_object_type_is_drawn_first_and_uniformly():
    """Each object type is equally likely, however many receptacles it fits."""
    scene, state = scene_of(RICH), state_of(RICH)
    allowed = feasible_params(scene, state, "pick_and_place_simple")
    objects = sorted({p.object_target for p in allowed})
    counts = dict.fromkeys(objects, 0)
    rng = np.random.default_rng(0)
    for _ in range(100 * len(objects)):
        counts[draw_params(allowed, rng).object_target] += 1
    assert min(counts.values()) > 60 and max(counts.values()) < 140
    first = sample_task(scene, state, "pick_and_place_simple", np.random.default_rng(3)).params
    assert first == draw_params(allowed, np.random.default_rng(3))


def test_sliced_option_and_closed_receptacles():
    scene, state = scene_of(RICH), state_of(RICH)
    task = sample_task(
        scene,
        state,
        "pick_cool_then_place_in_recep",
        np.random.default_rng(0),
        sliced=True,
        closed_receptacles=True,
    )
    assert task.params.object_sliced and task.goal_key.endswith("_slice")
    assert "forall" in str(task.to_dict()["goal"])
    task = sample_task(
        scene, state, "pick_cool_then_place_in_recep", np.random.default_rng(0), sliced=False
    )
    assert not task.params.object_sliced


def test_draw_kept_is_the_draw_over_the_kept_candidates_asking_less():
    """`draw_kept` draws what filtering every candidate first would, leaves the stream in the same state,
    and asks the filter about fewer candidates (it is the expensive physical check in a world)."""
    from luminous_sim.tasks import draw_kept

    scene, state = scene_of(RICH), state_of(RICH)
    for task_type in ("pick_and_place_simple", "pick_and_place_with_movable_recep", "pick_heat_then_place_in_recep"):
        cands = feasible_params(scene, state, task_type)
        for seed in range(40):
            chosen = set(np.random.default_rng(1000 + seed).choice(len(cands), size=max(1, len(cands) // 3),
                                                                   replace=False).tolist())
            asked = []

            def keep(p, chosen=chosen, asked=asked, cands=cands):
                asked.append(p)
                return cands.index(p) in chosen

            a, b = np.random.default_rng(seed), np.random.default_rng(seed)
            assert draw_kept(cands, a, keep) == draw_params([p for i, p in enumerate(cands) if i in chosen], b)
            assert a.random() == b.random()
            assert len(asked) == len(set(asked)) <= len(cands)
        assert len(asked) < len(cands)
    with pytest.raises(TaskSamplingError, match=f"none of the {len(cands)} candidates passes the filter"):
        draw_kept(cands, np.random.default_rng(0), lambda p: False)


def test_sample_task_with_a_filter_names_the_task_when_nothing_passes():
    scene, state = scene_of(RICH), state_of(RICH)
    with pytest.raises(TaskSamplingError, match="no pick_and_place_simple task in .*none of the .* candidates"):
        sample_task(scene, state, "pick_and_place_simple", np.random.default_rng(0), keep=lambda p: False)
    keep_mugs = lambda p: p.object_target == "Mug"  # noqa: E731
    task = sample_task(scene, state, "pick_and_place_simple", np.random.default_rng(0), keep=keep_mugs)
    assert task.params.object_target == "Mug"


def test_a_target_alfred_matches_by_substring_to_another_type_is_rejected_with_the_reason():
    from luminous_sim.tasks import SUBSTRING_CLASH, alfred_name_clash

    state = state_of(KITCHEN)
    assert alfred_name_clash(PddlParams("Pot", "Cabinet"), state) == (
        "object_type 'Pot' also matches Potato|1 (Potato)")  # ALFRED: `'Pot' in 'Potato|1'`
    assert alfred_name_clash(PddlParams("Potato", "Cabinet"), state) is None
    assert alfred_name_clash(PddlParams("Apple", "Cabinet", object_sliced=True), state) is None  # slices are ours too
    assert alfred_name_clash(PddlParams("Apple", "Sink"), state) == (
        "parent_target 'Sink' also matches SinkBasin|1 (SinkBasin)")
    butter = with_(KITCHEN, ButterKnife_1=("ButterKnife", "SinkBasin|1"))  # S+ episode 0's clash
    assert "ButterKnife" in (alfred_name_clash(PddlParams("Knife", "SinkBasin"), state_of(butter)) or "")
    pots = feasible(KITCHEN, "pick_and_place_simple")
    assert pots and all("Pot" not in (p.object_target, p.mrecep_target) for p in pots)
    kept = feasible(KITCHEN, "pick_and_place_simple", judged_alike=False)  # ALFRED's own tasks (--from-alfred)
    assert any(p.object_target == "Pot" for p in kept) and set(pots) < set(kept)
    bathroom = {"Toilet|1": ("Toilet", None), "ToiletPaperHanger|1": ("ToiletPaperHanger", None),
                "SoapBar|1": ("SoapBar", None)}
    rejected(bathroom, "pick_and_place_simple", SUBSTRING_CLASH + r".*'Toilet' also matches ToiletPaperHanger",
             room="Bathroom")
