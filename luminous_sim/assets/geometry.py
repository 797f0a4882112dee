"""The shape kit of the procedural asset builders: meshes and 2D outlines (trimesh, metres, z up).

Primitives first (boxes, cylinders, lathe shapes, boolean ops), then the shapes the builder families
share: outlines, solids, slabs, bodies lying along x, sweeps and walls, and mesh cutting/moving. Functions
here know nothing of parts, links or palettes (that is `builders/common.py`). Where two shapes look alike
but are built from different point sets (the rounded rectangles), both are kept so that every asset stays
byte-identical.

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


# --------------------------------------------------------------------------------------------------
# 2D outlines (lists or arrays of (x, y) points, counter-clockwise)


def rounded_rect(w: float, d: float, r: float, n: int = 3) -> list[tuple[float, float]]:
    """Outline of a w x d rectangle with corners rounded by r (counter-clockwise).

    Each corner is n + 1 points (angles stepped in degrees); r is clamped to just under half the smaller side.
    `rounded_outline` and `rrect_loop` are the same shape with other point sets, kept apart so that the
    assets built from each stay byte-identical.
    """
    r = min(r, w / 2 - 1e-4, d / 2 - 1e-4)
    pts = []
    for cx, cy, a0 in ((w / 2 - r, d / 2 - r, 0), (-w / 2 + r, d / 2 - r, 90), (-w / 2 + r, -d / 2 + r, 180),
                       (w / 2 - r, -d / 2 + r, 270)):
        for k in range(n + 1):
            a = np.radians(a0 + 90 * k / n)
            pts.append((cx + r * np.cos(a), cy + r * np.sin(a)))
    return pts


def rounded_outline(w: float, d: float, r: float, n: int = 4) -> list[tuple[float, float]]:
    """A w x d rectangle (centred) with corners rounded by r: n points per corner (plain floats), r not clamped."""
    pts = []
    for cx, cy, a0 in ((w / 2 - r, d / 2 - r, 0.0), (-w / 2 + r, d / 2 - r, np.pi / 2),
                       (-w / 2 + r, -d / 2 + r, np.pi), (w / 2 - r, -d / 2 + r, 1.5 * np.pi)):
        for a in np.linspace(a0, a0 + np.pi / 2, n):
            pts.append((float(cx + r * np.cos(a)), float(cy + r * np.sin(a))))
    return pts


def rrect_loop(a: float, b: float, r: float, m: int = 3) -> np.ndarray:
    """A rounded rectangle of half sizes a x b and corner radius r as a CCW loop of 4 (m + 1) points.

    Loops of the same m match point for point, so two of them bound a ring of convex segments; r = 0
    gives a sharp rectangle with the same point count.
    """
    r = min(r, a, b)
    pts = []
    for k, (sx, sy) in enumerate(((1, 1), (-1, 1), (-1, -1), (1, -1))):
        cx, cy = sx * (a - r), sy * (b - r)
        for t in np.linspace(k * np.pi / 2, (k + 1) * np.pi / 2, m + 1):
            pts.append((cx + r * np.cos(t), cy + r * np.sin(t)))
    return np.array(pts)


def oval(rx: float, ry_front: float, ry_back: float, n: int = 20, cy: float = 0.0) -> np.ndarray:
    """An egg-shaped CCW loop: half-ellipses of depth ry_front towards +y and ry_back towards -y."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    s = np.sin(t)
    return np.stack([rx * np.cos(t), cy + s * np.where(s >= 0, ry_front, ry_back)], axis=1)


def circle_points(r: float, n: int, rx: float | None = None) -> list[tuple[float, float]]:
    """n points on a circle of radius r (an ellipse with x semi-axis `rx` when given), from angle 0."""
    rx = r if rx is None else rx
    return [(rx * np.cos(2 * np.pi * k / n), r * np.sin(2 * np.pi * k / n)) for k in range(n)]


