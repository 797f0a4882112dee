"""The compiled rasteriser (`rasteriser="compiled"`) draws TinyRenderer's frames: the same RGB and
segmentation (equal in these views; elsewhere about 6 pixels in a million differ, where two surfaces lie within
float rounding of each other) and depth within float rounding, against PyBullet's own TinyRenderer on the same
views, through walking and interactions."""

from __future__ import annotations

import numpy as np
import pybullet as pb
import pytest
from pybullet_utils.bullet_client import BulletClient

from luminous_sim.world.config import WorldConfig
from luminous_sim.world.culling import Boxes
from luminous_sim.world.raster_scene import RasterScene, UnsupportedGeometry, _visual_files
from luminous_sim.world.world import World
from tests.world.conftest import mug_into_fridge, obj

NAV = ["MoveAhead", "RotateRight", "MoveAhead", "LookDown", "RotateLeft", "MoveAhead", "LookUp", "RotateLeft"]
DEPTH_TOLERANCE = 1e-4
"""Metres depth may differ (measured at most 5.2e-5 m, on 1-2% of pixels: where PyBullet's float32 rounding of
a link's pose or a mesh vertex differs in the last bit from ours); RGB and segmentation must be equal."""


def _assert_same(a, b, where) -> None:
    assert np.array_equal(a.rgb, b.rgb), ("rgb", where, int((a.rgb != b.rgb).any(axis=2).sum()))
    assert np.array_equal(a.seg, b.seg), ("seg", where, int((a.seg != b.seg).sum()))
    assert np.abs(a.depth - b.depth).max() <= DEPTH_TOLERANCE, ("depth", where)


def test_a_box_is_drawn_as_tinyrenderer_draws_it():
    """One box, turned and seen from above at an angle: RGB and segmentation equal pixel for pixel."""
    c = BulletClient(pb.DIRECT)
    try:
        vis = c.createVisualShape(pb.GEOM_BOX, halfExtents=[0.5, 0.3, 0.2], rgbaColor=[0.8, 0.5, 0.3, 1])
        c.createMultiBody(0, -1, vis, [1.0, 0.2, 0.3], c.getQuaternionFromEuler([0, 0, 0.7]))
        scene = RasterScene(c, {})
        view = c.computeViewMatrix([-1.2, -0.7, 1.1], [1.0, 0.2, 0.3], [0, 0, 1])
        proj = c.computeProjectionMatrixFOV(60, 1, 0.05, 20)
        light = [0.4, -0.6, 1.0]
        rgb, depth, seg = scene.render(view, proj, 64, 64, light, Boxes(c, []), np.zeros(0, bool), [])
        _, _, rgba, z, ref_seg = c.getCameraImage(64, 64, view, proj, renderer=pb.ER_TINY_RENDERER, shadow=0,
                                                  lightDirection=light,
                                                  flags=pb.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)
        ref_rgb = np.asarray(rgba, np.uint8).reshape(64, 64, 4)[:, :, :3]
        covered = np.asarray(ref_seg).reshape(64, 64) >= 0
        assert covered.sum() > 200
        assert np.array_equal(rgb, ref_rgb)
        assert np.array_equal(seg, np.asarray(ref_seg).reshape(64, 64))
        assert np.allclose(depth, np.asarray(z, np.float32).reshape(64, 64), rtol=0, atol=1e-6)
    finally:
        c.disconnect()


@pytest.mark.parametrize("size", [64, 128, 300])
def test_compiled_frames_are_tinyrenderers_while_walking(kitchen_scene, size):
    config = WorldConfig(width=size, height=size, settle_steps=120, rasteriser="tinyrenderer")
    with World(kitchen_scene, config) as ref, \
            World(kitchen_scene, WorldConfig(width=size, height=size, settle_steps=120, rasteriser="compiled")) as w:
        assert w._compiled is not None
        culled = 0
        for i in range(48):
            ref.step(NAV[i % len(NAV)])
            w.step(NAV[i % len(NAV)])
            a, b = w.frame(), ref.frame()
            assert (b.seg >= 0).mean() > 0.9  # a real view, not the background
            _assert_same(a, b, i)
            culled += len(w._culler.outside(*_matrices(w), size, size))
        assert culled > 0, "no view left a link out: the culled path is not tested"


