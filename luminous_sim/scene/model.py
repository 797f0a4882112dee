"""A generated scene: the room shell and every object with its asset, pose, support and state.

Serialised as deterministic JSON (sorted keys, rounded floats) so that the same CDF, room and seed
give byte-identical files.

Every scene is checked where it is made or read, by one set of rules (`SceneError` when one fails): numbers
finite and within `luminous_sim.limits`' bounds (coordinates, yaw, scale, colour, seeds), text fields of a
bounded length, states among `SCENE_STATES`, at most `MAX_SCENE_OBJECTS` objects with unique ids whose parents
are present and form no cycle, a room within `MAX_SCENE_SIDE_M`. A scene file is read strictly (a number
given as text, a flag as 0/1 are refused); `check_scene` checks a `Scene` that was copied or built without
validation (`model_copy`, `model_construct`).
"""

from __future__ import annotations

import hashlib
import json
import math
import warnings
from collections.abc import Iterator, Mapping
from functools import partial
from pathlib import Path
from typing import Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator
from shapely.errors import ShapelyError

from luminous_sim.errors import LuminousError, read_file_bytes
from luminous_sim.fileio import one_line, shown
from luminous_sim.limits import (
    MAX_INPUT_BYTES,
    MAX_LAYOUT_COORDINATE_M,
    MAX_SCENE_ID_CHARS,
    MAX_SCENE_OBJECTS,
    MAX_SCENE_SCALE,
    MAX_SCENE_SIDE_M,
    MAX_SCENE_YAW_RAD,
    MIN_SCENE_SCALE,
)
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.vocab import ALL_TYPES

SCENE_FORMAT: Final = "luminous-scene/1"
Layer = Literal["structure", "fixture", "furniture", "object", "decoration"]
SCENE_STATES: Final[tuple[str, ...]] = ("isOpen", "isToggled", "isDirty", "isSliced", "isHot", "isCold", "isFilled")
"""The initial states a scene object may set (the CDF's initial-state flags, `cdf.ObjectStateSpec`)."""
MAX_SEED: Final = 2**63 - 1
"""Largest scene seed and colour seed (what `luminous generate --seed` takes)."""
KEY_HEX: Final = 20
"""Hex digits of the sha256 a scene's content key keeps (80 bits, as `benchmark.episode_key`)."""


class SceneError(LuminousError):
    """A scene whose values are wrong; the message names the file (or where the scene came from), the object
    id and the field, what was expected and what was given.

    Attributes:
        where: the file or source ("" when raised while a scene is built in code).
        object_id: the object's id ("" for a field of the scene itself).
        field: the field (`position`, `parent`, `room.outline[0][1]`, ...).
        problem: what was expected and what was given.
    """

    def __init__(self, problem: str, *, where: str = "", object_id: str = "", field: str = ""):
        self.where, self.object_id, self.field, self.problem = where, object_id, field, problem
        what = f"object {object_id!r}: " if object_id else ""
        head = where or ("scene" if object_id or field else "")  # neither: `problem` is the whole message
        super().__init__(f"{head + ': ' if head else ''}{what}{field + ': ' if field else ''}{problem}")

    def at(self, where: str) -> SceneError:
        """The same error, said of `where` (a file)."""
        if not (self.object_id or self.field or self.where):
            return SceneError(f"{where}: {self.problem}")
        return SceneError(self.problem, where=where, object_id=self.object_id, field=self.field)


ROOM_MARGIN_M = 1.0
"""How far outside its room's floor box (and below the floor, above the ceiling) an object's origin may lie."""


_show = partial(shown, limit=60)

def _number(v: Any) -> bool:
    return isinstance(v, int | float) and not isinstance(v, bool)


def _finite_within(v: Any, bound: float) -> bool:
    return _number(v) and math.isfinite(v) and abs(v) <= bound


