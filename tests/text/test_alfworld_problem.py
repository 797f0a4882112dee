"""ALFWorld's problem of a trial (`text.alfworld_problem`) and ALFWorld's names (`text.alfworld_names`), on a
small hand-made room: what each departure from a plain listing does, and the errors."""

from __future__ import annotations

import re

import pytest

from luminous_sim.states import ObjectState, WorldState
from luminous_sim.text import ProblemError, alfworld_id, alfworld_problem, demangled_names, mangle, names_of

COUNTER = "CounterTop|+01.00|+00.00|+00.00"
SAFE = "Safe|-02.00|+00.00|+00.20"
FRIDGE = "Fridge|+01.00|+00.00|+02.00"
SINK = "Sink|+01.00|+00.00|-01.00"
BASIN = "SinkBasin|+00.95|+00.70|-01.00"
POT = "Pot|+01.00|+00.91|+00.10"
POTATO = "Potato|+01.00|+00.95|+00.10"
APPLE = "Apple|+01.00|+00.95|+02.00"
LAMP = "FloorLamp|-01.80|+00.00|+00.00"
PLACES = {COUNTER: "loc|3|0|1|30", SAFE: "loc|-6|1|3|30", FRIDGE: "loc|3|7|1|15", BASIN: "loc|3|-4|1|15"}
START = "loc|0|0|0|30"


def room(fridge_open: bool = False) -> WorldState:
    return WorldState.of([
        ObjectState(COUNTER, "CounterTop"), ObjectState(SAFE, "Safe"),
        ObjectState(FRIDGE, "Fridge", isOpen=fridge_open),
        ObjectState(SINK, "Sink"), ObjectState(BASIN, "SinkBasin", parent=SINK),
        ObjectState(POT, "Pot", parent=COUNTER), ObjectState(POTATO, "Potato", parent=POT),
        ObjectState(APPLE, "Apple", parent=FRIDGE), ObjectState(LAMP, "FloorLamp")])


def simple(parent: str = "CounterTop", obj: str = "Apple") -> dict:
    return {"object_target": obj, "parent_target": parent, "toggle_target": "", "mrecep_target": "",
            "object_sliced": False}


def facts(text: str) -> set[str]:
    return set(re.findall(r"^\s+(\(.*\))$", text.split("(:init")[1].split("(:goal")[0], flags=re.M))


def test_a_basin_takes_alfreds_id_shape_and_reads_sinkbasin():
    assert alfworld_id(BASIN, "SinkBasin") == "Sink|+00.95|+00.70|-01.00|SinkBasin"
    assert alfworld_id(APPLE, "Apple") == APPLE
    problem = alfworld_problem(room(), PLACES, START, "pick_and_place_simple", simple(), "plan_t")
    assert problem.ids[BASIN] == "Sink_bar__plus_00_dot_95_bar__plus_00_dot_70_bar__minus_01_dot_00_bar_SinkBasin"
    names = names_of({**problem.ids, **{lo: lo for lo in problem.locations}})
    assert names[BASIN] == "sinkbasin 1" and names[SINK] == "sink 1" and names[APPLE] == "apple 1"


def test_what_is_in_what_and_what_is_open():
    problem = alfworld_problem(room(fridge_open=True), PLACES, START, "pick_and_place_simple", simple(), "plan_t")
    got, i = facts(problem.text), problem.ids
    assert f"(atLocation agent1 {mangle(START)})" in got
    assert f"(inReceptacle {i[APPLE]} {i[FRIDGE]})" in got and f"(opened {i[FRIDGE]})" in got
    assert f"(openable {i[SAFE]})" in got and f"(opened {i[SAFE]})" not in got
    # the potato in the pot on the counter: in the counter (ALFWorld's text shows it there) and in the pot
    assert f"(inReceptacle {i[POTATO]} {i[COUNTER]})" in got and f"(inReceptacleObject {i[POTATO]} {i[POT]})" in got
    assert f"(isReceptacleObject {i[POT]})" in got and f"{i[POT]} - object" in problem.text
    assert "(canContain FridgeType AppleType)" in got and "(canContain SafeType AppleType)" not in got
    assert f"(receptacleAtLocation {i[FRIDGE]} {mangle(PLACES[FRIDGE])})" in got


