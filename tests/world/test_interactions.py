"""Interaction actions and ALFRED's state changes, physically, in a generated kitchen."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.world import FailureCode, interaction_args
from luminous_sim.world.poses import find_interaction_pose
from tests.world.conftest import obj


def go_to(world, object_id: str) -> None:
    pose = find_interaction_pose(world, object_id)
    assert pose is not None, f"no pose sees {object_id}"
    r = world.step({"action": "TeleportFull", "x": pose.x, "z": pose.y, "rotation": pose.rotation,
                    "horizon": pose.horizon})
    assert r.success, r.error
    assert object_id in world.visible_objects()


def state(world, object_id: str):
    return world.view().state.objects[object_id]


def test_pickup_and_hand_full(world, kitchen_scene):
    apple, mug = obj(kitchen_scene, "apple"), obj(kitchen_scene, "mug")
    go_to(world, apple)
    r = world.step({"action": "PickupObject", "objectId": apple})
    assert r.success, r.error
    assert world.view().held == apple and state(world, apple).isPickedUp and state(world, apple).parent is None
    md = world.metadata()
    assert md["inventoryObjects"][0]["objectId"] == apple and md["lastActionSuccess"]
    go_to(world, mug)
    r = world.step({"action": "PickupObject", "objectId": mug})
    assert not r.success and ("hand is full" in r.error.lower() or "holding" in r.error.lower())


def test_invalid_interactions_fail_without_changing_anything(world, kitchen_scene):
    apple = obj(kitchen_scene, "apple")
    before = world.view().state
    for action in [{"action": "PickupObject", "objectId": "Unicorn|+0|+0|+0"},
                   {"action": "PutObject", "receptacleObjectId": apple},
                   {"action": "OpenObject", "objectId": apple},
                   {"action": "PickupObject"},
                   {"action": "SliceObject", "objectId": apple}]:
        r = world.step(action)
        assert not r.success and r.error, action
    assert world.view().state == before


def test_far_objects_cannot_be_touched(world, kitchen_scene):
    fridge = obj(kitchen_scene, "fridge")
    pts = world.nav.points()
    fpos = np.array(world.built.pose_of(fridge)[0][:2])
    far = pts[int(np.argmax(np.linalg.norm(pts - fpos, axis=1)))]
    world.step({"action": "TeleportFull", "x": float(far[0]), "z": float(far[1]), "rotation": 0, "horizon": 30})
    r = world.step({"action": "OpenObject", "objectId": fridge})
    assert not r.success and ("too far" in r.error or "not visible" in r.error)


def test_cool_in_fridge_and_put_rules(world, kitchen_scene):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    go_to(world, apple)
    assert world.step({"action": "PickupObject", "objectId": apple}).success
    go_to(world, fridge)
    r = world.step({"action": "PutObject", "objectId": apple, "receptacleObjectId": fridge})
    assert not r.success and "closed" in r.error
    assert world.step({"action": "OpenObject", "objectId": fridge}).success and state(world, fridge).isOpen
    r = world.step({"action": "PutObject", "objectId": apple, "receptacleObjectId": fridge})
    assert r.success, r.error
    assert state(world, apple).parent == fridge and world.view().held is None
    assert apple not in world.view().state.cooled
    assert world.step({"action": "CloseObject", "objectId": fridge}).success
    assert apple in world.view().state.cooled and state(world, apple).temperature == "Cold"
    pos = world.built.pose_of(apple)[0]
    lo, hi = map(np.array, world.client.getAABB(world.built.objects[fridge].body, -1))
    assert np.all(pos >= lo - 0.01) and np.all(pos <= hi + 0.01), "the apple is physically in the fridge"
    assert not world.step({"action": "PickupObject", "objectId": apple}).success  # shut in the fridge
    assert world.step({"action": "OpenObject", "objectId": fridge}).success
    near = world.object_distance(apple) <= world.config.visibility_distance
    assert (world.view().open_container_in_view(apple) == fridge) == near
    r = world.step({"action": "PickupObject", "objectId": apple})
    assert r.success == near, r.error  # out of the open fridge in view, if it is within 1.5 m


def test_heat_in_microwave(world, kitchen_scene):
    mug, micro = obj(kitchen_scene, "mug"), obj(kitchen_scene, "microwave")
    go_to(world, mug)
    assert world.step({"action": "PickupObject", "objectId": mug}).success
    go_to(world, micro)
    assert world.step({"action": "OpenObject", "objectId": micro}).success
    r = world.step({"action": "PutObject", "objectId": mug, "receptacleObjectId": micro})
    assert r.success, r.error
    r = world.step({"action": "ToggleObjectOn", "objectId": micro})
    assert not r.success and "closed" in r.error  # a microwave runs only when closed
    assert world.step({"action": "CloseObject", "objectId": micro}).success
    assert world.step({"action": "ToggleObjectOn", "objectId": micro}).success
    assert mug in world.view().state.heated and state(world, mug).temperature == "Hot"
    assert not world.step({"action": "ToggleObjectOn", "objectId": micro}).success  # already on


def test_clean_in_sink(world, kitchen_scene):
    mug = obj(kitchen_scene, "mug")
    basin = next(o.id for o in kitchen_scene.objects if o.type == "SinkBasin")
    faucet = next(o.id for o in kitchen_scene.objects if o.type == "Faucet")
    assert state(world, mug).isDirty
    go_to(world, mug)
    assert world.step({"action": "PickupObject", "objectId": mug}).success
    go_to(world, basin)
    r = world.step({"action": "PutObject", "objectId": mug, "receptacleObjectId": basin})
    assert r.success, r.error
    go_to(world, faucet)
    assert world.step({"action": "ToggleObjectOn", "objectId": faucet}).success
    assert not state(world, mug).isDirty and mug in world.view().state.cleaned


def test_slice_with_a_knife(world, kitchen_scene):
    apple, knife = obj(kitchen_scene, "apple"), obj(kitchen_scene, "knife")
    go_to(world, apple)
    r = world.step({"action": "SliceObject", "objectId": apple})
    assert not r.success and "Knife" in r.error
    go_to(world, knife)
    assert world.step({"action": "PickupObject", "objectId": knife}).success
    go_to(world, apple)
    r = world.step({"action": "SliceObject", "objectId": apple})
    assert r.success, r.error
    slices = [o for o in world.view().state.objects if o.startswith(apple + "|AppleSliced_")]
    assert len(slices) >= 2 and apple not in world.view().state.objects
    assert all(s in world.built.objects for s in slices) and apple not in world.built.objects
    assert all(world.built.pose_of(s)[0][2] > 0.5 for s in slices), "slices stay on the counter"


def test_movable_receptacle_carries_its_contents(world, kitchen_scene):
    apple, plate = obj(kitchen_scene, "apple"), obj(kitchen_scene, "plate")
    go_to(world, apple)
    assert world.step({"action": "PickupObject", "objectId": apple}).success
    go_to(world, plate)
    r = world.step({"action": "PutObject", "objectId": apple, "receptacleObjectId": plate})
    assert r.success, r.error
    assert world.step({"action": "PickupObject", "objectId": plate}).success
    before = world.built.pose_of(plate)[0]
    assert world.step("RotateRight").success
    after = world.built.pose_of(plate)[0]
    assert np.linalg.norm(after - before) > 0.2, "the held plate turns with the agent"
    gap = np.linalg.norm(world.built.pose_of(apple)[0] - after)
    assert gap < 0.15, "the apple rides on the plate"
    assert state(world, apple).parent == plate
    world.step("RotateLeft")
    assert state(world, plate).isPickedUp
    counter = kitchen_scene.object(plate).parent
    go_to(world, counter)
    r = world.step({"action": "PutObject", "objectId": plate, "receptacleObjectId": counter})
    assert r.success, r.error
    assert state(world, plate).parent == counter and state(world, apple).parent == plate
    gap = np.linalg.norm(world.built.pose_of(apple)[0][:2] - world.built.pose_of(plate)[0][:2])
    assert gap < 0.12, "put down, the plate still carries the apple"
    # AI2-THOR's containment (what ALFRED's ThorEnv reads when a fridge closes): the apple is in the plate and
    # in what the plate stands on
    objects = {o["objectId"]: o for o in world.metadata()["objects"]}
    assert objects[apple]["parentReceptacles"] == [plate, counter]
    assert apple in objects[counter]["receptacleObjectIds"] and plate in objects[counter]["receptacleObjectIds"]
    assert objects[plate]["receptacleObjectIds"] == [apple]


def test_put_refuses_incompatible_and_full_receptacles(world, kitchen_scene, monkeypatch):
    knife, micro = obj(kitchen_scene, "knife"), obj(kitchen_scene, "microwave")
    go_to(world, knife)
    assert world.step({"action": "PickupObject", "objectId": knife}).success
    go_to(world, micro)
    assert world.step({"action": "OpenObject", "objectId": micro}).success
    before = world.view().state
    r = world.step({"action": "PutObject", "objectId": knife, "receptacleObjectId": micro})
    # a knife never goes in a microwave in ALFRED
    assert not r.success and "compatib" in r.error and r.code == FailureCode.INCOMPATIBLE
    assert world.view().state == before and world.view().held == knife
    counter = kitchen_scene.object(knife).parent
    go_to(world, counter)
    from luminous_sim.world import placement

    monkeypatch.setattr(placement, "sample_in_region", lambda *a, **k: None)  # no free spot anywhere:
    monkeypatch.setattr(placement, "scan_region", lambda *a, **k: iter(()))  # not by draws, nor by a scan
    r = world.step({"action": "PutObject", "objectId": knife, "receptacleObjectId": counter})
    assert not r.success and "full" in r.error and r.code == FailureCode.RECEPTACLE_FULL
    assert world.view().held == knife and state(world, knife).parent is None


def test_target_by_mask_and_point(world, kitchen_scene):
    apple = obj(kitchen_scene, "apple")
    go_to(world, apple)
    mask = world.instance_masks()[apple]
    args = interaction_args(mask)
    r = world.step({"action": "PickupObject", "mask": args["mask"]})
    assert r.success and world.view().held == apple, r.error


@pytest.mark.parametrize("action", ["OpenObject", "ToggleObjectOn"])
def test_wrong_target_kind(world, kitchen_scene, action):
    apple = obj(kitchen_scene, "apple")
    go_to(world, apple)
    r = world.step({"action": action, "objectId": apple})
    assert not r.success and r.error
