"""ALFRED's task parser (paper section 3.6, appendix "Task parser"): one `traj_data.json` -> a CDF.

What is read, and what it becomes:

- the objects the actions name (`objectId`, `receptacleObjectId`, `cleanObjectId` of `plan.high_pddl` and
  `plan.low_actions`, the receptacle a high-level PickupObject took its object from, and the types of the
  GotoLocation targets): one declared CDF object per AI2-THOR instance (a slice stands for its parent);
- where an object was first picked up from (`coordinateReceptacleObjectId`): `<object> on|in <receptacle>`;
  where objects were put makes that receptacle required, not an initial placement;
- initial states: `scene.object_toggles` (a lamp off), `scene.dirty_and_empty` (declared dirtyable objects
  dirty, fillable ones empty), and what the expert's first action on an object shows (opened first: it
  started closed; switched on first: it started off);
- `scene.init_action` -> `task.agent` (THOR x, z are the room shell's x, y) when it lies inside the shell;
- `pddl_params` + `task_type` -> `task.type` and ALFRED's goal (`tasks.cdf_for_task`, the goal library);
- `scene.floor_plan` -> `scene.room` (the converted AI2-THOR room) and its room type.

Everything else is listed as dropped, with the reason (`AlfredParse.dropped`).
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cache, lru_cache
from pathlib import Path
from typing import Any

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cdf import CDFValidationError, ChallengeDefinition, from_document, to_sexpr
from luminous_sim.errors import LuminousError, RoomError, VocabularyError, path_kind
from luminous_sim.rooms import load_room
from luminous_sim.scene.ids import type_of_id
from luminous_sim.tasks import PddlParams, TaskError, cdf_for_task, required_objects
from luminous_sim.vocab import ALL_TYPES, FILLABLE, SLICED_TYPES, SLICING_TOOLS, abilities, can_contain

GRID = 0.25
"""ALFRED's `coordinate*ObjectId` values are positions in 0.25 m grid units."""
SAME_SPOT = 0.06
"""Metres within which a coordinate and an objectId of the same type are one object (ids round to 0.01 m)."""
SAME_BASIN = 1.0
"""A basin's id carries its sink's or bathtub's position, up to about 0.8 m from the basin's own."""
_LOWER_TYPES = {t.lower(): t for t in ALL_TYPES}


class AlfredParseError(LuminousError):
    """A traj_data.json that cannot be parsed: a missing key, a value of the wrong kind, an unknown room."""


@dataclass(frozen=True)
class ParseNote:
    """One thing the parser kept or dropped.

    Attributes:
        field: where it came from in traj_data.json (`plan.high_pddl[1]`, `scene.object_toggles`, ...).
        item: what it is (`apple (Apple|+00.46|+00.82|+02.27)`, `apple in fridge`, ...).
        reason: why it was kept (what it became) or dropped.
    """

    field: str
    item: str
    reason: str

    def to_json(self) -> dict[str, str]:
        return {"field": self.field, "item": self.item, "reason": self.reason}


@dataclass(frozen=True)
class AlfredParse:
    """The CDF deduced from one ALFRED trajectory, and what the parse kept and dropped.

    Attributes:
        source: the file (or the name given for in-memory data).
        task_id: ALFRED's `task_id`.
        task_type: ALFRED's `task_type`.
        params: ALFRED's `pddl_params`.
        floor_plan: `scene.floor_plan` (`FloorPlan12`).
        cdf: the validated CDF: room, objects, relations, states, agent start, task type and goal.
        kept: what became part of the CDF.
        dropped: what did not, with the reason.
        keys: CDF object name -> the AI2-THOR instance it stands for (its objectId, or one made from the
            type and position ALFRED recorded), the identity the merge matches objects by.
    """

    source: str
    task_id: str
    task_type: str
    params: PddlParams
    floor_plan: str
    cdf: ChallengeDefinition
    kept: tuple[ParseNote, ...]
    dropped: tuple[ParseNote, ...]
    keys: Mapping[str, str] = field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        """The parse's report entry (the CDF itself is written beside it)."""
        return {
            "source": self.source,
            "task_id": self.task_id,
            "task_type": self.task_type,
            "pddl_params": self.params.to_json(),
            "floor_plan": self.floor_plan,
            "objects": {n: self.keys[n] for n in sorted(self.keys)},
            "kept": [n.to_json() for n in self.kept],
            "dropped": [n.to_json() for n in self.dropped],
        }


