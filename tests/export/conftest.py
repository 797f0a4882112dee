"""A kitchen generated once for the export tests, as generated and with its states changed: the fridge,
microwave, cabinets and drawers open and the apple sliced (the scene's initial states, which the world
applies when it builds it), built once and read out (`posed_scene`)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from luminous_sim import cdf
from luminous_sim.cssg import generate
from luminous_sim.scene import Scene

REPO = Path(__file__).resolve().parents[2]
KITCHEN = REPO / "cdf" / "examples" / "kitchen_apple_fridge.yaml"
OPENED = ("Fridge", "Microwave", "Cabinet", "Drawer")


@pytest.fixture(scope="package")
def kitchen() -> Scene:
    return generate(cdf.load(KITCHEN), seed=0).scene


@pytest.fixture(scope="package")
def changed(kitchen: Scene) -> Scene:
    """The kitchen with its openable furniture open and the apple to be sliced."""
    objects = []
    for o in kitchen.objects:
        if o.type in OPENED:
            o = o.model_copy(update={"states": {**o.states, "isOpen": True}})
        elif o.type == "Apple":
            o = o.model_copy(update={"states": {**o.states, "isSliced": True}})
        objects.append(o)
    return kitchen.model_copy(update={"objects": tuple(objects)})


@pytest.fixture(scope="package")
def changed_dir(changed: Scene, tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("changed")
    changed.save(out / "scene.json")
    return out


@pytest.fixture(scope="package")
def world(changed: Scene) -> Iterator:
    from luminous_sim.export import build_world

    with build_world(changed) as w:
        yield w


@pytest.fixture(scope="package")
def posed(world):
    from luminous_sim.world.posed import posed_scene

    return posed_scene(world)
