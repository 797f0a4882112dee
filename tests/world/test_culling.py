"""The render optimisations (frustum culling, the structure painted last) leave every frame as it was, pixel for
pixel, and culling puts every visual back as it was."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.world.agent import AgentPose
from luminous_sim.world.articulation import move_joint
from luminous_sim.world.camera import render
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.world import World
from tests.world.conftest import mug_into_fridge, obj


def _views(world: World, sample: int = 1) -> list[AgentPose]:
    """Every fourth reachable point, looking four ways, at three horizons (about 100 views); with `sample`
    k, every k-th of those."""
    pts = world.nav.points()[::4]
    return [AgentPose(float(x), float(y), rot, hor) for x, y in pts for rot in (0, 90, 180, 270)
            for hor in (-30, 30, 60)][::3][::sample]


SIZES = [pytest.param(300, 3, id="300-sample"), pytest.param(64, 1, id="64"),
         pytest.param(300, 1, id="300", marks=pytest.mark.slow)]
"""Image size and view sample: at 300 px the fast suite checks a third of the views (30 s -> 10 s); the whole
set is the `slow` case."""


def _plain(world: World, pose: AgentPose, size: int):
    eye = np.array(pose.eye())
    return render(world.client, eye, eye + np.array(pose.view_direction()), width=size, height=size,
                  guard=world.eye_guard)


@pytest.mark.parametrize(("size", "sample"), SIZES)
def test_culled_frames_equal_plain_frames(kitchen_scene, size, sample):
    with World(kitchen_scene, WorldConfig(width=size, height=size, settle_steps=120)) as w:
        fridge, mug = obj(kitchen_scene, "fridge"), obj(kitchen_scene, "mug")
        move_joint(w, w.interactions.state, fridge, True)  # a door link moved away from its loaded pose
        assert w.view().state.objects[mug].isDirty  # a shown state visual; hidden ones elsewhere
        views = _views(w, sample)
        before = [_plain(w, pose, size) for pose in views]
        culled_any = 0
        for pose in views:
            eye = np.array(pose.eye())
            target = eye + np.array(pose.view_direction())
            plain = render(w.client, eye, target, width=size, height=size, guard=w.eye_guard)
            view = w.client.computeViewMatrix(list(eye), list(target), [0, 0, 1])
            proj = w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
            culled_any += len(w._culler.outside(view, proj, size, size))
            fast = render(w.client, eye, target, width=size, height=size, culler=w._culler)
            for name in ("rgb", "depth", "seg"):
                assert np.array_equal(getattr(plain, name), getattr(fast, name)), (name, pose)
        assert culled_any > 0, "no view culled anything: the test tests nothing"
        # every visual got its colour and alpha back (hidden state visuals stay hidden): the same frames as before
        for pose, ref in zip(views, before, strict=True):
            assert np.array_equal(_plain(w, pose, size).rgb, ref.rgb), ("a visual changed by culling", pose)


def _objects_only(world: World, seg: np.ndarray) -> np.ndarray:
    """Segmentation with every non-object body (floor, walls, their painted copies) as -2."""
    bodies = np.where(seg >= 0, seg & 0xFFFFFF, -1)
    objects = np.array(sorted(lo.body for lo in world.built.objects.values()))
    return np.where(np.isin(bodies, objects) | (seg < 0), seg, -2)


@pytest.mark.parametrize(("size", "sample"), SIZES)
def test_optimised_world_renders_what_the_plain_one_renders(kitchen_scene, size, sample):
    """Culling and the structure painted last against neither, on the same views: identical RGB and depth,
    identical segmentation of every object; the settled physics is the same too."""
    plain_cfg = WorldConfig(width=size, height=size, settle_steps=120, cull=False, structure_last=False)
    with World(kitchen_scene, WorldConfig(width=size, height=size, settle_steps=120)) as fast, \
            World(kitchen_scene, plain_cfg) as plain:
        assert fast._culler is not None and plain._culler is None
        assert fast.built.painted_structure and not plain.built.painted_structure
        for oid in fast.built.objects:
            assert np.array_equal(fast.built.pose_of(oid)[0], plain.built.pose_of(oid)[0]), oid
        for pose in _views(fast, sample):
            for w in (fast, plain):
                w.agent = pose
                w.invalidate_frame()
            a, b = fast.frame(), plain.frame()
            assert np.array_equal(a.rgb, b.rgb) and np.array_equal(a.depth, b.depth), pose
            assert np.array_equal(_objects_only(fast, a.seg), _objects_only(plain, b.seg)), pose


def test_links_the_culler_cannot_bound_are_never_culled(tmp_path):
    from luminous_sim.world.culling import link_visual_bounds

    (tmp_path / "a.obj").write_text("v 0 0 0\nv 1 2 3\nf 1 2 1\n")
    (tmp_path / "t.urdf").write_text(
        '<robot name="t">\n  <link name="base">\n'
        '    <visual name="v"><origin xyz="0 0 0" rpy="0 0 0"/><geometry><mesh filename="a.obj"/></geometry></visual>\n'
        '  </link>\n  <link name="lid">\n'
        '    <visual name="w"><origin xyz="0 0 0.5" rpy="0 0 0"/><geometry><mesh filename="a.obj"/></geometry>'
        '</visual>\n'
        '  </link>\n</robot>\n')
    bounds = link_visual_bounds(str(tmp_path / "t.urdf"))
    assert set(bounds) == {"base"}, "a visual with an offset origin is not bounded by its mesh file"
    assert bounds["base"][0].tolist() == [0, 0, 0] and bounds["base"][1].tolist() == [1, 2, 3]


def test_culled_render_leaves_what_pybullet_reports_unchanged(kitchen_scene):
    """PyBullet reports, for every visual of a link, the colour last set on that link: the restore sets the
    link's last-set visual last, so `getVisualShapeData` reads as before the render."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120)) as w:
        w.set_up_dirty([obj(kitchen_scene, "plate")])
        report = [w.client.getVisualShapeData(lo.body) for lo in w.built.objects.values()]
        culled = 0
        for pose in _views(w)[:12]:
            w.agent = pose
            w.invalidate_frame()
            w.frame()
            view = w.client.computeViewMatrix(list(pose.eye()), list(np.array(pose.eye())
                                                                     + np.array(pose.view_direction())), [0, 0, 1])
            culled += len(w._culler.outside(view, w.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0), 64, 64))
            assert [w.client.getVisualShapeData(lo.body) for lo in w.built.objects.values()] == report, pose
        assert culled


