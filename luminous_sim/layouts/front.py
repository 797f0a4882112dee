"""3D-FRONT scene JSON -> layout (docs/layouts.md says what is read and what is ignored).

Read: `furniture[]` (`uid`, `jid`, `valid`, `category` or `title`, `bbox` or `size`), `mesh[]` (`uid`, `type`,
`xyz`, `faces`), `scene.room[]` (`type`, `instanceid`, `children[]` with `ref`, `instanceid`, `pos`, `rot`,
`scale`). A piece's category comes from the 3D-FUTURE `model_info.json` (`model_id` -> `category`) when
given, else from the furniture entry itself. A 3D-FUTURE model stands on its origin (the bottom centre of
its box) and faces its own +z.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject, Provenance
from luminous_sim.layouts.room_build import Opening, build_room
from luminous_sim.layouts.yup import outline_from_triangles, rotate_by_quaternion, to_ours, yaw_and_tilt

ROOM_TYPES = {
    "kitchen": "Kitchen", "bathroom": "Bathroom", "masterbathroom": "Bathroom", "secondbathroom": "Bathroom",
    "bedroom": "Bedroom", "masterbedroom": "Bedroom", "secondbedroom": "Bedroom", "kidsroom": "Bedroom",
    "elderlyroom": "Bedroom", "nannyroom": "Bedroom", "livingroom": "LivingRoom", "diningroom": "LivingRoom",
    "livingdiningroom": "LivingRoom", "library": "LivingRoom",
}
"""3D-FRONT room types (lower case, letters only) -> ours."""
TILT = math.radians(5)
"""A piece tilted more than this off upright is noted (the layout keeps only its turn about the vertical)."""


def room_type_of(label: str) -> str | None:
    """Our room type of a 3D-FRONT (or ATISS) room type, or None."""
    return ROOM_TYPES.get(re.sub(r"[^a-z]", "", label.lower()))


def _vec(value: Any, n: int, where: str) -> np.ndarray:
    try:
        arr = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise LayoutError(f"{where}: expected {n} numbers, got {value!r}") from None
    if arr.shape != (n,) or not np.isfinite(arr).all():
        raise LayoutError(f"{where}: expected {n} finite numbers, got {value!r}")
    return arr


def _get(d: Any, key: str, where: str, kind: type) -> Any:
    if not isinstance(d, dict) or key not in d:
        raise LayoutError(f"{where}.{key}: missing")
    if not isinstance(d[key], kind):
        raise LayoutError(f"{where}.{key}: expected {kind.__name__}, got {type(d[key]).__name__}")
    return d[key]


def read_model_info(path: Path) -> dict[str, str]:
    """3D-FUTURE's model_info.json: model_id -> category (entries without a category are skipped)."""
    path = Path(path)
    if not path.is_file():
        raise LayoutError(f"{path}: no such model info file (or not a regular file)")
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise LayoutError(f"{path}: cannot read model info ({exc})") from None
    if not isinstance(data, list):
        raise LayoutError(f"{path}: expected a list of models, got {type(data).__name__}")
    out = {}
    for i, m in enumerate(data):
        if not isinstance(m, dict) or "model_id" not in m:
            raise LayoutError(f"{path}: [{i}].model_id: missing")
        if m.get("category"):
            out[str(m["model_id"])] = str(m["category"])
    return out


def _transform(child: dict, where: str) -> tuple[np.ndarray, tuple[float, float, float, float], np.ndarray]:
    pos = _vec(child.get("pos", [0, 0, 0]), 3, f"{where}.pos")
    rot = _vec(child.get("rot", [0, 0, 0, 1]), 4, f"{where}.rot")
    scale = _vec(child.get("scale", [1, 1, 1]), 3, f"{where}.scale")
    if (scale <= 0).any():
        raise LayoutError(f"{where}.scale: expected positive numbers, got {child.get('scale')!r}")
    return pos, tuple(rot), scale  # type: ignore[return-value]


