"""View-frustum culling for TinyRenderer: links wholly outside the camera's view are left out of a render.

TinyRenderer transforms and sets up every triangle of every visual it is given, whether or not it lands
on the picture, but skips a visual whose alpha is 0 at no cost (measured: a kitchen with every visual at
alpha 0 renders as fast as an empty world). So before a render each object link whose visual bounding box
lies wholly outside one plane of the view frustum (with a margin of `MARGIN_PX` pixels) has its visuals
set to alpha 0, and they get their colour back right after. A culled link has no pixel in the frame, so
the frame is the same, pixel for pixel (tests/world/test_culling.py checks RGB, depth and segmentation).
The floor, walls and ceiling are never culled; the outdoors is, when no doorway or window can show it
(`world.portals`). Only TinyRenderer is culled: the EGL path draws on the GPU.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path

import numpy as np

from luminous_sim.world.asset_loader import LoadedAsset
from luminous_sim.world.client import BulletClient
from luminous_sim.world.portals import OutdoorCuller, outside_view

MARGIN_PX = 2.0
"""A link is culled only if its box is at least this many pixels beyond the picture's edge."""

_LINK = re.compile(r'<link name="([^"]+)"')
_VISUAL = re.compile(r'<visual [^>]*><origin xyz="0 0 0" rpy="0 0 0"/><geometry><mesh filename="([^"]+)"/>')


@lru_cache(maxsize=4096)
def _obj_bounds(path: str) -> tuple[tuple[float, ...], tuple[float, ...]] | None:
    verts = [line.split()[1:4] for line in Path(path).read_text().splitlines() if line.startswith("v ")]
    if not verts:
        return None
    v = np.asarray(verts, dtype=float)
    return tuple(v.min(axis=0)), tuple(v.max(axis=0))


def link_visual_bounds(urdf: str) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each link's visual bounding box (lo, hi) in its own frame, every visual included (hidden state
    visuals too), at scale 1, read from the URDF's mesh files. A link with a visual this cannot bound (an
    offset origin, a scaled mesh, another geometry) is left out: it is never culled."""
    return _link_visual_bounds(urdf, Path(urdf).stat().st_mtime_ns)


@lru_cache(maxsize=1024)
def _link_visual_bounds(urdf: str, _mtime: int) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    out: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    unbounded: set[str] = set()
    link = None
    for line in Path(urdf).read_text().splitlines():
        m = _LINK.search(line)
        if m:
            link = m.group(1)
        if "<visual" not in line or link is None:
            continue
        mesh = _VISUAL.search(line)
        b = _obj_bounds(str(Path(urdf).parent / mesh.group(1))) if mesh and "scale=" not in line else None
        if b is None:
            unbounded.add(link)
            continue
        lo, hi = np.array(b[0]), np.array(b[1])
        if link in out:
            lo, hi = np.minimum(out[link][0], lo), np.maximum(out[link][1], hi)
        out[link] = (lo, hi)
    return {k: v for k, v in out.items() if k not in unbounded}


def _corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    return np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])


def _rotations(quats: np.ndarray) -> np.ndarray:
    """(n, 4) quaternions (x, y, z, w) as (n, 3, 3) rotation matrices."""
    x, y, z, w = quats.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], axis=-1),
        np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], axis=-1),
        np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=1)


class _BodyBoxes:
    """One loaded asset's link boxes (8 corners each, in the link frame, at the asset's scale)."""

    def __init__(self, client: BulletClient, loaded: LoadedAsset):
        bounds = link_visual_bounds(str(loaded.entry.urdf_for(loaded.lod)))
        s = loaded.entry.scale
        self.loaded = loaded
        self.has_base = "base" in bounds
        self.base_corners = _corners(bounds["base"][0] * s, bounds["base"][1] * s) if self.has_base else None
        self.links = [(name, j) for name, j in loaded.link_index.items() if name != "base" and name in bounds]
        self.link_ids = [j for _, j in self.links]
        self.visuals: dict[str, list[int]] = {}
        """Each link's visual indices."""
        for vis in loaded.entry.visuals:
            self.visuals.setdefault(vis["link"], []).append(vis["index"])
        self.link_corners = [_corners(bounds[name][0] * s, bounds[name][1] * s) for name, _ in self.links]
        # PyBullet reports the base's inertial frame; the visuals hang off the base link frame
        local_pos, local_orn = client.getDynamicsInfo(loaded.body, -1)[3:5]
        inv_pos, inv_orn = client.invertTransform(local_pos, local_orn)
        self.inv_rot = _rotations(np.array([inv_orn]))[0]
        self.inv_pos = np.array(inv_pos)
        self._seen: dict[str, tuple[tuple, np.ndarray]] = {}

    def world(self, link: str, pose: tuple) -> np.ndarray:
        """The link box's corners in world coordinates for the link's `pose` as PyBullet reports it (for the
        base, its inertial frame); cached until the pose changes."""
        seen = self._seen.get(link)
        if seen is not None and seen[0] == pose:
            return seen[1]
        rot = _rotations(np.asarray([pose[1]], dtype=float))[0]
        pos = np.asarray(pose[0], dtype=float)
        if link == "base":  # world <- inertial <- base link
            pos, rot = rot @ self.inv_pos + pos, rot @ self.inv_rot
            local = self.base_corners
        else:
            local = self.link_corners[[name for name, _ in self.links].index(link)]
        out = local @ rot.T + pos
        self._seen[link] = (pose, out)
        return out