def _plain_now(world: World) -> object:
    pose = world.agent
    return _plain(world, pose, world.config.width)


def test_hidden_links_stay_hidden_between_frames_but_no_one_else_sees_them(kitchen_scene):
    """After a culled frame the culled links keep alpha 0 in PyBullet itself; anything asked through the World's
    client (a visual's colour, another render) first gets them back, and the next frame hides them again."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120)) as w:
        raw = w._culler.client
        bodies = [lo.body for lo in w.built.objects.values()]
        before = [raw.getVisualShapeData(b) for b in bodies]
        w.frame()
        hidden_raw = [raw.getVisualShapeData(b) for b in bodies]
        assert hidden_raw != before, "nothing kept hidden after the frame: the test tests nothing"
        assert [w.client.getVisualShapeData(b) for b in bodies] == before
        assert [raw.getVisualShapeData(b) for b in bodies] == before, "asking through the World showed them all"
        w.invalidate_frame()
        first = w.frame()
        assert [raw.getVisualShapeData(b) for b in bodies] == hidden_raw
        plain = _plain_now(w)  # a render through the World's client: every link drawn
        for name in ("rgb", "depth", "seg"):
            assert np.array_equal(getattr(first, name), getattr(plain, name)), name
        assert [raw.getVisualShapeData(b) for b in bodies] == before


def test_culled_frames_follow_bodies_moved_between_them(kitchen_scene):
    """Poses are asked again after any call that can move a body: an object put in front of the camera
    from where the last frame culled it is in the next frame."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120)) as w:
        apple = w.built.objects[obj(kitchen_scene, "apple")]
        for pose in _views(w):
            w.agent = pose
            w.invalidate_frame()
            w.frame()
            if any(lo is apple for lo, _ in w._culler.outside(*_matrices(w, pose), 64, 64)):
                break
        else:
            pytest.fail("no view culls the apple")
        ahead = np.array(pose.eye()) + 0.8 * np.array(pose.view_direction())
        w.client.resetBasePositionAndOrientation(apple.body, ahead.tolist(), [0, 0, 0, 1])
        w.invalidate_frame()
        moved = w.frame()
        assert apple.body in set((moved.seg[moved.seg >= 0] & 0xFFFFFF).tolist()), "the moved apple was culled"
        assert np.array_equal(moved.rgb, _plain_now(w).rgb)


def test_culled_frames_equal_plain_frames_through_an_episode(kitchen_scene):
    """Pick up, open, put, close and walk: after every action the World's culled frame is the plain render."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120)) as w:
        checked = 0
        for action, target, args in mug_into_fridge(kitchen_scene):
            pose = w.view().interaction_pose(target)
            assert pose is not None, target
            w.agent = pose
            w.invalidate_frame()
            w.frame()
            assert w.step(action, **args).success, (action, w.last.error)
            for walk in ("", "RotateLeft", "MoveAhead", "RotateRight", "LookDown"):
                if walk:
                    w.step(walk)
                frame = w.frame()
                plain = _plain_now(w)
                for name in ("rgb", "depth", "seg"):
                    assert np.array_equal(getattr(frame, name), getattr(plain, name)), (action, walk, name)
                checked += 1
        assert checked == 20


def _matrices(world: World, pose: AgentPose) -> tuple[list[float], list[float]]:
    eye = np.array(pose.eye())
    view = world.client.computeViewMatrix(list(eye), list(eye + np.array(pose.view_direction())), [0, 0, 1])
    return view, world.client.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
