"""What the compiled rasteriser draws for one built scene, and the frame it makes (`raster_kernel`).

The scene's drawable geometry is gathered once, as TinyRenderer holds it: one render object per visual of
every link (objects: their URDF's OBJ meshes, read as `culling` reads them, scaled by the asset's scale and
moved into the link's inertial frame, as PyBullet bakes them; everything else: its box visuals), each with its
own vertices, unit normals and triangles. Per frame only poses and colours are read: the assets' poses from
the `FrustumCuller`'s box table (which asks PyBullet again only after a call that can move a body; its inertial
poses are the frames TinyRenderer draws links in), colours and alphas from each `LoadedAsset` (every visual
change goes through `asset_loader.set_visual_alpha`, which counts them), and the structure's as they were
built. Links outside the view and outdoor boxes no opening shows are skipped, as the culled TinyRenderer frame
leaves them out. Objects or bodies added or removed (slicing) make the table again."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.world.asset_loader import visual_changes
from luminous_sim.world.client import BulletClient, p
from luminous_sim.world.culling import link_visual_files, visual_obj_arrays

if TYPE_CHECKING:
    from luminous_sim.world.asset_loader import LoadedAsset
    from luminous_sim.world.culling import Boxes, FrustumCuller

# PyBullet's box visual (bullet3 examples/OpenGLWindow/ShapeData.h: cube_vertices_textured, cube_indices): each
# corner's signs and normal, and the triangles, in PyBullet's order (the order sets the rounding of depth)
_CUBE = ((-1, -1, 1, 0, 0, 1), (1, -1, 1, 0, 0, 1), (1, 1, 1, 0, 0, 1), (-1, 1, 1, 0, 0, 1),
         (-1, -1, -1, 0, 0, -1), (1, -1, -1, 0, 0, -1), (1, 1, -1, 0, 0, -1), (-1, 1, -1, 0, 0, -1),
         (-1, -1, -1, -1, 0, 0), (-1, 1, -1, -1, 0, 0), (-1, 1, 1, -1, 0, 0), (-1, -1, 1, -1, 0, 0),
         (1, -1, -1, 1, 0, 0), (1, 1, -1, 1, 0, 0), (1, 1, 1, 1, 0, 0), (1, -1, 1, 1, 0, 0),
         (-1, -1, -1, 0, -1, 0), (-1, -1, 1, 0, -1, 0), (1, -1, 1, 0, -1, 0), (1, -1, -1, 0, -1, 0),
         (-1, 1, -1, 0, 1, 0), (-1, 1, 1, 0, 1, 0), (1, 1, 1, 0, 1, 0), (1, 1, -1, 0, 1, 0))
_CUBE_TRIANGLES = ((0, 1, 2), (0, 2, 3), (6, 5, 4), (7, 6, 4), (10, 9, 8), (11, 10, 8), (12, 13, 14), (12, 14, 15),
                   (18, 17, 16), (19, 18, 16), (20, 21, 22), (20, 22, 23))


class UnsupportedGeometry(ValueError):
    """A body has a visual the compiled rasteriser cannot draw (it then renders with TinyRenderer)."""


def _visual_files(urdf: str) -> dict[str, list[str]]:
    """`culling.link_visual_files`, an unreadable visual named (the compiled rasteriser cannot draw it)."""
    files = link_visual_files(urdf)
    bad = [link for link, f in files.items() if f is None]
    if bad:
        raise UnsupportedGeometry(f"{urdf}: link {bad[0]} has a visual other than an unscaled mesh at its origin")
    return {link: f for link, f in files.items() if f is not None}


def _mesh(path: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A visual OBJ's vertices rounded to float32 (tinyobjloader parses to double, then stores float), its
    per-vertex normals and triangles."""
    v, n, f = visual_obj_arrays(path)
    if n is None:
        raise UnsupportedGeometry(f"{path}: no per-vertex normals")
    return v.astype(np.float32), n.astype(np.float32), f


def _unit(n: np.ndarray) -> np.ndarray:
    """Model::normal: each normal times one over its float32 length (a zero normal gives nan, as there)."""
    n = n.astype(np.float32)
    length = np.sqrt(n[:, 0] * n[:, 0] + n[:, 1] * n[:, 1] + n[:, 2] * n[:, 2])
    with np.errstate(divide="ignore", invalid="ignore"):
        return (n * (np.float32(1.0) / length)[:, None]).astype(np.float32)