def ellipse_points(a: float, b: float, n: int = 16) -> list[tuple[float, float]]:
    """n points (plain floats) on an ellipse with semi-axes a (x) and b (y), from angle 0."""
    return [(float(a * np.cos(t)), float(b * np.sin(t))) for t in np.linspace(0, 2 * np.pi, n, endpoint=False)]


def arch_outline(w: float, h: float, n: int = 10) -> np.ndarray:
    """A round-topped outline (x, z): straight sides up to h - w/2, a half circle on top; CCW."""
    r = w / 2
    pts = [(r, 0.0), (r, h - r)]
    pts += [(r * np.cos(t), h - r + r * np.sin(t)) for t in np.linspace(0, np.pi, n + 1)[1:-1]]
    pts += [(-r, h - r), (-r, 0.0), (0.0, 0.0)]
    return np.array(pts)


def inset_outline(outline: Sequence[tuple[float, float]], d: float) -> list[tuple[float, float]]:
    """The outline shrunk by d (the cut face inside a crust or skin)."""
    poly = Polygon(outline).buffer(-d, join_style=2).simplify(1e-4)
    return [(float(x), float(y)) for x, y in list(poly.exterior.coords)[:-1]]


# --------------------------------------------------------------------------------------------------
# solids


def hull(points: Sequence[Vec3]) -> trimesh.Trimesh:
    """The convex hull of a few 3D points (wedges, slanted slabs, ring segments)."""
    return trimesh.convex.convex_hull(np.asarray(points, dtype=float))


def soft_box(size: Vec3, center: Vec3 = (0.0, 0.0, 0.0), r: float = 0.02) -> trimesh.Trimesh:
    """A box with chamfered edges (24 vertices, convex): cushions, mattresses, padded panels."""
    sx, sy, sz = (float(s) for s in size)
    r = min(r, sx / 3, sy / 3, sz / 3)
    pts = []
    for a, b, c in ((sx, sy - 2 * r, sz - 2 * r), (sx - 2 * r, sy, sz - 2 * r), (sx - 2 * r, sy - 2 * r, sz)):
        for i in (-1, 1):
            for j in (-1, 1):
                for k in (-1, 1):
                    pts.append((i * a / 2, j * b / 2, k * c / 2))
    mesh = trimesh.convex.convex_hull(np.asarray(pts))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def soft_box_at(lo: Vec3, hi: Vec3, r: float = 0.02) -> trimesh.Trimesh:
    """`soft_box` spanning the corners `lo` and `hi`."""
    lo_a, hi_a = np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)
    return soft_box(hi_a - lo_a, (lo_a + hi_a) / 2, r)


def rounded_box(w: float, d: float, h: float, r: float, edges: str, z0: float = 0.0, sections: int = 16,
                cx: float = 0.0, cy: float = 0.0) -> trimesh.Trimesh:
    """A convex box w x d x h standing at z0 with rounded edges.

    edges "z": the four vertical edges rounded; "x": the two top edges running along x (a loaf);
    "y": the two top edges running along y (domed ends).
    """
    if edges == "z":
        pieces = [cylinder(r, h, (sx * (w / 2 - r), sy * (d / 2 - r), z0 + h / 2), sections=sections)
                  for sx in (-1, 1) for sy in (-1, 1)]
    elif edges == "x":
        pieces = [box_at((-w / 2, -d / 2, z0), (w / 2, d / 2, z0 + h - r))]
        pieces += [cylinder(r, w, (0, sy * (d / 2 - r), z0 + h - r), axis="x", sections=sections) for sy in (-1, 1)]
    else:
        pieces = [box_at((-w / 2, -d / 2, z0), (w / 2, d / 2, z0 + h - r))]
        pieces += [cylinder(r, d, (sx * (w / 2 - r), 0, z0 + h - r), axis="y", sections=sections) for sx in (-1, 1)]
    shape = trimesh.util.concatenate(pieces).convex_hull
    shape.apply_translation((cx, cy, 0.0))
    return shape


