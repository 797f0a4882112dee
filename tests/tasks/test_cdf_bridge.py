"""Tasks from CDFs, and CDFs that ask CSSG for a scene supporting a task."""

from __future__ import annotations

from pathlib import Path

import pytest

from luminous_sim import cdf
from luminous_sim.cdf.affordances import can_support
from luminous_sim.tasks import (
    PddlParams,
    TaskError,
    cdf_for_task,
    goal_conditions,
    goal_for,
    goal_satisfied,
    params_from_goal,
    required_objects,
    task_from_cdf,
)
from luminous_sim.tasks.cdf_bridge import fits_on
from tests.tasks.helpers import state_of

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples"

TASKS = [
    ("pick_and_place_simple", PddlParams("Apple", "Fridge"), "Kitchen"),
    ("pick_and_place_simple", PddlParams("Mug", "CoffeeMachine"), "Kitchen"),
    ("pick_and_place_simple", PddlParams("SoapBar", "Toilet"), "Bathroom"),
    ("pick_two_obj_and_place", PddlParams("KeyChain", "Sofa"), "LivingRoom"),
    ("pick_two_obj_and_place", PddlParams("Bread", "DiningTable", object_sliced=True), "Kitchen"),
    ("look_at_obj_in_light", PddlParams("Book", toggle_target="DeskLamp"), "Bedroom"),
    ("look_at_obj_in_light", PddlParams("RemoteControl", toggle_target="FloorLamp"), "LivingRoom"),
    ("pick_clean_then_place_in_recep", PddlParams("Mug", "Cabinet"), "Kitchen"),
    ("pick_clean_then_place_in_recep", PddlParams("Cloth", "CounterTop"), "Bathroom"),
    (
        "pick_heat_then_place_in_recep",
        PddlParams("Apple", "CounterTop", object_sliced=True),
        "Kitchen",
    ),
    ("pick_cool_then_place_in_recep", PddlParams("Tomato", "DiningTable"), "Kitchen"),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Pencil", "Shelf", mrecep_target="Mug"),
        "Bedroom",
    ),
    (
        "pick_and_place_with_movable_recep",
        PddlParams("Potato", "CounterTop", mrecep_target="Pan", object_sliced=True),
        "Kitchen",
    ),
]
IDS = [f"{t}/{p.object_type}/{r}" for t, p, r in TASKS]


def test_required_objects():
    assert required_objects("pick_and_place_simple", PddlParams("Apple", "Fridge")) == [
        ("Apple", 1),
        ("Fridge", 1),
    ]
    assert required_objects("pick_two_obj_and_place", PddlParams("Mug", "Cabinet")) == [
        ("Mug", 2),
        ("Cabinet", 1),
    ]
    assert required_objects(
        "pick_heat_then_place_in_recep", PddlParams("Apple", "CounterTop", object_sliced=True)
    ) == [("Apple", 1), ("Knife", 1), ("CounterTop", 1), ("Microwave", 1)]
    assert required_objects("pick_clean_then_place_in_recep", PddlParams("Mug", "Cabinet")) == [
        ("Mug", 1),
        ("Cabinet", 1),
        ("SinkBasin", 1),
        ("Faucet", 1),
    ]
    assert required_objects(
        "look_at_obj_in_light", PddlParams("Book", toggle_target="FloorLamp")
    ) == [("Book", 1), ("FloorLamp", 1)]
    assert required_objects(
        "pick_and_place_with_movable_recep", PddlParams("Pencil", "Shelf", mrecep_target="Mug")
    ) == [("Pencil", 1), ("Mug", 1), ("Shelf", 1)]
    with pytest.raises(TaskError, match="Bed does not accept Apple"):
        required_objects("pick_and_place_simple", PddlParams("Apple", "Bed"))


