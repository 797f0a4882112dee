"""Mesh primitives for the procedural asset builders (trimesh, metres, z up).

Asset frame convention: origin at the bottom centre of the asset's footprint (z=0 touches the floor
or the surface it stands on), +y is the asset's front (a chair's seat faces +y, a fridge's door opens
towards +y), +x is its right-hand side seen from the back.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import trimesh
from shapely.geometry import Polygon

Vec3 = Sequence[float]

_AXIS_ROT = {
    "z": np.eye(4),
    "x": trimesh.transformations.rotation_matrix(np.pi / 2, [0, 1, 0]),
    "y": trimesh.transformations.rotation_matrix(-np.pi / 2, [1, 0, 0]),
}


def _place(mesh: trimesh.Trimesh, center: Vec3, axis: str = "z") -> trimesh.Trimesh:
    mesh.apply_transform(_AXIS_ROT[axis])
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def box(size: Vec3, center: Vec3 = (0.0, 0.0, 0.0)) -> trimesh.Trimesh:
    """An axis-aligned box of full extents `size` centred at `center`."""
    return _place(trimesh.creation.box(extents=np.asarray(size, dtype=float)), center)


def box_at(lo: Vec3, hi: Vec3) -> trimesh.Trimesh:
    """An axis-aligned box spanning the corners `lo` and `hi`."""
    lo_a, hi_a = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return box(hi_a - lo_a, (lo_a + hi_a) / 2)


def cylinder(
    radius: float, height: float, center: Vec3 = (0.0, 0.0, 0.0), axis: str = "z", sections: int = 16
) -> trimesh.Trimesh:
    """A cylinder along `axis` ("x", "y" or "z") centred at `center`."""
    return _place(trimesh.creation.cylinder(radius=radius, height=height, sections=sections), center, axis)


def rod(p0: Vec3, p1: Vec3, radius: float, sections: int = 10) -> trimesh.Trimesh:
    """A cylinder from point `p0` to point `p1` (legs, rails, stretchers)."""
    return trimesh.creation.cylinder(radius=radius, segment=np.array([p0, p1], dtype=float), sections=sections)


def revolve(
    profile: Sequence[tuple[float, float]], center: Vec3 = (0.0, 0.0, 0.0), axis: str = "z", sections: int = 24
) -> trimesh.Trimesh:
    """Revolve a (radius, height) profile about the z axis (lathe shapes: cups, bottles, lamp shades).

    A profile that starts and ends on the axis (radius 0) gives a closed, watertight solid.
    """
    mesh = trimesh.creation.revolve(np.asarray(profile, dtype=float), sections=sections)
    mesh.merge_vertices()
    mesh.fix_normals()
    return _place(mesh, center, axis)


def frustum(
    r_bottom: float, r_top: float, height: float, center: Vec3 = (0.0, 0.0, 0.0), sections: int = 16
) -> trimesh.Trimesh:
    """A truncated cone standing on its base; `center` is the centre of the base."""
    return revolve([(0, 0), (r_bottom, 0), (r_top, height), (0, height)], center, sections=sections)


def container(
    profile: Sequence[tuple[float, float]], wall: float, bottom: float, center: Vec3 = (0.0, 0.0, 0.0),
    sections: int = 24,
) -> trimesh.Trimesh:
    """An open-topped vessel (mug, bowl, pot, vase) from its outer (radius, height) profile.

    The profile runs from the bottom rim to the top rim (radius > 0 everywhere); the inner wall is the
    outer one offset inwards by `wall`, and the floor is `bottom` thick.
    """
    outer = [(float(r), float(z)) for r, z in profile]
    top_z = outer[-1][1]
    inner = [(max(r - wall, 1e-3), max(z, bottom)) for r, z in reversed(outer)]
    inner[0] = (inner[0][0], top_z)
    pts = [(0.0, 0.0)] + outer + inner + [(0.0, bottom)]
    return revolve(pts, center, sections=sections)


def ellipsoid(radii: Vec3, center: Vec3 = (0.0, 0.0, 0.0), subdivisions: int = 2) -> trimesh.Trimesh:
    """An ellipsoid with semi-axes `radii` (fruit, pillows, stones)."""
    mesh = trimesh.creation.icosphere(subdivisions=subdivisions)
    mesh.apply_scale(np.asarray(radii, dtype=float))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def sphere(radius: float, center: Vec3 = (0.0, 0.0, 0.0), subdivisions: int = 2) -> trimesh.Trimesh:
    """A sphere."""
    return ellipsoid((radius, radius, radius), center, subdivisions)


def capsule(radius: float, length: float, center: Vec3 = (0.0, 0.0, 0.0), axis: str = "z") -> trimesh.Trimesh:
    """A capsule whose straight part is `length` long, along `axis`."""
    return _place(trimesh.creation.capsule(height=length, radius=radius, count=[8, 8]), center, axis)


def torus_arc(
    major: float, minor: float, center: Vec3 = (0.0, 0.0, 0.0), plane: str = "xz",
    start: float = -np.pi / 2, end: float = np.pi / 2, sections: int = 12, minor_sections: int = 8,
) -> trimesh.Trimesh:
    """Part of a torus (a handle): the ring lies in `plane` ("xz", "yz" or "xy"), angles in radians.

    Angles are measured in the plane from its first axis towards its second.
    """
    angles = np.linspace(start, end, sections + 1)
    phis = np.linspace(0, 2 * np.pi, minor_sections, endpoint=False)
    verts = []
    for a in angles:
        c, s = np.cos(a), np.sin(a)
        for ph in phis:
            rr = major + minor * np.cos(ph)
            verts.append((rr * c, rr * s, minor * np.sin(ph)))
    verts_a = np.asarray(verts)
    faces = []
    m = minor_sections
    for i in range(sections):
        for j in range(m):
            a0, a1 = i * m + j, i * m + (j + 1) % m
            b0, b1 = a0 + m, a1 + m
            faces += [(a0, b0, a1), (a1, b0, b1)]
    # cap both ends so the handle is a closed solid
    for ring, flip in ((0, True), (sections, False)):
        cidx = len(verts_a)
        ring_pts = verts_a[ring * m:(ring + 1) * m]
        verts_a = np.vstack([verts_a, ring_pts.mean(axis=0)])
        for j in range(m):
            f = (cidx, ring * m + j, ring * m + (j + 1) % m)
            faces.append(f if flip else (f[0], f[2], f[1]))
    mesh = trimesh.Trimesh(verts_a, np.asarray(faces), process=True)
    mesh.fix_normals()
    # map local (u, v, w) = (plane axis 1, plane axis 2, normal) to xyz
    perm = {"xz": [0, 2, 1], "yz": [1, 2, 0], "xy": [0, 1, 2]}[plane]
    out = np.zeros_like(mesh.vertices)
    for src, dst in enumerate(perm):
        out[:, dst] = mesh.vertices[:, src]
    mesh = trimesh.Trimesh(out, mesh.faces, process=True)
    mesh.fix_normals()
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def extrude(outline: Sequence[tuple[float, float]], height: float, z0: float = 0.0) -> trimesh.Trimesh:
    """Extrude a 2D outline (x, y) upwards by `height` starting at `z0` (L-shaped tops, slabs)."""
    mesh = trimesh.creation.extrude_polygon(Polygon(outline), height)
    mesh.apply_translation((0.0, 0.0, z0))
    return mesh


def transformed(mesh: trimesh.Trimesh, yaw: float = 0.0, offset: Vec3 = (0.0, 0.0, 0.0),
                pitch: float = 0.0, roll: float = 0.0) -> trimesh.Trimesh:
    """A copy rotated (roll about x, pitch about y, then yaw about z, radians) and then translated."""
    out = mesh.copy()
    rot = trimesh.transformations.euler_matrix(roll, pitch, yaw, axes="sxyz")
    out.apply_transform(rot)
    out.apply_translation(np.asarray(offset, dtype=float))
    return out


def union_all(meshes: Sequence[trimesh.Trimesh]) -> trimesh.Trimesh:
    """Boolean union (manifold3d) of closed meshes, for visual meshes that must be one surface."""
    return trimesh.boolean.union(list(meshes), engine="manifold")


def difference(a: trimesh.Trimesh, b: trimesh.Trimesh) -> trimesh.Trimesh:
    """Boolean difference a - b (manifold3d): cut-outs such as a sink opening."""
    return trimesh.boolean.difference([a, b], engine="manifold")
