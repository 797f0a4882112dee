"""Doors swing clear of the agent: OpenObject refuses to hit it, and interaction poses stand clear."""

from __future__ import annotations

import numpy as np

from luminous_sim.world.agent import AgentPose
from luminous_sim.world.doors import hits_agent, swept_boxes
from luminous_sim.world.poses import find_interaction_pose
from tests.world.conftest import obj


def test_hits_agent_on_synthetic_boxes():
    door = [(np.array([0.0, 0.0, 0.0]), np.array([0.5, 0.05, 1.8]))]
    assert hits_agent(door, 0.25, 0.2)  # 0.15 m in front of the door: inside the 0.2 m radius
    assert not hits_agent(door, 0.25, 0.3)
    high = [(np.array([0.0, 0.0, 1.7]), np.array([0.5, 0.4, 2.2]))]  # a wall cabinet above the camera
    assert not hits_agent(high, 0.25, 0.2)


def test_swept_boxes_reach_beyond_the_closed_body_and_restore_joints(world, kitchen_scene):
    fridge = obj(kitchen_scene, "fridge")
    loaded = world.built.objects[fridge]
    before = [world.client.getJointState(loaded.body, j)[0] for j in loaded.joint_index.values()]
    closed_lo, closed_hi = map(np.array, world.client.getAABB(loaded.body, -1))
    boxes = swept_boxes(world, fridge)
    assert boxes
    lo = np.min([b[0] for b in boxes], axis=0)
    hi = np.max([b[1] for b in boxes], axis=0)
    assert (lo[:2] < closed_lo[:2] - 0.2).any() or (hi[:2] > closed_hi[:2] + 0.2).any()  # the door swings out
    assert [world.client.getJointState(loaded.body, j)[0] for j in loaded.joint_index.values()] == before


def test_open_refused_when_the_door_would_hit_the_agent(world, kitchen_scene):
    fridge = obj(kitchen_scene, "fridge")
    boxes = swept_boxes(world, fridge)
    inside = [(x, y) for x, y in world.nav.points() if hits_agent(boxes, x, y)]
    assert inside, "the fixture kitchen has grid points in the fridge door's swing"
    refused = False
    for x, y in inside:
        for rot in (0, 90, 180, 270):
            world.agent = AgentPose(float(x), float(y), rot, 30)
            world.invalidate_frame()
            if fridge in world.visible_objects():
                r = world.step({"action": "OpenObject", "objectId": fridge})
                assert not r.success and "hit the agent" in r.error
                assert not world.view().state.objects[fridge].isOpen
                refused = True
                break
        if refused:
            break
    assert refused
    pose = find_interaction_pose(world, fridge)
    assert pose is not None and not hits_agent(boxes, pose.x, pose.y)
    world.agent = pose
    world.invalidate_frame()
    assert world.step({"action": "OpenObject", "objectId": fridge}).success