@pytest.mark.parametrize(("task_type", "params", "room"), TASKS, ids=IDS)
def test_cdf_for_task_requests_what_the_task_needs(task_type, params, room):
    doc = cdf_for_task(task_type, params, room)
    assert cdf.loads(cdf.dumps(doc)) == doc
    declared: dict[str, int] = {}
    for o in doc.scene.objects:
        declared[o.type] = declared.get(o.type, 0) + o.count
    for t, n in required_objects(task_type, params):
        assert declared.get(t, 0) >= n, (t, declared)
    target = doc.object_named("target")
    assert target is not None and target.type == params.object_target
    support = {r.subject: r.target for r in doc.scene.relations if r.relation == "on"}
    if "target" in support:
        surface = doc.object_named(support["target"])
        assert surface.type != params.parent_target and can_support(
            surface.type, params.object_type
        )
    assert doc.task is not None and doc.task.type == task_type
    assert doc.scene.room_type == (room,)
    # the CDF goal is ALFRED's goal (less the isSliced atoms its slice type implies)
    assert task_from_cdf(doc, {}).params == params
    if params.toggle_target:
        assert doc.object_named("lamp").state.isToggled is False
    if task_type == "pick_clean_then_place_in_recep" and params.object_target == "Mug":
        assert target.state.isDirty is True


def test_cdf_for_task_puts_the_desk_lamp_on_a_side_table():
    doc = cdf_for_task(
        "look_at_obj_in_light", PddlParams("Book", toggle_target="DeskLamp"), "Bedroom"
    )
    (rel,) = [r for r in doc.scene.relations if r.subject == "lamp"]
    assert rel.relation == "on" and doc.object_named(rel.target).type == "SideTable"


def test_cdf_for_task_puts_an_object_where_it_fits_and_not_in_its_target():
    """A baseball bat is longer than any side table is wide: it goes on the bed (a side table made every
    layout fail); a plunger, which only a cabinet or a cart holds, goes on a cart (in a cabinet, the goal
    "plunger in a cabinet" held from the start)."""
    assert not fits_on("SideTable", "BaseballBat") and fits_on("Bed", "BaseballBat")
    bat = cdf_for_task("look_at_obj_in_light", PddlParams("BaseballBat", toggle_target="DeskLamp"), "Bedroom")
    (rel,) = [r for r in bat.scene.relations if r.subject == "target"]
    assert bat.object_named(rel.target).type == "Bed"
    plunger = cdf_for_task("pick_and_place_simple", PddlParams("Plunger", "Cabinet"), "Bathroom")
    (rel,) = [r for r in plunger.scene.relations if r.subject == "target"]
    assert plunger.object_named(rel.target).type == "Cart"


def test_cdf_for_task_errors():
    with pytest.raises(TaskError, match="only in Kitchen; got 'Bedroom'"):
        cdf_for_task("pick_heat_then_place_in_recep", PddlParams("Apple", "CounterTop"), "Bedroom")
    with pytest.raises(TaskError, match="not heatable"):
        cdf_for_task("pick_heat_then_place_in_recep", PddlParams("Book", "CounterTop"), "Kitchen")


def test_task_from_the_look_at_example():
    doc = cdf.load(EXAMPLES / "bedroom_reading_desk.yaml")
    names = {"book": "Book|1", "lamp": "DeskLamp|1", "bed": "Bed|1", "desk": "Desk|1"}
    task = task_from_cdf(doc, names, scene_seed=4)
    assert task.custom and task.task_type == "look_at_obj_in_light" and task.scene_seed == 4
    assert task.params == PddlParams("Book", toggle_target="DeskLamp")
    assert task.instruction in {
        "look at a book under the desk lamp",
        "examine the book by the light of the desk lamp",
    }
    layout = {
        "Bed|1": ("Bed", None),
        "Desk|1": ("Desk", None),
        "DeskLamp|1": ("DeskLamp", "Desk|1"),
        "Book|1": ("Book", "Bed|1"),
    }
    before = state_of(layout)
    after = state_of(layout, {"DeskLamp|1": {"isToggled": True}}, held="Book|1")
    assert goal_conditions(task, before) == (0, 2)
    assert goal_conditions(task, state_of(layout, held="Book|1")) == (1, 2)
    assert goal_conditions(task, after) == (2, 2) and goal_satisfied(task.goal, after, task.names)


