"""Portal culling of the outdoors: the ground and sky around a room show only through its doorways and windows.

The outdoors (`scene_builder._outdoors`: a ground slab under and around the room, a sky slab and four sky
walls) is drawn behind the walls in every frame, and TinyRenderer rasterises every triangle it is given
over the triangle's whole screen bounding box, whether or not the depth test then hides it: the ground alone,
two huge triangles cut by the near plane, was about a fifth of a 300x300 frame's CPU time. From inside the
room the outdoors can be seen only through an opening (a doorway or a window: a tunnel through the wall),
so before a render each outdoor box is left out when no opening could show it: the opening is wholly
outside the view, or the box lies wholly beyond one side of the cone from the eye through the opening's
inner or outer face (the openings grown by `OPENING_MARGIN` on every side). Then no pixel of the box can
be in the frame: depth and segmentation are the same, pixel for pixel, and so is RGB but for TinyRenderer's
own rounding: which bodies are drawn at all (even one moved out of the view instead of hidden) can move a
pixel's colour by one level: none of 137 million pixels in 3,056 views of five rooms, one pixel in the
880 views of tests/world/test_portals.py (which bounds it). With the eye outside the room, or too near a
wall's plane for its cone, every box is drawn.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
from shapely import contains_xy

OPENING_MARGIN = 0.05
"""Metres an opening is grown on every side (along the wall and up and down) before its cones are made."""
MIN_EYE_DEPTH = 0.1
"""An eye nearer than this to an opening's wall plane (or beyond it) sees through the opening at any angle."""

Point3 = Sequence[float] | np.ndarray
"""An (x, y, z) point: a sequence of floats or a numpy array of 3."""


def box_corners(lo: Point3, hi: Point3) -> np.ndarray:
    """The 8 corners of an axis-aligned box, shape (8, 3)."""
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def view_planes(view_proj: np.ndarray, margin: tuple[float, float]) -> np.ndarray:
    """The view frustum's 7 planes (the side planes moved out by `margin`) in world coordinates, (7, 4): a point
    p is beyond plane k where (p, 1) . plane < 0 (at or below 0 for the last, w)."""
    mx, my = margin
    return np.array([[1.0, 0.0, 0.0, mx], [-1.0, 0.0, 0.0, mx], [0.0, 1.0, 0.0, my], [0.0, -1.0, 0.0, my],
                     [0.0, 0.0, 1.0, 1.0], [0.0, 0.0, -1.0, 1.0], [0.0, 0.0, 0.0, 1.0]]) @ view_proj


def outside_view(corners: np.ndarray, view_proj: np.ndarray, margin: tuple[float, float]) -> np.ndarray:
    """For boxes given by their corners (n, 8, 3): whether each lies wholly beyond one plane of the view
    frustum (`view_proj` the 4x4 projection @ view matrix; the side planes moved out by `margin`, in
    normalised device units, x and y).

    In clip coordinates (x, y, z, w) a box is out when all its corners have x < -mx w, or all x > mx w, (y
    likewise), z < -w, z > w, or w <= 0; each of these is one linear function of the corner below 0 (at or
    below, for w), so the seven functions are taken back to world coordinates once and applied to every
    corner in one product."""
    planes = view_planes(view_proj, margin)
    d = corners.reshape(-1, 3) @ planes[:, :3].T + planes[:, 3]  # one 2-D product: a stack of small ones is slower
    beyond = d < 0
    beyond[:, 6] = d[:, 6] <= 0
    return beyond.reshape(corners.shape[:-2] + (8, 7)).all(axis=-2).any(axis=-1)


class Opening:
    """One doorway or window: its tunnel through the wall (8 corners) and its inner and outer faces."""

    def __init__(self, room: Any, wall_id: str, u0: float, u1: float, z0: float, z1: float):
        """`room` a scene's room (`rooms.RoomShell`); the opening spans `u0..u1` along wall `wall_id` and
        `z0..z1` in height."""
        wall = next(w for w in room.walls if w.id == wall_id)
        m, t = OPENING_MARGIN, room.wall_thickness
        u0, u1, z0, z1 = u0 - m, u1 + m, z0 - m, z1 + m
        self.origin = np.array([*wall.point(0.0, 0.0), 0.0])
        self.normal = np.array([*wall.normal, 0.0])
        """Into the room."""
        faces = []
        for v in (0.0, -t):
            (ax, ay), (bx, by) = wall.point(u0, v), wall.point(u1, v)
            faces.append([[ax, ay, z0], [bx, by, z0], [bx, by, z1], [ax, ay, z1]])
        self.faces = np.array(faces)
        """The inner and outer faces' corners, in order around each face, shape (2, 4, 3)."""
        self.corners = self.faces.reshape(8, 3)

    def depth(self, eye: np.ndarray) -> float:
        """How far the eye is in front of the wall's inner plane (into the room)."""
        return float((eye - self.origin) @ self.normal)

    def hides(self, eye: np.ndarray, corners: np.ndarray) -> np.ndarray:
        """For boxes (n, 8, 3): whether each lies wholly beyond one side of a cone from `eye` through one of
        this opening's two faces (so no ray from the eye through the opening reaches it)."""
        edges = self.faces - eye  # (2, 4, 3)
        planes = np.cross(edges, np.roll(edges, -1, axis=1))  # each side of each cone, as a normal
        inward = np.einsum("fpc,fc->fp", planes, edges.mean(axis=1))
        planes = (planes * np.where(inward < 0, -1.0, 1.0)[..., None]).reshape(8, 3)
        return ((corners - eye) @ planes.T < 0).all(axis=1).any(axis=1)


