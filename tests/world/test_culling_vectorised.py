"""The vectorised culling (every box at once, corners cached per pose) answers what the per-box reference
(tests/world/culling_reference.py, the culling as it was) answers, over random boxes, cameras and poses."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.culling import _margin, _view_proj
from luminous_sim.world.portals import OutdoorCuller, box_corners, outside_view
from luminous_sim.world.world import World
from tests.world import culling_reference as ref


def _quat(rng: np.random.Generator) -> np.ndarray:
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def _camera(rng: np.random.Generator, lo, hi) -> tuple[np.ndarray, np.ndarray]:
    """A random eye in the box lo..hi looking a random way, as a view-projection matrix."""
    eye = rng.uniform(lo, hi)
    d = rng.normal(size=3)
    d[2] *= 0.5
    return eye, ref.perspective(60.0, 1.0, 0.05, 20.0) @ ref.look_at(eye, eye + d)


def test_outside_view_is_the_per_box_test():
    rng = np.random.default_rng(0)
    for _ in range(40):
        centres = rng.uniform(-6, 6, size=(60, 3))
        halves = rng.uniform(0.01, 1.5, size=(60, 3))
        boxes = np.stack([box_corners(c - h, c + h) for c, h in zip(centres, halves, strict=True)])
        boxes = boxes @ ref.quat_matrix(_quat(rng)).T  # turned: not axis-aligned any more
        _, vp = _camera(rng, [-2, -2, 0], [2, 2, 2])
        margin = _margin(int(rng.integers(16, 400)), int(rng.integers(16, 400)))
        want = [ref.box_outside(b, vp, margin) for b in boxes]
        assert outside_view(boxes, vp, margin).tolist() == want
        assert 0 < sum(want) < len(want)


@pytest.mark.parametrize(("room", "seed"), [("Kitchen", 0), ("LivingRoom", 1), ("Bathroom", 3)])
def test_outdoor_culler_is_the_per_opening_reference(room, seed):
    shell = generate(empty_cdf(room), seed=seed).scene.room
    minx, miny, maxx, maxy = shell.bounds
    rng = np.random.default_rng(seed)
    lo = np.array([minx - 6, miny - 6, -1.0])
    boxes = [(c, c + rng.uniform(0.1, 4.0, size=3)) for c in rng.uniform(lo, [maxx + 6, maxy + 6, 9.0], size=(12, 3))]
    culler = OutdoorCuller(shell, boxes)
    corners = np.stack([box_corners(a, b) for a, b in boxes])
    hidden = 0
    for _ in range(150):
        eye, vp = _camera(rng, [minx - 0.5, miny - 0.5, 0.2], [maxx + 0.5, maxy + 0.5, 2.0])
        margin = _margin(64, 64)
        want = ref.outdoors_hidden(shell, corners, eye, vp, margin)
        assert culler.hidden(eye, vp, margin).tolist() == want.tolist(), eye
        hidden += int(want.sum())
    assert hidden, "nothing hidden: the test tests nothing"


def test_frustum_culler_is_the_per_link_reference_as_objects_move(kitchen_scene):
    """Random cameras, with objects moved and doors swung between them (the corners cached per pose must
    follow), and an object removed (the table made again)."""
    rng = np.random.default_rng(7)
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=0)) as w:
        c, culler = w.built.client, w._culler
        assert culler is not None
        minx, miny, maxx, maxy = kitchen_scene.room.bounds
        culled = kept = 0
        for i in range(60):
            if i % 3 == 0:
                for loaded in rng.choice(list(w.built.objects.values()), size=3, replace=False):
                    pos = rng.uniform([minx, miny, 0.0], [maxx, maxy, 2.0])
                    c.resetBasePositionAndOrientation(loaded.body, pos.tolist(), _quat(rng).tolist())
                    for j in loaded.joint_index.values():
                        c.resetJointState(loaded.body, j, float(rng.uniform(0.0, 1.0)))
            if i == 30:
                del w.built.objects[next(iter(w.built.objects))]
            eye, _ = _camera(rng, [minx, miny, 0.5], [maxx, maxy, 1.8])
            target = eye + rng.normal(size=3)
            view = c.computeViewMatrix(eye.tolist(), target.tolist(), [0, 0, 1])
            proj = c.computeProjectionMatrixFOV(60.0, 1.0, 0.05, 20.0)
            want = ref.outside_links(c, w.built.objects, _view_proj(view, proj), _margin(64, 64))
            got = culler.outside(view, proj, 64, 64)
            assert [(lo.body, n) for lo, n in got] == [(lo.body, n) for lo, n in want], i
            culled += len(want)
            kept += len(ref.link_boxes(c, w.built.objects)) - len(want)
        assert culled and kept
