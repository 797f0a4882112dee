"""ObjectState and WorldState: validation, containment queries, immutability, invariants."""

from __future__ import annotations

import pytest

from luminous_sim.errors import LuminousError, VocabularyError
from luminous_sim.states import STATE_FIELDS, ObjectState, StateError, WorldState
from tests.states.kitchen import kitchen


def test_object_state_defaults_and_validation():
    o = ObjectState("Apple|1", "Apple")
    assert (o.isOpen, o.temperature, o.parent, o.isPickedUp) == (False, "RoomTemp", None, False)
    with pytest.raises(VocabularyError, match="Aple"):
        ObjectState("Aple|1", "Aple")
    with pytest.raises(StateError, match="temperature 'Warm'"):
        ObjectState("Apple|1", "Apple", temperature="Warm")
    with pytest.raises(StateError, match="own parent"):
        ObjectState("Apple|1", "Apple", parent="Apple|1")
    with pytest.raises(StateError, match="temperature"):
        o.replace(temperature="Lukewarm")
    assert o.replace(temperature="Hot").temperature == "Hot"
    assert "object_id" not in STATE_FIELDS and "parent" in STATE_FIELDS and "temperature" in STATE_FIELDS


def test_world_state_validation():
    with pytest.raises(StateError, match="holds the state of"):
        WorldState({"Apple|2": ObjectState("Apple|1", "Apple")})
    with pytest.raises(StateError, match="held object 'Mug|1'"):
        WorldState({}, held="Mug|1")
    assert issubclass(StateError, LuminousError) and issubclass(StateError, KeyError)


def test_contents_direct_and_recursive():
    s = kitchen({"Plate|1": {"parent": "Fridge|1"}, "Apple|1": {"parent": "Plate|1"}, "Mug|1": {"parent": "Fridge|1"},
                 "Egg|1": {"parent": "Plate|1"}})
    assert s.contents("Fridge|1") == ["Plate|1", "Mug|1"]
    assert s.contents("Fridge|1", recursive=True) == ["Plate|1", "Apple|1", "Egg|1", "Mug|1"]
    assert s.contents("Apple|1") == [] and s.contents("Nothing|1", recursive=True) == []
    assert s.ancestors("Apple|1") == ["Plate|1", "Fridge|1"]
    assert s.ancestors("Fridge|1") == []


def test_parent_receptacles_cut_after_the_first_fixed_receptacle():
    """AI2-THOR's `parentReceptacles`: the bowl and the fridge holding it, not what holds the fridge."""
    s = kitchen({"Plate|1": {"parent": "Fridge|1"}, "Apple|1": {"parent": "Plate|1"}, "Mug|1": {"parent": "Fridge|1"}})
    assert s.parent_receptacles("Apple|1") == ["Plate|1", "Fridge|1"]
    assert s.parent_receptacles("Mug|1") == ["Fridge|1"] and s.parent_receptacles("Fridge|1") == []
    nested = s.replace(objects={**s.objects, "Fridge|1": s["Fridge|1"].replace(parent="CounterTop|1")})
    assert nested.parent_receptacles("Apple|1") == ["Plate|1", "Fridge|1"]


def test_queries():
    s = kitchen()
    assert s.of_type("Faucet") == ["Faucet|1", "Faucet|2"] and s.of_type("Sofa") == []
    assert s.get("Apple|1") is s.objects["Apple|1"] and s.get("Apple|9") is None and s.get(None) is None
    assert s["Apple|1"].object_type == "Apple" and "Apple|1" in s and "Apple|9" not in s
    with pytest.raises(StateError, match="unknown object id 'Apple|9'") as e:
        s["Apple|9"]
    assert str(e.value) == "unknown object id 'Apple|9'"


def test_world_state_is_an_immutable_value():
    s = kitchen()
    with pytest.raises(TypeError):
        s.objects["Apple|1"] = ObjectState("Apple|1", "Apple")  # type: ignore[index]
    with pytest.raises(AttributeError):
        s.held = "Apple|1"  # type: ignore[misc]
    assert s == kitchen() and hash(s) == hash(kitchen())
    t = s.with_object("Apple|1", temperature="Cold")
    assert t != s and s["Apple|1"].temperature == "RoomTemp" and t["Apple|1"].temperature == "Cold"
    u = s.replace(heated={"Apple|1"})
    assert isinstance(u.heated, frozenset) and not s.heated
    assert len({s, kitchen(), t}) == 2


def test_caches_do_not_leak_between_states():
    s = kitchen()
    assert s.contents("Plate|1") == []
    t = s.with_object("Apple|1", parent="Plate|1")
    assert t.contents("Plate|1") == ["Apple|1"] and s.contents("Plate|1") == []


@pytest.mark.parametrize(
    ("changes", "held", "expected"),
    [
        ({}, None, None),
        ({"Apple|1": {"isPickedUp": True}}, None, "Apple|1 is marked picked up but not held"),
        ({"Apple|1": {"parent": "Shelf|9"}}, None, "Apple|1 has a parent Shelf|9 that does not exist"),
        ({"Bowl|1": {"parent": "Plate|1"}, "Plate|1": {"parent": "Bowl|1"}}, None, "loops back"),
    ],
)
def test_problems(changes, held, expected):
    got = kitchen(changes, held=held).problems()
    assert (not got) if expected is None else any(expected in g for g in got), got


def test_problems_with_a_held_object_in_a_receptacle():
    s = kitchen(held="Mug|1").with_object("Mug|1", parent="CounterTop|1")
    assert s.problems() == ["held object Mug|1 must have isPickedUp and no parent"]