def _mesh_points(mesh: dict, where: str, child: dict | None, child_where: str) -> tuple[np.ndarray, np.ndarray]:
    xyz = np.asarray(_get(mesh, "xyz", where, list), dtype=float).reshape(-1, 3)
    faces = np.asarray(mesh.get("faces", []), dtype=int).reshape(-1, 3)
    if child is not None:
        pos, rot, scale = _transform(child, child_where)
        xyz = rotate_by_quaternion(rot, xyz * scale) + pos
    return xyz, faces


def _choose_room(rooms: list, furniture: dict, room: str | None, where: str) -> tuple[int, dict, list[str]]:
    notes: list[str] = []
    if room is not None:
        for i, r in enumerate(rooms):
            if isinstance(r, dict) and r.get("instanceid") == room:
                return i, r, notes
        ids = ", ".join(str(r.get("instanceid")) for r in rooms if isinstance(r, dict))
        raise LayoutError(f"{where}: scene.room: no room {room!r} (rooms: {ids})")
    candidates = [(i, r) for i, r in enumerate(rooms) if isinstance(r, dict) and room_type_of(str(r.get("type", "")))
                  and any(isinstance(c, dict) and c.get("ref") in furniture for c in r.get("children", []))]
    if not candidates:
        raise LayoutError(f"{where}: scene.room: no room of a known type ({', '.join(sorted(set(ROOM_TYPES)))}) "
                          "with furniture")
    if len(candidates) > 1:
        notes.append(f"{len(candidates)} furnished rooms; took {candidates[0][1].get('instanceid')} "
                     "(choose another with room=)")
    return candidates[0][0], candidates[0][1], notes