def _matrices(world: World) -> tuple[list[float], list[float]]:
    eye = np.array(world.agent.eye())
    view = world.client.computeViewMatrix(list(eye), list(eye + np.array(world.agent.view_direction())), [0, 0, 1])
    return view, world.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)


def test_compiled_frames_follow_interactions(kitchen_scene):
    """Pick up, open, put, close, toggle and walk: moved links, a held object, state visuals shown and hidden,
    all drawn as TinyRenderer draws them."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="tinyrenderer")) as ref, \
            World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="compiled")) as w:
        microwave = obj(kitchen_scene, "microwave")
        steps = mug_into_fridge(kitchen_scene) + [("ToggleObjectOn", microwave, {"objectId": microwave}),
                                                  ("ToggleObjectOff", microwave, {"objectId": microwave})]
        frames = 0
        for action, target, args in steps:
            pose = w.view().interaction_pose(target)
            assert pose is not None, target
            for world in (w, ref):
                world.agent = pose
                world.invalidate_frame()
                assert world.step(action, **args).success, (action, world.last.error)
            for walk in ("", "RotateLeft", "MoveAhead", "RotateRight", "LookDown"):
                if walk:
                    w.step(walk)
                    ref.step(walk)
                _assert_same(w.frame(), ref.frame(), (action, walk))
                frames += 1
        assert frames == 30


def test_a_visual_it_cannot_draw_is_named_and_tinyrenderer_draws(kitchen_scene, tmp_path, monkeypatch):
    (tmp_path / "a.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n")
    (tmp_path / "t.urdf").write_text(
        '<robot name="t">\n  <link name="base">\n'
        '    <visual name="w"><origin xyz="0 0 0.5" rpy="0 0 0"/><geometry><mesh filename="a.obj"/></geometry>'
        '</visual>\n  </link>\n</robot>\n')
    with pytest.raises(UnsupportedGeometry, match="link base"):
        _visual_files(str(tmp_path / "t.urdf"))

    import luminous_sim.world.raster_scene as rs

    def unsupported(self, body):
        raise UnsupportedGeometry(f"body {body}: a test's sphere")

    monkeypatch.setattr(rs.RasterScene, "_box_objects", unsupported)
    with pytest.warns(UserWarning, match="TinyRenderer draws it"), \
            World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="compiled")) as w:
        assert w._compiled is None
        assert w.frame().rgb.shape == (64, 64, 3)


def test_the_env_passes_the_rasteriser_on():
    from luminous_sim.env.config import EnvConfig
    from luminous_sim.env.worlds import world_config
    from luminous_sim.errors import LuminousError

    assert world_config(EnvConfig(rasteriser="compiled")).rasteriser == "compiled"
    assert world_config(EnvConfig()).rasteriser == "tinyrenderer"
    with pytest.raises(LuminousError, match="rasteriser"):
        EnvConfig(rasteriser="opengl")


def test_bodies_added_later_are_drawn_or_handed_to_tinyrenderer(kitchen_scene):
    """A box added after the World was made is drawn like TinyRenderer draws it; a sphere, which the compiled
    rasteriser cannot draw, hands the frames to TinyRenderer with a warning."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="tinyrenderer")) as ref, \
            World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="compiled")) as w:
        eye = np.array(w.agent.eye()) + 0.8 * np.array(w.agent.view_direction())
        added = []
        for world in (w, ref):
            vis = world.client.createVisualShape(pb.GEOM_BOX, halfExtents=[0.1, 0.1, 0.1], rgbaColor=[1, 0, 0, 1])
            added.append(world.client.createMultiBody(0, -1, vis, eye.tolist()))
            world.invalidate_frame()
        a, b = w.frame(), ref.frame()
        assert added[0] == added[1] and ((b.seg & 0xFFFFFF) == added[0]).sum() > 20, "the box is not in view"
        _assert_same(a, b, "box added")
        assert w._compiled is not None
        vis = w.client.createVisualShape(pb.GEOM_SPHERE, radius=0.05)
        w.client.createMultiBody(0, -1, vis, (eye + [0, 0, 0.3]).tolist())
        w.invalidate_frame()
        with pytest.warns(UserWarning, match="TinyRenderer draws it"):
            frame = w.frame()
        assert w._compiled is None and frame.rgb.shape == (64, 64, 3)