# -- object identities --------------------------------------------------------------------------


def thor_position(object_id: str) -> tuple[float, float, float] | None:
    """THOR (x, y, z) an objectId carries (`Type|+x|+y|+z[|Part]`), or None when it has none."""
    parts = object_id.split("|")
    try:
        return (float(parts[1]), float(parts[2]), float(parts[3]))
    except (IndexError, ValueError):
        return None


def instance_id(object_id: str) -> str:
    """The instance an id stands for in a CDF: a slice (`Apple|...|AppleSliced_2`) stands for its parent."""
    parts = object_id.split("|")
    if len(parts) == 5 and type_of_id(object_id) in SLICED_TYPES:
        return "|".join(parts[:4])
    return object_id


def _id_from(object_type: str, xyz: tuple[float, float, float]) -> str:
    """An objectId-shaped key for an object known only by type and position (no `-00.00`)."""
    return object_type + "".join(f"|{v + 0.0:+06.2f}".replace("-00.00", "+00.00") for v in xyz)


def coordinate_position(value: Any, where: str) -> tuple[str, tuple[float, float, float]]:
    """(type, THOR x, y, z) of a `coordinate*ObjectId` value `[Type, [x, x, z, z, y, y]]` in grid units."""
    try:
        object_type, v = value
        xyz = (float(v[0]) * GRID, float(v[4]) * GRID, float(v[2]) * GRID)
    except (TypeError, ValueError, IndexError):
        raise AlfredParseError(f"{where}: expected [Type, [x, x, z, z, y, y]], got {value!r:.80}") from None
    if not isinstance(object_type, str):
        raise AlfredParseError(f"{where}: expected a type name first, got {object_type!r:.40}")
    return object_type, xyz


def match_instance(
    object_type: str, xyz: tuple[float, float, float], known: Sequence[str]
) -> str | None:
    """The id among `known` of the same type nearest `xyz`, if near enough to be the same object."""
    limit = SAME_BASIN if object_type.endswith("Basin") else SAME_SPOT
    best, best_d = None, limit
    for oid in known:
        pos = thor_position(oid)
        if pos is None or type_of_id(oid) != object_type:
            continue
        d = math.dist(pos, xyz)
        if d <= best_d:
            best, best_d = oid, d
    return best


# -- how an object rests on a receptacle ----------------------------------------------------------


@cache
def support_relation(receptacle_type: str) -> str:
    """`in` or `on`, by the regions the type's assets offer: `in` where they have only interior volumes
    (basins, bins, bowls, a fridge), `on` where they have only a top surface (a toilet's lid, a counter);
    where they have both, `in` for an openable type (a drawer) and `on` otherwise (a dresser's top)."""
    kinds = {r["kind"] for e in default_catalog().of_type(receptacle_type) for r in e.regions}
    if kinds == {"volume"}:
        return "in"
    if kinds == {"surface"}:
        return "on"
    return "in" if abilities(receptacle_type).openable else "on"


@lru_cache(maxsize=16)
def _room(name: str) -> Any:
    """The room shell of a floor plan, read once per parse run (only its outline and type are used)."""
    return load_room(name)


