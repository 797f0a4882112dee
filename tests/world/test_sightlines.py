"""Sight lines from reachable poses: what an agent could see, checked by rays (and against the renderer)."""

from __future__ import annotations

import numpy as np

from luminous_sim.planning.task_fit import unseeable
from luminous_sim.world.poses import find_interaction_pose
from luminous_sim.world.sightlines import seeable
from tests.world.conftest import obj


def _move(world, oid, xyz):
    body = world.built.objects[oid].body
    _, orn = world.client.getBasePositionAndOrientation(body)
    world.client.resetBasePositionAndOrientation(body, xyz, orn)


def test_objects_on_the_counter_are_seeable_and_the_renderer_agrees(world, kitchen_scene):
    names = ["apple", "knife", "mug", "plate"]
    ids = [obj(kitchen_scene, n) for n in names]
    seen = seeable(world, ids)
    assert all(seen.values()), seen
    for oid in ids:
        assert find_interaction_pose(world, oid) is not None


def test_an_object_shut_in_the_fridge_or_out_of_reach_is_not(world, kitchen_scene):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    lo, hi = map(np.array, world.client.getAABB(world.built.objects[fridge].body, -1))
    _move(world, apple, tuple((lo + hi) / 2))  # inside the closed fridge's body
    assert seeable(world, [apple]) == {apple: False}
    far = world.nav.points().max(axis=0) + 3.0  # beyond the room, out of every pose's reach
    _move(world, apple, (float(far[0]), float(far[1]), 0.9))
    assert seeable(world, [apple]) == {apple: False}
    assert apple in unseeable(world.view())


def test_physics_check_reports_unseeable_objects(kitchen_scene):
    from luminous_sim.vocab import abilities
    from luminous_sim.world.physics_check import check_physics

    report = check_physics(kitchen_scene, settle_steps=10)
    types = {o.id: o.type for o in kitchen_scene.objects}
    assert all(abilities(types[o]).pickupable or abilities(types[o]).receptacle or abilities(types[o]).toggleable
               or abilities(types[o]).openable for o in report.unseeable)
    assert not {obj(kitchen_scene, n) for n in ("apple", "knife", "mug", "plate")} & set(report.unseeable)
    assert set(report.seconds) == {"build", "settle", "sight"} and all(v >= 0 for v in report.seconds.values())
    assert "seconds" not in report.to_dict()  # the file next to a scene stays the same from run to run
    apple = obj(kitchen_scene, "apple")
    lo = np.array(kitchen_scene.room.bounds[:2])
    away = [o.model_copy(update={"position": (float(lo[0]) - 3.0, float(lo[1]) - 3.0, 0.5), "parent": None})
            if o.id == apple else o for o in kitchen_scene.objects]
    moved = check_physics(kitchen_scene.model_copy(update={"objects": away}), settle_steps=10)
    assert apple in moved.unseeable and "unseeable" in moved.to_dict()


def test_worlds_of_one_scene_share_the_answer_while_their_physics_is_as_built(kitchen_scene, monkeypatch):
    import luminous_sim.world.sightlines as sightlines
    from luminous_sim.world.world import World, WorldConfig

    config = WorldConfig(settle_steps=120)
    calls = []
    original = sightlines.unseen

    def counted(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(sightlines, "_ANSWERS", type(sightlines._ANSWERS)())
    monkeypatch.setattr(sightlines, "unseen", counted)
    with World(kitchen_scene, config) as first:
        bodies = {oid: lo.body for oid, lo in first.built.objects.items()}
        truth = original(first.client, first.view().state, bodies, first.nav.points(), config.visibility_distance)
        assert unseeable(first.view()) == truth and len(calls) == 1
    with World(kitchen_scene, config) as second:
        assert unseeable(second.view()) == truth and len(calls) == 1  # remembered
        apple = obj(kitchen_scene, "apple")
        lo, hi = map(np.array, second.client.getAABB(second.built.objects[obj(kitchen_scene, "fridge")].body, -1))
        _move(second, apple, tuple((lo + hi) / 2))  # the physics is touched: asked anew
        assert apple in unseeable(second.view()) and len(calls) == 2
    with World(kitchen_scene, WorldConfig(settle_steps=100)) as other:
        unseeable(other.view())  # other settings: another world, asked anew
        assert len(calls) == 3