def _text_problem(v: Any, optional: bool = False) -> str | None:
    if v is None and optional:
        return None
    if not isinstance(v, str) or not 1 <= len(v) <= MAX_SCENE_ID_CHARS:
        return f"expected {'null or ' if optional else ''}text of 1 to {MAX_SCENE_ID_CHARS} characters, got {_show(v)}"
    return None


def _field_problem(name: str, v: Any) -> str | None:
    """What is wrong with an object's field `name` of value `v` (None: nothing), kinds checked strictly."""
    if name == "type":
        if isinstance(v, str) and v not in ALL_TYPES:
            return f"unknown object type {_show(v)}; expected an ALFRED object type"
        return _text_problem(v)
    if name in ("id", "asset"):
        return _text_problem(v)
    if name in ("parent", "region", "name"):
        return _text_problem(v, optional=True)
    if name == "position":
        if not (isinstance(v, list | tuple) and len(v) == 3
                and all(_finite_within(c, MAX_LAYOUT_COORDINATE_M) for c in v)):
            return (f"expected 3 finite numbers within +-{MAX_LAYOUT_COORDINATE_M:g} m "
                    f"(luminous_sim.limits.MAX_LAYOUT_COORDINATE_M), got {_show(v)}")
    elif name == "yaw":
        if not _finite_within(v, MAX_SCENE_YAW_RAD):
            return (f"expected a finite number of radians within +-{MAX_SCENE_YAW_RAD:g} "
                    f"(luminous_sim.limits.MAX_SCENE_YAW_RAD), got {_show(v)}")
    elif name == "scale":
        if not (_number(v) and math.isfinite(v) and MIN_SCENE_SCALE <= v <= MAX_SCENE_SCALE):
            return (f"expected a number in {MIN_SCENE_SCALE:g}..{MAX_SCENE_SCALE:g} (luminous_sim.limits."
                    f"MIN_SCENE_SCALE, MAX_SCENE_SCALE), got {_show(v)}")
    elif name == "color":
        if v is not None and not (isinstance(v, list | tuple) and len(v) == 3
                                  and all(_number(c) and 0.0 <= c <= 1.0 for c in v)):
            return f"expected null or 3 numbers in 0..1 (RGB), got {_show(v)}"
    elif name == "color_seed":
        if not (isinstance(v, int) and not isinstance(v, bool) and 0 <= v <= MAX_SEED):
            return f"expected a whole number in 0..2**63-1, got {_show(v)}"
    elif name == "fixed":
        if not isinstance(v, bool):
            return f"expected true or false, got {_show(v)}"
    elif name == "states":
        if not isinstance(v, Mapping):
            return f"expected an object of states ({', '.join(SCENE_STATES)}), got {_show(v)}"
        for key, flag in v.items():
            if key not in SCENE_STATES:
                return f"unknown state {_show(key)}; expected some of {', '.join(SCENE_STATES)}"
            if not isinstance(flag, bool):
                return f"{key}: expected true or false, got {_show(flag)}"
    elif name == "layer":
        if v not in ("structure", "fixture", "furniture", "object", "decoration"):
            return f"expected one of structure, fixture, furniture, object, decoration, got {_show(v)}"
    return None


OBJECT_FIELDS: Final = ("id", "type", "asset", "position", "yaw", "layer", "fixed", "parent", "region", "name",
                        "states", "color_seed", "scale", "color")


def _numbers(value: Any, path: str) -> Iterator[tuple[str, Any]]:
    """Every number in plain data with its key path (`outline[0][1]`)."""
    stack = [(path, value)]
    while stack:
        where, v = stack.pop()
        if isinstance(v, Mapping):
            stack.extend((f"{where}.{k}", x) for k, x in v.items())
        elif isinstance(v, list | tuple):
            stack.extend((f"{where}[{i}]", x) for i, x in enumerate(v))
        elif _number(v):
            yield where, v


