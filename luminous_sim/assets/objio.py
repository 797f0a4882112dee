"""Deterministic OBJ text for visual meshes (with normals) and multi-part collision meshes."""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path
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


def write_atomic(path: Path, text: str | bytes) -> None:
    """Write a file so that readers see the old or the new content, never a torn one."""
    data = text.encode() if isinstance(text, str) else text
    with atomic_file(Path(path)) as tmp, open(tmp, "wb") as fh:
        fh.write(data)


@contextlib.contextmanager
def atomic_file(path: Path, suffix: str = ".tmp") -> Iterator[Path]:
    """A temporary file beside `path` for a writer (of `suffix`, for writers that pick a format by it), moved
    onto `path` when the block ends without an error (removed when it raises): readers see the old file or the
    new one, never a torn one."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=suffix)
    os.close(fd)
    try:
        yield Path(tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; written files should read like any other
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
