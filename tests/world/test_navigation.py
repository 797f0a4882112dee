"""ALFRED's navigation actions: grid moves, 90-degree turns, 15-degree looks within -30..60, teleports."""

from __future__ import annotations

import numpy as np

from luminous_sim.world.agent import AgentPose


def test_move_rotate_look(world):
    start = world.agent
    assert start.grid_key() in world.nav and start.horizon == 30
    r = world.step("RotateRight")
    assert r.success and world.agent.rotation == (start.rotation + 90) % 360
    world.step("RotateLeft")
    assert world.agent == start
    for _ in range(2):
        assert world.step("LookDown").success
    assert world.agent.horizon == 60
    r = world.step("LookDown")
    assert not r.success and "-30..60" in r.error and world.agent.horizon == 60
    for _ in range(6):
        world.step("LookUp")
    assert world.agent.horizon == -30 and not world.step("LookUp").success


def test_move_ahead_follows_the_grid_and_stops_at_obstacles(world):
    moved = blocked = 0
    for _ in range(40):
        before = world.agent
        r = world.step({"action": "MoveAhead", "forceAction": True, "moveMagnitude": 0.25})
        if r.success:
            moved += 1
            assert world.agent.grid_key() in world.nav
            assert abs(np.hypot(world.agent.x - before.x, world.agent.y - before.y) - 0.25) < 1e-6
        else:
            blocked += 1
            assert world.agent == before and "blocked" in r.error
            world.step("RotateRight")
    assert moved > 0 and blocked > 0


def test_bad_actions_fail_cleanly(world):
    before = world.agent
    for action in ["Fly", {"action": 3}, {"action": "MoveAhead", "moveMagnitude": 0.5},
                   {"action": "TeleportFull", "x": 99.0, "z": 99.0, "rotation": 0, "horizon": 30},
                   {"action": "TeleportFull", "x": before.x, "z": before.y, "rotation": 45, "horizon": 30},
                   {"action": "Teleport"}]:
        r = world.step(action)
        assert not r.success and r.error, action
        assert world.agent == before
    assert world.metadata()["lastActionSuccess"] is False


def test_teleport_full_uses_thor_axes(world):
    pts = world.nav.points()
    x, y = pts[len(pts) // 3]
    r = world.step({"action": "TeleportFull", "x": float(x), "y": 0.9, "z": float(y), "rotation": 270, "horizon": 15})
    assert r.success and world.agent == AgentPose(float(x), float(y), 270, 15)
    md = world.metadata()["agent"]
    assert md["position"]["x"] == float(x) and md["position"]["z"] == float(y) and md["cameraHorizon"] == 15


def test_frames_have_alfred_shape_and_are_deterministic(kitchen_scene):
    from luminous_sim.world.world import World, WorldConfig

    runs = []
    for _ in range(2):
        with World(kitchen_scene, WorldConfig(settle_steps=120)) as w:
            frames = []
            for a in ["RotateRight", "MoveAhead", "LookDown", "RotateLeft", "MoveAhead"]:
                w.step(a)
                f = w.frame()
                frames.append((f.rgb.copy(), f.depth.copy(), f.seg.copy()))
            runs.append(frames)
    for (a_rgb, a_d, a_s), (b_rgb, b_d, b_s) in zip(*runs):
        assert a_rgb.shape == (300, 300, 3) and a_rgb.dtype == np.uint8
        assert np.array_equal(a_rgb, b_rgb) and np.array_equal(a_d, b_d) and np.array_equal(a_s, b_s)
    assert np.isfinite(runs[0][0][1]).all() and (runs[0][0][1] > 0).all()


def test_egl_renderer_matches_tiny_renderer_geometry(kitchen_scene):
    """The EGL plugin (hardware OpenGL, or Mesa without a GPU) sees the same objects as TinyRenderer."""
    import pkgutil

    import pytest

    from luminous_sim.world.client import resolve_renderer
    from luminous_sim.world.world import World, WorldConfig

    if pkgutil.get_loader("eglRenderer") is None:
        pytest.skip("PyBullet's eglRenderer plugin is not available here")
    assert resolve_renderer("tiny") == "tiny" and resolve_renderer("egl") == "egl"
    seen = {}
    for renderer in ("tiny", "egl"):
        with World(kitchen_scene, WorldConfig(settle_steps=60, renderer=renderer)) as w:
            w.step("RotateRight")
            f = w.frame()
            assert f.rgb.std() > 10
            seen[renderer] = set(w.instance_masks())
    assert len(seen["tiny"] & seen["egl"]) >= 0.8 * len(seen["tiny"])


def test_sensors_boxes_depth_segmentation_and_map(world):
    f = world.frame()
    masks = world.instance_masks()
    boxes = world.boxes()
    assert masks and set(boxes) == set(masks)
    for oid, (x0, y0, x1, y1) in boxes.items():
        rows, cols = np.nonzero(masks[oid])
        assert x0 == cols.min() and x1 == cols.max() and y0 == rows.min() + 1 and y1 == rows.max() + 1
        assert float(np.median(f.depth[masks[oid]])) < 20.0
    img = world.top_down()
    assert img.size[0] > 100 and np.asarray(img).std() > 10
