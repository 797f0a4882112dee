"""ATISS / 3D-SLN-style object lists -> layout (docs/layouts.md says what is read and what is ignored).

The input is ATISS's per-room record (`boxes.npz`, or the same keys in JSON): `class_labels` (names, or
one-hot rows over `object_types`), `translations` (box centres, y up, relative to `floor_plan_centroid`),
`sizes` (half extents, as ATISS writes them; `"size_convention": "full"` for full sizes, as 3D-SLN gives
them), `angles` (turn about y, radians), and the floor plan `floor_plan_vertices` / `floor_plan_faces`.
An `objects` list of {class_label, translation, size, angle} may stand in for the four arrays.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.layouts.front import room_type_of
from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject, Provenance
from luminous_sim.layouts.room_build import build_room
from luminous_sim.layouts.yup import outline_from_triangles, to_ours, yaw_of_angle

MARKERS = frozenset({"start", "end"})
"""ATISS's sequence markers in its class vocabulary; a box labelled with one is not an object."""


def _read(path: Path) -> dict[str, Any]:
    where = str(path)
    if not path.is_file():
        raise LayoutError(f"{where}: no such file (or not a regular file)")
    if path.suffix == ".npz":
        try:
            with np.load(path, allow_pickle=False) as z:
                return {k: z[k].tolist() for k in z.files}
        except (OSError, ValueError) as exc:
            raise LayoutError(f"{where}: not a readable .npz ({exc})") from None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise LayoutError(f"{where}: cannot read ({exc.strerror or exc})") from None
    except ValueError as exc:
        raise LayoutError(f"{where}: not JSON ({exc})") from None
    if not isinstance(data, dict):
        raise LayoutError(f"{where}: expected an object with class_labels, translations, sizes, angles")
    return data


def _array(data: dict, key: str, where: str, width: int | None) -> np.ndarray:
    if key not in data:
        raise LayoutError(f"{where}: {key}: missing")
    try:
        arr = np.asarray(data[key], dtype=float)
    except (TypeError, ValueError):
        raise LayoutError(f"{where}: {key}: expected numbers") from None
    if width is not None:
        if arr.size % width or (arr.ndim > 1 and arr.shape[-1] != width):
            raise LayoutError(f"{where}: {key}: expected rows of {width} numbers, got shape {list(arr.shape)}")
        arr = arr.reshape(-1, width)
    if not np.isfinite(arr).all():
        raise LayoutError(f"{where}: {key}: numbers must be finite")
    return arr


def _labels(data: dict, n: int, where: str) -> list[str]:
    raw = data.get("class_labels")
    if raw is None:
        raise LayoutError(f"{where}: class_labels: missing")
    if not isinstance(raw, list) or len(raw) != n:
        raise LayoutError(f"{where}: class_labels: expected {n} labels (one per box), got "
                          f"{len(raw) if isinstance(raw, list) else type(raw).__name__}")
    if all(isinstance(c, str) for c in raw):
        return list(raw)
    names = data.get("object_types") or data.get("class_names")
    if not isinstance(names, list) or not all(isinstance(x, str) for x in names):
        raise LayoutError(f"{where}: object_types: needed (the class names) when class_labels are one-hot rows")
    vocab = list(names) + ([] if len(names) == len(raw[0] if raw else []) else ["start", "end"])
    try:
        rows = np.asarray(raw, dtype=float).reshape(n, -1)
    except (TypeError, ValueError):
        raise LayoutError(f"{where}: class_labels: expected names or one-hot rows") from None
    if rows.shape[1] != len(vocab):
        raise LayoutError(f"{where}: class_labels: rows of {rows.shape[1]} do not match {len(names)} object_types")
    return [vocab[int(i)] for i in rows.argmax(axis=1)]


def _from_objects(data: dict, where: str) -> dict:
    objs = data["objects"]
    if not isinstance(objs, list):
        raise LayoutError(f"{where}: objects: expected a list")
    cols: dict[str, list] = {"class_labels": [], "translations": [], "sizes": [], "angles": []}
    for i, o in enumerate(objs):
        if not isinstance(o, dict):
            raise LayoutError(f"{where}: objects[{i}]: expected an object")
        label = o.get("class_label", o.get("class", o.get("label")))
        if not isinstance(label, str):
            raise LayoutError(f"{where}: objects[{i}].class_label: missing (a class name)")
        for key, col in (("translation", "translations"), ("size", "sizes"), ("angle", "angles")):
            if key not in o:
                raise LayoutError(f"{where}: objects[{i}].{key}: missing")
            cols[col].append(o[key])
        cols["class_labels"].append(label)
    return {**data, **cols}


def import_atiss(path: Path, room_type: str | None = None) -> Layout:
    """An ATISS-style room record as a layout (class labels kept; `realize` matches them to the catalog).

    Raises:
        LayoutError: naming the file and the key that is missing or malformed.
    """
    path = Path(path)
    where = str(path)
    data = _read(path)
    if "objects" in data:
        data = _from_objects(data, where)
    trans = _array(data, "translations", where, 3)
    n = len(trans)
    sizes = _array(data, "sizes", where, 3)
    angles = _array(data, "angles", where, 1)[:, 0]
    for key, arr in (("sizes", sizes), ("angles", angles)):
        if len(arr) != n:
            raise LayoutError(f"{where}: {key}: {len(arr)} rows for {n} translations")
    labels = _labels(data, n, where)
    convention = data.get("size_convention", "half")
    if convention not in ("half", "full"):
        raise LayoutError(f"{where}: size_convention: expected 'half' or 'full', got {convention!r}")
    full = sizes * (2.0 if convention == "half" else 1.0)
    if (full <= 0).any():
        raise LayoutError(f"{where}: sizes: expected positive sizes")
    centroid = _array(data, "floor_plan_centroid", where, 3)[0] if "floor_plan_centroid" in data else np.zeros(3)
    vertices = _array(data, "floor_plan_vertices", where, 3)
    faces = _array(data, "floor_plan_faces", where, 3)
    try:
        poly = outline_from_triangles(vertices, faces.astype(int))
    except ValueError as exc:
        raise LayoutError(f"{where}: floor_plan_faces: {exc}") from None
    scene_type = str(data.get("scene_type", data.get("room_type", "")))
    ours = room_type or room_type_of(scene_type)
    if ours is None:
        raise LayoutError(f"{where}: scene_type: {scene_type or '(missing)'!r} is not a room type we know; "
                          "give the room type")
    notes: list[str] = ["ATISS layouts have no doors or windows"]
    stem = str(data.get("scene_id", path.stem))
    name = re.sub(r"[^A-Za-z0-9_\-]", "_", f"atiss_{stem}")[:80]
    room, offset = build_room(poly, ours, name, [], notes, source=f"ATISS {path.name}")
    centres = to_ours(trans + centroid)
    objects = []
    skipped = 0
    for i in range(n):
        if labels[i] in MARKERS:
            skipped += 1
            continue
        x, y, z = centres[i]
        sx, sy, sz = full[i]
        objects.append(LayoutObject(
            id=f"box_{i}", category=labels[i], size=(float(sx), float(sz), float(sy)),
            position=(round(x - offset[0], 6), round(y - offset[1], 6), round(float(z), 6)),
            yaw=round(yaw_of_angle(float(angles[i])), 6)))
    prov = Provenance(generator="atiss", source=str(path), notes={
        "scene_type": scene_type, "offset": list(offset), "size_convention": convention,
        "ignored": {"start/end markers": skipped} if skipped else {}, "import_notes": notes})
    return Layout(room=room, objects=tuple(objects), provenance=prov)