def _check_room_numbers(room: Any) -> None:
    """A room's raw numbers finite and within the coordinate bound (before shapely sees them: a NaN
    vertex makes it raise, not report)."""
    for where, v in _numbers(room, "room"):
        if not _finite_within(v, MAX_LAYOUT_COORDINATE_M):
            raise SceneError(f"expected a finite number within +-{MAX_LAYOUT_COORDINATE_M:g} "
                             f"(luminous_sim.limits.MAX_LAYOUT_COORDINATE_M), got {_show(v)}", field=where)


def _check_seed(seed: Any) -> None:
    if _number(seed) and not 0 <= seed <= MAX_SEED:
        raise SceneError(f"expected a whole number in 0..2**63-1, got {_show(seed)}", field="seed")


def _check_raw(data: Mapping[str, Any]) -> None:
    """What a scene file's plain data is checked for before it is built: the object count (so that a huge
    file is not built first), the room's numbers (so that shapely never sees a NaN) and the seed."""
    objects = data.get("objects")
    if isinstance(objects, list) and len(objects) > MAX_SCENE_OBJECTS:
        raise SceneError(f"{len(objects)} objects; a scene may hold at most {MAX_SCENE_OBJECTS} "
                         "(luminous_sim.limits.MAX_SCENE_OBJECTS)", field="objects")
    _check_room_numbers(data.get("room"))
    _check_seed(data.get("seed"))


def _check_objects(objects: Any) -> None:
    """The scene-wide rules: the object count, unique ids, parents present and acyclic."""
    if len(objects) > MAX_SCENE_OBJECTS:
        raise SceneError(f"{len(objects)} objects; a scene may hold at most {MAX_SCENE_OBJECTS} "
                         "(luminous_sim.limits.MAX_SCENE_OBJECTS)", field="objects")
    parents: dict[str, str | None] = {}
    for o in objects:
        if o.id in parents:
            raise SceneError("duplicate id; expected each object's id to be unique", object_id=o.id, field="id")
        parents[o.id] = o.parent
    for oid, parent in parents.items():
        if parent is None:
            continue
        if parent == oid:
            raise SceneError("the object is its own parent", object_id=oid, field="parent")
        if parent not in parents:
            raise SceneError(f"no object {parent!r} in the scene; expected the id of the object it rests on or in",
                             object_id=oid, field="parent")
    done: set[str] = set()
    for oid in parents:
        chain: list[str] = []
        at: str | None = oid
        while at is not None and at not in done:
            if at in chain:
                raise SceneError(f"parents form a cycle ({' -> '.join(chain[chain.index(at):] + [at])})",
                                 object_id=oid, field="parent")
            chain.append(at)
            at = parents[at]
        done.update(chain)


def auto_name(object_type: str, index: int) -> str:
    """The name the generator gives the `index`-th object of a type that the CDF did not ask for."""
    return f"{object_type.lower()}_auto{index}"


def _r(x: float, digits: int = 4) -> float:
    return round(float(x), digits) + 0.0


