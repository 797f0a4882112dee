"""Deterministic OBJ text for visual meshes (with normals) and multi-part collision meshes."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import trimesh  # loaded by the mesh functions alone: the atomic writers serve World processes (no scipy)

PRECISION = 5


def _fmt_rows(prefix: str, rows: np.ndarray) -> str:
    fmt = f"{prefix} %.{PRECISION}f %.{PRECISION}f %.{PRECISION}f"
    # "-0.00000" and "0.00000" must not depend on float noise
    rows = np.round(rows, PRECISION) + 0.0
    return "\n".join(fmt % tuple(r) for r in rows)


def visual_obj(mesh: trimesh.Trimesh, smooth_angle_deg: float = 35.0) -> str:
    """One mesh as OBJ with per-vertex normals, split at edges sharper than `smooth_angle_deg`."""
    import trimesh

    shaded = trimesh.graph.smooth_shade(mesh, angle=np.radians(smooth_angle_deg))
    normals = shaded.vertex_normals
    lines = [_fmt_rows("v", shaded.vertices), _fmt_rows("vn", normals)]
    faces = shaded.faces + 1
    lines.append("\n".join(f"f {a}//{a} {b}//{b} {c}//{c}" for a, b, c in faces))
    return "\n".join(lines) + "\n"


def collision_obj(hulls: Sequence[trimesh.Trimesh]) -> str:
    """Convex hulls as one OBJ with an `o` group per hull (PyBullet makes one convex shape per group)."""
    out, offset = [], 1
    for i, hull in enumerate(hulls):
        out.append(f"o hull_{i}")
        out.append(_fmt_rows("v", hull.vertices))
        out.append("\n".join(f"f {a} {b} {c}" for a, b, c in hull.faces + offset))
        offset += len(hull.vertices)
    return "\n".join(out) + "\n"


def read_collision_obj(text: str) -> list[trimesh.Trimesh]:
    """Parse `collision_obj` output back into meshes."""
    import trimesh

    hulls: list[trimesh.Trimesh] = []
    verts: list[list[float]] = []
    faces: list[list[int]] = []
    base = 1

    def flush() -> None:
        nonlocal verts, faces, base
        if verts:
            hulls.append(trimesh.Trimesh(np.array(verts), np.array(faces) - base, process=False))
            base += len(verts)
        verts, faces = [], []

    for line in text.splitlines():
        if line.startswith("o "):
            flush()
        elif line.startswith("v "):
            verts.append([float(x) for x in line.split()[1:4]])
        elif line.startswith("f "):
            faces.append([int(x.split("/")[0]) for x in line.split()[1:4]])
    flush()
    return hulls


def png_bytes(image) -> bytes:
    """PNG file content of a PIL image or an (H, W, 3) uint8 array."""
    import io

    from PIL import Image

    img = Image.fromarray(image) if isinstance(image, np.ndarray) else image
    buf = io.BytesIO()
    img.save(buf, format="PNG")
    return buf.getvalue()


def __getattr__(name: str):
    """The atomic writers' old home, kept for one release (they live in `luminous_sim.fileio`)."""
    if name in ("write_atomic", "atomic_file"):
        import warnings

        from luminous_sim import fileio

        warnings.warn(f"luminous_sim.assets.objio.{name} moved to luminous_sim.fileio.{name}", DeprecationWarning,
                      stacklevel=2)
        return getattr(fileio, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