def openings(room: Any) -> list[Opening]:
    """Every doorway and window of a scene's room (a `rooms.RoomShell`)."""
    out = [Opening(room, d.wall, d.offset, d.offset + d.width, 0.0, d.height) for d in room.doors]
    out += [Opening(room, w.wall, w.offset, w.offset + w.width, w.sill_height, w.sill_height + w.height)
            for w in room.windows]
    return out


class OutdoorCuller:
    """Which outdoor boxes no opening of the room can show from a camera."""

    def __init__(self, room: Any, boxes: Sequence[tuple[Point3, Point3]]):
        """`room`: the scene's room (a `rooms.RoomShell`); `boxes`: each outdoor box's world (lo, hi) corners,
        axis-aligned, in the order of `hidden`'s answer."""
        self._openings = openings(room)
        ops = self._openings
        self._opening_corners = np.stack([op.corners for op in ops]) if ops else np.zeros((0, 8, 3))
        self._faces = np.stack([op.faces for op in ops]) if ops else np.zeros((0, 2, 4, 3))
        self._origins = np.stack([op.origin for op in ops]) if ops else np.zeros((0, 3))
        self._normals = np.stack([op.normal for op in ops]) if ops else np.zeros((0, 3))
        self._room = room.polygon()
        self._corners = np.stack([box_corners(lo, hi) for lo, hi in boxes]) if boxes else np.zeros((0, 8, 3))
        self._all_corners = np.concatenate([self._corners, self._opening_corners])
        """The boxes' corners, then the openings': both tested against the view in one call."""

    def hidden(self, eye: np.ndarray, view_proj: np.ndarray, margin: tuple[float, float]) -> np.ndarray:
        """Whether each outdoor box is out of sight from `eye` for this camera (a bool per box): out of the
        view, or, for every opening in the view, beyond one side of one of its two cones (`Opening.hides`,
        for all openings at once)."""
        n = len(self._corners)
        if n == 0 or not contains_xy(self._room, float(eye[0]), float(eye[1])):
            return np.zeros(n, dtype=bool)
        out = outside_view(self._all_corners, view_proj, margin)
        seen, shown = out[:n], ~out[n:]  # start: only boxes out of the view are hidden
        if not shown.any():
            return np.ones(n, dtype=bool)
        if (((eye - self._origins[shown]) * self._normals[shown]).sum(axis=-1) < MIN_EYE_DEPTH).any():
            return seen
        edges = self._faces[shown] - eye  # (m, 2, 4, 3)
        planes = np.cross(edges, np.roll(edges, -1, axis=2))
        inward = np.einsum("mfpc,mfc->mfp", planes, edges.mean(axis=2))
        planes = (planes * np.where(inward < 0, -1.0, 1.0)[..., None]).reshape(-1, 8, 3)  # (m, 8, 3)
        d = (self._corners - eye) @ planes.reshape(-1, 3).T  # (n, 8, m * 8)
        beyond = (d < 0).all(axis=1).reshape(n, -1, 8).any(axis=2)  # (n, m): beyond a side of a cone of each
        return beyond.all(axis=1) | seen

    def hidden_compiled(self, eye: np.ndarray, view_proj: np.ndarray, margin: tuple[float, float]) -> np.ndarray:
        """`hidden`, with the compiled rasteriser's copy of the test (`raster_kernel.outdoors_hidden`)."""
        from luminous_sim.world.raster_kernel import outdoors_hidden

        n = len(self._corners)
        if n == 0 or not contains_xy(self._room, float(eye[0]), float(eye[1])):
            return np.zeros(n, dtype=bool)
        return outdoors_hidden(np.asarray(eye, dtype=float), view_planes(view_proj, margin), self._corners,
                               self._opening_corners, self._faces, self._origins, self._normals, MIN_EYE_DEPTH)
