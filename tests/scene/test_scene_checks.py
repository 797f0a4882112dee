"""Hostile scene files: every value of a scene is checked where the scene is read or built (finite, within
`luminous_sim.limits`' bounds, of the right kind, unique ids, parents present and acyclic, an object-count
limit); a bad one is a one-line `SceneError` naming the file, the object id and the field, never a pydantic,
shapely or math traceback, and never a scene taken silently."""

from __future__ import annotations

import copy
import json
import math
import os
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from luminous_sim.errors import LuminousError
from luminous_sim.limits import MAX_SCENE_OBJECTS
from luminous_sim.rooms.library import shell_for
from luminous_sim.scene import SCENE_STATES, Scene, SceneError, SceneObject, check_scene

ROOM = shell_for("FloorPlan1", np.random.default_rng(0))


def _object(i: int, **kw: Any) -> dict[str, Any]:
    return {"id": f"Apple|{i}", "type": "Apple", "asset": "Apple_1", "position": [1.0, 1.0, 0.9], "yaw": 0.0,
            "layer": "object", **kw}


def _doc(objects: list[dict[str, Any]] | None = None) -> dict[str, Any]:
    table = {"id": "DiningTable|0", "type": "DiningTable", "asset": "DiningTable_1", "position": [1.0, 1.0, 0.0],
             "yaw": 1.5708, "layer": "furniture"}
    return {"room": json.loads(ROOM.to_json()), "seed": 3, "generator": "test",
            "objects": [table, *(objects if objects is not None else [_object(0, parent="DiningTable|0")])]}


def _write(tmp_path: Path, doc: dict[str, Any]) -> Path:
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(doc))
    return path


def test_a_plain_scene_file_is_read(tmp_path: Path) -> None:
    scene = Scene.load(_write(tmp_path, _doc()))
    assert [o.id for o in scene.objects] == ["DiningTable|0", "Apple|0"]
    assert check_scene(scene) is scene


BAD_OBJECTS = [
    ("position", [math.nan, 1.0, 0.9], "position: expected 3 finite numbers"),
    ("position", [math.inf, 1.0, 0.9], "position: expected 3 finite numbers"),
    ("position", [1e308, 1.0, 0.9], "position: expected 3 finite numbers within +-1000 m"),
    ("position", [1.0, 1.0], "position"),
    ("position", ["1", 1.0, 0.9], "position"),
    ("yaw", math.nan, "yaw: expected a finite number of radians"),
    ("yaw", 1e308, "yaw: expected a finite number of radians within +-25"),
    ("scale", 0, "scale: expected a number in 0.001..100"),
    ("scale", -1.0, "scale: expected a number in 0.001..100"),
    ("scale", 1e9, "scale: expected a number in 0.001..100"),
    ("color", [math.nan, 0.0, 0.0], "color: expected null or 3 numbers in 0..1"),
    ("color", [2.0, 0.0, 0.0], "color: expected null or 3 numbers in 0..1"),
    ("color_seed", -1, "color_seed: expected a whole number in 0..2**63-1"),
    ("color_seed", 2**70, "color_seed: expected a whole number in 0..2**63-1"),
    ("states", {"isOpen": 1}, "states"),
    ("states", {"isOpen": "true"}, "states"),
    ("states", {"isExploded": True}, "unknown state 'isExploded'"),
    ("fixed", 1, "fixed"),
    ("type", "Nonsense", "type: unknown object type 'Nonsense'"),
    ("id", "", "id: expected text of 1 to 256 characters"),
    ("id", "x" * 300, "id: expected text of 1 to 256 characters"),
    ("asset", "", "asset: expected text"),
    ("parent", "Nope|1", "parent: no object 'Nope|1' in the scene"),
    ("parent", "Apple|0", "parent: the object is its own parent"),
]


@pytest.mark.parametrize(("field", "value", "needle"), BAD_OBJECTS, ids=[f"{f}={v!r}"[:40] for f, v, _ in BAD_OBJECTS])
def test_a_bad_object_value_is_named_with_the_file_the_object_and_the_field(tmp_path: Path, field: str, value: Any,
                                                                             needle: str) -> None:
    path = _write(tmp_path, _doc([_object(0, **{field: value})]))
    with pytest.raises(SceneError) as err:
        Scene.load(path)
    text = str(err.value)
    assert text.startswith(f"{path}: ") and "\n" not in text and needle in text, text
    if field not in ("id", "position", "states", "fixed") or needle != field:
        assert "Apple|0" in text or field == "id", text


def test_duplicate_ids_and_parent_cycles_are_refused(tmp_path: Path) -> None:
    path = _write(tmp_path, _doc([_object(0), _object(0)]))
    with pytest.raises(SceneError, match=r"object 'Apple\|0': id: duplicate id"):
        Scene.load(path)
    path = _write(tmp_path, _doc([_object(0, parent="Apple|1"), _object(1, parent="Apple|2"),
                                  _object(2, parent="Apple|0")]))
    with pytest.raises(SceneError, match=r"parent: parents form a cycle \(Apple\|0 -> Apple\|1 -> Apple\|2 -> "
                                         r"Apple\|0\)"):
        Scene.load(path)


