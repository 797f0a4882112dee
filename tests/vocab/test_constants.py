"""The named type groups, action names and placement layers read from `vocab/data` (spec/alfred.md)."""

from __future__ import annotations

import json
from importlib import resources
from typing import get_args

import pytest

from luminous_sim.cdf.schema import HighLevelAction, LowLevelAction
from luminous_sim.vocab import (
    AGENT_ACTIONS,
    BASINS,
    DECORATION_TYPES,
    DISCRETE_NAVIGATION,
    FILLABLE,
    FIXTURE_TYPES,
    FURNITURE_TYPES,
    HANGERS,
    HIGH_LEVEL_ACTIONS,
    INTERACTION_ACTIONS,
    LAMPS,
    MOVABLE_RECEPTACLES,
    NAVIGATION_ACTIONS,
    NOOP_ACTION,
    OBJECTS,
    PILING_RECEPTACLES,
    SLICING_TOOLS,
    STATE_NEUTRAL_ACTIONS,
    STRUCTURE_TYPES,
    TELEPORT_ACTIONS,
    WALL_TYPES,
    abilities,
    check_type,
)

GROUPS = {
    "FILLABLE": FILLABLE,
    "LAMPS": LAMPS,
    "MOVABLE_RECEPTACLES": MOVABLE_RECEPTACLES,
    "SLICING_TOOLS": SLICING_TOOLS,
    "BASINS": BASINS,
    "PILING_RECEPTACLES": PILING_RECEPTACLES,
    "HANGERS": HANGERS,
    "STRUCTURE_TYPES": STRUCTURE_TYPES,
    "DECORATION_TYPES": DECORATION_TYPES,
    "FIXTURE_TYPES": FIXTURE_TYPES,
    "FURNITURE_TYPES": FURNITURE_TYPES,
    "WALL_TYPES": WALL_TYPES,
}


@pytest.mark.parametrize("name", sorted(GROUPS))
def test_every_group_names_known_types_once(name: str) -> None:
    group = GROUPS[name]
    assert isinstance(group, (tuple, frozenset)) and group
    assert len(set(group)) == len(group)
    for t in group:
        check_type(t, name)


def test_alfred_groups() -> None:
    assert MOVABLE_RECEPTACLES == ("Bowl", "Box", "Cup", "Mug", "Pan", "Plate", "Pot")
    assert all(abilities(t).movable_receptacle for t in MOVABLE_RECEPTACLES)
    assert LAMPS == ("DeskLamp", "FloorLamp")
    assert SLICING_TOOLS[0] == "Knife" and set(SLICING_TOOLS) == {t for t in OBJECTS if "Knife" in t}
    assert FILLABLE == {"Bowl", "Cup", "Glassbottle", "HousePlant", "Kettle", "Mug", "Pot", "WateringCan",
                        "WineBottle"}


def test_piling_receptacles_are_the_movable_ones_and_the_basins() -> None:
    assert PILING_RECEPTACLES == set(MOVABLE_RECEPTACLES) | {"SinkBasin", "BathtubBasin"}
    assert not any(abilities(t).movable_receptacle for t in BASINS)


def test_action_names() -> None:
    assert NAVIGATION_ACTIONS == ("MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown")
    assert len(INTERACTION_ACTIONS) == 7 and "SliceObject" in INTERACTION_ACTIONS
    assert len(HIGH_LEVEL_ACTIONS) == 10 and HIGH_LEVEL_ACTIONS[0] == "GotoLocation"
    assert dict(DISCRETE_NAVIGATION) == {
        "MoveAhead": "MoveAhead_25",
        "RotateLeft": "RotateLeft_90",
        "RotateRight": "RotateRight_90",
        "LookUp": "LookUp_15",
        "LookDown": "LookDown_15",
    }
    assert STATE_NEUTRAL_ACTIONS == (*NAVIGATION_ACTIONS, NOOP_ACTION)
    assert AGENT_ACTIONS == (*NAVIGATION_ACTIONS, *TELEPORT_ACTIONS, "Pass", "NoOp")
    assert not set(AGENT_ACTIONS) & set(INTERACTION_ACTIONS)


def test_the_cdf_action_literals_agree_with_the_vocabulary() -> None:
    """The CDF schema keeps its action names as `Literal`s (for typing and the JSON Schema)."""
    assert get_args(LowLevelAction) == NAVIGATION_ACTIONS + INTERACTION_ACTIONS
    assert set(HIGH_LEVEL_ACTIONS) <= set(get_args(HighLevelAction))


def test_layer_lists() -> None:
    assert not STRUCTURE_TYPES & DECORATION_TYPES
    assert not FIXTURE_TYPES & (FURNITURE_TYPES | WALL_TYPES)
    assert FURNITURE_TYPES & WALL_TYPES == {"Cabinet"}  # wall cabinets, in some room types only
    placement = json.loads(resources.files("luminous_sim.cssg").joinpath("data/placement.json").read_text())
    assert set(placement["wall_height"]) == WALL_TYPES


@pytest.mark.parametrize(
    ("object_type", "cdf_layer", "generation"),
    [
        ("Window", "STRUCTURE", "wall"),
        ("Painting", "DECORATION", "wall"),
        ("CounterTop", "FURNITURE", "fixture"),
        ("Sofa", "FURNITURE", "furniture"),
        ("Microwave", "FURNITURE", "object"),  # CDF order: before the objects; CSSG: stands on a counter
        ("TowelHolder", "FURNITURE", "wall"),
        ("Boots", "OBJECT", "furniture"),  # pickupable, but CSSG stands it on the floor
        ("Apple", "OBJECT", "object"),
    ],
)
def test_the_two_layer_classifications(object_type: str, cdf_layer: str, generation: str) -> None:
    """The CDF's placement-order layer and CSSG's placement class are different questions."""
    from luminous_sim.cdf.layers import layer_of
    from luminous_sim.cssg.tables import generation_layer

    assert layer_of(object_type).name == cdf_layer
    assert generation_layer(object_type) == generation


def test_the_task_layer_knows_exactly_vocabs_task_types_in_order():
    from luminous_sim.tasks import TASK_TYPES
    from luminous_sim.vocab import ALFRED_TASK_TYPES

    assert tuple(TASK_TYPES) == ALFRED_TASK_TYPES