def superquadric(radii: Sequence[float], e1: float, e2: float, center: Sequence[float] = (0, 0, 0), nu: int = 10,
                 nv: int = 20) -> trimesh.Trimesh:
    """A superquadric: e2 shapes the footprint (1 round, <1 boxy), e1 the side profile (>1 pinched)."""
    a, b, c = radii

    def f(w: np.ndarray, e: float) -> np.ndarray:
        return np.sign(w) * np.abs(w) ** e

    verts = [(0.0, 0.0, -c)]
    for i in range(1, nu):
        phi = -np.pi / 2 + np.pi * i / nu
        for j in range(nv):
            th = 2 * np.pi * j / nv
            verts.append((a * f(np.cos(phi), e1) * f(np.cos(th), e2), b * f(np.cos(phi), e1) * f(np.sin(th), e2),
                          c * f(np.sin(phi), e1)))
    verts.append((0.0, 0.0, c))
    faces = []
    for j in range(nv):
        faces.append((0, 1 + (j + 1) % nv, 1 + j))
    for i in range(nu - 2):
        for j in range(nv):
            a0, a1 = 1 + i * nv + j, 1 + i * nv + (j + 1) % nv
            b0, b1 = a0 + nv, a1 + nv
            faces += [(a0, a1, b0), (a1, b1, b0)]
    top = len(verts) - 1
    last = 1 + (nu - 2) * nv
    for j in range(nv):
        faces.append((top, last + j, last + (j + 1) % nv))
    m = trimesh.Trimesh(np.asarray(verts), np.asarray(faces), process=True)
    m.fix_normals()
    m.apply_translation(np.asarray(center, dtype=float))
    return m


def smooth_ellipsoid(radii: Sequence[float], center: Sequence[float] = (0, 0, 0)) -> trimesh.Trimesh:
    """A lean, smooth ellipsoid (about 100 vertices) for limbs and features."""
    return superquadric(radii, 1.0, 1.0, center, nu=8, nv=14)


def spheroid(radii: Sequence[float], center: Sequence[float] = (0.0, 0.0, 0.0), sections: int = 14,
             rings: int = 7) -> trimesh.Trimesh:
    """A low-poly ellipsoid (a revolved half circle, scaled): smooth at a few dozen vertices."""
    phis = np.linspace(0.0, np.pi, rings + 1)
    profile = [(float(np.sin(p)), float(-np.cos(p))) for p in phis]
    profile[0], profile[-1] = (0.0, -1.0), (0.0, 1.0)
    mesh = revolve(profile, sections=sections)
    mesh.apply_scale(np.asarray(radii, dtype=float))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def hollow_cylinder(r_in: float, r_out: float, h: float, bevel: float = 0.0, sections: int = 24,
                    angle: float | None = None) -> trimesh.Trimesh:
    """A hollow cylinder (a roll) standing on z = 0; `angle` < 2 pi gives a curved strip."""
    prof = [(r_in, 0), (r_out - bevel, 0), (r_out, bevel), (r_out, h - bevel), (r_out - bevel, h), (r_in, h), (r_in, 0)]
    if bevel <= 0:
        prof = [(r_in, 0), (r_out, 0), (r_out, h), (r_in, h), (r_in, 0)]
    if angle is None:
        return revolve(prof, sections=sections)
    m = trimesh.creation.revolve(np.asarray(prof, dtype=float), angle=angle, sections=sections, cap=True)
    m.fix_normals()
    return m


def annulus_band(r_in: float, r_out: float, z0: float, z1: float, sections: int = 18) -> trimesh.Trimesh:
    """A thin horizontal ring (rims, weave bands, hoops)."""
    return trimesh.creation.annulus(r_min=r_in, r_max=r_out, segment=[[0, 0, z0], [0, 0, z1]], sections=sections)


