"""A small generated kitchen shared by the world tests (built once per module)."""

from __future__ import annotations

from pathlib import Path

import pytest

from luminous_sim import cdf
from luminous_sim.cssg import generate

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples"


@pytest.fixture(scope="session")
def kitchen_scene():
    """A kitchen with an apple on the counter, a fridge, a microwave, a sink and a knife."""
    doc = cdf.loads(
        """
cdf_version: 2
name: world_test_kitchen
scene:
  room_type: Kitchen
  room: {shape: rect, min_area: 14, max_area: 20}
  objects:
    - {name: counter, type: CounterTop}
    - {name: fridge, type: Fridge}
    - {name: microwave, type: Microwave}
    - {name: apple, type: Apple}
    - {name: knife, type: Knife}
    - {name: mug, type: Mug, state: {isDirty: true}}
    - {name: plate, type: Plate}
  relations:
    - {subject: microwave, relation: on, target: counter}
    - {subject: apple, relation: on, target: counter}
    - {subject: knife, relation: on, target: counter}
    - {subject: mug, relation: on, target: counter}
    - {subject: plate, relation: on, target: counter}
""",
        source="world_test_kitchen.yaml",
    )
    return generate(doc, seed=3).scene


@pytest.fixture()
def world(kitchen_scene):
    from luminous_sim.world.world import World, WorldConfig

    w = World(kitchen_scene, WorldConfig(settle_steps=120))
    yield w
    w.close()


def obj(scene, name: str) -> str:
    return next(o.id for o in scene.objects if o.name == name)


def mug_into_fridge(scene) -> list[tuple[str, str, dict]]:
    """(action, the object to stand at, its arguments) to pick the kitchen's mug up, open the fridge, put the
    mug in and close it: held objects and moved links for the frame tests."""
    mug, fridge = obj(scene, "mug"), obj(scene, "fridge")
    return [("PickupObject", mug, {"objectId": mug}), ("OpenObject", fridge, {"objectId": fridge}),
            ("PutObject", fridge, {"objectId": mug, "receptacleObjectId": fridge}),
            ("CloseObject", fridge, {"objectId": fridge})]