def test_a_room_with_a_nan_or_huge_number_is_refused_before_shapely_sees_it(tmp_path: Path) -> None:
    for value, shown in ((math.nan, "nan"), (1e308, "1e+308")):
        doc = _doc()
        doc["room"]["outline"][0][0] = value
        path = _write(tmp_path, doc)
        with pytest.raises(SceneError) as err:
            Scene.load(path)
        assert str(err.value) == (f"{path}: room.outline[0][0]: expected a finite number within +-1000 "
                                  f"(luminous_sim.limits.MAX_LAYOUT_COORDINATE_M), got {shown}")


def test_the_seed_is_bounded(tmp_path: Path) -> None:
    doc = _doc()
    doc["seed"] = 10**30
    with pytest.raises(SceneError, match=r"seed: expected a whole number in 0..2\*\*63-1"):
        Scene.load(_write(tmp_path, doc))


def test_too_many_objects_are_refused_before_they_are_built(tmp_path: Path) -> None:
    path = _write(tmp_path, _doc([_object(i) for i in range(MAX_SCENE_OBJECTS + 1)]))
    with pytest.raises(SceneError, match=f"objects: {MAX_SCENE_OBJECTS + 2} objects; a scene may hold at most "
                                         f"{MAX_SCENE_OBJECTS} "):
        Scene.load(path)
    assert len(Scene.load(_write(tmp_path, _doc([_object(i) for i in range(MAX_SCENE_OBJECTS - 1)]))).objects) \
        == MAX_SCENE_OBJECTS


def test_a_scene_built_in_code_is_checked_too() -> None:
    """SceneError is no ValueError: pydantic passes it on, so a generator or importer that makes a bad object
    fails in one line too (the CLI's exit 2), not with a ValidationError traceback."""
    with pytest.raises(SceneError, match=r"object 'Apple\|0': position: expected 3 finite numbers"):
        SceneObject(**_object(0, position=(math.nan, 0.0, 0.0)))
    with pytest.raises(SceneError, match="parent: no object"):
        Scene.model_validate(_doc([_object(0, parent="Nope")]))


def test_a_copied_scene_is_checked_by_check_scene(tmp_path: Path) -> None:
    scene = Scene.model_validate(_doc())
    apple = scene.objects[1].model_copy(update={"position": (1e308, 0.0, 0.0)})
    bad = scene.model_copy(update={"objects": (scene.objects[0], apple)})
    with pytest.raises(SceneError, match=r"^here: object 'Apple\|0': position: expected 3 finite"):
        check_scene(bad, "here")
    with pytest.raises(SceneError, match=r"scene.json: object 'Apple\|0': position"):
        bad.save(tmp_path / "scene.json")
    assert not (tmp_path / "scene.json").exists()
    dup = scene.model_copy(update={"objects": (scene.objects[0], scene.objects[0])})
    with pytest.raises(SceneError, match="duplicate id"):
        check_scene(dup)
    with pytest.raises(SceneError, match="expected a luminous_sim.scene.Scene, got dict"):
        check_scene({}, "x")  # type: ignore[arg-type]


def test_the_content_key_is_the_scene_s_content() -> None:
    a = Scene.model_validate(_doc())
    b = Scene.model_validate(copy.deepcopy(_doc()))
    c = Scene.model_validate(_doc([_object(0, parent="DiningTable|0", yaw=0.5)]))
    assert a.content_key() == b.content_key() != c.content_key() and len(a.content_key()) == 20


def test_scene_states_are_the_cdf_initial_state_flags() -> None:
    from luminous_sim.cdf.validate import STATE_ABILITY

    assert set(SCENE_STATES) == set(STATE_ABILITY)


def test_a_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = tmp_path / "scene.json"
    os.mkfifo(fifo)
    with pytest.raises(LuminousError, match=r"a FIFO \(named pipe\); expected a scene file"):
        Scene.load(fifo)


@pytest.mark.slow
def test_the_object_limit_is_ten_times_the_largest_generated_house() -> None:
    """MAX_SCENE_OBJECTS's measured figure: the five-room flat, the largest shipped house."""
    from luminous_sim import cdf
    from luminous_sim.cssg import generate_house
    from luminous_sim.resources import default_house

    flat = default_house().parent / "two_bedroom_flat.yaml"
    count = len(generate_house(cdf.load(flat), seed=0).scene.objects)
    assert 100 < count and 10 * count <= MAX_SCENE_OBJECTS


@pytest.mark.parametrize("position", [[500.0, 1.0, 0.9], [1.0, -40.0, 0.9], [1.0, 1.0, -5.0], [1.0, 1.0, 30.0]])
def test_an_object_far_outside_its_room_is_refused(tmp_path: Path, position: list[float]) -> None:
    with pytest.raises(SceneError, match=r"object 'Apple\|0': position: expected a place in its room"):
        Scene.load(_write(tmp_path, _doc([_object(0, position=position)])))