def lathe_shell(profile: Sequence[tuple[float, float]], wall: float, sections: int = 24) -> trimesh.Trimesh:
    """A thin lathe shell open at both ends (lamp shades) from its outer (radius, z) profile."""
    outer = [(float(r), float(z)) for r, z in profile]
    inner = [(r - wall, z) for r, z in reversed(outer)]
    return revolve(outer + inner + [outer[0]], sections=sections)


def tapered_rod(p0: Vec3, p1: Vec3, r0: float, r1: float, sections: int = 12) -> trimesh.Trimesh:
    """A truncated cone from p0 (radius r0) to p1 (radius r1): spouts, tapered handles."""
    a, b = np.asarray(p0, dtype=float), np.asarray(p1, dtype=float)
    length = float(np.linalg.norm(b - a))
    mesh = revolve([(0, 0), (r0, 0), (r1, length), (0, length)], sections=sections)
    mesh.apply_transform(trimesh.geometry.align_vectors([0, 0, 1], (b - a) / length))
    mesh.apply_translation(a)
    return mesh


def strut(p0: Vec3, p1: Vec3, wx: float, wy: float) -> trimesh.Trimesh:
    """A slanted bar of rectangular section wx x wy from p0 to p1 (horizontal end faces): legs, feet."""
    return hull([(p[0] + sx * wx / 2, p[1] + sy * wy / 2, p[2]) for p in (p0, p1) for sx in (-1, 1) for sy in (-1, 1)])


def splayed_leg(top: Vec3, bottom: Vec3, r_top: float, r_bottom: float, sections: int = 10) -> trimesh.Trimesh:
    """A tapered round leg from `top` to `bottom`, its foot cut flat at z = bottom z."""
    p0, p1 = np.asarray(top, dtype=float), np.asarray(bottom, dtype=float)
    axis = p0 - p1
    length = float(np.linalg.norm(axis))
    leg = frustum(r_bottom, r_top, length + 0.04, (0, 0, -0.02), sections=sections)
    rot = trimesh.geometry.align_vectors([0, 0, 1], axis / length)
    leg.apply_transform(rot)
    leg.apply_translation(p1)
    leg = trimesh.intersections.slice_mesh_plane(leg, [0, 0, 1], [0, 0, p1[2]], cap=True)
    return trimesh.intersections.slice_mesh_plane(leg, -axis / length, p0, cap=True)


def turned_leg(x: float, y: float, h: float, r: float, z0: float = 0.0, sections: int = 10) -> trimesh.Trimesh:
    """A lathe-turned furniture leg (narrow foot, bulb, collar) standing at (x, y)."""
    prof = [(0, 0), (r * 0.6, 0), (r * 0.75, h * 0.12), (r * 0.6, h * 0.35), (r, h * 0.55), (r * 0.7, h * 0.78),
            (r * 0.95, h * 0.88), (r * 0.95, h), (0, h)]
    return revolve(prof, (x, y, z0), sections=sections)


# --------------------------------------------------------------------------------------------------
# slabs and flat pieces


def rounded_slab(w: float, d: float, h: float, r: float = 0.0, z0: float = 0.0, cx: float = 0.0, cy: float = 0.0,
                 n: int = 3) -> trimesh.Trimesh:
    """A flat w x d x h slab with rounded vertical corners, bottom at z0."""
    if r <= 0:
        return box_at((cx - w / 2, cy - d / 2, z0), (cx + w / 2, cy + d / 2, z0 + h))
    m = extrude(rounded_rect(w, d, r, n), h, z0)
    m.apply_translation((cx, cy, 0.0))
    return m


def rounded_slab_y(w: float, h: float, d: float, r: float, center: Sequence[float]) -> trimesh.Trimesh:
    """A w (x) by h (z) slab d deep (y) with rounded corners seen from the front."""
    m = extrude(rounded_rect(w, h, r), d, -d / 2)
    m.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    m.apply_translation(np.asarray(center, dtype=float))
    return m