def import_front(path: Path, room: str | None = None, model_info: Path | dict[str, str] | None = None,
                 room_type: str | None = None) -> Layout:
    """One room of a 3D-FRONT scene as a layout (categories as 3D-FRONT names them; `realize` matches them).

    Args:
        room: the room's `instanceid` (default: the first furnished room of a known type).
        model_info: 3D-FUTURE's model_info.json (or its jid -> category mapping).
        room_type: ours, overriding the room's own type.

    Raises:
        LayoutError: naming the file and the field that is missing or malformed.
    """
    path = Path(path)
    where = str(path)
    if not path.is_file():
        raise LayoutError(f"{where}: no such file (or not a regular file)")
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise LayoutError(f"{where}: cannot read ({exc.strerror or exc})") from None
    except ValueError as exc:
        raise LayoutError(f"{where}: not JSON ({exc})") from None
    info = read_model_info(model_info) if isinstance(model_info, (str, Path)) else dict(model_info or {})
    furniture_list = _get(data, "furniture", where, list)
    meshes_list = _get(data, "mesh", where, list)
    rooms = _get(_get(data, "scene", where, dict), "room", f"{where}: scene", list)
    furniture = {}
    ignored: dict[str, int] = {}
    for i, f in enumerate(furniture_list):
        uid = _get(f, "uid", f"{where}: furniture[{i}]", str)
        if f.get("valid") is False:
            ignored["furniture marked valid: false"] = ignored.get("furniture marked valid: false", 0) + 1
            continue
        furniture[uid] = (i, f)
    meshes = {}
    for i, m in enumerate(meshes_list):
        meshes[_get(m, "uid", f"{where}: mesh[{i}]", str)] = (i, m)
    ri, chosen, notes = _choose_room(rooms, furniture, room, where)
    rwhere = f"{where}: scene.room[{ri}]"
    ours = room_type or room_type_of(str(chosen.get("type", "")))
    if ours is None:
        raise LayoutError(f"{rwhere}.type: {chosen.get('type')!r} is not a room type we know "
                          f"({', '.join(sorted(set(ROOM_TYPES)))}); give the room type")
    children = _get(chosen, "children", rwhere, list)
    floor_v, floor_f, n = [], [], 0
    objects_src = []
    placed_refs: dict[str, tuple[dict, str]] = {}
    for j, c in enumerate(children):
        cwhere = f"{rwhere}.children[{j}]"
        ref = _get(c, "ref", cwhere, str)
        placed_refs[ref] = (c, cwhere)
        if ref in furniture:
            objects_src.append((j, c, cwhere, furniture[ref]))
        elif ref in meshes:
            mi, mesh = meshes[ref]
            mtype = str(mesh.get("type", ""))
            if mtype.lower() == "floor":
                v, f = _mesh_points(mesh, f"{where}: mesh[{mi}]", c, cwhere)
                floor_v.append(v)
                floor_f.append(f + n)
                n += len(v)
            else:
                ignored[f"mesh {mtype or '(no type)'}"] = ignored.get(f"mesh {mtype or '(no type)'}", 0) + 1
        else:
            ignored["children whose ref names nothing"] = ignored.get("children whose ref names nothing", 0) + 1
    if not floor_v:
        raise LayoutError(f"{rwhere}.children: no mesh of type Floor (the room's outline comes from its floor)")
    try:
        poly = outline_from_triangles(np.concatenate(floor_v), np.concatenate(floor_f))
    except ValueError as exc:
        raise LayoutError(f"{rwhere}: floor mesh: {exc}") from None
    openings = []
    for uid, (mi, mesh) in meshes.items():
        kind = str(mesh.get("type", "")).lower()
        if "door" in kind or "window" in kind:
            child, cwhere = placed_refs.get(uid, (None, ""))
            v, _ = _mesh_points(mesh, f"{where}: mesh[{mi}]", child, cwhere)
            openings.append(Opening("door" if "door" in kind else "window", to_ours(v), f"mesh[{mi}]"))
    name = re.sub(r"[^A-Za-z0-9_\-]", "_", f"front_{path.stem}_{chosen.get('instanceid', ri)}")[:80]
    layout_room, offset = build_room(poly, ours, name, openings, notes, source=f"3D-FRONT {path.name}")
    objects = []
    for j, c, cwhere, (fi, f) in objects_src:
        fwhere = f"{where}: furniture[{fi}]"
        jid = str(f.get("jid", ""))
        category = info.get(jid) or f.get("category") or f.get("title")
        if not category:
            if info:
                ignored["furniture with no category in model_info"] = ignored.get(
                    "furniture with no category in model_info", 0) + 1
                continue
            raise LayoutError(f"{fwhere}.category: missing (jid {jid!r}); give 3D-FUTURE's model_info.json")
        box = f.get("bbox", f.get("size"))
        if box is None:
            raise LayoutError(f"{fwhere}.bbox: missing (the model's box size, metres; or size)")
        size = _vec(box, 3, f"{fwhere}.bbox" if "bbox" in f else f"{fwhere}.size")
        if (size <= 0).any():
            raise LayoutError(f"{fwhere}.bbox: expected positive sizes, got {box!r}")
        pos, rot, scale = _transform(c, cwhere)
        size = size * scale
        centre = pos + rotate_by_quaternion(rot, np.array([0.0, size[1] / 2, 0.0]))[0]
        x, y, z = to_ours(centre)[0]
        yaw, tilt = yaw_and_tilt(rot)
        if tilt > TILT:
            notes.append(f"{cwhere}: tilted {math.degrees(tilt):.0f} degrees; only its turn about the vertical is kept")
        oid = str(c.get("instanceid") or f"{f['uid']}_{j}")
        objects.append(LayoutObject(
            id=oid, category=str(category), size=(float(size[0]), float(size[2]), float(size[1])),
            position=(round(x - offset[0], 6), round(y - offset[1], 6), round(float(z), 6)), yaw=round(yaw, 6)))
    prov = Provenance(generator="3d-front", source=str(path), notes={
        "room": str(chosen.get("instanceid", ri)), "room_type": str(chosen.get("type", "")),
        "offset": list(offset), "ignored": dict(sorted(ignored.items())), "import_notes": notes})
    try:
        return Layout(room=layout_room, objects=tuple(objects), provenance=prov)
    except ValueError as exc:
        raise LayoutError(f"{where}: {exc}") from None
