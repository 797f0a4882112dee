"""TinyRenderer's rasteriser, compiled with numba: the same arithmetic, without PyBullet's per-call costs.

Each step follows PyBullet's TinyRenderer (bullet3 `examples/TinyRenderer`: `TinyRenderer::renderObject`,
`our_gl.cpp`'s `triangle` / `triangleClipped` / `barycentric`, `Shader::vertex` / `Shader::fragment`, and
`TinyRendererVisualShapeConverter::render` / `copyCameraImageData`) in float32, in the order TinyRenderer does
it (its small-vector dot products add from the last component down), but for what PyBullet 3.2.7's build does
in float64 (read from its machine code: barycentric weights, their perspective correction, the depth and the
depth test; the back-face test), so that a frame comes out as TinyRenderer draws it but for rounding in the
few places that are not copied exactly (each link's model matrix is made from its pose quaternion, the camera
position for the back-face test in float64): depth's last bits, and so the rare pixel where two surfaces lie
within that rounding of each other (about 6 in a million); see `raster_scene` for what is drawn and
`tests/world/test_raster.py` and docs/benchmarks.md ("Performance") for the measured agreement.

What makes it cheaper: one compiled loop over every object (no call, matrix set-up or virtual shader per
object and face), each vertex transformed once, not once per face corner; the light-view transform that only
shadows use is skipped (shadows are off); objects outside the view are skipped by their bounding box.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# error_model="numpy": a division by zero gives inf or nan, as in C, where TinyRenderer divides by zero

F = np.float32


@njit(cache=True, inline="always", error_model="numpy")
def _dot4(m, i, x, y, z, w):
    """Row i of m times (x, y, z, w), added from the last component down (TinyRenderer's `vec` dot)."""
    acc = F(0.0)
    acc += m[i, 3] * w
    acc += m[i, 2] * z
    acc += m[i, 1] * y
    acc += m[i, 0] * x
    return acc


@njit(cache=True, error_model="numpy")
def matmul4(a, b):
    """a @ b in float32 with TinyRenderer's order of additions."""
    out = np.empty((4, 4), np.float32)
    for i in range(4):
        for j in range(4):
            out[i, j] = _dot4(a, i, b[0, j], b[1, j], b[2, j], b[3, j])
    return out


@njit(cache=True, inline="always", error_model="numpy")
def _barycentric(ax, ay, bx, by, cx, cy, px, py):
    """our_gl's barycentric as PyBullet 3.2.7 compiles it: float32 corners, every operation in float64."""
    ax, ay, bx, by = np.float64(ax), np.float64(ay), np.float64(bx), np.float64(by)
    cx, cy, px, py = np.float64(cx), np.float64(cy), np.float64(px), np.float64(py)
    s0x = cx - ax
    s0y = bx - ax
    s0z = ax - px
    s1x = cy - ay
    s1y = by - ay
    s1z = ay - py
    ux = s0y * s1z - s0z * s1y
    uy = s0z * s1x - s0x * s1z
    uz = s0x * s1y - s0y * s1x
    if abs(uz) > 1e-2:
        return 1.0 - (ux + uy) / uz, uy / uz, ux / uz
    return -1.0, 1.0, 1.0


@njit(cache=True, inline="always", error_model="numpy")
def _perspective(b0, b1, b2, w0, w1, w2):
    """Screen barycentrics to clip-space ones (over each corner's w, normalised), in float64."""
    c0 = b0 / np.float64(w0)
    c1 = b1 / np.float64(w1)
    c2 = b2 / np.float64(w2)
    s = c0 + c1 + c2
    return c0 / s, c1 / s, c2 / s


@njit(cache=True, inline="always", error_model="numpy")
def _shade(n, bar0, bar1, bar2, light, color, out_rgb, k):
    """Shader::fragment for a face with no texture and no shadow: the colour written at pixel k."""
    b0 = F(0.0)
    b0 += n[2, 0] * bar2
    b0 += n[1, 0] * bar1
    b0 += n[0, 0] * bar0
    b1 = F(0.0)
    b1 += n[2, 1] * bar2
    b1 += n[1, 1] * bar1
    b1 += n[0, 1] * bar0
    b2 = F(0.0)
    b2 += n[2, 2] * bar2
    b2 += n[1, 2] * bar1
    b2 += n[0, 2] * bar0
    inv = F(1.0) / np.float32(np.sqrt(b0 * b0 + b1 * b1 + b2 * b2))
    b0 *= inv
    b1 *= inv
    b2 *= inv
    nl = F(0.0)
    nl += b2 * light[2]
    nl += b1 * light[1]
    nl += b0 * light[0]
    two = nl * F(2.0)
    rx = b0 * two - light[0]
    ry = b1 * two - light[1]
    rz = b2 * two - light[2]
    rz = rz * (F(1.0) / np.float32(np.sqrt(rx * rx + ry * ry + rz * rz)))
    r = max(rz, F(0.0))
    specular = r * r  # pow(r, 2): the model's specular exponent without a specular map
    diffuse = max(F(0.0), nl)
    lit = F(0.35) * diffuse + F(0.05) * specular
    for c in range(3):
        base = np.float32(np.uint8(F(255.0) * color[c]))  # TGAColor(255) channel *= rgba, kept a byte
        v = F(0.6) * base + lit * base
        iv = np.int32(v) if v == v else np.int32(0)
        out_rgb[k, c] = np.uint8(min(iv, 255))


@njit(cache=True, inline="always", error_model="numpy")
def _screen(clip, i, hw, hh):
    """Vertex i's screen x, y (the viewport row times the clip point, added last to first, over w) and w."""
    x, y, w = clip[i, 0], clip[i, 1], clip[i, 3]
    px = F(0.0)
    px += hw * w
    px += hw * x
    py = F(0.0)
    py += hh * w
    py += hh * y
    return px / w, py / w, w


@njit(cache=True, error_model="numpy", inline="always")
def _raster(tri_clip, org_clip, clipped, normals, light, color, seg_id, width, height, near, far,
            zbuf, rgb, seg):
    """our_gl's `triangle` (clipped False) or `triangleClipped` for one triangle given in clip coordinates."""
    hw = F(width) / F(2.0)
    hh = F(height) / F(2.0)
    s0x, s0y, w0 = _screen(tri_clip, 0, hw, hh)
    s1x, s1y, w1 = _screen(tri_clip, 1, hw, hh)
    s2x, s2y, w2 = _screen(tri_clip, 2, hw, hh)
    big = F(np.finfo(np.float32).max)
    cx = F(width - 1)
    cy = F(height - 1)
    bminx = max(F(0.0), min(big, s0x))
    bmaxx = min(cx, max(-big, s0x))
    bminy = max(F(0.0), min(big, s0y))
    bmaxy = min(cy, max(-big, s0y))
    bminx = max(F(0.0), min(bminx, s1x))
    bmaxx = min(cx, max(bmaxx, s1x))
    bminy = max(F(0.0), min(bminy, s1y))
    bmaxy = min(cy, max(bmaxy, s1y))
    bminx = max(F(0.0), min(bminx, s2x))
    bmaxx = min(cx, max(bmaxx, s2x))
    bminy = max(F(0.0), min(bminy, s2y))
    bmaxy = min(cy, max(bmaxy, s2y))
    o0x, o0y, v0 = s0x, s0y, w0
    o1x, o1y, v1 = s1x, s1y, w1
    o2x, o2y, v2 = s2x, s2y, w2
    if clipped:
        o0x, o0y, v0 = _screen(org_clip, 0, hw, hh)
        o1x, o1y, v1 = _screen(org_clip, 1, hw, hh)
        o2x, o2y, v2 = _screen(org_clip, 2, hw, hh)
    if not (bminx <= bmaxx and bminy <= bmaxy):
        return
    x0 = np.int64(bminx)
    y0 = np.int64(bminy)
    for ix in range(x0, width):
        if F(ix) > bmaxx:
            break
        for iy in range(y0, height):
            if F(iy) > bmaxy:
                break
            b0, b1, b2 = _barycentric(s0x, s0y, s1x, s1y, s2x, s2y, F(ix), F(iy))
            if b0 < 0 or b1 < 0 or b2 < 0:
                continue
            c0, c1, c2 = _perspective(b0, b1, b2, w0, w1, w2)
            d = 0.0
            d += np.float64(tri_clip[2, 2]) * c2
            d += np.float64(tri_clip[1, 2]) * c1
            d += np.float64(tri_clip[0, 2]) * c0
            depth = -d
            k = ix + iy * width
            if np.float64(zbuf[k]) > depth:
                continue
            if clipped:
                e0, e1, e2 = _barycentric(o0x, o0y, o1x, o1y, o2x, o2y, F(ix), F(iy))
                c0, c1, c2 = _perspective(e0, e1, e2, v0, v1, v2)
            elif depth < -np.float64(far) or depth > np.float64(near):
                continue
            _shade(normals, F(c0), F(c1), F(c2), light, color, rgb, k)
            zbuf[k] = np.float32(depth)
            seg[k] = seg_id


@njit(cache=True, error_model="numpy")
def _clip_edge(t, a, b, out, n):
    """clipEdge: appends to out[n:] the part of edge a-b in front of the near plane; the new count."""
    v0 = t[a].copy()
    v1 = t[b].copy()
    in0 = v0[3] > F(0.0) and v0[2] > -v0[3]
    in1 = v1[3] > F(0.0) and v1[2] > -v1[3]
    if not (in0 or in1):
        return n
    if in0 != in1:  # the edge crosses the near plane: the outside end moves onto it
        d0 = v0[2] + v0[3]
        d1 = v1[2] + v1[3]
        factor = np.float32(1.0 / np.float64(d1 - d0))
        new = np.empty(4, np.float32)
        for i in range(4):
            new[i] = (v0[i] * d1 - v1[i] * d0) * factor
        if in0:
            v1 = new
        else:
            v0 = new
    out[n] = v0
    out[n + 1] = v1
    return n + 2


@njit(cache=True, error_model="numpy")
def render_objects(vertices, normals, faces, obj_first, obj_count, obj_vfirst, obj_vcount, models, colors,
                   seg_ids, drawn, view, proj, eye, light, width, height, near, far, zbuf, rgb, seg):
    """Draw every object with drawn[o] (in order) into the buffers (TinyRenderer's: zbuf holds -depth in clip
    units, rows bottom-up). vertices/normals (n, 3) are each object's own, faces (m, 3) index into them."""
    clip = np.empty((vertices.shape[0], 4), np.float32)
    world = np.empty((vertices.shape[0], 3), np.float32)
    nrm = np.empty((vertices.shape[0], 3), np.float32)
    tri = np.empty((3, 4), np.float32)
    tn = np.empty((3, 3), np.float32)
    poly = np.empty((6, 4), np.float32)
    sub = np.empty((3, 4), np.float32)
    for o in range(models.shape[0]):
        if not drawn[o]:
            continue
        model = models[o]
        pmv = matmul4(proj, matmul4(view, model))
        v0, vn = obj_vfirst[o], obj_vcount[o]
        for v in range(v0, v0 + vn):
            x, y, z = vertices[v, 0], vertices[v, 1], vertices[v, 2]
            for r in range(4):
                clip[v, r] = _dot4(pmv, r, x, y, z, F(1.0))
            for r in range(3):
                world[v, r] = _dot4(model, r, x, y, z, F(1.0))
            nx, ny, nz = normals[v, 0], normals[v, 1], normals[v, 2]
            for r in range(3):  # the model's rotation: its inverse transpose for a rigid transform
                nrm[v, r] = _dot4(model, r, nx, ny, nz, F(0.0))
        for f in range(obj_first[o], obj_first[o] + obj_count[o]):
            i0, i1, i2 = faces[f, 0] + v0, faces[f, 1] + v0, faces[f, 2] + v0
            # back-face culling, in float64 as btVector3
            ax, ay, az = np.float64(world[i0, 0]), np.float64(world[i0, 1]), np.float64(world[i0, 2])
            ux, uy, uz = world[i1, 0] - ax, world[i1, 1] - ay, world[i1, 2] - az
            wx, wy, wz = world[i2, 0] - ax, world[i2, 1] - ay, world[i2, 2] - az
            ux, uy, uz = np.float64(ux), np.float64(uy), np.float64(uz)
            wx, wy, wz = np.float64(wx), np.float64(wy), np.float64(wz)
            nx = uy * wz - uz * wy
            ny = uz * wx - ux * wz
            nz = ux * wy - uy * wx
            if (ax - eye[0]) * nx + (ay - eye[1]) * ny + (az - eye[2]) * nz >= 0:
                continue
            for j, i in enumerate((i0, i1, i2)):
                tri[j] = clip[i]
                tn[j] = nrm[i]
            w0, w1, w2 = tri[0, 3], tri[1, 3], tri[2, 3]
            if w0 < 0 and w1 < 0 and w2 < 0:
                continue
            if w0 >= 0 and w1 >= 0 and w2 >= 0:
                _raster(tri, tri, False, tn, light, colors[o], seg_ids[o], width, height, near, far, zbuf, rgb, seg)
                continue
            n = _clip_edge(tri, 0, 1, poly, 0)
            n = _clip_edge(tri, 1, 2, poly, n)
            n = _clip_edge(tri, 2, 0, poly, n)
            if n < 3:
                continue
            for i in range(1, n - 1):
                sub[0] = poly[0]
                sub[1] = poly[i]
                sub[2] = poly[i + 1]
                _raster(sub, tri, True, tn, light, colors[o], seg_ids[o], width, height, near, far, zbuf, rgb, seg)


@njit(cache=True, error_model="numpy")
def touches_eye_plane(row, structure, box_faces, vertices, triangles, eps):
    """`culling.FrustumCuller.touches_eye_plane` compiled: whether a face of a structure box (corners (n, 8, 3),
    faces as corner indices (6, 4)) or a triangle of `vertices` lies within `eps` of the plane through the eye
    (`row`: the view matrix's third row: a point's eye depth is -(row[:3] . p + row[3]))."""
    for b in range(structure.shape[0]):
        near = np.empty(8, np.bool_)
        for c in range(8):
            d = -(structure[b, c, 0] * row[0] + structure[b, c, 1] * row[1] + structure[b, c, 2] * row[2] + row[3])
            near[c] = abs(d) < eps
        for f in range(box_faces.shape[0]):
            if near[box_faces[f, 0]] and near[box_faces[f, 1]] and near[box_faces[f, 2]] and near[box_faces[f, 3]]:
                return True
    n = vertices.shape[0]
    near_v = np.empty(n, np.bool_)
    anyv = False
    for v in range(n):
        d = -(vertices[v, 0] * row[0] + vertices[v, 1] * row[1] + vertices[v, 2] * row[2] + row[3])
        near_v[v] = abs(d) < eps
        anyv = anyv or near_v[v]
    if not anyv:
        return False
    for t in range(triangles.shape[0]):
        if near_v[triangles[t, 0]] and near_v[triangles[t, 1]] and near_v[triangles[t, 2]]:
            return True
    return False


@njit(cache=True, error_model="numpy", inline="always")
def _box_outside(corners, b, planes):
    """`portals.outside_view` for box b of corners (n, 8, 3): beyond one of the 7 planes (the last: w <= 0)."""
    for k in range(7):
        beyond = True
        for c in range(8):
            d = corners[b, c, 0] * planes[k, 0] + corners[b, c, 1] * planes[k, 1] \
                + corners[b, c, 2] * planes[k, 2] + planes[k, 3]
            if (d > 0) if k == 6 else (d >= 0):
                beyond = False
                break
        if beyond:
            return True
    return False


@njit(cache=True, error_model="numpy")
def outdoors_hidden(eye, planes, corners, opening_corners, faces, origins, normals, min_eye_depth):
    """`portals.OutdoorCuller.hidden` compiled, for an eye inside the room: whether each outdoor box (corners
    (n, 8, 3)) is out of sight: out of the view (`planes`: the view's 7 planes in world coordinates, as
    `outside_view` makes them), or beyond one side of a cone from the eye through each opening in view (openings:
    corners (m, 8, 3), inner and outer faces (m, 2, 4, 3), wall origins and inward normals (m, 3))."""
    n, m = corners.shape[0], opening_corners.shape[0]
    seen = np.empty(n, np.bool_)
    for b in range(n):
        seen[b] = _box_outside(corners, b, planes)
    shown = np.empty(m, np.bool_)
    any_shown = False
    for o in range(m):
        shown[o] = not _box_outside(opening_corners, o, planes)
        any_shown = any_shown or shown[o]
    if not any_shown:
        return np.ones(n, np.bool_)
    for o in range(m):
        if shown[o]:
            depth = (eye[0] - origins[o, 0]) * normals[o, 0] + (eye[1] - origins[o, 1]) * normals[o, 1] \
                + (eye[2] - origins[o, 2]) * normals[o, 2]
            if depth < min_eye_depth:
                return seen
    hidden = seen.copy()
    cone = np.empty((8, 3))
    edges = np.empty((4, 3))
    for b in range(n):
        if seen[b]:
            continue
        every = True  # beyond a side of a cone of every shown opening
        for o in range(m):
            if not shown[o]:
                continue
            for f in range(2):
                mean = np.zeros(3)
                for p in range(4):
                    for a in range(3):
                        edges[p, a] = faces[o, f, p, a] - eye[a]
                        mean[a] += edges[p, a] / 4.0
                for p in range(4):
                    q = (p + 1) % 4
                    x = edges[p, 1] * edges[q, 2] - edges[p, 2] * edges[q, 1]
                    y = edges[p, 2] * edges[q, 0] - edges[p, 0] * edges[q, 2]
                    z = edges[p, 0] * edges[q, 1] - edges[p, 1] * edges[q, 0]
                    sign = -1.0 if x * mean[0] + y * mean[1] + z * mean[2] < 0 else 1.0
                    cone[4 * f + p, 0], cone[4 * f + p, 1], cone[4 * f + p, 2] = sign * x, sign * y, sign * z
            beyond = False
            for k in range(8):
                out = True
                for c in range(8):
                    d = (corners[b, c, 0] - eye[0]) * cone[k, 0] + (corners[b, c, 1] - eye[1]) * cone[k, 1] \
                        + (corners[b, c, 2] - eye[2]) * cone[k, 2]
                    if d >= 0:
                        out = False
                        break
                if out:
                    beyond = True
                    break
            if not beyond:
                every = False
                break
        hidden[b] = every
    return hidden
