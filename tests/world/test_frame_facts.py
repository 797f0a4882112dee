"""What a frame shows is computed only when asked and once per frame, and equals the uncached computation;
a failed action leaves the current frame in place."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.world import frame_facts
from luminous_sim.world.camera import render
from luminous_sim.world.frame_facts import body_ids, object_masks
from luminous_sim.world.masks import bbox_from_mask
from luminous_sim.world.metadata import object_metadata
from tests.world.conftest import obj

LOOK = ["RotateRight", "LookDown", "RotateRight", "MoveAhead", "RotateLeft", "LookUp", "RotateLeft", "RotateLeft"]


@pytest.fixture()
def mask_calls(monkeypatch):
    calls = []
    real = frame_facts.body_counts

    def counted(bodies):
        calls.append(1)
        return real(bodies)

    monkeypatch.setattr(frame_facts, "body_counts", counted)
    return calls


def fresh_render(world):
    pose, c = world.agent, world.config
    eye = np.array(pose.eye())
    return render(world.client, eye, eye + np.array(pose.view_direction()), width=c.width, height=c.height,
                  fov=c.fov, near=0.05, far=20.0, guard=world.eye_guard)


def test_one_step_computes_the_masks_once(world, mask_calls):
    assert world.step("RotateRight").success
    assert mask_calls == []  # nothing is computed until asked
    world.visible_objects()
    assert world._facts._masks is None, "visibility needs pixel counts, not a mask per object"
    world.boxes()
    world.visible_objects()
    world.instance_masks()
    world.metadata()
    world.instance_masks()
    assert len(mask_calls) == 1
    assert world.step("RotateLeft").success
    world.visible_objects()
    world.boxes()
    assert len(mask_calls) == 2


def test_metadata_objects_computed_once_per_frame(world, monkeypatch):
    import luminous_sim.world.metadata as md

    calls = []
    real = md.object_metadata
    monkeypatch.setattr(md, "object_metadata", lambda w, v: calls.append(1) or real(w, v))
    world.step("RotateRight")
    assert world.metadata() == world.metadata()
    assert len(calls) == 1
    world.step("MoveAhead")
    world.metadata()
    assert len(calls) == 2


def test_cached_facts_equal_the_uncached_computation(world):
    cfg = world.config
    for action in LOOK:
        world.step(action)
        seg = world.frame().seg
        bodies = body_ids(seg)
        names = world.body_to_object()
        masks = object_masks(bodies, names)
        assert np.array_equal(world.instance_ids(), bodies)
        got = world.instance_masks()
        assert got.keys() == masks.keys()
        assert all(np.array_equal(got[k], masks[k]) for k in masks)
        assert world.boxes() == {k: bbox_from_mask(m) for k, m in masks.items()}
        visible = {k: int(m.sum()) for k, m in masks.items()
                   if m.sum() >= cfg.min_visible_pixels and world.object_distance(k) <= cfg.visibility_distance}
        assert world.visible_objects() == visible
        objects = world.metadata()["objects"]
        assert objects == object_metadata(world, visible)
        state = world.view().state
        assert all(o["receptacleObjectIds"] == [c for c in state.objects
                                                 if o["objectId"] in state.parent_receptacles(c)]
                   for o in objects)
        assert all(o["parentReceptacles"] == state.parent_receptacles(o["objectId"]) for o in objects)
        assert np.array_equal(world.frame().rgb, fresh_render(world).rgb)


def test_cached_answers_cannot_be_changed_by_a_caller(world):
    world.step("LookDown")
    masks = world.instance_masks()
    assert masks, "the test view shows no object"
    oid = next(iter(masks))
    with pytest.raises(ValueError):
        masks[oid][0, 0] = True
    masks.clear()
    world.visible_objects().clear()
    world.boxes().clear()
    world.metadata()["objects"].clear()
    assert world.instance_masks() and world.boxes() and world.metadata()["objects"]


@pytest.mark.parametrize("rendered_before", [True, False])
def test_a_failed_action_leaves_the_current_frame(world, kitchen_scene, rendered_before):
    fridge = obj(kitchen_scene, "fridge")
    world.step("RotateRight")
    if rendered_before:
        before = world.frame()
    state = world.view().state
    # the fridge cannot be picked up: the reach check renders (when nothing was), then the rules refuse it
    r = world.step({"action": "PickupObject", "objectId": fridge})
    assert not r.success
    assert world.view().state == state
    if rendered_before:
        assert world.frame() is before
    frame, fresh = world.frame(), fresh_render(world)
    assert np.array_equal(frame.rgb, fresh.rgb)
    assert np.array_equal(frame.depth, fresh.depth)
    assert np.array_equal(frame.seg, fresh.seg)


def test_a_frame_rendered_during_a_failed_action_is_not_kept(world, kitchen_scene):
    world.step("RotateRight")
    assert world._facts is None
    r = world.step({"action": "PickupObject", "objectId": obj(kitchen_scene, "fridge")})
    assert not r.success
    assert world._facts is None  # the reach check's frame is dropped; the next question renders the view
