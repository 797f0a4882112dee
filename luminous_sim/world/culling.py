"""View-frustum culling for TinyRenderer: links wholly outside the camera's view are left out of a render.

TinyRenderer transforms and sets up every triangle of every visual it is given, whether or not it lands
on the picture, but skips a visual whose alpha is 0 at no cost (measured: a kitchen with every visual at
alpha 0 renders as fast as an empty world). So before a render each object link whose visual bounding box
lies wholly outside one plane of the view frustum (with a margin of `MARGIN_PX` pixels) has its visuals
set to alpha 0. A culled link has no pixel in the frame, so the frame is the same, pixel for pixel
(tests/world/test_culling.py checks RGB, depth and segmentation). The floor, walls and ceiling are never
culled; the outdoors is, when no doorway or window can show it (`world.portals`). Only TinyRenderer is
culled: the EGL path draws on the GPU.

The test is vectorised: a table of every object link's box (`Boxes`, made again when an object is added,
removed or replaced), every pose asked of PyBullet into one array, the corners transformed again only for
the boxes whose pose changed, and one product against the frustum's planes for all of them.

Hiding and showing are the cost that cannot be batched: one `changeVisualShape` call hides a link, one per
visual shows it again (about 2.4 us each). Showing every culled link right after each render made about 180
calls a 64x64 frame of the bench_world kitchen (about 49 of 59 boxes culled), 0.36 ms of a 2.2 ms step. So
culled links stay hidden between renders (`FrustumCuller.cull`), and each cull changes only the links whose
side of the view changed (about 6 hidden and 6 shown a navigation step); poses are asked again only after a
call that can move a body. Nothing else may see a link hidden: the World's client is a `CullingClient`,
which shows them all before any call that draws, reads or changes a visual or adds or removes a body, and
notes any call that can move one. What a culled 64x64 step still pays for culling: about 0.1 ms.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from functools import lru_cache
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.world.asset_loader import LoadedAsset
from luminous_sim.world.client import BulletClient, p
from luminous_sim.world.eye_plane import near_eye_plane
from luminous_sim.world.portals import OutdoorCuller, outside_view
from luminous_sim.world.restore import HARMLESS, HARMLESS_PREFIXES

MARGIN_PX = 2.0
"""A link is culled only if its box is at least this many pixels beyond the picture's edge."""

_LINK = re.compile(r'<link name="([^"]+)"')
_VISUAL = re.compile(r'<visual [^>]*><origin xyz="0 0 0" rpy="0 0 0"/><geometry><mesh filename="([^"]+)"/>')


@lru_cache(maxsize=4096)
def visual_obj_arrays(path: str) -> tuple[np.ndarray, np.ndarray | None, np.ndarray]:
    """A visual OBJ file's vertices (n, 3, float64), its per-vertex normals (n, 3; None where the file has not
    one per vertex: `objio.visual_obj` writes `f a//a`) and triangles (m, 3; 0-based)."""
    verts, norms, faces = [], [], []
    for line in Path(path).read_text().splitlines():
        if line.startswith("v "):
            verts.append(line.split()[1:4])
        elif line.startswith("vn "):
            norms.append(line.split()[1:4])
        elif line.startswith("f "):
            faces.append([int(f.split("/")[0]) - 1 for f in line.split()[1:4]])
    normals = np.asarray(norms, dtype=float) if norms and len(norms) == len(verts) else None
    return np.asarray(verts, dtype=float).reshape(-1, 3), normals, np.asarray(faces, dtype=np.int64).reshape(-1, 3)


def link_visual_files(urdf: str) -> dict[str, list[str] | None]:
    """Each link's visual mesh files in URDF order, for the links that have visuals; None for a link with a
    visual other than an unscaled mesh at the link's origin (one its mesh file alone does not describe)."""
    return _link_visual_files(urdf, Path(urdf).stat().st_mtime_ns)


@lru_cache(maxsize=1024)
def _link_visual_files(urdf: str, _mtime: int) -> dict[str, list[str] | None]:
    out: dict[str, list[str] | None] = {}
    link = None
    for line in Path(urdf).read_text().splitlines():
        m = _LINK.search(line)
        if m:
            link = m.group(1)
        if "<visual" not in line or link is None:
            continue
        mesh = _VISUAL.search(line)
        files = out.setdefault(link, [])
        if mesh is None or "scale=" in line or files is None:
            out[link] = None
        else:
            files.append(str(Path(urdf).parent / mesh.group(1)))
    return out


