"""Settling stops once everything movable is at rest, and not before."""

from __future__ import annotations

from luminous_sim.world.scene_builder import MIN_SETTLE_STEPS, build_scene, settle, settle_report
from tests.world.conftest import obj


def test_a_scene_at_rest_stops_settling_early_and_the_same_way_twice(kitchen_scene):
    steps = []
    for _ in range(2):
        built = build_scene(kitchen_scene, settle_steps=0)
        try:
            steps.append(settle(built, 240))
            assert not settle_report(built).moved
        finally:
            built.client.disconnect()
    assert MIN_SETTLE_STEPS <= steps[0] < 240 and steps[0] == steps[1]


def test_something_still_falling_keeps_the_simulation_going(kitchen_scene):
    apple = obj(kitchen_scene, "apple")
    lifted = [o.model_copy(update={"position": (o.position[0], o.position[1], o.position[2] + 1.0)})
              if o.id == apple else o for o in kitchen_scene.objects]
    built = build_scene(kitchen_scene.model_copy(update={"objects": lifted}), settle_steps=0)
    try:
        assert settle(built, 240) > MIN_SETTLE_STEPS  # a metre's fall takes longer than the minimum
        assert apple in settle_report(built).moved
    finally:
        built.client.disconnect()
