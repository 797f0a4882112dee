"""Objects stacked into one another are refused before any physics (a few hundred in one spot took about 240 s
to settle, every step colliding every pair): deterministic, by the assets' boxes; generated scenes pass."""

from __future__ import annotations

import time

import pytest

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.scene import SceneError, SceneObject
from luminous_sim.world.scene_builder import MAX_DEEP_OVERLAPS, build_scene, check_stacking


@pytest.fixture(scope="module")
def kitchen():
    return generate(empty_cdf("Kitchen"), seed=0).scene


def _apples(n: int, at: tuple[float, float, float], start: int = 0) -> list[SceneObject]:
    return [SceneObject(id=f"Apple|stack{start + i}", type="Apple", asset="Apple_00", position=at, yaw=0.01 * i,
                        layer="object") for i in range(n)]


def test_a_generated_scene_passes(kitchen):
    check_stacking(kitchen, default_catalog())


def test_hundreds_of_objects_in_one_spot_are_refused_at_once(kitchen):
    x, y = kitchen.room.polygon().representative_point().coords[0]
    stacked = kitchen.model_copy(update={"objects": [*kitchen.objects, *_apples(300, (x, y, 0.05))]})
    start = time.perf_counter()
    with pytest.raises(SceneError, match=r"object 'Apple\|stack\d+': position: lies deep inside \d+ other movable "
                                         r"objects \(at most 8"):
        build_scene(stacked)
    assert time.perf_counter() - start < 60  # refused before loading, not after minutes of settling


def test_a_few_objects_together_are_a_pile_not_a_refusal(kitchen):
    x, y = kitchen.room.polygon().representative_point().coords[0]
    pile = kitchen.model_copy(update={"objects": [*kitchen.objects, *_apples(MAX_DEEP_OVERLAPS + 1, (x, y, 0.05))]})
    check_stacking(pile, default_catalog())  # each lies inside 8 others: the limit itself
    more = pile.model_copy(update={"objects": [*pile.objects, *_apples(1, (x, y, 0.05), start=99)]})
    with pytest.raises(SceneError, match="lies deep inside 9 other"):
        check_stacking(more, default_catalog())