def loop_slab(loop: np.ndarray, z0: float, z1: float) -> trimesh.Trimesh:
    """A flat prism over a convex loop, from z0 to z1."""
    return hull([(x, y, z) for x, y in loop for z in (z0, z1)])


def extrude_yz(outline_yz: Sequence[tuple[float, float]], width: float, cx: float = 0.0) -> trimesh.Trimesh:
    """Extrude a (y, z) side outline along x, `width` wide, centred at x = cx."""
    m = extrude(outline_yz, width, -width / 2)
    perm = np.eye(4)
    perm[:3, :3] = [[0, 0, 1], [1, 0, 0], [0, 1, 0]]
    m.apply_transform(perm)
    m.apply_translation((cx, 0.0, 0.0))
    return m


def flat_decal(w: float, d: float, z: float, cx: float = 0.0, cy: float = 0.0, t: float = 0.0004,
               r: float = 0.0) -> trimesh.Trimesh:
    """A thin printed/applied rectangle lying on a top surface at height z."""
    return rounded_slab(w, d, t, r, z, cx, cy, n=2)


def flat_disc(r: float, z: float, cx: float = 0.0, cy: float = 0.0, t: float = 0.0004,
              n: int = 16) -> trimesh.Trimesh:
    """A thin disc (a printed dot, a label) lying on a top surface at height z."""
    return cylinder(r, t, (cx, cy, z + t / 2), sections=n)


def disc_y(r: float, center: Vec3, t: float = 0.002, sections: int = 20) -> trimesh.Trimesh:
    """A thin disc facing +y (a sun in a picture, an LED, a screw head)."""
    return cylinder(r, t, center, axis="y", sections=sections)


def flat_poly(pts_xz: Sequence[tuple[float, float]], y_back: float, t: float = 0.002) -> trimesh.Trimesh:
    """A flat shape drawn in the x-z plane (a picture's hill, a roof), t thick from y_back towards +y."""
    mesh = extrude(pts_xz, t)
    mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    mesh.apply_translation((0.0, y_back + t, 0.0))
    return mesh


def oval_patch(radii: Vec3, center: Vec3, yaw: float = 0.0, pitch: float = 0.0) -> trimesh.Trimesh:
    """A flat oval patch (a stain, a smear, a crumb): an octagonal disc with semi-axes radii[0], radii[1]
    and thickness 2 * radii[2]."""
    disc = cylinder(1.0, 2.0, sections=8)
    disc.apply_scale(np.asarray(radii, dtype=float))
    return transformed(disc, yaw=yaw, pitch=pitch, offset=center)


def tilted_plate(outline: Sequence[tuple[float, float]], t: float, start: Vec3, end_x: float, end_z: float,
                 ) -> trimesh.Trimesh:
    """A flat handle, `t` thick, from an (x, y) outline running from x = 0 to its length: stretched and
    tilted so that its bottom face runs from `start` (x, y, z) to height `end_z` at x = `end_x` (either side)."""
    length = max(x for x, _ in outline)
    run, drop = abs(end_x - start[0]), start[2] - end_z
    pitch = float(np.arctan2(drop, run))
    scale = float(np.hypot(run, drop)) / length
    mesh = transformed(extrude([(x * scale, y) for x, y in outline], t), pitch=pitch)
    if end_x < start[0]:
        mesh = transformed(mesh, yaw=np.pi)
    mesh.apply_translation(np.asarray(start, dtype=float))
    return mesh


# --------------------------------------------------------------------------------------------------
# bodies along x (things lying on the floor)


def lathe_x(profile: Sequence[tuple[float, float]], x0: float, zc: float, sections: int = 8,
            y: float = 0.0) -> trimesh.Trimesh:
    """Revolve a (radius, length) profile about an axis along +x starting at x0, at height zc; a polygonal
    section has a flat facet facing down (so pens, pencils and bats do not roll)."""
    m = revolve(profile, (0.0, 0.0, 0.0), axis="x", sections=sections)
    m.apply_transform(trimesh.transformations.rotation_matrix(np.pi / sections, [1, 0, 0]))
    m.apply_translation((x0, y, zc))
    return m