class SceneObject(BaseModel):
    """One object instance.

    `position` is the asset's base-frame origin in the world (its bottom centre), `yaw` its heading in
    radians about z (the asset's front, +y, turned by yaw). `parent` is the object it rests on or in,
    with the parent's `region`. `states` holds ALFRED-style states (isOpen, isToggled, isDirty, ...).
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    id: str
    type: str
    asset: str
    position: tuple[float, float, float]
    yaw: float = 0.0
    layer: Layer
    fixed: bool = False
    parent: str | None = None
    region: str | None = None
    name: str | None = None
    states: dict[str, bool] = Field(default_factory=dict)
    color_seed: int = 0
    scale: float = 1.0
    color: tuple[float, float, float] | None = None
    """A CDF colour for the object's main material slot (else drawn from the palette by color_seed)."""

    @property
    def cdf_name(self) -> str | None:
        """The instance name the CDF gave it (`mug`, `chair#2`); None when unnamed or named by the generator."""
        prefix = auto_name(self.type, 0).removesuffix("0")
        if self.name is None or (self.name.startswith(prefix) and self.name[len(prefix):].isdigit()):
            return None
        return self.name

    @field_validator("position")
    @classmethod
    def _round_position(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        if not all(math.isfinite(c) for c in v):  # rounding keeps NaN, inf; the check below names them
            return v
        return (_r(v[0]), _r(v[1]), _r(v[2]))

    @field_validator("yaw")
    @classmethod
    def _round_yaw(cls, v: float) -> float:
        return _r(v, 5) if math.isfinite(v) else v

    @model_validator(mode="after")
    def _check_values(self) -> SceneObject:
        # SceneError is no ValueError, so pydantic passes it on as it is: a one-line LuminousError naming the
        # object and the field wherever a scene is built (a file, the generator, an importer)
        oid = self.id if isinstance(self.id, str) else ""
        for name in OBJECT_FIELDS:
            problem = _field_problem(name, getattr(self, name))
            if problem is not None:
                raise SceneError(problem, object_id=oid, field=name)
        return self


class Scene(BaseModel):
    """A complete scene: room structure, objects, and how it was made."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    format: Literal["luminous-scene/1"] = SCENE_FORMAT
    room: RoomShell
    seed: int
    generator: str
    objects: tuple[SceneObject, ...]
    source: str = ""
    notes: dict[str, Any] = Field(default_factory=dict)

    @model_validator(mode="after")
    def _check_scene(self) -> Scene:
        _check_seed(self.seed)
        _check_objects(self.objects)
        x0, y0, x1, y1 = self.room.bounds
        if max(x1 - x0, y1 - y0) > MAX_SCENE_SIDE_M:
            raise SceneError(f"the floor spans {x1 - x0:g} x {y1 - y0:g} m; a scene's room may span at most "
                             f"{MAX_SCENE_SIDE_M:g} m (luminous_sim.limits.MAX_SCENE_SIDE_M)", field="room.outline")
        top = float(self.room.wall_height) + ROOM_MARGIN_M
        for o in self.objects:
            x, y, z = o.position
            if not (x0 - ROOM_MARGIN_M <= x <= x1 + ROOM_MARGIN_M and y0 - ROOM_MARGIN_M <= y <= y1 + ROOM_MARGIN_M
                    and -ROOM_MARGIN_M <= z <= top):
                raise SceneError(f"expected a place in its room (x {x0:g}..{x1:g}, y {y0:g}..{y1:g}, z 0..{top - 1:g} "
                                 f"m, give or take {ROOM_MARGIN_M:g} m), got ({x:g}, {y:g}, {z:g})", object_id=o.id,
                                 field="position")
        return self

    def content_key(self) -> str:
        """The scene's content key: a digest of its canonical JSON (`to_json`), the same for the same scene
        however it was made (an episode's trajectory.json records it as `scene_key`)."""
        return hashlib.sha256(self.to_json().encode()).hexdigest()[:KEY_HEX]

    def object(self, object_id: str) -> SceneObject:
        for o in self.objects:
            if o.id == object_id:
                return o
        raise KeyError(object_id)

    def of_type(self, object_type: str) -> list[SceneObject]:
        return [o for o in self.objects if o.type == object_type]

    def children(self, parent_id: str) -> list[SceneObject]:
        return [o for o in self.objects if o.parent == parent_id]

    def to_json(self) -> str:
        """Deterministic JSON text."""
        return json.dumps(self.model_dump(mode="json"), indent=1, sort_keys=True) + "\n"

    @classmethod
    def from_json(cls, text: str, where: str = "scene") -> Scene:
        """A scene from its JSON text, read strictly (a number must be a number, a flag true or false) and
        checked (the module's rules).

        Raises:
            SceneError: one line naming `where`: not JSON, or the first field that is wrong (with the object's id).
        """
        try:
            data = json.loads(text)
        except RecursionError:
            raise SceneError("not a valid scene file (nested too deeply)", where=where) from None
        except ValueError as exc:
            raise SceneError(f"not a valid scene file (not JSON: {exc})", where=where) from None
        if not isinstance(data, dict):
            raise SceneError(f"not a valid scene file (expected a JSON object, got {type(data).__name__})",
                             where=where)
        try:
            _check_raw(data)
            # strict: a number given as text, a flag as 0/1 are refused, not converted (JSON mode keeps arrays
            # valid for tuples; no validator here runs before the fields, which would turn that off)
            return cls.model_validate_json(text, strict=True)
        except SceneError as exc:
            raise exc.at(where) from None
        except ValidationError as exc:
            errors = exc.errors(include_url=False)
            shown = "; ".join(f"{_path(e['loc'], data)}: {e['msg']}" for e in errors[:3])
            more = f" (and {len(errors) - 3} more)" if len(errors) > 3 else ""
            raise SceneError(f"not a valid scene file ({shown}{more})", where=where) from None
        except (ValueError, ShapelyError) as exc:
            raise SceneError(f"not a valid scene file ({' '.join(str(exc).split())})", where=where) from None

    def save(self, path: Path) -> None:
        """Write the scene file (atomically), after checking it (`check_scene`): a scene the readers would
        refuse is never written.

        Raises:
            SceneError: the scene breaks a rule (naming `path`, the object and the field).
        """
        from luminous_sim.fileio import write_atomic

        check_scene(self, str(path))
        write_atomic(Path(path), self.to_json())

    @classmethod
    def load(cls, path: Path) -> Scene:
        """A scene file (`scene.json`): a regular file within `limits.MAX_INPUT_BYTES`.

        Raises:
            LuminousError: one line naming the file: missing, a folder, a device or a FIFO, too large, not UTF-8,
                or not a valid scene.
        """
        path = Path(path)
        raw = read_file_bytes(path, MAX_INPUT_BYTES, "a scene file (scene.json; luminous_sim.limits.MAX_INPUT_BYTES)",
                              SceneError, follow_links=True)
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise SceneError(f"not UTF-8 text ({exc.reason} at byte {exc.start})", where=str(path)) from None
        return cls.from_json(text, where=str(path))


def check_scene(scene: Scene, where: str = "scene") -> Scene:
    """`scene` checked by the rules a scene file is read by (for a `Scene` copied or built without validation:
    `model_copy`, `model_construct`, or handed in by a caller); returns it.

    Raises:
        SceneError: not a Scene, or a rule broken (naming `where`, the object and the field).
    """
    if not isinstance(scene, Scene):
        raise SceneError(f"expected a luminous_sim.scene.Scene, got {type(scene).__name__}", where=where)
    try:
        with warnings.catch_warnings():  # a value of the wrong kind: refused below, not warned about
            warnings.simplefilter("ignore")
            text = scene.to_json()
    except (ValueError, TypeError) as exc:  # a field of a kind JSON cannot hold
        raise SceneError(f"not a valid scene ({one_line(str(exc), 200)})", where=where) from None
    Scene.from_json(text, where)
    return scene



def _path(loc: tuple[Any, ...], data: Any = None) -> str:
    """A pydantic error location as a key path, with the object's id after `objects[i]` when it has one."""
    out = ""
    for i, p in enumerate(loc):
        out += f"[{p}]" if isinstance(p, int) else f".{p}"
        if i == 1 and loc[0] == "objects" and isinstance(p, int) and isinstance(data, dict):
            objects = data.get("objects")
            item = objects[p] if isinstance(objects, list) and 0 <= p < len(objects) else None
            if isinstance(item, dict) and isinstance(item.get("id"), str):
                out += f" (id {item['id'][:MAX_SCENE_ID_CHARS]!r})"
    return out.lstrip(".") or "(top level)"
