"""`reset(options={"scene": ...})` checks the scene as a scene file is checked: a copied `Scene` (never
validated again by pydantic) with a 1e308 pose, a NaN yaw, a zero scale, a duplicate id or a missing parent is
refused in one line naming the option, the object and the field, before any world is built (it used to end in
a GEOSException or a math domain error)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from luminous_sim.env.config import EnvConfig
from luminous_sim.env.reset_options import reset_options
from luminous_sim.errors import LuminousError
from luminous_sim.rooms.library import shell_for
from luminous_sim.scene import Scene, SceneObject


@pytest.fixture(scope="module")
def scene() -> Scene:
    table = SceneObject(id="DiningTable|0", type="DiningTable", asset="DiningTable_1", position=(1.0, 1.0, 0.0),
                        layer="furniture")
    apple = SceneObject(id="Apple|0", type="Apple", asset="Apple_1", position=(1.0, 1.0, 0.9), layer="object",
                        parent="DiningTable|0")
    return Scene(room=shell_for("FloorPlan1", np.random.default_rng(0)), seed=0, generator="test",
                 objects=(table, apple))


def _with(scene: Scene, **update: Any) -> Scene:
    apple = scene.objects[1].model_copy(update=update)
    return scene.model_copy(update={"objects": (scene.objects[0], apple)})


@pytest.mark.parametrize(("update", "needle"), [
    ({"position": (1e308, 1.0, 0.9)}, "position: expected 3 finite numbers"),
    ({"position": (math.nan, 1.0, 0.9)}, "position: expected 3 finite numbers"),
    ({"yaw": math.nan}, "yaw: expected a finite number"),
    ({"scale": 0.0}, "scale: expected a number in"),
    ({"parent": "Nope|0"}, "parent: no object 'Nope|0'"),
    ({"id": "DiningTable|0"}, "id: duplicate id"),
    ({"states": {"isOpen": "yes"}}, "states"),
])
def test_a_hostile_scene_option_is_refused_in_one_line(scene: Scene, update: dict[str, Any], needle: str) -> None:
    with pytest.raises(LuminousError) as err:
        reset_options({"scene": _with(scene, **update)}, EnvConfig())
    text = str(err.value)
    assert text.startswith("reset options scene: ") and needle in text and "\n" not in text, text


def test_a_good_scene_option_is_taken(scene: Scene) -> None:
    assert reset_options({"scene": scene}, EnvConfig()).scene is scene