def _rotations(quats: np.ndarray) -> np.ndarray:
    """btMatrix3x3::setRotation of quaternions (n, 4) (x, y, z, w), in float64, its operations in its order
    (`culling._rotations` assumes unit quaternions and rounds differently), shape (n, 3, 3)."""
    x, y, z, w = np.asarray(quats, dtype=float).T
    s = 2.0 / (x * x + y * y + z * z + w * w)
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    return np.stack([np.stack([1.0 - (yy + zz), xy - wz, xz + wy], axis=-1),
                     np.stack([xy + wz, 1.0 - (xx + zz), yz - wx], axis=-1),
                     np.stack([xz - wy, yz + wx, 1.0 - (xx + yy)], axis=-1)], axis=1)


def _box_mesh(half: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    cube = np.asarray(_CUBE, dtype=float)
    return ((cube[:, :3] * half).astype(np.float32), cube[:, 3:].astype(np.float32),
            np.asarray(_CUBE_TRIANGLES, dtype=np.int64))


@dataclass
class _Object:
    """One render object: a visual of one link."""

    body: int
    link: int
    vertices: np.ndarray
    normals: np.ndarray
    faces: np.ndarray
    loaded: LoadedAsset | None = None
    key: tuple[str, int] | None = None
    """(link name, visual index) in `loaded`'s colours; None for a structure box."""
    rgba: tuple[float, float, float, float] = (1.0, 1.0, 1.0, 1.0)


class RasterScene:
    """The render objects of one built scene, kept as flat arrays for `raster_kernel.render_objects`."""

    def __init__(self, client: BulletClient, objects: dict[str, LoadedAsset]):
        self.client = client
        self._objects = objects
        self._loaded = tuple(objects.values())
        loaded_by_body = {lo.body: lo for lo in self._loaded}
        items: list[_Object] = []
        for i in range(client.getNumBodies()):
            body = client.getBodyUniqueId(i)
            lo = loaded_by_body.get(body)
            items += self._asset_objects(lo) if lo is not None else self._box_objects(body)
        self._items = items
        self._num_bodies = client.getNumBodies()
        counts_v = [len(o.vertices) for o in items]
        counts_f = [len(o.faces) for o in items]
        self.vertices = np.concatenate([o.vertices for o in items]).astype(np.float32)
        self.normals = np.concatenate([o.normals for o in items]).astype(np.float32)
        self.faces = np.concatenate([o.faces for o in items]).astype(np.int64)
        self.obj_vfirst = np.concatenate([[0], np.cumsum(counts_v)[:-1]]).astype(np.int64)
        self.obj_vcount = np.asarray(counts_v, dtype=np.int64)
        self.obj_first = np.concatenate([[0], np.cumsum(counts_f)[:-1]]).astype(np.int64)
        self.obj_count = np.asarray(counts_f, dtype=np.int64)
        self.seg_ids = np.asarray([o.body + ((o.link + 1) << 24) for o in items], dtype=np.int32)
        self.colors = np.asarray([o.rgba for o in items], dtype=np.float32)
        self.models = np.zeros((len(items), 4, 4), dtype=np.float32)
        self.models[:, 3, 3] = 1.0
        self._assets = np.flatnonzero([o.loaded is not None for o in items])
        """The render objects of assets (posed from the culler's table); the rest, structure boxes, never move."""
        structure = [k for k, o in enumerate(items) if o.loaded is None]
        if structure:
            poses = np.array([[*pos, *orn] for pos, orn in
                              (client.getBasePositionAndOrientation(items[k].body) for k in structure)])
            self._set_models(np.asarray(structure), poses)
        self._of_body: dict[int, list[int]] = {}
        """Each body's render objects."""
        for k, o in enumerate(items):
            self._of_body.setdefault(o.body, []).append(k)
        self._boxes_of: tuple[list, np.ndarray] | None = None
        self._posed: tuple[object, int] | None = None
        """The culler's table and version the asset models were set from."""
        self._colors_at = -1

    def _asset_objects(self, lo: LoadedAsset) -> list[_Object]:
        visuals = _visual_files(str(lo.entry.urdf_for(lo.lod)))
        s = float(lo.entry.scale)
        out = []
        for name, j in sorted(lo.link_index.items(), key=lambda kv: kv[1]):
            files = visuals.get(name, [])
            if not files:
                continue
            pos, orn = self.client.getDynamicsInfo(lo.body, j)[3:5]
            inv_pos, inv_orn = self.client.invertTransform(pos, orn)
            rot, shift = _rotations(np.array([inv_orn]))[0], np.asarray(inv_pos, dtype=float)
            for index, path in enumerate(files):
                v, n, f = _mesh(path)
                scaled = (v.astype(float) * s).astype(np.float32)  # the mesh scale, kept in float32
                baked = scaled.astype(float) @ rot.T + shift
                normals = _unit(((n.astype(float)) @ rot.T).astype(np.float32))
                out.append(_Object(lo.body, j, baked.astype(np.float32), normals, f, lo, (name, index)))
        return out

    def _box_objects(self, body: int) -> list[_Object]:
        out = []
        for shape in self.client.getVisualShapeData(body):
            if shape[7][3] == 0:
                continue
            if shape[2] != p.GEOM_BOX or shape[1] != -1 or any(abs(c) > 0 for c in shape[5]) \
                    or tuple(shape[6]) != (0.0, 0.0, 0.0, 1.0):
                raise UnsupportedGeometry(f"body {body}: a visual other than a box at the base's origin")
            v, n, f = _box_mesh(np.asarray(shape[3], dtype=float) * 0.5)
            out.append(_Object(body, -1, v, n, f, rgba=tuple(shape[7])))
        return out

    def current(self) -> bool:
        """Whether the table still describes the scene (no object added, removed or replaced, no body added or
        removed)."""
        objects = tuple(self._objects.values())
        return len(objects) == len(self._loaded) and all(a is b for a, b in zip(objects, self._loaded, strict=True)) \
            and self.client.getNumBodies() == self._num_bodies

    def _set_models(self, items: np.ndarray, poses: np.ndarray) -> None:
        """Model matrices from poses (n, 7: position, quaternion), as btTransform::getOpenGLMatrix gives them."""
        self.models[items, :3, :3] = _rotations(poses[:, 3:])
        self.models[items, :3, 3] = poses[:, :3]

    def update(self, table: Boxes) -> None:
        """The assets' model matrices for the culler's poses (set again only when its table or a pose changed)
        and their colours of now (read again only after `set_visual_alpha` changed one)."""
        if self._posed is None or self._posed[0] is not table or self._posed[1] != table.version:
            boxes = self._item_boxes(table.keys)[self._assets]
            if (boxes < 0).any():
                raise UnsupportedGeometry("an asset link the culler has no box for")
            self._set_models(self._assets, table.inertial_poses[boxes])
            self._posed = (table, table.version)
        changes = visual_changes()
        if changes == self._colors_at:
            return
        self._colors_at = changes
        for k in self._assets:
            o = self._items[k]
            assert o.loaded is not None and o.key is not None
            color = o.loaded.colors.get(o.key)
            if color is not None:
                self.colors[k, :3] = color[:3]
            self.colors[k, 3] = o.loaded.alphas.get(o.key, 1.0)

    def _item_boxes(self, keys: list[tuple[LoadedAsset, str]]) -> np.ndarray:
        """Each render object's row in the culler's box list `keys` (-1: a structure box, or a link the culler
        has no box for)."""
        if self._boxes_of is None or self._boxes_of[0] is not keys:
            row = {(id(lo), name): k for k, (lo, name) in enumerate(keys)}
            boxes = np.asarray([row.get((id(o.loaded), o.key[0]), -1) if o.loaded is not None and o.key else -1
                                for o in self._items], dtype=np.int64)
            self._boxes_of = (keys, boxes)
        return self._boxes_of[1]

    def drawn(self, keys: list[tuple[LoadedAsset, str]], outside: np.ndarray, hidden_bodies: list[int]) -> np.ndarray:
        """Which render objects are drawn: alpha above 0, not in a link outside the view (`outside` over the
        culler's `keys`), not in a hidden body."""
        out = self.colors[:, 3] != 0
        if len(outside):
            boxes = self._item_boxes(keys)
            out &= ~(outside[np.maximum(boxes, 0)] & (boxes >= 0))
        for body in hidden_bodies:
            out[self._of_body.get(body, [])] = False
        return out

    def render(self, view: list[float], proj: list[float], width: int, height: int, light, table: Boxes,
               outside: np.ndarray, hidden_bodies: list[int]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """RGB (h, w, 3) uint8, PyBullet's depth buffer (h, w) float32 and segmentation (h, w) int32, as
        `getCameraImage` with TinyRenderer returns them for this view (rows top-down); `table` is the culler's
        posed box table, `outside` which of its boxes lie outside the view (empty: draw every link)."""
        from luminous_sim.world.raster_kernel import render_objects

        self.update(table)
        v = np.asarray(view, dtype=np.float32).reshape(4, 4).T.copy()
        pr = np.asarray(proj, dtype=np.float32).reshape(4, 4).T.copy()
        one = np.float32(1.0)
        near, far = np.float32(pr[2, 3] / (pr[2, 2] - one)), np.float32(pr[2, 3] / (pr[2, 2] + one))
        v64 = np.asarray(view, dtype=float).reshape(4, 4).T
        eye = -v64[:3, :3].T @ v64[:3, 3]
        lt = np.asarray(light, dtype=float)
        lt = (lt * (1.0 / np.sqrt(lt[0] * lt[0] + lt[1] * lt[1] + lt[2] * lt[2]))).astype(np.float32)
        zbuf = np.full(width * height, -far, dtype=np.float32)
        rgb = np.full((width * height, 3), 255, dtype=np.uint8)
        seg = np.full(width * height, -1, dtype=np.int32)
        render_objects(self.vertices, self.normals, self.faces, self.obj_first, self.obj_count, self.obj_vfirst,
                       self.obj_vcount, self.models, self.colors, self.seg_ids,
                       self.drawn(table.keys, outside, hidden_bodies), v, pr, eye, lt, width, height, near, far,
                       zbuf, rgb, seg)
        depth = gl_depth(zbuf, near, far).reshape(height, width)
        return (rgb.reshape(height, width, 3)[::-1].copy(), depth[::-1].copy(), seg.reshape(height, width)[::-1].copy())


def gl_depth(zbuf: np.ndarray, near: np.float32, far: np.float32) -> np.ndarray:
    """TinyRenderer's depth buffer (-clip z) as PyBullet hands it out (copyCameraImageData), float32."""
    z_c = -zbuf.astype(np.float32)
    num = (far * (near + z_c)).astype(np.float64)
    den = 2.0 * np.float64(far) * np.float64(near) + (far * z_c).astype(np.float64) - (near * z_c).astype(np.float64)
    return (num / den).astype(np.float32)


class CompiledRenderer:
    """A World's frames drawn by the compiled rasteriser: the render objects made again when the scene's
    objects or bodies change, posed from the culler's box table, links outside the view and outdoor boxes no
    opening shows left out (`culler`'s tests), as the culled TinyRenderer frame leaves them out."""

    def __init__(self, client: BulletClient, objects: dict[str, LoadedAsset], culler: FrustumCuller, cull: bool):
        self.client = client
        """The client itself (not the `CullingClient` around it)."""
        self._objects = objects
        self._culler = culler
        self._cull = cull
        self._scene: RasterScene | None = None
        self.scene()  # an unsupported visual is named now, not at the first frame

    def scene(self) -> RasterScene:
        """The render objects for the scene of now."""
        if self._scene is None or not self._scene.current():
            self._culler.reveal()  # a hidden link would be taken for one drawn at alpha 0
            self._scene = RasterScene(self.client, self._objects)
        return self._scene

    def touches_eye_plane(self, view: list[float]) -> bool:
        """`FrustumCuller.touches_eye_plane`, compiled (the same test, about a tenth of its cost)."""
        from luminous_sim.world.eye_plane import EYE_PLANE_EPS
        from luminous_sim.world.raster_kernel import touches_eye_plane

        structure, faces, vertices, triangles = self._culler.eye_plane_geometry()
        row = np.asarray(view, dtype=float).reshape(4, 4).T[2].copy()
        return bool(touches_eye_plane(row, structure, faces, vertices, triangles, EYE_PLANE_EPS))

    def render(self, view: list[float], proj: list[float], width: int, height: int, light
               ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """RGB, PyBullet's depth buffer and segmentation for this view (`RasterScene.render`)."""
        scene = self.scene()
        outside = np.zeros(0, dtype=bool)
        bodies: list[int] = []
        if self._cull:
            _, outside = self._culler.outside_mask(view, proj, width, height)
            bodies = self._culler.outdoors_hidden(view, proj, width, height, compiled=True)
        return scene.render(view, proj, width, height, light, self._culler.posed_boxes(), outside, bodies)
