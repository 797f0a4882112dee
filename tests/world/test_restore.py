"""`World.reset_to_start`: a world put back as built plays exactly like a new one; a world whose physics was
touched is not put back."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.world.poses import find_interaction_pose
from luminous_sim.world.world import World, WorldConfig
from tests.world.conftest import obj

CONFIG = WorldConfig(width=96, height=96, settle_steps=120)


def go_to(world: World, object_id: str) -> dict:
    pose = find_interaction_pose(world, object_id)
    assert pose is not None, f"no pose sees {object_id}"
    return {"action": "TeleportFull", "x": pose.x, "z": pose.y, "rotation": pose.rotation, "horizon": pose.horizon}


def snapshot(world: World) -> tuple:
    """Everything an agent or a test could read: frame, instances, poses, pure state, pose, metadata."""
    f = world.frame()
    poses = {o: (tuple(p.tolist()), yaw) for o, (p, yaw) in ((o, world.built.pose_of(o)) for o in world.built.objects)}
    return (f.rgb.tobytes(), f.depth.tobytes(), world.instance_ids().tobytes(), poses, world.view().state,
            world.agent, repr(world.metadata()))


def poses(scene) -> dict[str, dict]:
    """A teleport to where each object is seen within reach, found in a world of its own (the search tries
    doors' swings, which touches the physics)."""
    with World(scene, CONFIG) as scout:
        return {name: go_to(scout, obj(scene, name)) for name in ("mug", "fridge", "microwave", "plate", "apple")}


def episode(world: World, scene, at: dict[str, dict]) -> list[tuple]:
    """Look at the plate, pick the mug up, open the fridge and the microwave, put the mug in, switch it on."""
    mug, fridge, microwave = obj(scene, "mug"), obj(scene, "fridge"), obj(scene, "microwave")
    out = []
    for action in [at["plate"], at["mug"], {"action": "PickupObject", "objectId": mug}, {"action": "RotateLeft"},
                   at["fridge"], {"action": "OpenObject", "objectId": fridge},
                   at["microwave"], {"action": "OpenObject", "objectId": microwave},
                   {"action": "PutObject", "receptacleObjectId": microwave},
                   {"action": "CloseObject", "objectId": microwave},
                   {"action": "ToggleObjectOn", "objectId": microwave}, {"action": "MoveAhead"}]:
        r = world.step(action)
        out.append((action["action"], r.success, r.error, snapshot(world)))
    return out


def test_a_restored_world_plays_an_episode_exactly_as_a_new_one(kitchen_scene):
    plate, microwave, apple = (obj(kitchen_scene, n) for n in ("plate", "microwave", "apple"))
    at = poses(kitchen_scene)
    with World(kitchen_scene, CONFIG) as new, World(kitchen_scene, CONFIG) as used:
        start = snapshot(new)
        used.set_up_dirty([plate])  # a state visual shown
        used.view().unseeable()  # ray tests and renders do not touch the physics
        for action in [at["plate"], {"action": "LookDown"}, at["microwave"],
                       {"action": "ToggleObjectOn", "objectId": microwave},  # another state visual
                       {"action": "PickupObject", "objectId": "Unicorn|+0|+0|+0"},
                       {"action": "OpenObject", "objectId": apple}, {"action": "MoveAhead"}]:
            used.step(action)
        assert used.view().state.objects[microwave].isToggled and used.view().state.objects[plate].isDirty
        assert snapshot(used) != start
        assert used.reset_to_start()
        assert snapshot(used) == start and used.last.action["action"] == "Initialize"
        for world in (new, used):
            world.set_up_dirty([apple])  # set-up is allowed again
        played_new, played_used = episode(new, kitchen_scene, at), episode(used, kitchen_scene, at)
        assert [s[:3] for s in played_new] == [s[:3] for s in played_used]
        assert all(ok for _, ok, _, _ in played_new)  # a pick-up, openings, a put (physics), a toggle
        for (name, _, _, a), (_, _, _, b) in zip(played_new, played_used, strict=True):
            assert a == b, name


@pytest.mark.parametrize("touch", ["pickup", "planner_swing"])
def test_a_world_whose_physics_was_touched_is_not_restored(kitchen_scene, touch):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    with World(kitchen_scene, CONFIG) as w:
        if touch == "pickup":
            for action in [go_to(w, apple), {"action": "PickupObject", "objectId": apple}]:
                assert w.step(action).success, action
        else:  # a closed door's swing, tried and undone: hidden broadphase state steers later physics
            w.view().interaction_pose(fridge)
        before, agent, pose = w.view().state, w.agent, w.built.pose_of(apple)
        assert not w.reset_to_start()
        assert w.view().state == before and w.agent == agent and np.array_equal(w.built.pose_of(apple)[0], pose[0])
