"""A vertex in the plane through the eye sends TinyRenderer into a loop of some two billion columns: the culled
render moves the camera a tenth of a millimetre forward instead (luminous_sim/world/eye_plane.py)."""

from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np

from luminous_sim.world.articulation import move_joint
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.eye_plane import EYE_NUDGE, EYE_PLANE_EPS, eye_depth, near_eye_plane, nudged
from luminous_sim.world.world import World
from tests.world.conftest import obj

ROOT = Path(__file__).resolve().parents[2]


def _view(world: World, eye, target) -> list[float]:
    return world.client.computeViewMatrix(list(eye), list(target), [0, 0, 1])


def test_eye_depth_is_the_distance_along_the_view(world):
    view = _view(world, [1.0, 2.0, 1.5], [1.0, 3.0, 1.5])  # looking +y
    pts = np.array([[1.0, 4.5, 1.5], [7.0, 2.0, -3.0], [0.0, 1.0, 1.5]])
    assert np.allclose(eye_depth(view, pts), [2.5, 0.0, -1.0])
    assert near_eye_plane(view, pts).tolist() == [False, True, False]
    assert near_eye_plane(view, np.array([[5.0, 2.0 + EYE_PLANE_EPS / 2, 0.0]])).all()
    eye, target = nudged(np.array([1.0, 2.0, 1.5]), np.array([1.0, 3.0, 1.5]))
    assert np.allclose(eye, [1.0, 2.0 + EYE_NUDGE, 1.5]) and np.allclose(target, [1.0, 3.0 + EYE_NUDGE, 1.5])


def test_the_culler_sees_structure_corners_and_object_vertices_in_the_eye_plane(kitchen_scene):
    """And the compiled rasteriser's copy of the test (`CompiledRenderer.touches_eye_plane`) answers the same."""
    with World(kitchen_scene, WorldConfig(width=64, height=64, settle_steps=120, rasteriser="compiled")) as w:
        fridge = obj(kitchen_scene, "fridge")
        move_joint(w, w.interactions.state, fridge, True)  # a link away from its loaded pose
        culler = w._culler
        culler.touches_eye_plane(_view(w, [1.0, 1.0, 1.2], [1.0, 2.0, 1.2]))  # asks the moved poses again
        table = culler._boxes()
        # vertices of every box, through PyBullet's own transforms (float32), where the culler has them
        c = w.client
        for k, (loaded, name) in enumerate(table.keys):
            link = table.links[k]
            if link == -1:
                pos, orn = c.getBasePositionAndOrientation(loaded.body)
            else:
                pos, orn = c.getLinkState(loaded.body, link, computeForwardKinematics=1)[4:6]
            mine = table.world_vertices[table.vertex_box == k]
            local = table.local_vertices[table.vertex_box == k][:3]
            want = [c.multiplyTransforms(pos, orn, list(v), [0, 0, 0, 1])[0] for v in local]
            assert np.allclose(mine[:3], want, atol=1e-6), (loaded.entry.id, name)
        # views whose eye plane holds a triangle of the fridge's door, one through a single vertex of it, and one
        # whose eye plane holds a face of a wall box
        door = next(k for k, (lo, n) in enumerate(table.keys) if lo is w.built.objects[fridge] and n != "base")
        rows = np.flatnonzero(table.vertex_box == door)
        tri = next(t for t in table.triangles if rows[0] <= t[0] <= rows[-1])
        a, b, c3 = table.world_vertices[tri]
        normal = np.cross(b - a, c3 - a)
        normal /= np.linalg.norm(normal)
        along = (b - a) / np.linalg.norm(b - a)
        compiled = w._compiled
        assert compiled is not None

        def touches(view: list[float]) -> bool:
            answer = culler.touches_eye_plane(view)
            assert compiled.touches_eye_plane(view) == answer
            return answer

        eye = (a + b + c3) / 3 + 0.4 * along
        assert touches(_view(w, eye, eye + normal))
        beside = a + 0.4 * np.cross(normal, along)  # in the triangle's plane; the view tilted: only `a` in its plane
        assert not touches(_view(w, beside, beside + normal + 0.3 * along))
        face = culler._structure[0][[0, 1, 2, 3]]  # a face of a wall or floor box
        up, across = face[1] - face[0], face[2] - face[0]
        facing = np.cross(up, across) / np.linalg.norm(np.cross(up, across))
        eye = face.mean(axis=0) + 0.2 * up + 0.3 * across
        assert touches(_view(w, eye, eye + facing))
        assert not touches(_view(w, eye + 0.0123 * facing, eye + 1.0123 * facing))


def test_the_view_that_hung_the_render_now_renders():
    """S+ entry 465's bathroom, the agent at (0.25, -2.75) facing -x: its eye plane holds a door lintel's end face.
    Rendered in a child process, so that a regression fails on the timeout instead of hanging the suite."""
    code = textwrap.dedent("""
        from luminous_sim.benchmark import layout_scene
        from luminous_sim.world.agent import AgentPose
        from luminous_sim.world.config import WorldConfig
        from luminous_sim.world.world import World
        import numpy as np
        scene = layout_scene("FloorPlan429", "Bathroom", 4080800402)
        with World(scene, WorldConfig(width=64, height=64)) as w:
            w.agent = AgentPose(0.25, -2.75, 270, 0)
            eye = np.array(w.agent.eye())
            view = w.client.computeViewMatrix(list(eye), list(eye + np.array(w.agent.view_direction())), [0, 0, 1])
            assert w._culler.touches_eye_plane(view), "the lintel is not in the eye plane: the test tests nothing"
            frame = w.frame()
            assert (frame.depth > 0).all()
            print("rendered")
    """)
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0 and "rendered" in done.stdout, done.stderr[-2000:]
