"""Level of detail: each visual mesh decimated for small camera frames (collision meshes are not touched).

A visual mesh is several closed parts (a stool's seat and legs). Each part with more than
`LOD_MIN_FACES` triangles is decimated on its own (`fast-simplification`'s quadric decimation, open
borders kept in place) to about `LOD_KEEP` of its triangles; a result that is not faithful to the part
(bounds moved by more than `MAX_BOUNDS_SHIFT` of its size, or, for a closed part, volume or area changed by
more than `MAX_VOLUME_CHANGE` / `MAX_AREA_CHANGE`) is retried keeping more (`RETRY_KEEP`), and the part is
kept as it is if none passes. Boxes and other simple parts are never touched.
"""

from __future__ import annotations

import numpy as np
import trimesh

LOD_KEEP = 0.35
"""Fraction of a part's triangles the LOD set aims to keep (silhouette IoU measured in tests/assets)."""
RETRY_KEEP = (0.5, 0.7)
"""Fractions tried, in turn, when decimating to `LOD_KEEP` spoils a part."""
LOD_MIN_FACES = 32
"""Parts with this many triangles or fewer are not decimated."""
MAX_BOUNDS_SHIFT = 0.02
MAX_VOLUME_CHANGE = 0.10
MAX_AREA_CHANGE = 0.10
LOD_SUFFIX = ".lod"
"""A LOD file is named like its full-detail one with this before the extension (`base__body.lod.obj`)."""


def _faithful(part: trimesh.Trimesh, out: trimesh.Trimesh) -> bool:
    size = float(np.linalg.norm(part.extents)) or 1.0
    if np.abs(out.bounds - part.bounds).max() > MAX_BOUNDS_SHIFT * size:
        return False
    if abs(out.area - part.area) > MAX_AREA_CHANGE * part.area:
        return False
    if part.is_watertight:
        if not out.is_watertight or not out.is_winding_consistent:
            return False
        return abs(out.volume - part.volume) <= MAX_VOLUME_CHANGE * abs(part.volume)
    return True


def _decimate_part(part: trimesh.Trimesh, keep: float, min_faces: int) -> trimesh.Trimesh | None:
    import fast_simplification

    n = len(part.faces)
    verts = np.ascontiguousarray(part.vertices, dtype=np.float64)
    faces = np.ascontiguousarray(part.faces, dtype=np.int64)
    for k in (keep, *RETRY_KEEP):
        target = max(min_faces, round(n * k))
        if target >= n:
            return None
        v, f = fast_simplification.simplify(verts, faces, target_count=target, preserve_border=True)
        if 0 < len(f) < n:
            out = trimesh.Trimesh(v, f, process=False)
            out.remove_unreferenced_vertices()
            if _faithful(part, out):
                return out
    return None


def decimate(mesh: trimesh.Trimesh, keep: float = LOD_KEEP, min_faces: int = LOD_MIN_FACES) -> trimesh.Trimesh | None:
    """The decimated mesh, or None where no part could lose a triangle faithfully (use the mesh itself).

    Deterministic: the same mesh gives the same output, bit for bit.
    """
    if len(mesh.faces) <= min_faces:
        return None
    parts = mesh.split(only_watertight=False)
    done = [_decimate_part(p, keep, min_faces) if len(p.faces) > min_faces else None for p in parts]
    if all(d is None for d in done):
        return None
    return trimesh.util.concatenate([p if d is None else d for p, d in zip(parts, done, strict=True)])