def prism_x(r: float, length: float, x0: float, zc: float, sections: int = 8, y: float = 0.0) -> trimesh.Trimesh:
    """A polygonal rod of circumradius r along +x from x0, lying on a facet (see `lathe_x`)."""
    return lathe_x([(0, 0), (r, 0), (r, length), (0, length)], x0, zc, sections, y)


def prism_axis_height(r: float, sections: int) -> float:
    """Height of the axis of a facet-down polygonal prism of circumradius r lying on the floor."""
    return r * float(np.cos(np.pi / sections))


def loft_x(outline: Sequence[tuple[float, float]], stations: Sequence[tuple[float, float, float]]) -> trimesh.Trimesh:
    """A solid swept along x through convex (y, z) cross-sections: `outline` scaled by (sy, sz) at each x.

    z is scaled about z = 0 so a flat-bottomed outline keeps its bottom on the floor.
    """
    ring = np.asarray(outline, dtype=float)
    m = len(ring)
    verts = []
    for x, sy, sz in stations:
        verts += [(x, sy * y, sz * z) for y, z in ring]
    cz = float(ring[:, 1].mean())
    verts.append((stations[0][0], 0.0, stations[0][2] * cz))
    verts.append((stations[-1][0], 0.0, stations[-1][2] * cz))
    faces = []
    for i in range(len(stations) - 1):
        for j in range(m):
            a0, a1 = i * m + j, i * m + (j + 1) % m
            b0, b1 = a0 + m, a1 + m
            faces += [(a0, b0, a1), (a1, b0, b1)]
    c0, c1 = len(verts) - 2, len(verts) - 1
    last = (len(stations) - 1) * m
    for j in range(m):
        faces.append((c0, (j + 1) % m, j))
        faces.append((c1, last + j, last + (j + 1) % m))
    mesh = trimesh.Trimesh(np.asarray(verts), np.asarray(faces), process=True)
    mesh.fix_normals()
    return mesh


# --------------------------------------------------------------------------------------------------
# sweeps, rings and walls


def sweep_loop(path: Sequence[Sequence[float]], section: Sequence[tuple[float, float]],
               z: float = 0.0) -> trimesh.Trimesh:
    """Sweep a closed (u, w) cross-section (u: in-plane normal offset, w: height) along a closed xy path."""
    path_a = np.asarray(path, dtype=float)
    n = len(path_a)
    tang = np.roll(path_a, -1, 0) - np.roll(path_a, 1, 0)
    tang /= np.linalg.norm(tang, axis=1)[:, None]
    nrm = np.stack([tang[:, 1], -tang[:, 0]], 1)
    m = len(section)
    verts = [(path_a[i, 0] + nrm[i, 0] * u, path_a[i, 1] + nrm[i, 1] * u, z + w) for i in range(n) for u, w in section]
    faces = []
    for i in range(n):
        i2 = (i + 1) % n
        for j in range(m):
            j2 = (j + 1) % m
            a, b, c, d = i * m + j, i * m + j2, i2 * m + j, i2 * m + j2
            faces += [(a, c, b), (b, c, d)]
    mesh = trimesh.Trimesh(np.asarray(verts), np.asarray(faces), process=True)
    mesh.fix_normals()
    return mesh


def torus_ring(major: float, minor: float, center: Sequence[float] = (0, 0, 0), plane: str = "xy", n: int = 24,
               m: int = 6) -> trimesh.Trimesh:
    """A closed torus ring (key rings, seams, rims) lying in `plane` ("xy", "xz" or "yz")."""
    mesh = sweep_loop(circle_points(major, n), circle_points(minor, m))
    if plane == "xz":
        mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    elif plane == "yz":
        mesh.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [0, 1, 0]))
    mesh.apply_translation(np.asarray(center, dtype=float))
    return mesh


