"""ATISS / 3D-SLN-style object lists -> layout (docs/layouts.md says what is read and what is ignored).

The input is ATISS's per-room record (`boxes.npz`, or the same keys in JSON): `class_labels` (names, or
one-hot rows over `object_types`), `translations` (box centres, y up, relative to `floor_plan_centroid`),
`sizes` (half extents, as ATISS writes them; `"size_convention": "full"` for full sizes, as 3D-SLN gives
them), `angles` (turn about y, radians), and the floor plan `floor_plan_vertices` / `floor_plan_faces`.
An `objects` list of {class_label, translation, size, angle} may stand in for the four arrays.
"""

from __future__ import annotations

import io
import re
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import ValidationError

from luminous_sim.layouts.front import room_type_of
from luminous_sim.layouts.inputs import Fields, read_bytes, read_json, short, type_name
from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject, Provenance, problems, room_problem
from luminous_sim.layouts.room_build import build_room
from luminous_sim.layouts.yup import outline_from_triangles, to_ours, yaw_of_angle
from luminous_sim.limits import MAX_LAYOUT_OBJECTS, MAX_LAYOUT_SIDE_M

MARKERS = frozenset({"start", "end"})
"""ATISS's sequence markers in its class vocabulary; a box labelled with one is not an object."""


COLUMNS = (("class_labels", "class_label"), ("translations", "translation"), ("sizes", "size"), ("angles", "angle"))
"""The four arrays of an ATISS record and the key of each in an `objects` list entry."""


def _read(path: Path) -> dict[str, Any]:
    what = "an ATISS record (.npz, or JSON with class_labels, translations, sizes, angles)"
    if path.suffix == ".npz":
        raw = read_bytes(path, what)
        try:
            with np.load(io.BytesIO(raw), allow_pickle=False) as z:
                return {k: z[k].tolist() for k in z.files}
        except (OSError, ValueError, EOFError) as exc:
            raise LayoutError(f"{path}: not a readable .npz ({exc}); expected {what}") from None
    data = read_json(path, what)
    if not isinstance(data, dict):
        raise LayoutError(f"{path}: expected a JSON object with class_labels, translations, sizes, angles, got "
                          f"{type(data).__name__}")
    return data


class _Boxes:
    """The per-box columns of a record, and how to name element j of box i's `key` (as the file spells it)."""

    def __init__(self, fields: Fields, data: dict) -> None:
        self.fields = fields
        self.listed = "objects" in data
        if self.listed:
            objs = fields.items(data["objects"], "objects", MAX_LAYOUT_OBJECTS)
            self.columns: dict[str, list[Any]] = {col: [] for col, _ in COLUMNS}
            for i, o in enumerate(objs):
                if not isinstance(o, dict):
                    raise fields.fail(f"objects[{i}]", "a JSON object {class_label, translation, size, angle}",
                                      type_name(o))
                label = o.get("class_label", o.get("class", o.get("label")))
                if label is None:
                    raise LayoutError(f"{fields.source}: objects[{i}].class_label: missing (a class name)")
                self.columns["class_labels"].append(label)
                for col, key in COLUMNS[1:]:
                    if key not in o:
                        raise LayoutError(f"{fields.source}: objects[{i}].{key}: missing")
                    self.columns[col].append(o[key])
        else:
            self.columns = {}
            for col, _ in COLUMNS:
                if col not in data:
                    raise LayoutError(f"{fields.source}: {col}: missing")
                self.columns[col] = data[col]
            fields.items(self.columns["translations"], "translations", MAX_LAYOUT_OBJECTS)

    def path(self, col: str, i: int, j: int | None = None) -> str:
        if self.listed:
            key = dict(COLUMNS)[col]
            return f"objects[{i}].{key}" + ("" if j is None else f"[{j}]")
        return f"{col}[{i}]" + ("" if j is None else f"[{j}]")

    def rows(self, col: str, width: int, kind: str, n: int | None) -> np.ndarray:
        value = self.columns[col]
        flat_angles = width == 1 and isinstance(value, list) and bool(value) and not isinstance(value[0], list)

        def name(i: int, j: int) -> str:
            if self.listed or flat_angles:
                return self.path(col, i, None if width == 1 else j)
            return self.path(col, i, j)

        if self.listed and width == 1:
            value = [[v] if not isinstance(v, list) else v for v in value]
        elif self.listed:
            for i, v in enumerate(value):
                if not isinstance(v, list):
                    raise self.fields.fail(self.path(col, i), f"a list of {width} numbers", v)
        arr = self.fields.rows(value, width, col if not self.listed else "objects", kind, row_path=name)
        if n is not None and len(arr) != n:
            raise LayoutError(f"{self.fields.source}: {col}: {len(arr)} rows for {n} translations")
        return arr


def _one_hot(fields: Fields, boxes: _Boxes, raw: list, names: list[str]) -> list[str]:
    """The class of each one-hot row; each row must hold exactly one 1 and 0 elsewhere."""
    widths = {len(names), len(names) + 2}
    vocab = list(names) + ["start", "end"]
    out = []
    for i, row in enumerate(raw):
        where = boxes.path("class_labels", i)
        if not isinstance(row, list) or len(row) not in widths:
            raise fields.fail(where, f"a one-hot row of {len(names)} (or {len(names) + 2}, with ATISS's start and "
                              "end) numbers, one per object_types entry", row)
        ones = []
        for j, v in enumerate(row):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or v not in (0, 1):
                raise fields.fail(f"{where}[{j}]", "0 or 1 (a one-hot row)", v)
            if v == 1:
                ones.append(j)
        if len(ones) != 1:
            raise fields.fail(where, "a one-hot row (exactly one 1)", f"{len(ones)} ones")
        out.append(vocab[ones[0]])
    return out


