"""Portal culling of the outdoors: a frame with the outdoors left out where no doorway or window shows it is
the frame with everything drawn (depth and segmentation identical, RGB within one level on a few pixels: see
`world.portals`), and the outdoors is still drawn where an opening shows it."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.world.agent import AgentPose
from luminous_sim.world.camera import render
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.portals import Opening, box_corners
from luminous_sim.world.world import World

RGB_TOLERANCE = 1
"""Largest RGB difference allowed (measured: 1, on 1 pixel of the 22 million in these views)."""
MAX_OFF_SHARE = 1e-5
"""Largest share of pixels allowed to differ at all."""


def _views(world: World, step: int) -> list[AgentPose]:
    return [AgentPose(float(x), float(y), rot, hor) for x, y in world.nav.points()[::step]
            for rot in (0, 90, 180, 270) for hor in (-30, 0, 30, 60)]


@pytest.mark.parametrize(("room", "seed", "size", "step"), [
    ("Kitchen", 0, 300, 27), ("LivingRoom", 1, 64, 4), ("Bathroom", 3, 128, 2),
    # every 9th point takes 26 s: the fast suite takes every 27th, the whole sweep is slow
    pytest.param("Kitchen", 0, 300, 9, marks=pytest.mark.slow),
])
def test_outdoors_culled_frames_equal_plain_frames(room, seed, size, step):
    scene = generate(empty_cdf(room), seed=seed).scene
    assert scene.room.doors or scene.room.windows
    with World(scene, WorldConfig(width=size, height=size, settle_steps=0)) as w:
        ground = w.built.outdoors[0]
        hidden_in = shown_in = off = pixels = 0
        for pose in _views(w, step):
            eye = np.array(pose.eye())
            target = eye + np.array(pose.view_direction())
            view = w.client.computeViewMatrix(list(eye), list(target), [0, 0, 1])
            proj = w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
            away = w._culler.outdoors_hidden(view, proj, size, size)
            hidden_in += ground in away
            shown_in += ground not in away
            plain = render(w.client, eye, target, width=size, height=size, guard=w.eye_guard)
            fast = render(w.client, eye, target, width=size, height=size, culler=w._culler)
            for name in ("depth", "seg"):
                assert np.array_equal(getattr(plain, name), getattr(fast, name)), (name, pose, away)
            diff = np.abs(plain.rgb.astype(int) - fast.rgb.astype(int))
            assert diff.max() <= RGB_TOLERANCE, (pose, away, diff.max())
            off += int(diff.any(axis=-1).sum())
            pixels += size * size
        assert hidden_in and shown_in, (hidden_in, shown_in)
        assert off <= MAX_OFF_SHARE * pixels, (off, pixels)
        assert all(w.client.getVisualShapeData(b)[0][7][3] == 1.0 for b in w.built.outdoors), "colours put back"


def test_the_outdoors_is_drawn_through_an_open_doorway():
    """Standing in front of a door and looking through it, the ground beyond shows in the frame and is not
    culled (the views where it is left out are in the test above)."""
    scene = generate(empty_cdf("Kitchen"), seed=0).scene
    door = scene.room.doors[0]
    wall = next(wl for wl in scene.room.walls if wl.id == door.wall)
    with World(scene, WorldConfig(width=64, height=64, settle_steps=0)) as w:
        mid = np.array(wall.point(door.offset + door.width / 2, 0.0))
        pts = w.nav.points()
        x, y = pts[int(np.argmin(np.linalg.norm(pts - mid, axis=1)))]
        yaw = float(np.degrees(np.arctan2(mid[0] - x, mid[1] - y)))  # 0 = +y, 90 = +x
        facing = round(yaw / 90.0) % 4 * 90
        hidden = {}
        for rot in (0, 90, 180, 270):
            pose = AgentPose(float(x), float(y), rot, 30)
            eye = np.array(pose.eye())
            view = w.client.computeViewMatrix(list(eye), list(eye + np.array(pose.view_direction())), [0, 0, 1])
            proj = w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
            hidden[rot] = set(w._culler.outdoors_hidden(view, proj, 64, 64))
            if rot == facing:
                w.agent = pose
                w.invalidate_frame()
                assert (w.frame().seg == w.built.outdoors[0]).any(), "the ground is seen through the doorway"
        assert w.built.outdoors[0] not in hidden[facing]


def test_a_box_beside_an_opening_is_hidden_and_one_behind_it_is_not():
    scene = generate(empty_cdf("Bedroom"), seed=0).scene
    room = scene.room
    wall = room.walls[0]
    op = Opening(room, wall.id, 1.0, 2.0, 0.0, 2.0)
    eye = np.array([*wall.point(1.5, 2.0), 1.5])
    n = np.array([*wall.normal, 0.0])
    d = np.array([*wall.direction, 0.0])
    behind = np.array([*wall.point(1.5, -2.0), 1.0])
    aside = np.array([*wall.point(8.0, -0.5), 1.0])  # beyond the wall, far along it: no ray through the hole
    boxes = np.stack([box_corners(c - 0.2, c + 0.2) for c in (behind, aside)])
    assert op.hides(eye, boxes).tolist() == [False, True]
    assert op.depth(eye) == pytest.approx(2.0)
    assert float(n @ d) == pytest.approx(0.0)


def test_cull_outdoors_off_draws_the_outdoors_in_every_view():
    scene = generate(empty_cdf("Kitchen"), seed=0).scene
    with World(scene, WorldConfig(width=64, height=64, settle_steps=0, cull_outdoors=False)) as w:
        pose = _views(w, 9)[0]
        eye = np.array(pose.eye())
        view = w.client.computeViewMatrix(list(eye), list(eye + np.array(pose.view_direction())), [0, 0, 1])
        proj = w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
        assert w._culler is not None and w._culler.outdoors_hidden(view, proj, 64, 64) == []


@pytest.mark.parametrize(("room", "seed"), [("Kitchen", 0), ("LivingRoom", 1), ("Bathroom", 3)])
def test_the_compiled_outdoor_test_answers_as_numpy_does(room, seed):
    """The compiled rasteriser's copy of the portal test (`OutdoorCuller.hidden_compiled`) hides the same outdoor
    boxes as `hidden` in every view at every reachable point, and both hide and show some."""
    scene = generate(empty_cdf(room), seed=seed).scene
    with World(scene, WorldConfig(width=64, height=64, settle_steps=0)) as w:
        hidden = shown = 0
        for pose in _views(w, 1):
            eye = np.array(pose.eye())
            view = w.client.computeViewMatrix(list(eye), list(eye + np.array(pose.view_direction())), [0, 0, 1])
            proj = w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
            away = w._culler.outdoors_hidden(view, proj, 64, 64)
            assert w._culler.outdoors_hidden(view, proj, 64, 64, compiled=True) == away, pose
            hidden += len(away)
            shown += len(w.built.outdoors) - len(away)
        assert hidden and shown