def test_only_what_alfred_opens_is_openable():
    toilet = "Toilet|-01.00|+00.00|-01.50"
    state = WorldState.of([*room().objects.values(), ObjectState(toilet, "Toilet")])
    problem = alfworld_problem(state, {**PLACES, toilet: "loc|-4|-6|2|45"}, START, "pick_and_place_simple", simple(),
                               "plan_t")
    got, i = facts(problem.text), problem.ids
    assert f"(openable {i[FRIDGE]})" in got and f"(openable {i[toilet]})" not in got  # a lid does not hide


def test_a_pot_the_task_puts_into_is_a_receptacle_at_the_place_of_what_it_stands_on():
    problem = alfworld_problem(room(), PLACES, START, "pick_and_place_simple", simple("Pot", "Apple"), "plan_t")
    got, i = facts(problem.text), problem.ids
    assert f"{i[POT]} - receptacle" in problem.text
    assert f"(receptacleType {i[POT]} PotType)" in got
    assert f"(receptacleAtLocation {i[POT]} {mangle(PLACES[COUNTER])})" in got
    assert f"(inReceptacle {i[POTATO]} {i[POT]})" in got and f"(inReceptacle {i[POTATO]} {i[COUNTER]})" not in got
    assert "(receptacleType ?r PotType)" in problem.text.split("(:goal")[1]


def test_a_floor_lamp_is_on_the_nearest_receptacle_that_does_not_close():
    params = {**simple(), "parent_target": "", "toggle_target": "FloorLamp"}
    problem = alfworld_problem(room(), PLACES, START, "look_at_obj_in_light", params, "plan_t")
    got, i = facts(problem.text), problem.ids
    assert f"(toggleable {i[LAMP]})" in got
    # the safe is nearer (0.3 m) but closes; the counter is the nearest that does not
    assert f"(inReceptacle {i[LAMP]} {i[COUNTER]})" in got
    assert f"(objectAtLocation {i[LAMP]} {mangle(PLACES[COUNTER])})" in got


@pytest.mark.parametrize("task_type, needs", [
    ("pick_heat_then_place_in_recep", "(isHot ?o)"), ("pick_cool_then_place_in_recep", "(isCool ?o)"),
    ("pick_clean_then_place_in_recep", "(isClean ?o)"), ("pick_two_obj_and_place", "(not (= ?o1 ?o2))"),
    ("pick_and_place_with_movable_recep", "(inReceptacleObject ?o ?mo)")])
def test_each_goal_says_what_its_type_needs(task_type, needs):
    params = {**simple(), "mrecep_target": "Pot" if "movable" in task_type else ""}
    goal = alfworld_problem(room(), PLACES, START, task_type, params, "plan_t").text.split("(:goal")[1]
    assert needs in goal and goal.count(")") == goal.count("(") + 2  # closing (:goal and the define


def test_a_sliced_target_must_be_sliced():
    goal = alfworld_problem(room(), PLACES, START, "pick_and_place_simple", {**simple(), "object_sliced": True},
                            "plan_t").text.split("(:goal")[1]
    assert "(sliceable ?o) (isSliced ?o)" in goal


def test_errors_name_what_is_wrong():
    with pytest.raises(ProblemError, match="receptacles without a place to stand: Safe"):
        alfworld_problem(room(), {k: v for k, v in PLACES.items() if k != SAFE}, START, "pick_and_place_simple",
                         simple(), "plan_t")
    with pytest.raises(ProblemError, match="'pick_up' is none of ALFRED's seven"):
        alfworld_problem(room(), PLACES, START, "pick_up", simple(), "plan_t")


def test_numbers_are_handed_out_last_first_over_the_sorted_identifiers():
    ids = ["Cabinet_bar__plus_01", "Cabinet_bar__minus_02", "Sink_bar_x_bar_SinkBasin", "AppleType", "agent1"]
    names = demangled_names(ids)
    # sorted: cabinet_bar__minus_02 < cabinet_bar__plus_01; the first sorted takes the highest number
    assert names["cabinet_bar__minus_02"] == "cabinet 2" and names["cabinet_bar__plus_01"] == "cabinet 1"
    assert names["sink_bar_x_bar_sinkbasin"] == "sinkbasin 1"
    assert names["appletype"] == "appletype" and names["agent1"] == "agent1"