def ring_wall(
    top_out: np.ndarray,
    top_in: np.ndarray,
    z_top: float,
    z_bot: float,
    bot_out: np.ndarray | None = None,
    bot_in: np.ndarray | None = None,
) -> list[trimesh.Trimesh]:
    """A wall between two matching loops as convex segments (vessel walls, frames with a hole, rims).

    The top loops sit at z_top and the bottom loops (the top ones when not given) at z_bot.
    """
    bot_out = top_out if bot_out is None else bot_out
    bot_in = top_in if bot_in is None else bot_in
    n = len(top_out)
    out = []
    for i in range(n):
        j = (i + 1) % n
        if np.allclose(top_out[i], top_out[j]) and np.allclose(top_in[i], top_in[j]):
            continue
        pts = [
            (p[0], p[1], z)
            for lo, li, z in ((top_out, top_in, z_top), (bot_out, bot_in, z_bot))
            for p in (lo[i], lo[j], li[i], li[j])
        ]
        out.append(hull(pts))
    return out


def ring_wall_xz(outer: np.ndarray, inner: np.ndarray, y0: float, y1: float) -> list[trimesh.Trimesh]:
    """A flat frame in the x-z plane between two matching (x, z) loops, y0..y1 deep."""
    return [stand_xz(m) for m in ring_wall(outer, inner, -y0, -y1)]


def round_wall_wedges(r_bot: float, r_top: float, wall: float, z0: float, z1: float, sections: int = 18
                      ) -> list[trimesh.Trimesh]:
    """The wall of a round open vessel as convex wedges (exact collision, no decomposition).

    The outer radius runs from `r_bot` at z0 to `r_top` at z1; the wall is `wall` thick horizontally.
    """
    out = []
    for i in range(sections):
        a0, a1 = 2 * np.pi * i / sections, 2 * np.pi * (i + 1) / sections
        pts = []
        for r, z in ((r_bot, z0), (r_top, z1)):
            for rr in (r, r - wall):
                for a in (a0, a1):
                    pts.append((rr * np.cos(a), rr * np.sin(a), z))
        out.append(hull(pts))
    return out


def tapered_walls(wb: float, db: float, wt: float, dt: float, z0: float, z1: float, t: float
                  ) -> list[trimesh.Trimesh]:
    """Four walls of a rectangular open vessel whose outer size goes from wb x db (at z0) to wt x dt (at z1)."""
    ends = ((wb, db, z0), (wt, dt, z1))
    front_back = [hull([(x, y, z) for w, d, z in ends for y in (s * d / 2, s * (d / 2 - t)) for x in (-w / 2, w / 2)])
                  for s in (-1, 1)]  # these span the full width
    sides = [hull([(x, y, z) for w, d, z in ends for x in (s * w / 2, s * (w / 2 - t)) for y in (-d / 2, d / 2)])
             for s in (-1, 1)]
    return front_back + sides


def rect_rim(w: float, d: float, z0: float, z1: float, out: float, inn: float) -> list[trimesh.Trimesh]:
    """A rectangular frame band around the outside of a w x d wall: `out` proud of it, `inn` into it."""
    xo, yo, xi, yi = w / 2 + out, d / 2 + out, w / 2 - inn, d / 2 - inn
    return [box_at((-xo, yi, z0), (xo, yo, z1)), box_at((-xo, -yo, z0), (xo, -yi, z1)),
            box_at((-xo, -yi, z0), (-xi, yi, z1)), box_at((xi, -yi, z0), (xo, yi, z1))]