def link_visual_meshes(urdf: str) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each link's visual vertices (n, 3) and triangles (m, 3), every visual included (hidden state visuals
    too), in its own frame, at scale 1, read from the URDF's mesh files. A link with a visual this cannot
    read (an offset origin, a scaled mesh, another geometry) is left out: it is never culled."""
    return _link_visual_meshes(urdf, Path(urdf).stat().st_mtime_ns)


def link_visual_bounds(urdf: str) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Each link's visual bounding box (lo, hi) in its own frame (`link_visual_meshes`' links)."""
    return {k: (v.min(axis=0), v.max(axis=0)) for k, (v, _) in link_visual_meshes(urdf).items()}


@lru_cache(maxsize=1024)
def _link_visual_meshes(urdf: str, _mtime: int) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    out = {}
    for link, files in link_visual_files(urdf).items():
        parts = [visual_obj_arrays(f) for f in files or []]
        if parts and all(len(v) for v, _, _ in parts):  # a visual with no vertices: left out, never culled
            out[link] = _joined([(v, f) for v, _, f in parts])
    return out


def _joined(parts: list[tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """Meshes as one: vertices stacked, each mesh's triangles moved past the vertices before it."""
    starts = np.cumsum([0] + [len(v) for v, _ in parts[:-1]])
    faces = [f + k for (_, f), k in zip(parts, starts, strict=True)]
    return np.concatenate([v for v, _ in parts]), np.concatenate(faces)


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


class Boxes:
    """Every object link with a bounded visual, as flat arrays: the corners of its box in the frame PyBullet
    reports the link's pose in (for a base, its inertial frame), where its pose is asked for, and its world
    corners for the poses last seen. Made for one set of loaded assets (`loaded`); made again when it changes."""

    def __init__(self, client: BulletClient, objects: Sequence[LoadedAsset]):
        self.loaded = tuple(objects)
        self.keys: list[tuple[LoadedAsset, str]] = []
        """Each box's asset and link name, in the order of the arrays."""
        self.links: list[int] = []
        """Each box's PyBullet link index."""
        self.visuals: list[list[int]] = []
        """Each box's visual indices."""
        self.queries: list[tuple[int, bool, list[int]]] = []
        """Per body with a box: its id, whether its base has one, the link indices of its other boxes."""
        vertices_of: list[np.ndarray] = []  # each box's visual vertices, in the frame of its corners
        triangles: list[np.ndarray] = []
        local: list[np.ndarray] = []
        for loaded in objects:
            meshes = link_visual_meshes(str(loaded.entry.urdf_for(loaded.lod)))
            vertices = {k: v for k, (v, _) in meshes.items()}
            bounds = {k: (v.min(axis=0), v.max(axis=0)) for k, v in vertices.items()}
            s = loaded.entry.scale
            visuals: dict[str, list[int]] = {}
            for vis in loaded.entry.visuals:
                visuals.setdefault(vis["link"], []).append(vis["index"])
            has_base = "base" in bounds
            if has_base:
                # PyBullet reports the base's inertial frame; the visuals hang off the base link frame
                local_pos, local_orn = client.getDynamicsInfo(loaded.body, -1)[3:5]
                inv_pos, inv_orn = client.invertTransform(local_pos, local_orn)
                inv = _rotations(np.array([inv_orn]))[0].T
                corners = _corners(bounds["base"][0] * s, bounds["base"][1] * s)
                local.append(corners @ inv + np.array(inv_pos))
                triangles.append(meshes["base"][1] + sum(len(v) for v in vertices_of))
                vertices_of.append(vertices["base"] * s @ inv + np.array(inv_pos))
                self._add(loaded, "base", -1, visuals)
            ids = []
            for name, j in loaded.link_index.items():
                if name != "base" and name in bounds:
                    local.append(_corners(bounds[name][0] * s, bounds[name][1] * s))
                    triangles.append(meshes[name][1] + sum(len(v) for v in vertices_of))
                    vertices_of.append(vertices[name] * s)
                    self._add(loaded, name, j, visuals)
                    ids.append(j)
            if has_base or ids:
                self.queries.append((loaded.body, has_base, ids))
        self.local = np.array(local, dtype=float).reshape(-1, 8, 3)
        self.poses = np.full((len(self.keys), 7), np.nan)
        """The pose (position, quaternion) each box's world corners were computed for."""
        self.inertial_poses = np.full((len(self.keys), 7), np.nan)
        """The pose of each box's link's inertial frame (PyBullet's collision frame, which TinyRenderer draws a
        link's visuals in), for the same poses."""
        self.version = 0
        """Counts the updates that found a pose changed."""
        self.world = np.zeros_like(self.local)
        self.vertex_box = np.concatenate([np.full(len(v), k) for k, v in enumerate(vertices_of)]) \
            if vertices_of else np.zeros(0, dtype=int)
        """Each vertex's box index, in the order of `world_vertices`."""
        self.local_vertices = np.concatenate(vertices_of) if vertices_of else np.zeros((0, 3))
        self.world_vertices = np.zeros_like(self.local_vertices)
        """Every box's visual vertices in world coordinates for the poses last seen, shape (n, 3)."""
        self.triangles = np.concatenate(triangles) if triangles else np.zeros((0, 3), dtype=np.int64)
        """Every visual triangle, as three rows of `world_vertices`."""

    def _add(self, loaded: LoadedAsset, name: str, link: int, visuals: dict[str, list[int]]) -> None:
        self.keys.append((loaded, name))
        self.links.append(link)
        self.visuals.append(visuals.get(name, []))

    def update(self, client: BulletClient) -> np.ndarray:
        """Every box's 8 corners in world coordinates now, shape (n, 8, 3): each pose is asked for (PyBullet
        tells no one when a body moves), and only the boxes whose pose changed are transformed again."""
        base_pose, link_states = client.getBasePositionAndOrientation, client.getLinkStates  # lookup is slow
        flat: list[float] = []
        com: list[float] = []
        for body, has_base, ids in self.queries:
            if has_base:
                pos, orn = base_pose(body)
                flat += pos
                flat += orn
                com += pos
                com += orn
            if ids:
                for st in link_states(body, ids, computeForwardKinematics=1):
                    flat += st[4]
                    flat += st[5]
                    com += st[0]
                    com += st[1]
        poses = np.array(flat, dtype=float).reshape(-1, 7)
        moved = (poses != self.poses).any(axis=1)
        if moved.any():
            self.inertial_poses = np.array(com, dtype=float).reshape(-1, 7)
            self.version += 1
            rot = _rotations(poses[moved, 3:])
            self.world[moved] = np.einsum("nij,nkj->nki", rot, self.local[moved]) + poses[moved, None, :3]
            which = np.cumsum(moved) - 1  # box index -> row of `rot`
            vertex_moved = moved[self.vertex_box]
            boxes = self.vertex_box[vertex_moved]
            self.world_vertices[vertex_moved] = np.einsum("nij,nj->ni", rot[which[boxes]],
                                                          self.local_vertices[vertex_moved]) + poses[boxes, :3]
            self.poses = poses
        return self.world


def _view_proj(view: list[float], proj: list[float]) -> np.ndarray:
    return np.asarray(proj, dtype=float).reshape(4, 4).T @ np.asarray(view, dtype=float).reshape(4, 4).T


def _margin(width: int, height: int) -> tuple[float, float]:
    return 1.0 + 2.0 * MARGIN_PX / width, 1.0 + 2.0 * MARGIN_PX / height


class FrustumCuller:
    """Keeps hidden the object links (and outdoor bodies) that the last culled view cannot show.

    `cull` brings the hidden set in line with a view, changing only the links whose side of the view changed
    since the last cull (a navigation step changes about a tenth of them), and leaves them hidden after the
    render; `reveal` shows them all again. Everyone else uses the client through `CullingClient`, which
    reveals them before any call that draws, reads or changes a visual, or adds or removes a body, so nothing
    but the culled render ever sees a link hidden. Poses are asked of PyBullet again only after a call that
    can move a body (`poses_moved`)."""

    def __init__(self, client: BulletClient, objects: Mapping[str, LoadedAsset], room: object | None = None,
                 outdoors: Sequence[int] = ()):
        """`objects` are culled by the view frustum; `outdoors` (bodies of axis-aligned boxes with one visual,
        seen only through the openings of `room`, a `rooms.RoomShell`) by the view and the openings."""
        self.client = client
        """The client itself (not the `CullingClient` around it): the culled render draws through it."""
        self._objects = objects
        self._table: Boxes | None = None
        self._stale = True
        self._hidden: dict[int, tuple[LoadedAsset, str, int, list[int]]] = {}
        """Links kept hidden, by box index: asset, link name, link index, the visuals to show again."""
        self._away: set[int] = set()
        """Outdoor bodies kept hidden."""
        self._outdoor_bodies: list[tuple[int, list[float]]] = []
        boxes = []
        for body in outdoors if room is not None else ():
            shape = client.getVisualShapeData(body)[0]
            pos = np.array(client.getBasePositionAndOrientation(body)[0])
            half = np.array(shape[3]) / 2
            boxes.append((pos - half, pos + half))
            self._outdoor_bodies.append((body, list(shape[7])))
        self._outdoor_colors = dict(self._outdoor_bodies)
        self._outdoors = OutdoorCuller(room, boxes) if boxes else None
        self._structure = _structure_corners(client, {lo.body for lo in objects.values()})
        """The corners of every visible box that is not an object (floor, walls, ceiling, outdoors), (n, 8, 3):
        they never move."""

    def touches_eye_plane(self, view: list[float]) -> bool:
        """Whether a face of a visible structure box or a triangle of an object link lies in the plane through
        this view's eye (`eye_plane`: TinyRenderer would loop for good)."""
        if near_eye_plane(view, self._structure)[:, _BOX_FACES].all(axis=2).any():
            return True
        table = self._posed()
        near = near_eye_plane(view, table.world_vertices)
        return bool(near.any()) and bool(near[table.triangles].all(axis=1).any())

    def posed_boxes(self) -> Boxes:
        """The box table with the poses of now (asked of PyBullet again only after a call that can move a body)."""
        return self._posed()

    def eye_plane_geometry(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """What `touches_eye_plane` tests, for the poses of now: structure box corners (n, 8, 3), each box face's
        corner indices (6, 4), object link vertices (m, 3) and their triangles (k, 3)."""
        table = self._posed()
        return self._structure, _BOX_FACES, table.world_vertices, table.triangles

    def poses_moved(self) -> None:
        """A body or link may have moved: ask every pose again at the next cull."""
        self._stale = True

    def _boxes(self) -> Boxes:
        """The box table for the objects now (made again when an object was added, removed or replaced: a body
        id can be reused after removeBody, so the assets themselves are compared)."""
        table = self._table
        objects = self._objects.values()
        if table is None or len(table.loaded) != len(objects) \
                or any(a is not b for a, b in zip(table.loaded, objects, strict=True)):
            self.reveal()  # the hidden links are indexed by the old table
            table = self._table = Boxes(self.client, list(objects))
            self._stale = True
        return table

    def _posed(self) -> Boxes:
        """The box table with the poses of now (asked again only after a call that can move a body)."""
        table = self._boxes()
        if self._stale and table.keys:
            table.update(self.client)
            self._stale = False
        return table

    def _outside(self, view_proj: np.ndarray, margin: tuple[float, float]) -> tuple[Boxes, np.ndarray]:
        table = self._posed()
        if not table.keys:
            return table, np.zeros(0, dtype=bool)
        return table, outside_view(table.world, view_proj, margin)

    def _away_from(self, view: list[float], view_proj: np.ndarray, margin: tuple[float, float],
                   compiled: bool = False) -> list[int]:
        if self._outdoors is None:
            return []
        v = np.asarray(view, dtype=float).reshape(4, 4).T
        test = self._outdoors.hidden_compiled if compiled else self._outdoors.hidden
        hidden = test(-v[:3, :3].T @ v[:3, 3], view_proj, margin)
        return [body for (body, _), h in zip(self._outdoor_bodies, hidden.tolist(), strict=True) if h]

    def outside(self, view: list[float], proj: list[float], width: int, height: int) -> list[tuple[LoadedAsset, str]]:
        """The object links whose visual box lies wholly beyond one plane of this camera's frustum."""
        table, out = self._outside(_view_proj(view, proj), _margin(width, height))
        return [table.keys[k] for k in np.flatnonzero(out)]

    def outside_mask(self, view: list[float], proj: list[float], width: int, height: int
                     ) -> tuple[list[tuple[LoadedAsset, str]], np.ndarray]:
        """Every object link with a box (asset, link name; the same list until the objects change) and whether
        each lies wholly beyond one plane of this camera's frustum."""
        table, out = self._outside(_view_proj(view, proj), _margin(width, height))
        return table.keys, out

    def outdoors_hidden(self, view: list[float], proj: list[float], width: int, height: int,
                        compiled: bool = False) -> list[int]:
        """The outdoor bodies that no doorway or window shows to this camera (`compiled`: with the compiled
        rasteriser's copy of the test)."""
        return self._away_from(view, _view_proj(view, proj), _margin(width, height), compiled)

    def cull(self, view: list[float], proj: list[float], width: int, height: int) -> int:
        """Hide exactly the links outside this view and the outdoor bodies no opening shows (each with one
        call, every visual of it at alpha 0), showing again those the view can show; they stay so until the
        next cull or `reveal`. How many links and bodies are hidden."""
        change = self.client.changeVisualShape
        view_proj, margin = _view_proj(view, proj), _margin(width, height)
        away = set(self._away_from(view, view_proj, margin))
        for body in self._away - away:
            change(body, -1, rgbaColor=self._outdoor_colors[body])
        for body in away - self._away:
            change(body, -1, rgbaColor=[0.0, 0.0, 0.0, 0.0])
        self._away = away
        table, out = self._outside(view_proj, margin)
        out_now = np.flatnonzero(out).tolist()
        hidden = self._hidden
        for k in hidden.keys() - set(out_now):
            self._show(*hidden.pop(k))
        keys, links, visuals = table.keys, table.links, table.visuals
        for k in out_now:
            if k in hidden:
                continue
            loaded, name = keys[k]
            alphas = loaded.alphas
            showing = [i for i in visuals[k] if alphas[name, i] > 0]
            if showing:
                change(loaded.body, links[k], rgbaColor=[0.0, 0.0, 0.0, 0.0])
                hidden[k] = (loaded, name, links[k], showing)
        return len(hidden) + len(away)

    def _show(self, loaded: LoadedAsset, name: str, link: int, showing: list[int]) -> None:
        """Each visual that was showing gets its colour and alpha as they are now (one hidden since stays so),
        the link's last-set visual last, as `getVisualShapeData` reports the last colour set on a link."""
        last = loaded.last_set.get(name)
        if last is not None:
            showing = [i for i in showing if i != last] + [last]
        colors, alphas, change = loaded.colors, loaded.alphas, self.client.changeVisualShape
        for i in showing:
            change(loaded.body, link, shapeIndex=i, rgbaColor=[*colors[(name, i)][:3], alphas[(name, i)]])

    def reveal(self) -> None:
        """Show every link and outdoor body the last cull hid."""
        for body in self._away:
            self.client.changeVisualShape(body, -1, rgbaColor=self._outdoor_colors[body])
        self._away = set()
        hidden, self._hidden = self._hidden, {}
        for entry in hidden.values():
            self._show(*entry)

    @contextmanager
    def culled(self, view: list[float], proj: list[float], width: int, height: int) -> Iterator[int]:
        """Within the block, the links outside the view are hidden; yields how many links were hidden; every
        one is shown again after it."""
        try:
            yield self.cull(view, proj, width, height)
        finally:
            self.reveal()


_BOX_FACES = np.array([[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 4, 5], [2, 3, 6, 7], [0, 2, 4, 6], [1, 3, 5, 7]])
"""The corners of each face of a box, as `_corners` orders them."""


def _structure_corners(client: BulletClient, objects: set[int]) -> np.ndarray:
    """The corners (n, 8, 3) of every visible box visual of the bodies that are not `objects`."""
    corners = []
    for i in range(client.getNumBodies()):
        body = client.getBodyUniqueId(i)
        if body in objects:
            continue
        pos, orn = client.getBasePositionAndOrientation(body)
        for shape in client.getVisualShapeData(body):
            if shape[2] != p.GEOM_BOX or shape[1] != -1 or shape[7][3] == 0:
                continue
            half = np.array(shape[3]) / 2
            at, turn = client.multiplyTransforms(pos, orn, shape[5], shape[6])
            corners.append(_corners(-half, half) @ _rotations(np.array([turn]))[0].T + np.array(at))
    return np.stack(corners) if corners else np.zeros((0, 8, 3))


REVEALING = frozenset({"getCameraImage", "getVisualShapeData", "changeVisualShape", "changeTexture", "removeBody",
                       "loadURDF", "loadSDF", "loadMJCF", "createMultiBody", "resetSimulation"})
"""Client calls before which the culler shows every link it keeps hidden: they draw, read or change visuals,
or add or remove bodies (and with them the culler's box table)."""


class CullingClient:
    """A scene's client as everyone but its culler uses it: before any `REVEALING` call every link the culler
    keeps hidden is shown again, and any call that can move a body (anything but queries, ray tests,
    transforms, rendering and colours: `restore.HARMLESS`) makes the culler ask every pose again."""

    def __init__(self, client: BulletClient, culler: FrustumCuller):
        self._client = client
        self._culler = culler

    def __getattr__(self, name: str) -> Any:
        attr = getattr(self._client, name)
        if not callable(attr):
            return attr
        if name in REVEALING:
            self._culler.reveal()
        if not (name in HARMLESS or name.startswith(HARMLESS_PREFIXES)):
            self._culler.poses_moved()
        return attr