def snake(object_type: str) -> str:
    """`SinkBasin` -> `sink_basin`, `CD` -> `cd`, `TVStand` -> `tv_stand`: a CDF name from a type."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", object_type).lower()


# -- reading the file -----------------------------------------------------------------------------


MAX_TRAJ_BYTES = 64 * 1024 * 1024
"""Largest traj_data.json read (ALFRED's largest is under 2 MB)."""


def _first_not_finite(value: Any, where: str = "") -> str | None:
    """The key path of the first NaN or infinite number in `value`, if any."""
    if isinstance(value, float) and not math.isfinite(value):
        return where or "(top)"
    if isinstance(value, Mapping):
        items: Iterator[tuple[str, Any]] = ((f"{where}.{k}" if where else str(k), v) for k, v in value.items())
    elif isinstance(value, list | tuple):
        items = ((f"{where}[{i}]", v) for i, v in enumerate(value))
    else:
        return None
    for path, item in items:
        found = _first_not_finite(item, path)
        if found:
            return found
    return None


def read_traj(path: str | Path, source: str | None = None) -> Mapping[str, Any]:
    """A traj_data.json's content, checked as both ALFRED readers (`parse_alfred`, `data.read_design`) need
    it: a regular file (a folder or a device is named as such) within `MAX_TRAJ_BYTES`, JSON without NaN or
    infinities, an object at the top, and `check_traj`'s fields.

    Raises:
        AlfredParseError: the first problem, naming the file and the key.
    """
    path = Path(path)
    source = source or str(path)
    if not path.exists():
        raise AlfredParseError(f"{source}: no such file")
    if path.is_dir():
        raise AlfredParseError(f"{source}: a folder; expected a traj_data.json file")
    if not path.is_file():
        raise AlfredParseError(f"{source}: {path_kind(path)}; expected a traj_data.json file")
    size = path.stat().st_size
    if size > MAX_TRAJ_BYTES:
        raise AlfredParseError(f"{source}: {size} bytes; a traj_data.json may hold at most {MAX_TRAJ_BYTES}")
    try:
        data = json.loads(path.read_bytes())  # NaN and Infinity parse: `check_traj` names where they are
    except (ValueError, RecursionError) as exc:
        raise AlfredParseError(f"{source}: not JSON: {exc}") from None
    check_traj(data, source)
    return data


def check_traj(data: Any, source: str) -> None:
    """Refuse trajectory data that is not an object, lacks ALFRED's task_type, pddl_params, scene.floor_plan,
    scene.scene_num, plan.high_pddl or plan.low_actions, or holds a NaN or infinite number anywhere.

    Raises:
        AlfredParseError: naming `source` and the key.
    """
    if not isinstance(data, Mapping):
        raise AlfredParseError(f"{source}: expected a JSON object at the top, got {type(data).__name__}")
    _get(data, "task_type", str, source)
    _get(data, "pddl_params", Mapping, source)
    _get(data, "scene.floor_plan", str, source)
    _get(data, "scene.scene_num", int, source)
    _get(data, "plan.high_pddl", list, source)
    _get(data, "plan.low_actions", list, source)
    bad = _first_not_finite(data)
    if bad:
        raise AlfredParseError(f"{source}: {bad}: expected a finite number, got NaN or infinity")


def _get(data: Mapping[str, Any], path: str, kind: type | tuple[type, ...], source: str, within: str = "") -> Any:
    """`data[a][b]...` for `path` "a.b", checked to be of `kind`; `within` prefixes the path in messages."""
    value: Any = data
    for key in path.split("."):
        if not isinstance(value, Mapping) or key not in value:
            raise AlfredParseError(f"{source}: missing key {within + path!r}")
        value = value[key]
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        names = kind.__name__ if isinstance(kind, type) else " or ".join(k.__name__ for k in kind)
        raise AlfredParseError(f"{source}: {within}{path}: expected {names}, got {type(value).__name__} {value!r:.60}")
    return value


@dataclass
class _Instance:
    key: str
    type: str
    name: str
    named_by: list[str]
    state: dict[str, bool] = field(default_factory=dict)
    state_why: dict[str, str] = field(default_factory=dict)


class _Reader:
    """One pass over a trajectory's plan, collecting instances, first pickups, puts and first actions."""

    def __init__(self, data: Mapping[str, Any], source: str) -> None:
        self.source = source
        self.high: list[Any] = _get(data, "plan.high_pddl", list, source)
        self.low: list[Any] = _get(data, "plan.low_actions", list, source)
        self.instances: dict[str, _Instance] = {}
        self.kept: list[ParseNote] = []
        self.dropped: list[ParseNote] = []
        self.relations: list[tuple[str, str, str, str]] = []  # (subject key, relation, target key, field)
        self.picked: set[str] = set()
        self.all_ids = sorted({instance_id(i) for i, _ in self._ids()})

    def _ids(self) -> Iterator[tuple[str, str]]:
        for i, h in enumerate(self.high):
            pa = h.get("planner_action", {}) if isinstance(h, Mapping) else {}
            for k in ("objectId", "receptacleObjectId", "cleanObjectId"):
                if isinstance(pa.get(k), str):
                    yield pa[k], f"plan.high_pddl[{i}].planner_action.{k}"
        for i, lo in enumerate(self.low):
            api = lo.get("api_action", {}) if isinstance(lo, Mapping) else {}
            for k in ("objectId", "receptacleObjectId", "cleanObjectId"):
                if isinstance(api.get(k), str):
                    yield api[k], f"plan.low_actions[{i}].api_action.{k}"

    def instance(self, key: str, object_type: str, why: str) -> _Instance:
        inst = self.instances.get(key)
        if inst is None:
            taken = sum(1 for i in self.instances.values() if i.type == object_type)
            name = snake(object_type) + (f"_{taken + 1}" if taken else "")
            inst = self.instances[key] = _Instance(key, object_type, name, [])
        if why not in inst.named_by:
            inst.named_by.append(why)
        return inst

    def by_id(self, object_id: str, why: str) -> _Instance | None:
        key = instance_id(object_id)
        object_type = type_of_id(key)
        if object_type not in ALL_TYPES:
            self.dropped.append(ParseNote(why, object_id, f"{object_type!r} is not an ALFRED object type"))
            return None
        return self.instance(key, object_type, why)

    def by_coordinate(self, value: Any, where: str, why: str) -> _Instance | None:
        object_type, xyz = coordinate_position(value, where)
        if object_type not in ALL_TYPES:
            self.dropped.append(ParseNote(where, object_type, f"{object_type!r} is not an ALFRED object type"))
            return None
        key = match_instance(object_type, xyz, self.all_ids) or _id_from(object_type, xyz)
        return self.instance(key, object_type, why)

    def read(self) -> None:
        moved: set[str] = set()
        first_action: dict[str, tuple[str, str]] = {}
        gotos: list[tuple[Mapping[str, Any], str]] = []
        for i, h in enumerate(self.high):
            where = f"plan.high_pddl[{i}]"
            if not isinstance(h, Mapping) or not isinstance(h.get("planner_action"), Mapping):
                raise AlfredParseError(f"{self.source}: {where}: expected an object with a planner_action")
            pa = h["planner_action"]
            action = pa.get("action")
            if action == "GotoLocation":
                gotos.append((h, where))
            elif action == "PickupObject":
                self._pickup(pa, where, moved)
            elif action == "PutObject":
                self._put(pa, where)
            elif action in ("HeatObject", "CoolObject", "CleanObject", "SliceObject", "ToggleObject"):
                self._device(pa, where, action)
        for i, lo in enumerate(self.low):
            api = lo.get("api_action") if isinstance(lo, Mapping) else None
            if not isinstance(api, Mapping) or not isinstance(api.get("action"), str):
                raise AlfredParseError(f"{self.source}: plan.low_actions[{i}]: expected an api_action with an action")
            where = f"plan.low_actions[{i}]"
            for k in ("objectId", "receptacleObjectId"):
                if isinstance(api.get(k), str):
                    inst = self.by_id(api[k], f"{api['action']} ({where})")
                    if inst is not None and k == "objectId":
                        first_action.setdefault(inst.key, (api["action"], where))
        self._first_actions(first_action)
        for h, where in gotos:  # last: a target is usually the object or receptacle of the next step
            self._goto(h, where)

    def _goto(self, h: Mapping[str, Any], where: str) -> None:
        args = h.get("discrete_action", {}).get("args", []) if isinstance(h.get("discrete_action"), Mapping) else []
        for arg in args if isinstance(args, list) else []:
            t = _LOWER_TYPES.get(str(arg).lower())
            if t is None:
                self.dropped.append(ParseNote(where, str(arg), "GotoLocation target is not an ALFRED object type"))
            elif not any(i.type == t for i in self.instances.values()):
                self.instance(f"{t}|goto", t, f"GotoLocation ({where})")

    def _pickup(self, pa: Mapping[str, Any], where: str, moved: set[str]) -> None:
        oid = pa.get("objectId")
        if not isinstance(oid, str):
            raise AlfredParseError(f"{self.source}: {where}.planner_action.objectId: expected an objectId")
        obj = self.by_id(oid, f"PickupObject ({where})")
        if obj is None:
            return
        first = obj.key not in moved
        moved.add(obj.key)
        self.picked.add(obj.key)
        if not first:
            return
        source = pa.get("coordinateReceptacleObjectId")
        if source is None:
            self.dropped.append(ParseNote(
                where, f"{obj.name} ({obj.key})",
                "picked up from no receptacle (AI2-THOR recorded none under it: the floor, or a part that is not a "
                "receptacle); "
                "no placement constraint"))
            return
        rec = self.by_coordinate(source, f"{self.source}: {where}.planner_action.coordinateReceptacleObjectId",
                                 f"PickupObject source ({where})")
        if rec is not None:
            self.relations.append((obj.key, support_relation(rec.type), rec.key, where))

    def _put(self, pa: Mapping[str, Any], where: str) -> None:
        obj = self.by_id(str(pa.get("objectId", "")), f"PutObject ({where})") if pa.get("objectId") else None
        rid = pa.get("receptacleObjectId")
        if not isinstance(rid, str):
            raise AlfredParseError(f"{self.source}: {where}.planner_action.receptacleObjectId: expected an objectId")
        rec = self.by_id(rid, f"PutObject target ({where})")
        if obj is not None and rec is not None:
            self.kept.append(ParseNote(
                where, f"put {obj.name} {support_relation(rec.type)} {rec.name}",
                f"{rec.name} is required; where the expert puts things is the goal's business, "
                "not an initial placement"))

    def _device(self, pa: Mapping[str, Any], where: str, action: str) -> None:
        for k in ("objectId", "cleanObjectId"):
            if isinstance(pa.get(k), str):
                self.by_id(pa[k], f"{action} ({where})")

    def _first_actions(self, first_action: Mapping[str, tuple[str, str]]) -> None:
        """An object the expert opens (switches on) before anything else started closed (off); and the
        reverse. Only for types that can be opened (toggled)."""
        flag_of = {"OpenObject": ("isOpen", False, "openable"), "CloseObject": ("isOpen", True, "openable"),
                   "ToggleObjectOn": ("isToggled", False, "toggleable"),
                   "ToggleObjectOff": ("isToggled", True, "toggleable")}
        for key, (action, where) in first_action.items():
            if action not in flag_of:
                continue
            flag, value, ability = flag_of[action]
            inst = self.instances[key]
            if getattr(abilities(inst.type), ability):
                inst.state[flag] = value
                inst.state_why[flag] = f"the expert's first action on it is {action} ({where})"
            else:
                self.dropped.append(ParseNote(where, f"{inst.name} {flag}={value}",
                                              f"{inst.type} is not {ability} in ALFRED's vocabulary"))


# -- the parse ------------------------------------------------------------------------------------


def _scene_states(reader: _Reader, scene: Mapping[str, Any], source: str) -> None:
    toggles = _get(scene, "object_toggles", list, source, "scene.")
    for j, entry in enumerate(toggles):
        where = f"scene.object_toggles[{j}]"
        if not isinstance(entry, Mapping) or not isinstance(entry.get("objectType"), str) or not isinstance(
            entry.get("isOn"), bool
        ):
            raise AlfredParseError(f"{source}: {where}: expected {{objectType: str, isOn: bool}}, got {entry!r:.60}")
        hits = [i for i in reader.instances.values() if i.type == entry["objectType"]]
        for inst in hits:
            inst.state["isToggled"] = entry["isOn"]
            inst.state_why["isToggled"] = f"{where}: every {entry['objectType']} isOn={entry['isOn']}"
        if not hits:
            reader.dropped.append(ParseNote(where, f"{entry['objectType']} isOn={entry['isOn']}",
                                            f"no {entry['objectType']} among the objects the actions name"))
    if not _get(scene, "dirty_and_empty", bool, source, "scene."):
        return
    for inst in reader.instances.values():
        if abilities(inst.type).dirtyable:
            inst.state["isDirty"] = True
            inst.state_why["isDirty"] = "scene.dirty_and_empty: every dirtyable object starts dirty"
        if inst.type in FILLABLE:
            inst.state["isFilled"] = False
            inst.state_why["isFilled"] = "scene.dirty_and_empty: every fillable object starts empty"
    reader.dropped.append(ParseNote(
        "scene.dirty_and_empty", "the room's other dirtyable and fillable objects",
        "a CDF states the initial state of declared objects only; the rest are left to the generator"))


def _agent(scene: Mapping[str, Any], source: str, shell: Any) -> tuple[dict[str, Any] | None, ParseNote]:
    init = _get(scene, "init_action", Mapping, source, "scene.")
    where = "scene.init_action"
    try:
        x, z = float(init["x"]), float(init["z"])
        rotation, horizon = int(init["rotation"]), int(init["horizon"])
    except (KeyError, TypeError, ValueError):
        return None, ParseNote(where, repr(dict(init))[:80], "no x, z, rotation and horizon to read")
    item = f"TeleportFull x={x:g} z={z:g} rotation={rotation} horizon={horizon}"
    if init.get("action") != "TeleportFull":
        return None, ParseNote(where, item, f"action {init.get('action')!r}, expected TeleportFull")
    if rotation not in (0, 90, 180, 270) or horizon not in (-30, -15, 0, 15, 30, 45, 60):
        return None, ParseNote(where, item, "rotation or horizon off ALFRED's steps (90 and 15 degrees)")
    from shapely.geometry import Point

    if not shell.polygon().contains(Point(x, z)):
        minx, miny, maxx, maxy = shell.bounds
        return None, ParseNote(where, item, f"({x:g}, {z:g}) lies outside room {shell.name!r} "
                                            f"(x {minx:g}..{maxx:g}, y {miny:g}..{maxy:g} m)")
    pose = {"position": [x, z], "rotation": rotation, "horizon": horizon}
    return pose, ParseNote(where, item, f"task.agent: position ({x:g}, {z:g}) (THOR x, z are the room's x, y), "
                                        f"rotation {rotation}, horizon {horizon}")


def _required(reader: _Reader, task_type: str, params: PddlParams, source: str) -> None:
    """Add what the task needs and no action named (the knife of a sliced task whose expert used a
    ButterKnife is satisfied by it; any slicing tool will do)."""
    try:
        needed = required_objects(task_type, params)
    except TaskError as exc:
        raise AlfredParseError(f"{source}: pddl_params: {exc}") from None
    for object_type, count in needed:
        same = SLICING_TOOLS if object_type in SLICING_TOOLS else (object_type,)
        have = sum(1 for i in reader.instances.values() if i.type in same)
        for k in range(have, count):
            reader.instance(f"{object_type}|required|{k}", object_type, "required by the task (tasks.required_objects)")
    if task_type == "pick_and_place_with_movable_recep":
        _inside_mrecep(reader, params)


def _inside_mrecep(reader: _Reader, params: PddlParams) -> None:
    """An object the expert never picks up, in a task whose goal has it inside the movable receptacle,
    started there (ALFRED's "Pickup(mrecep), Put(mrecep -> recep)" plans)."""
    placed = {r[0] for r in reader.relations}
    objects = [i for i in reader.instances.values() if i.type == params.object_target]
    if any(i.key in placed or i.key in reader.picked for i in objects):
        return
    mreceps = [i for i in reader.instances.values() if i.type == params.mrecep_target and i.key in reader.picked]
    if objects and mreceps:
        rec = mreceps[0]
        reader.relations.append((objects[0].key, support_relation(rec.type), rec.key,
                                 "pddl_params.mrecep_target (never picked up, yet the goal has it inside)"))


def _document(
    reader: _Reader, name: str, description: str, room: str, room_type: str, task: dict[str, Any] | None,
    skip: set[tuple[str, int]],
) -> dict[str, Any]:
    objects: list[dict[str, Any]] = []
    for inst in reader.instances.values():
        entry: dict[str, Any] = {"name": inst.name, "type": inst.type}
        state = {f: v for f, v in inst.state.items() if (f"state:{f}", len(objects)) not in skip}
        if state:
            entry["state"] = state
        objects.append(entry)
    relations = []
    for j, (subj, rel, target, _) in enumerate(reader.relations):
        if ("relation", j) in skip:
            continue
        relations.append({"subject": reader.instances[subj].name, "relation": rel,
                          "target": reader.instances[target].name})
    doc: dict[str, Any] = {"cdf_version": 2, "name": name, "description": description,
                           "scene": {"room_type": room_type, "room": room, "objects": objects,
                                     "relations": relations}}
    if task is not None:
        doc["task"] = task
    return doc


def _placements(reader: _Reader) -> list[int]:
    """Check each first-pickup placement against ALFRED's receptacle table and keep one per object;
    returns the indices of those dropped."""
    out = []
    seen: set[str] = set()
    for j, (subj, rel, target, where) in enumerate(reader.relations):
        s, t = reader.instances[subj], reader.instances[target]
        item = f"{s.name} {rel} {t.name}"
        try:
            allowed = can_contain(t.type, s.type)
        except VocabularyError:
            allowed = False
        if subj in seen:
            reader.dropped.append(ParseNote(where, item, f"{s.name} already has a placement"))
            out.append(j)
        elif not allowed:
            reader.dropped.append(ParseNote(where, item, f"ALFRED's receptacle table does not let {_a(t.type)} "
                                                         f"hold {_a(s.type)} (AI2-THOR's spawn did)"))
            out.append(j)
        else:
            seen.add(subj)
            why = ("it is never picked up, yet the goal has it inside the movable receptacle, so it starts there"
                   if where.startswith("pddl_params") else f"picked up from {_a(t.type)}, so it starts there")
            reader.kept.append(ParseNote(where, item, f"scene.relations: {why}"))
    return out


def _a(word: str) -> str:
    return ("an " if word[:1].lower() in "aeiou" else "a ") + word


def parse_alfred(traj: Mapping[str, Any] | str | Path, source: str | None = None) -> AlfredParse:
    """Deduce a CDF from one ALFRED trajectory (a traj_data.json file, or its data).

    Args:
        traj: the path of a traj_data.json, or its parsed content.
        source: the name used in messages and the report (default: the path, or `<traj_data>`).

    Returns:
        The parse: the validated CDF and the notes on what was kept and dropped.

    Raises:
        AlfredParseError: unreadable JSON, a missing key or a value of the wrong kind, an unknown floor
            plan or task parameters ALFRED would not draw; the message names the file and the key.
    """
    if isinstance(traj, (str, Path)):
        source = source or str(traj)
        data = read_traj(traj, source)
    else:
        data, source = traj, source or "<traj_data>"
        check_traj(data, source)
    task_type = _get(data, "task_type", str, source)
    task_id = str(data.get("task_id", ""))
    try:
        params = PddlParams.from_json(_get(data, "pddl_params", Mapping, source))
    except TaskError as exc:
        raise AlfredParseError(f"{source}: {exc}") from None
    scene = _get(data, "scene", Mapping, source)
    floor_plan = _get(scene, "floor_plan", str, source, "scene.")
    try:
        shell = _room(floor_plan)
    except RoomError as exc:
        raise AlfredParseError(f"{source}: scene.floor_plan: {exc}") from None
    room_type = shell.room_type
    try:
        goal = cdf_for_task(task_type, params, room_type).task.goal  # type: ignore[union-attr]
    except TaskError as exc:
        raise AlfredParseError(f"{source}: task_type/pddl_params: {exc}") from None

    reader = _Reader(data, source)
    reader.read()
    _required(reader, task_type, params, source)
    _scene_states(reader, scene, source)
    skip: set[Any] = {("relation", j) for j in _placements(reader)}
    agent, agent_note = _agent(scene, source, shell)
    (reader.kept if agent else reader.dropped).append(agent_note)
    for inst in reader.instances.values():
        reader.kept.append(ParseNote(", ".join(inst.named_by[:3]) + (" ..." if len(inst.named_by) > 3 else ""),
                                     f"{inst.name} ({inst.key})", f"scene.objects: {inst.type}"))
        for flag, value in inst.state.items():
            reader.kept.append(ParseNote(inst.state_why[flag], f"{inst.name} {flag}={value}",
                                         f"scene.objects[{inst.name}].state"))
    reader.kept.append(ParseNote("task_type, pddl_params", f"{task_type} {json.dumps(params.to_json())}",
                                 f"task.type and ALFRED's goal {to_sexpr(goal)}"))
    reader.kept.append(ParseNote("scene.floor_plan", floor_plan, f"scene.room {floor_plan} ({room_type})"))
    _drop_unused(reader, data, scene)

    task: dict[str, Any] = {"type": task_type, "goal": to_sexpr(goal)}
    if agent:
        task["agent"] = agent
    dir_name = (f"{task_type}-{params.object_type}-{params.mrecep_target or 'None'}-"
                f"{params.parent_target or params.toggle_target}-{floor_plan.removeprefix('FloorPlan')}")
    name = f"{dir_name}.{task_id}" if task_id else dir_name
    description = f"Parsed from ALFRED traj_data.json {task_id or source} ({floor_plan})."
    cdf = _validated(reader, name, description, floor_plan, room_type, task, skip, source)
    keys = {i.name: i.key for i in reader.instances.values()}
    return AlfredParse(source, task_id, task_type, params, floor_plan, cdf, tuple(reader.kept),
                       tuple(reader.dropped), keys)


def _validated(
    reader: _Reader, name: str, description: str, room: str, room_type: str, task: dict[str, Any],
    skip: set[Any], source: str,
) -> ChallengeDefinition:
    """The CDF, validated; a relation or state the validation refuses is dropped with its message."""
    for _ in range(len(reader.relations) + 8):
        doc = _document(reader, name, description, room, room_type, task, skip)
        try:
            return from_document(doc, source)
        except CDFValidationError as exc:
            progressed = False
            for issue in exc.issues:
                m = re.match(r"scene\.relations\[(\d+)\]", issue.path)
                if m:
                    kept = [j for j in range(len(reader.relations)) if ("relation", j) not in skip]
                    j = kept[int(m.group(1))]
                    skip.add(("relation", j))
                    subj, rel, target, where = reader.relations[j]
                    item = f"{reader.instances[subj].name} {rel} {reader.instances[target].name}"
                    reader.kept[:] = [n for n in reader.kept if not (n.field == where and n.item == item)]
                    reader.dropped.append(ParseNote(where, item, f"CDF validation: {issue.message}"))
                    progressed = True
                    continue
                m = re.match(r"scene\.objects\[(\d+)\]\.state\.(\w+)", issue.path)
                if m:
                    skip.add((f"state:{m.group(2)}", int(m.group(1))))
                    inst = list(reader.instances.values())[int(m.group(1))]
                    reader.dropped.append(ParseNote("state", f"{inst.name} {m.group(2)}",
                                                    f"CDF validation: {issue.message}"))
                    progressed = True
            if not progressed:
                raise AlfredParseError(f"{source}: the parsed CDF does not validate: {exc}") from None
    raise AlfredParseError(f"{source}: the parsed CDF does not validate")


def _drop_unused(reader: _Reader, data: Mapping[str, Any], scene: Mapping[str, Any]) -> None:
    poses = scene.get("object_poses", [])
    if isinstance(poses, list) and poses:
        types = {str(p.get("objectName", "")).rsplit("_", 1)[0] for p in poses if isinstance(p, Mapping)}
        reader.dropped.append(ParseNote(
            "scene.object_poses", f"{len(poses)} poses of {len(types)} pickupable types",
            "absolute AI2-THOR positions among AI2-THOR's own furniture; a generated layout places objects "
            "by relation (where each was picked up from), not by position"))
    if "random_seed" in scene:
        reader.dropped.append(ParseNote("scene.random_seed", str(scene["random_seed"]),
                                        "AI2-THOR's InitialRandomSpawn seed; CSSG draws from its own seed"))
    reader.dropped.append(ParseNote(
        "plan", f"{len(reader.high)} high-level and {len(reader.low)} low-level actions",
        "read for objects, placements and initial states; not kept as an execution script (the oracle "
        "solves the CDF's goal in the generated scene)"))
    for key in ("turk_annotations", "images"):
        if key in data:
            reader.dropped.append(ParseNote(key, key, "language and frames of the original episode, "
                                                      "not part of a scene or task definition"))