def test_task_from_the_cleaning_example_counts_its_own_conjuncts():
    doc = cdf.load(EXAMPLES / "bathroom_soap.yaml")
    names = {o.name: f"{o.type}|1" for o in doc.scene.objects}
    task = task_from_cdf(doc, names)
    assert task.params == PddlParams("SoapBar", "Cabinet")
    layout = {
        "Cabinet|1": ("Cabinet", None),
        "Cabinet|2": ("Cabinet", None),
        "SoapBar|1": ("SoapBar", None),
    }
    s = state_of(layout)
    assert goal_conditions(task, s) == (
        1,
        3,
    )  # cabinets closed; soap neither clean nor in the cabinet
    s = s.with_object("SoapBar|1", parent="Cabinet|1").replace(cleaned={"SoapBar|1"})
    assert goal_conditions(task, s) == (3, 3)
    assert goal_conditions(task, s.with_object("Cabinet|2", isOpen=True)) == (2, 3)


def test_task_from_an_untyped_cdf_is_custom():
    doc = cdf.load(EXAMPLES / "kitchen_apple_fridge.yaml")
    task = task_from_cdf(doc, {"apple": "Apple|1", "fridge": "Fridge|1"})
    assert (
        task.task_type == "custom" and task.goal_key == "custom" and task.params.object_target == ""
    )
    assert task.instruction == "put the apple in the fridge and cool the apple"
    s = state_of({"Fridge|1": ("Fridge", None), "Apple|1": ("Apple", "Fridge|1")})
    assert goal_conditions(task, s) == (1, 2)
    assert goal_conditions(task, s.replace(cooled={"Apple|1"})) == (2, 2)


def test_task_from_cdf_errors():
    doc = cdf.load(EXAMPLES / "kitchen_apple_fridge.yaml")
    with pytest.raises(TaskError, match="names apple, which the scene does not map"):
        task_from_cdf(doc, {"fridge": "Fridge|1"})
    bare = cdf.loads("cdf_version: 2\nscene: {room_type: Kitchen}\n")
    with pytest.raises(TaskError, match="has no task section"):
        task_from_cdf(bare, {})


def test_params_from_goal_reads_movable_and_sliced_goals():
    doc = cdf_for_task(
        "pick_and_place_with_movable_recep",
        PddlParams("Potato", "CounterTop", mrecep_target="Pan", object_sliced=True),
        "Kitchen",
    )
    assert params_from_goal(doc, doc.task.goal) == PddlParams(
        "Potato", "CounterTop", mrecep_target="Pan", object_sliced=True
    )
    goal = goal_for(PddlParams("Apple", "Fridge"), "pick_cool_then_place_in_recep")
    assert params_from_goal(doc, goal) == PddlParams("Apple", "Fridge")


def test_two_things_go_on_a_surface_with_a_row_for_both_and_avoided_surfaces_are_not_used():
    """Two boxes in a row fit on no side table (their areas would): they start on the dining table; a
    surface the room had no room for is avoided, the lamp's table too."""
    assert fits_on("SideTable", "Box") and not fits_on("SideTable", "Box", 2) and fits_on("DiningTable", "Box", 2)
    boxes = cdf_for_task("pick_two_obj_and_place", PddlParams("Box", "CoffeeTable"), "LivingRoom")
    (rel,) = [r for r in boxes.scene.relations if r.subject == "target"]
    assert boxes.object_named(rel.target).type == "DiningTable"
    moved = cdf_for_task("pick_two_obj_and_place", PddlParams("Box", "CoffeeTable"), "LivingRoom",
                         avoid={"DiningTable"})
    (rel,) = [r for r in moved.scene.relations if r.subject == "target"]
    assert moved.object_named(rel.target).type not in ("DiningTable", "CoffeeTable")
    lamp = cdf_for_task("look_at_obj_in_light", PddlParams("Book", toggle_target="DeskLamp"), "Bedroom",
                        avoid={"SideTable"})
    (rel,) = [r for r in lamp.scene.relations if r.subject == "lamp"]
    assert lamp.object_named(rel.target).type != "SideTable"