def _labels(fields: Fields, boxes: _Boxes, data: dict, n: int) -> list[str]:
    raw = boxes.columns["class_labels"]
    if not isinstance(raw, list) or len(raw) != n:
        raise LayoutError(f"{fields.source}: class_labels: expected {n} labels (one per box), got "
                          f"{len(raw) if isinstance(raw, list) else type(raw).__name__}")
    if all(isinstance(c, str) for c in raw):
        return [fields.string(c, boxes.path("class_labels", i)) for i, c in enumerate(raw)]
    if boxes.listed:
        bad = next(i for i, c in enumerate(raw) if not isinstance(c, str))
        raise fields.fail(boxes.path("class_labels", bad), "a class name", raw[bad])
    names = data.get("object_types") or data.get("class_names")
    if not isinstance(names, list) or not all(isinstance(x, str) and x for x in names):
        raise LayoutError(f"{fields.source}: object_types: needed (the class names) when class_labels are one-hot "
                          "rows")
    return _one_hot(fields, boxes, raw, names)


def import_atiss(path: Path, room_type: str | None = None) -> Layout:
    """An ATISS-style room record as a layout (class labels kept; `realize` matches them to the catalog).

    Every field read is checked (finite numbers, positive sizes within limits.MAX_LAYOUT_SIDE_M, angles within
    +-4 pi, exactly one-hot label rows, whole face indices into the vertices); each box left out (ATISS's
    start/end markers) is listed in `provenance.notes["dropped"]` with its path and the reason.

    Raises:
        LayoutError: naming the file and the key that is missing or malformed.
    """
    path = Path(path)
    where = str(path)
    fields = Fields(path)
    data = _read(path)
    boxes = _Boxes(fields, data)
    trans = boxes.rows("translations", 3, "coordinate", None)
    n = len(trans)
    sizes = boxes.rows("sizes", 3, "size", n)
    angles = boxes.rows("angles", 1, "angle", n)[:, 0]
    labels = _labels(fields, boxes, data, n)
    convention = data.get("size_convention", "half")
    if convention not in ("half", "full"):
        raise LayoutError(f"{where}: size_convention: expected 'half' or 'full', got {short(convention)}")
    full = sizes * (2.0 if convention == "half" else 1.0)
    for (i, j), v in np.ndenumerate(full):
        if v > MAX_LAYOUT_SIDE_M:
            raise fields.fail(boxes.path("sizes", i, j), f"a {convention} size whose full size is at most "
                              f"{MAX_LAYOUT_SIDE_M:g} m (luminous_sim.limits.MAX_LAYOUT_SIDE_M)", sizes[i, j])
    centroid = (fields.vector(data["floor_plan_centroid"], 3, "floor_plan_centroid")
                if "floor_plan_centroid" in data else np.zeros(3))
    if "floor_plan_vertices" not in data:
        raise LayoutError(f"{where}: floor_plan_vertices: missing")
    vertices = fields.rows(data["floor_plan_vertices"], 3, "floor_plan_vertices", "coordinate")
    if "floor_plan_faces" not in data:
        raise LayoutError(f"{where}: floor_plan_faces: missing")
    faces = fields.indices(data["floor_plan_faces"], "floor_plan_faces", len(vertices))
    try:
        poly = outline_from_triangles(vertices, faces)
    except ValueError as exc:
        raise LayoutError(f"{where}: floor_plan_faces: {exc}") from None
    raw_type = data.get("scene_type", data.get("room_type", ""))
    if not isinstance(raw_type, str):
        raise fields.fail("scene_type", "a room type name", raw_type)
    ours = room_type or room_type_of(raw_type)
    if ours is None:
        raise LayoutError(f"{where}: scene_type: {raw_type or '(missing)'!r} is not a room type we know; "
                          "give the room type")
    notes: list[str] = ["ATISS layouts have no doors or windows"]
    stem = str(data.get("scene_id", path.stem))
    name = re.sub(r"[^A-Za-z0-9_\-]", "_", f"atiss_{stem}")[:80]
    try:
        room, offset = build_room(poly, ours, name, [], notes, source=f"ATISS {path.name}")
    except ValidationError as exc:
        raise LayoutError(f"{where}: floor_plan_vertices: the room they outline: {room_problem(exc)}") from None
    centres = to_ours(trans + centroid)
    objects = []
    dropped = []
    for i in range(n):
        if labels[i] in MARKERS:
            dropped.append({"entry": boxes.path("class_labels", i),
                            "reason": f"ATISS's {labels[i]!r} sequence marker, not an object"})
            continue
        x, y, z = centres[i]
        sx, sy, sz = full[i]
        objects.append(LayoutObject(
            id=f"box_{i}", category=labels[i], size=(float(sx), float(sz), float(sy)),
            position=(round(x - offset[0], 6), round(y - offset[1], 6), round(float(z), 6)),
            yaw=round(yaw_of_angle(float(angles[i])), 6)))
    prov = Provenance(generator="atiss", source=str(path), notes={
        "scene_type": raw_type, "offset": list(offset), "size_convention": convention,
        "ignored": {"start/end markers": len(dropped)} if dropped else {}, "dropped": dropped,
        "import_notes": notes})
    try:
        return Layout(room=room, objects=tuple(objects), provenance=prov)
    except ValidationError as exc:
        raise problems(exc, where) from None
