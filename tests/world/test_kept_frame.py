"""A frame rendered while searching for a pose that sees an object is served when the agent walks there,
and only while it shows exactly what a new render would."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.world.poses import find_interaction_pose
from tests.world.conftest import obj


@pytest.fixture()
def renders(monkeypatch):
    """Counts the World's full-size renders."""
    import luminous_sim.world.world as world_module

    calls = []
    original = world_module.render

    def counted(*args, **kwargs):
        calls.append(1)
        return original(*args, **kwargs)

    monkeypatch.setattr(world_module, "render", counted)
    return calls


def _teleport(world, pose):
    r = world.step({"action": "TeleportFull", "x": pose.x, "z": pose.y, "rotation": pose.rotation,
                    "horizon": pose.horizon})
    assert r.success, r.error
    assert world.agent == pose


def _same_as_a_new_render(world) -> None:
    served = world.frame()
    world.invalidate_frame()
    fresh = world.frame()
    for a, b in zip((served.rgb, served.depth, served.seg), (fresh.rgb, fresh.depth, fresh.seg), strict=True):
        assert np.array_equal(a, b)


def test_arriving_at_the_found_pose_serves_its_frame(world, kitchen_scene, renders):
    apple = obj(kitchen_scene, "apple")
    start = world.agent
    pose = find_interaction_pose(world, apple)
    assert pose is not None and world.agent == start
    searched = len(renders)
    world.frame()  # the start pose's frame: the kept one is not for it
    assert len(renders) == searched + 1
    _teleport(world, pose)
    assert apple in world.visible_objects()
    assert len(renders) == searched + 1  # served, not rendered
    _same_as_a_new_render(world)


def test_an_interaction_or_an_invalidation_drops_the_kept_frame(world, kitchen_scene, renders):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    pose = find_interaction_pose(world, apple)
    world.step({"action": "PickupObject", "objectId": fridge})  # fails, but it is not navigation
    before = len(renders)
    _teleport(world, pose)
    world.frame()
    assert len(renders) == before + 1
    pose = find_interaction_pose(world, fridge)
    world.invalidate_frame()
    before = len(renders)
    _teleport(world, pose)
    world.frame()
    assert len(renders) == before + 1


def test_a_held_object_must_be_where_it_was(world, kitchen_scene, renders):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    _teleport(world, find_interaction_pose(world, apple))
    assert world.step({"action": "PickupObject", "objectId": apple}).success
    pose = find_interaction_pose(world, fridge)
    assert pose is not None
    _teleport(world, pose)
    _same_as_a_new_render(world)  # served or rendered anew, the frame is the one a render gives
    body = world.built.objects[apple].body
    kept = world.frame_memo()
    world.invalidate_frame()
    world.keep_frame(kept)
    pos, orn = world.client.getBasePositionAndOrientation(body)
    world.client.resetBasePositionAndOrientation(body, (pos[0] + 0.01, pos[1], pos[2]), orn)
    before = len(renders)
    world.frame()
    assert len(renders) == before + 1  # the apple moved: the kept frame no longer shows it
