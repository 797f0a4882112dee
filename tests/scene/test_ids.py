"""AI2-THOR/ALFRED object ids: the one `type_of_id`, checked on hand examples and on ALFRED's own ids."""

from __future__ import annotations

import json

import pytest

from luminous_sim.scene.ids import thor_object_id, type_of_id
from luminous_sim.vocab import BASINS, SLICED_TYPES, parent_type


@pytest.mark.parametrize(
    ("object_id", "object_type"),
    [
        ("Apple|+00.46|+00.82|+02.27", "Apple"),
        ("Apple|+00.46|+00.82|+02.27|AppleSliced_1", "AppleSliced"),
        ("Bread|-01.10|+00.95|+00.40|BreadSliced_10", "BreadSliced"),
        ("Sink|+00.00|+00.89|-01.44|SinkBasin", "SinkBasin"),
        ("Bathtub|-01.60|+00.30|+00.70|BathtubBasin", "BathtubBasin"),
        ("SinkBasin|+00.00|+00.89|-01.44", "SinkBasin"),
        ("Mug|+00.10|+00.90|-01.20|2", "Mug"),
        ("Mug|1", "Mug"),
    ],
)
def test_type_of_id(object_id: str, object_type: str) -> None:
    assert type_of_id(object_id) == object_type


def test_type_of_id_reads_back_our_ids_and_their_clash_suffix() -> None:
    taken: set[str] = set()
    first = thor_object_id("CounterTop", (1.0, 2.0, 0.9), taken)
    second = thor_object_id("CounterTop", (1.0, 2.0, 0.9), taken)
    assert second == f"{first}|2"
    assert type_of_id(first) == type_of_id(second) == "CounterTop"


def _planner_actions(root):
    for path in sorted((root / "valid_seen").glob("*/*/traj_data.json")):
        for entry in json.loads(path.read_text())["plan"]["high_pddl"]:
            yield entry["planner_action"], entry["discrete_action"]["args"]


def test_type_of_id_agrees_with_alfred_discrete_args(shared_alfred) -> None:
    """ALFRED names a receptacle by its own type (`sinkbasin`) and a picked slice by its parent (`apple`)."""
    seen_slice = seen_basin = False
    for planner, args in _planner_actions(shared_alfred):
        if planner["action"] == "PutObject":
            recep = type_of_id(planner["receptacleObjectId"])
            assert recep.lower() == args[1], planner
            seen_basin |= recep in BASINS
        if planner["action"] == "PickupObject":
            kind = type_of_id(planner["objectId"])
            assert parent_type(kind).lower() == args[0], planner
            if "Sliced" in planner["objectId"]:
                assert kind in SLICED_TYPES, planner
                seen_slice = True
    assert seen_slice and seen_basin


def test_cdf_name_is_the_cdf_s_and_not_the_generator_s():
    from luminous_sim.scene.model import SceneObject, auto_name

    def named(name, t="Mug"):
        return SceneObject(id="x", type=t, asset="a", position=(0, 0, 0), layer="object", name=name).cdf_name

    assert named("mug") == "mug" and named("chair#2", "Chair") == "chair#2"
    assert named(auto_name("Mug", 3)) is None and named(None) is None
    assert named("mug_auto0", "Cup") == "mug_auto0"  # another type's auto name is a name the CDF chose