def drape(
    xs_top: Sequence[float],
    xs_bot: Sequence[float],
    z_top: float,
    z_bot: float,
    y0: float,
    amp: float,
    t: float = 0.003,
) -> list[trimesh.Trimesh]:
    """A pleated fabric panel: thin slanted strips zig-zagging in y between matching x positions.

    xs_top and xs_bot list the fold lines at the top and bottom (same length); the folds alternate between
    y0 - amp/2 and y0 + amp/2.
    """
    out = []
    for k in range(len(xs_top) - 1):
        ya = y0 + amp * (0.5 if k % 2 else -0.5)
        yb = y0 + amp * (-0.5 if k % 2 else 0.5)
        corners = [
            (xs_bot[k], ya, z_bot),
            (xs_bot[k + 1], yb, z_bot),
            (xs_top[k], ya, z_top),
            (xs_top[k + 1], yb, z_top),
        ]
        out.append(hull([(x, y + s * t / 2, z) for x, y, z in corners for s in (-1, 1)]))
    return out


# --------------------------------------------------------------------------------------------------
# cutting and moving meshes


def clip_below(mesh: trimesh.Trimesh, z: float) -> trimesh.Trimesh:
    """Cut a closed mesh at height z and keep (and cap) what is above: a flat bottom."""
    return mesh.slice_plane([0.0, 0.0, z], [0.0, 0.0, 1.0], cap=True)


def clip_to_box(mesh: trimesh.Trimesh, lo: Sequence[float], hi: Sequence[float]) -> trimesh.Trimesh:
    """The part of a (convex) mesh inside the box lo..hi; convex again."""
    return trimesh.boolean.intersection([mesh, box_at(lo, hi)], engine="manifold")


def pressed_flat(mesh: trimesh.Trimesh, depth: float) -> trimesh.Trimesh:
    """Press the lowest `depth` of a mesh flat (a resting spot) and move its bottom to z = 0."""
    v = np.array(mesh.vertices)
    cut = v[:, 2].min() + depth
    v[:, 2] = np.maximum(v[:, 2], cut) - cut
    return trimesh.Trimesh(v, np.array(mesh.faces), process=False)


def stand_xz(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """Stand a mesh drawn in the x-y plane up into the x-z plane.

    Rotating +90 degrees about x maps (x, y, z) to (x, -z, y): plane y becomes the height and a
    thickness spanning z in [-y1, -y0] ends up spanning y0..y1.
    """
    out = mesh.copy()
    out.apply_transform(trimesh.transformations.rotation_matrix(np.pi / 2, [1, 0, 0]))
    return out


def point_along(mesh: trimesh.Trimesh, direction: Sequence[float], base: Sequence[float]) -> trimesh.Trimesh:
    """Turn a mesh built along +z from the origin so +z points along `direction`, then move it to `base`."""
    d = np.asarray(direction, dtype=float)
    mesh.apply_transform(trimesh.geometry.align_vectors([0, 0, 1], d / np.linalg.norm(d)))
    mesh.apply_translation(np.asarray(base, dtype=float))
    return mesh


def rotate_x(mesh: trimesh.Trimesh, angle: float, about: Sequence[float] = (0, 0, 0)) -> trimesh.Trimesh:
    """Rotate `mesh` in place by `angle` radians about the x axis through `about`; returns it."""
    mesh.apply_transform(trimesh.transformations.rotation_matrix(angle, [1, 0, 0], point=about))
    return mesh


def rotate_y(mesh: trimesh.Trimesh, angle: float, about: Sequence[float] = (0, 0, 0)) -> trimesh.Trimesh:
    """Rotate `mesh` in place by `angle` radians about the y axis through `about`; returns it."""
    mesh.apply_transform(trimesh.transformations.rotation_matrix(angle, [0, 1, 0], point=about))
    return mesh


def rotate_z(mesh: trimesh.Trimesh, yaw: float, about: Sequence[float] = (0, 0, 0)) -> trimesh.Trimesh:
    """Rotate `mesh` in place by `yaw` radians about the z axis through `about`; returns it."""
    mesh.apply_transform(trimesh.transformations.rotation_matrix(yaw, [0, 0, 1], point=about))
    return mesh
