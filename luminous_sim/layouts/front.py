"""3D-FRONT scene JSON -> layout (docs/layouts.md says what is read and what is ignored).

Read: `furniture[]` (`uid`, `jid`, `valid`, `category` or `title`, `bbox` or `size`), `mesh[]` (`uid`, `type`,
`xyz`, `faces`), `scene.room[]` (`type`, `instanceid`, `children[]` with `ref`, `instanceid`, `pos`, `rot`,
`scale`). A piece's category comes from the 3D-FUTURE `model_info.json` (`model_id` -> `category`) when
given, else from the furniture entry itself. A 3D-FUTURE model stands on its origin (the bottom centre of
its box) and faces its own +z.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
from pydantic import ValidationError

from luminous_sim.layouts.inputs import Fields, read_json, type_name
from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject, Provenance, problems, room_problem
from luminous_sim.layouts.room_build import Opening, build_room
from luminous_sim.layouts.yup import outline_from_triangles, rotate_by_quaternion, to_ours, yaw_and_tilt
from luminous_sim.limits import MAX_LAYOUT_OBJECTS, MAX_LAYOUT_SIDE_M

ROOM_TYPES = {
    "kitchen": "Kitchen", "bathroom": "Bathroom", "masterbathroom": "Bathroom", "secondbathroom": "Bathroom",
    "bedroom": "Bedroom", "masterbedroom": "Bedroom", "secondbedroom": "Bedroom", "kidsroom": "Bedroom",
    "elderlyroom": "Bedroom", "nannyroom": "Bedroom", "livingroom": "LivingRoom", "diningroom": "LivingRoom",
    "livingdiningroom": "LivingRoom", "library": "LivingRoom",
}
"""3D-FRONT room types (lower case, letters only) -> ours."""
TILT = math.radians(5)
"""A piece tilted more than this off upright is noted (the layout keeps only its turn about the vertical)."""
QUATERNION_TOLERANCE = 0.01
"""How far from 1 a child's `rot` quaternion's norm may be (3D-FRONT writes unit quaternions, rounded)."""


def room_type_of(label: str) -> str | None:
    """Our room type of a 3D-FRONT (or ATISS) room type, or None."""
    return ROOM_TYPES.get(re.sub(r"[^a-z]", "", label.lower()))


def _optional_text(fields: Fields, entry: dict, key: str, path: str) -> str:
    """A string field that may be absent, null or empty (3D-FRONT leaves `title` empty): "" then."""
    value = entry.get(key)
    if value is None or value == "":
        return ""
    return fields.string(value, f"{path}.{key}")


def read_model_info(path: Path) -> dict[str, str]:
    """3D-FUTURE's model_info.json: model_id -> category (entries without a category are skipped).

    Raises:
        LayoutError: naming the file and the entry whose `model_id` or `category` is not a string.
    """
    fields = Fields(path)
    data = fields.items(read_json(path, "3D-FUTURE's model_info.json (a JSON list of models)"), "(top level)")
    out = {}
    for i, m in enumerate(data):
        model_id = fields.string(fields.get(m, "model_id", f"[{i}]"), f"[{i}].model_id")
        category = _optional_text(fields, m, "category", f"[{i}]")
        if category:
            out[model_id] = category
    return out


def _transform(fields: Fields, child: dict, where: str) -> tuple[np.ndarray, tuple[float, float, float, float],
                                                                 np.ndarray]:
    pos = fields.vector(child.get("pos", [0, 0, 0]), 3, f"{where}.pos")
    rot = fields.vector(child.get("rot", [0, 0, 0, 1]), 4, f"{where}.rot", "any")
    norm = math.hypot(*rot)
    if abs(norm - 1.0) > QUATERNION_TOLERANCE:
        raise fields.fail(f"{where}.rot", f"a unit quaternion (x, y, z, w) (its norm is {norm:.4g})", child.get("rot"))
    scale = fields.vector(child.get("scale", [1, 1, 1]), 3, f"{where}.scale", "scale")
    return pos, (float(rot[0]), float(rot[1]), float(rot[2]), float(rot[3])), scale


def _mesh_points(fields: Fields, mesh: dict, where: str, child: dict | None,
                 child_where: str) -> tuple[np.ndarray, np.ndarray]:
    xyz = fields.rows(fields.get(mesh, "xyz", where), 3, f"{where}.xyz", "coordinate",
                      row_path=lambda i, j: f"{where}.xyz[{3 * i + j}]")
    faces = fields.indices(mesh.get("faces", []), f"{where}.faces", len(xyz))
    if child is not None:
        pos, rot, scale = _transform(fields, child, child_where)
        xyz = rotate_by_quaternion(rot, xyz * scale) + pos
    return xyz, faces


def _choose_room(fields: Fields, rooms: list, furniture: dict, room: str | None) -> tuple[int, dict, list[str]]:
    notes: list[str] = []
    for i, r in enumerate(rooms):
        if not isinstance(r, dict):
            raise fields.fail(f"scene.room[{i}]", "a JSON object (a room)", type_name(r))
        _optional_text(fields, r, "type", f"scene.room[{i}]")
        _optional_text(fields, r, "instanceid", f"scene.room[{i}]")
        fields.items(r.get("children", []), f"scene.room[{i}].children")
    if room is not None:
        for i, r in enumerate(rooms):
            if r.get("instanceid") == room:
                return i, r, notes
        ids = ", ".join(str(r.get("instanceid")) for r in rooms)
        raise LayoutError(f"{fields.source}: scene.room: no room {room!r} (rooms: {ids})")
    candidates = [(i, r) for i, r in enumerate(rooms) if room_type_of(str(r.get("type", "")))
                  and any(isinstance(c, dict) and c.get("ref") in furniture for c in r.get("children", []))]
    if not candidates:
        raise LayoutError(f"{fields.source}: scene.room: no room of a known type "
                          f"({', '.join(sorted(set(ROOM_TYPES)))}) with furniture")
    if len(candidates) > 1:
        notes.append(f"{len(candidates)} furnished rooms; took {candidates[0][1].get('instanceid')} "
                     "(choose another with room=)")
    return candidates[0][0], candidates[0][1], notes


def _uids(fields: Fields, entries: list, key: str, taken: dict[str, str]) -> dict[str, tuple[int, dict]]:
    """uid -> (index, entry) of `furniture` or `mesh`; a uid given twice (in either list) is an error."""
    out = {}
    for i, e in enumerate(entries):
        uid = fields.string(fields.get(e, "uid", f"{key}[{i}]"), f"{key}[{i}].uid")
        if uid in taken:
            raise fields.fail(f"{key}[{i}].uid", f"a uid given once (it is also {taken[uid]}), so that a child's ref "
                              "names one entry", uid)
        taken[uid] = f"{key}[{i}]"
        out[uid] = (i, e)
    return out


def import_front(path: Path, room: str | None = None, model_info: Path | dict[str, str] | None = None,
                 room_type: str | None = None) -> Layout:
    """One room of a 3D-FRONT scene as a layout (categories as 3D-FRONT names them; `realize` matches them).

    Every field read is checked (types, finite numbers, positive sizes within limits.MAX_LAYOUT_SIDE_M, unit
    quaternions, face indices, unique uids and instance ids); each child of the room that is left out (its
    furniture marked `valid: false`, without a category, or its ref naming nothing) is listed in
    `provenance.notes["dropped"]` with its path and the reason.

    Args:
        room: the room's `instanceid` (default: the first furnished room of a known type).
        model_info: 3D-FUTURE's model_info.json (or its jid -> category mapping).
        room_type: ours, overriding the room's own type.

    Raises:
        LayoutError: naming the file and the field that is missing or malformed.
    """
    path = Path(path)
    where = str(path)
    fields = Fields(path)
    data = read_json(path, "a 3D-FRONT scene JSON file")
    info = read_model_info(model_info) if isinstance(model_info, (str, Path)) else dict(model_info or {})
    furniture_list = fields.items(fields.get(data, "furniture", ""), "furniture")
    meshes_list = fields.items(fields.get(data, "mesh", ""), "mesh")
    rooms = fields.items(fields.get(fields.get(data, "scene", ""), "room", "scene"), "scene.room")
    taken: dict[str, str] = {}
    entries = _uids(fields, furniture_list, "furniture", taken)
    meshes = _uids(fields, meshes_list, "mesh", taken)
    furniture, invalid = {}, {}
    ignored: dict[str, int] = {}
    for uid, (i, f) in entries.items():
        if "valid" in f and not fields.boolean(f["valid"], f"furniture[{i}].valid"):
            ignored["furniture marked valid: false"] = ignored.get("furniture marked valid: false", 0) + 1
            invalid[uid] = i
        else:
            furniture[uid] = (i, f)
    ri, chosen, notes = _choose_room(fields, rooms, furniture, room)
    rpath = f"scene.room[{ri}]"
    ours = room_type or room_type_of(str(chosen.get("type", "")))
    if ours is None:
        raise LayoutError(f"{where}: {rpath}.type: {chosen.get('type')!r} is not a room type we know "
                          f"({', '.join(sorted(set(ROOM_TYPES)))}); give the room type")
    children = fields.items(fields.get(chosen, "children", rpath), f"{rpath}.children")
    floor_v, floor_f, n = [], [], 0
    objects_src = []
    dropped: list[dict[str, str]] = []
    placed_refs: dict[str, tuple[dict, str]] = {}
    ids: dict[str, str] = {}
    for j, c in enumerate(children):
        cpath = f"{rpath}.children[{j}]"
        ref = fields.string(fields.get(c, "ref", cpath), f"{cpath}.ref")
        placed_refs[ref] = (c, cpath)
        if ref in furniture:
            fi, f = furniture[ref]
            oid = _optional_text(fields, c, "instanceid", cpath) or f"{ref}_{j}"
            if oid in ids:
                raise fields.fail(f"{cpath}.instanceid", f"an instance id given once in the room (also {ids[oid]})",
                                  oid)
            ids[oid] = cpath
            objects_src.append((c, cpath, oid, fi, f))
        elif ref in invalid:
            dropped.append({"entry": cpath, "ref": ref, "reason": f"its furniture[{invalid[ref]}] is marked "
                            "valid: false"})
        elif ref in meshes:
            mi, mesh = meshes[ref]
            mtype = _optional_text(fields, mesh, "type", f"mesh[{mi}]")
            if mtype.lower() == "floor":
                v, tri = _mesh_points(fields, mesh, f"mesh[{mi}]", c, cpath)
                floor_v.append(v)
                floor_f.append(tri + n)
                n += len(v)
            else:
                ignored[f"mesh {mtype or '(no type)'}"] = ignored.get(f"mesh {mtype or '(no type)'}", 0) + 1
        else:
            ignored["children whose ref names nothing"] = ignored.get("children whose ref names nothing", 0) + 1
            dropped.append({"entry": cpath, "ref": ref, "reason": "its ref names no furniture or mesh uid"})
    if len(objects_src) > MAX_LAYOUT_OBJECTS:
        raise LayoutError(f"{where}: {rpath}.children: {len(objects_src)} pieces of furniture; a layout may hold at "
                          f"most {MAX_LAYOUT_OBJECTS} (luminous_sim.limits.MAX_LAYOUT_OBJECTS)")
    if not floor_v:
        raise LayoutError(f"{where}: {rpath}.children: no mesh of type Floor (the room's outline comes from its floor)")
    try:
        poly = outline_from_triangles(np.concatenate(floor_v), np.concatenate(floor_f))
    except ValueError as exc:
        raise LayoutError(f"{where}: {rpath}: floor mesh: {exc}") from None
    openings = []
    for uid, (mi, mesh) in meshes.items():
        kind = _optional_text(fields, mesh, "type", f"mesh[{mi}]").lower()
        if "door" in kind or "window" in kind:
            child, cpath = placed_refs.get(uid, (None, ""))
            v, _ = _mesh_points(fields, mesh, f"mesh[{mi}]", child, cpath)
            openings.append(Opening("door" if "door" in kind else "window", to_ours(v), f"mesh[{mi}]"))
    name = re.sub(r"[^A-Za-z0-9_\-]", "_", f"front_{path.stem}_{chosen.get('instanceid', ri)}")[:80]
    try:
        layout_room, offset = build_room(poly, ours, name, openings, notes, source=f"3D-FRONT {path.name}")
    except ValidationError as exc:
        raise LayoutError(f"{where}: {rpath}: the room its floor mesh outlines: {room_problem(exc)}") from None
    objects = []
    for c, cpath, oid, fi, f in objects_src:
        fpath = f"furniture[{fi}]"
        jid = _optional_text(fields, f, "jid", fpath)
        category = info.get(jid) or _optional_text(fields, f, "category", fpath) or _optional_text(
            fields, f, "title", fpath)
        if not category:
            if model_info is not None:
                ignored["furniture with no category in model_info"] = ignored.get(
                    "furniture with no category in model_info", 0) + 1
                dropped.append({"entry": cpath, "ref": str(f["uid"]),
                                "reason": f"{fpath} (jid {jid!r}) has no category in model_info nor its own"})
                continue
            raise LayoutError(f"{where}: {fpath}.category: missing (jid {jid!r}); give 3D-FUTURE's model_info.json")
        key = "bbox" if "bbox" in f else "size" if "size" in f else None
        if key is None:
            raise LayoutError(f"{where}: {fpath}.bbox: missing (the model's box size, metres; or size)")
        size = fields.vector(f[key], 3, f"{fpath}.{key}", "size")
        pos, rot, scale = _transform(fields, c, cpath)
        size = size * scale
        if (size > MAX_LAYOUT_SIDE_M).any():
            raise fields.fail(f"{cpath}.scale", f"a scale that keeps {fpath}.{key} within {MAX_LAYOUT_SIDE_M:g} m "
                              "(luminous_sim.limits.MAX_LAYOUT_SIDE_M)", c.get("scale"))
        centre = pos + rotate_by_quaternion(rot, np.array([0.0, size[1] / 2, 0.0]))[0]
        x, y, z = to_ours(centre)[0]
        yaw, tilt = yaw_and_tilt(rot)
        if tilt > TILT:
            notes.append(f"{cpath}: tilted {math.degrees(tilt):.0f} degrees; only its turn about the vertical is kept")
        objects.append(LayoutObject(
            id=oid, category=category, size=(float(size[0]), float(size[2]), float(size[1])),
            position=(round(x - offset[0], 6), round(y - offset[1], 6), round(float(z), 6)), yaw=round(yaw, 6)))
    prov = Provenance(generator="3d-front", source=str(path), notes={
        "room": str(chosen.get("instanceid", ri)), "room_type": str(chosen.get("type", "")),
        "offset": list(offset), "ignored": dict(sorted(ignored.items())), "dropped": dropped,
        "import_notes": notes})
    try:
        return Layout(room=layout_room, objects=tuple(objects), provenance=prov)
    except ValidationError as exc:
        raise problems(exc, where) from None