def _view_proj(view: list[float], proj: list[float]) -> np.ndarray:
    return np.asarray(proj, dtype=float).reshape(4, 4).T @ np.asarray(view, dtype=float).reshape(4, 4).T


def _margin(width: int, height: int) -> tuple[float, float]:
    return 1.0 + 2.0 * MARGIN_PX / width, 1.0 + 2.0 * MARGIN_PX / height


class FrustumCuller:
    """Hides, for the length of one render, the object links that cannot appear in it."""

    def __init__(self, client: BulletClient, objects: Mapping[str, LoadedAsset], room: object | None = None,
                 outdoors: Sequence[int] = ()):
        """`objects` are culled by the view frustum; `outdoors` (bodies of axis-aligned boxes with one visual,
        seen only through the openings of `room`, a `rooms.RoomShell`) by the view and the openings."""
        self._client = client
        self._objects = objects
        self._boxes_of: dict[int, _BodyBoxes] = {}
        self._outdoor_bodies: list[tuple[int, list[float]]] = []
        boxes = []
        for body in outdoors if room is not None else ():
            shape = client.getVisualShapeData(body)[0]
            pos = np.array(client.getBasePositionAndOrientation(body)[0])
            half = np.array(shape[3]) / 2
            boxes.append((pos - half, pos + half))
            self._outdoor_bodies.append((body, list(shape[7])))
        self._outdoors = OutdoorCuller(room, boxes) if boxes else None

    def _body(self, loaded: LoadedAsset) -> _BodyBoxes:
        boxes = self._boxes_of.get(loaded.body)
        if boxes is None or boxes.loaded is not loaded:  # a body id can be reused after removeBody
            boxes = self._boxes_of[loaded.body] = _BodyBoxes(self._client, loaded)
        return boxes

    def _boxes(self) -> tuple[list[tuple[LoadedAsset, str]], np.ndarray]:
        """Every object link with a visual, and its box's 8 corners in world coordinates, shape (n, 8, 3).

        Each link's pose is asked for every time; its corners are recomputed only when that pose changed."""
        c = self._client
        base_pose, link_states = c.getBasePositionAndOrientation, c.getLinkStates  # BulletClient's lookup is slow
        keys: list[tuple[LoadedAsset, str]] = []
        corners: list[np.ndarray] = []
        for loaded in self._objects.values():
            boxes = self._body(loaded)
            if boxes.has_base:
                keys.append((loaded, "base"))
                corners.append(boxes.world("base", base_pose(loaded.body)))
            if boxes.links:
                states = link_states(loaded.body, boxes.link_ids, computeForwardKinematics=1)
                for (name, _), st in zip(boxes.links, states, strict=True):
                    keys.append((loaded, name))
                    corners.append(boxes.world(name, (st[4], st[5])))
        return keys, np.array(corners).reshape(-1, 8, 3)

    def outside(self, view: list[float], proj: list[float], width: int, height: int) -> list[tuple[LoadedAsset, str]]:
        """The object links whose visual box lies wholly beyond one plane of this camera's frustum."""
        keys, corners = self._boxes()
        if not keys:
            return []
        out = outside_view(corners, _view_proj(view, proj), _margin(width, height))
        return [k for k, o in zip(keys, out, strict=True) if o]

    def outdoors_hidden(self, view: list[float], proj: list[float], width: int, height: int) -> list[int]:
        """The outdoor bodies that no doorway or window shows to this camera."""
        if self._outdoors is None:
            return []
        v = np.asarray(view, dtype=float).reshape(4, 4).T
        eye = -v[:3, :3].T @ v[:3, 3]
        hidden = self._outdoors.hidden(eye, _view_proj(view, proj), _margin(width, height))
        return [body for (body, _), h in zip(self._outdoor_bodies, hidden, strict=True) if h]

    @contextmanager
    def culled(self, view: list[float], proj: list[float], width: int, height: int) -> Iterator[int]:
        """Within the block, the links outside the view are hidden; yields how many links were hidden.

        A link is hidden with one call (every visual of it at alpha 0); each of its visuals that was showing
        gets its own colour and alpha back afterwards (those already at alpha 0 stay so), the link's
        last-set visual last, as `getVisualShapeData` reports the last colour set on a link."""
        change = self._client.changeVisualShape
        outdoors = dict(self._outdoor_bodies)
        away = self.outdoors_hidden(view, proj, width, height)
        hidden = []
        for loaded, name in self.outside(view, proj, width, height):
            showing = [i for i in self._body(loaded).visuals.get(name, ()) if loaded.alphas[(name, i)] > 0]
            if showing:
                hidden.append((loaded, name, showing))
        try:
            for body in away:
                change(body, -1, rgbaColor=[0.0, 0.0, 0.0, 0.0])
            for loaded, name, _ in hidden:
                change(loaded.body, loaded.link_index[name], rgbaColor=[0.0, 0.0, 0.0, 0.0])
            yield len(hidden) + len(away)
        finally:
            for body in away:
                change(body, -1, rgbaColor=outdoors[body])
            for loaded, name, showing in hidden:
                link = loaded.link_index[name]
                last = loaded.last_set.get(name)  # set last again, so that PyBullet reports what it did before
                for i in [i for i in showing if i != last] + ([] if last is None else [last]):
                    change(loaded.body, link, shapeIndex=i, rgbaColor=[*loaded.colors[(name, i)][:3],
                                                                       loaded.alphas[(name, i)]])
