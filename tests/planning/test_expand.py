"""ALFRED's expansions of high-level actions (one source for the oracle and the planner's macros)."""

from __future__ import annotations

import pytest

from luminous_sim.errors import PlanningError
from luminous_sim.planning.expand import expand
from luminous_sim.planning.symbolic.actions import HighLevelAction
from luminous_sim.planning.symbolic.macros import expand_macro
from tests.planning.scenes import kitchen


def names(steps):
    return [(s.action, s.object_id) for s in steps]


def test_pickup_from_a_closed_fridge_opens_and_closes_it():
    s = kitchen()
    assert names(expand("PickupObject", {"objectId": "Apple|3"}, s)) == [
        ("OpenObject", "Fridge|1"), ("PickupObject", "Apple|3"), ("CloseObject", "Fridge|1")]
    # the next high-level action works at the same place: the door stays open (ALFRED's rule)
    assert names(expand("PickupObject", {"objectId": "Apple|3"}, s, keep_open=True)) == [
        ("OpenObject", "Fridge|1"), ("PickupObject", "Apple|3")]
    assert names(expand("PickupObject", {"objectId": "Apple|3"}, s, auto_doors=False)) == [("PickupObject", "Apple|3")]
    opened = kitchen(changes={"Fridge|1": {"isOpen": True}})
    assert names(expand("PickupObject", {"objectId": "Apple|3"}, opened)) == [("PickupObject", "Apple|3")]


def test_put_into_a_closed_cabinet_and_heat_cool_sequences():
    s = kitchen(held="Apple|1")
    put = expand("PutObject", {"objectId": "Apple|1", "receptacleObjectId": "Cabinet|1"}, s)
    assert [x.action for x in put] == ["OpenObject", "PutObject", "CloseObject"] and put[1].receptacle_id == "Cabinet|1"
    heat = expand("HeatObject", {"objectId": "Apple|1", "receptacleObjectId": "Microwave|1"}, s)
    assert [x.action for x in heat] == ["OpenObject", "PutObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff",
                                        "OpenObject", "PickupObject", "CloseObject"]
    cool = expand("CoolObject", {"objectId": "Apple|1", "receptacleObjectId": "Fridge|1"}, s)
    assert [x.action for x in cool] == ["OpenObject", "PutObject", "CloseObject", "OpenObject", "PickupObject",
                                        "CloseObject"]


def test_clean_switches_a_running_faucet_off_first_and_needs_a_faucet():
    running = kitchen(held="Mug|1", changes={"Faucet|1": {"isToggled": True}})
    clean = expand("CleanObject", {"objectId": "Mug|1", "receptacleObjectId": "SinkBasin|1"}, running)
    assert [x.action for x in clean] == ["PutObject", "ToggleObjectOff", "ToggleObjectOn", "ToggleObjectOff",
                                         "PickupObject"]
    with pytest.raises(PlanningError, match="no faucet"):
        expand("CleanObject", {"objectId": "Mug|1", "receptacleObjectId": "SinkBasin|1"},
               kitchen(held="Mug|1", faucet_basin={}))
    with pytest.raises(PlanningError, match="no expansion"):
        expand("Teleport", {"objectId": "Mug|1"}, running)


def test_an_action_without_an_object_is_refused():
    with pytest.raises(PlanningError, match="PickupObject needs an objectId"):
        expand("PickupObject", {}, kitchen())


def test_the_planner_macros_are_the_same_expansions_without_automatic_doors():
    s = kitchen(held="Apple|1")
    macro = expand_macro(HighLevelAction("HeatObject", {"objectId": "Apple|1", "receptacleObjectId": "Microwave|1"}), s)
    assert [m["action"] for m in macro] == [x.action for x in expand(
        "HeatObject", {"objectId": "Apple|1", "receptacleObjectId": "Microwave|1"}, s)]
    assert expand_macro(HighLevelAction("PutObject", {"objectId": "Apple|1", "receptacleObjectId": "Cabinet|1"}), s) == [  # noqa: E501
        {"action": "PutObject", "objectId": "Apple|1", "receptacleObjectId": "Cabinet|1"}]
    assert expand_macro(HighLevelAction("GotoLocation", {"objectId": "Fridge|1"}), s) == []
