"""The one layout format (`luminous-layout/1`): a furnished room as any scene-synthesis method can write it.

Coordinates: metres, z up, the floor at z = 0, the room outline counter-clockwise seen from above. An
object is an oriented box: `position` is the centre of its bounding box, `size` its extents (width along
its own x, depth along its own y, height), `yaw` the turn about z (radians) of its front, which faces its
own +y. Doors and windows sit on outline edges (`wall` i runs from outline[i] to outline[i+1]).
The optional fields `asset`, `scale` and those after them let a Luminous scene pass through unchanged;
a layout from elsewhere leaves them out and is matched to the asset catalog by category and size.
"""

from __future__ import annotations

import json
from collections import Counter
from pathlib import Path
from typing import Annotated, Any, Final, Literal, get_args

from pydantic import BaseModel, ConfigDict, Field, StrictBool, StrictInt, ValidationError, model_validator

from luminous_sim.cdf.issues import from_validation_error
from luminous_sim.layouts.inputs import MAX_ANGLE, LayoutError, read_json
from luminous_sim.limits import (
    MAX_LAYOUT_COORDINATE_M,
    MAX_LAYOUT_OBJECTS,
    MAX_LAYOUT_ROOM_SIDE_M,
    MAX_LAYOUT_SIDE_M,
)
from luminous_sim.rooms.shell import FixturePlan, RoomType

__all__ = [
    "LAYOUT_FORMAT",
    "STATE_KEYS",
    "Layout",
    "LayoutDoor",
    "LayoutError",
    "LayoutObject",
    "LayoutRoom",
    "LayoutWindow",
    "LayoutZone",
    "Provenance",
    "from_data",
    "load",
    "loads",
    "problems",
    "room_problem",
]

LAYOUT_FORMAT: Final = "luminous-layout/1"
"""The value of every layout file's `format` key (the `/1` is the format's version)."""

Finite = Annotated[float, Field(strict=True, allow_inf_nan=False)]
Coordinate = Annotated[float, Field(strict=True, allow_inf_nan=False, ge=-MAX_LAYOUT_COORDINATE_M,
                                    le=MAX_LAYOUT_COORDINATE_M)]
Positive = Annotated[float, Field(strict=True, gt=0, allow_inf_nan=False)]
Side = Annotated[float, Field(strict=True, gt=0, le=MAX_LAYOUT_SIDE_M, allow_inf_nan=False)]
Angle = Annotated[float, Field(strict=True, ge=-MAX_ANGLE, le=MAX_ANGLE, allow_inf_nan=False)]
Unit = Annotated[float, Field(strict=True, ge=0, le=1, allow_inf_nan=False)]
Id = Annotated[str, Field(min_length=1, max_length=256)]
Vec2 = tuple[Coordinate, Coordinate]
Vec3 = tuple[Coordinate, Coordinate, Coordinate]
StateKey = Literal["isOpen", "isToggled", "isDirty", "isSliced", "isHot", "isCold", "isFilled"]
STATE_KEYS: Final[tuple[str, ...]] = get_args(StateKey)
"""The object states a layout may set: the CDF's initial-state flags (`cdf.ObjectStateSpec`)."""


class _Model(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class LayoutDoor(_Model):
    """A door opening on outline edge `wall`, `offset` metres from the edge's start; it swings into the room."""

    id: Id | None = Field(default=None, description="default: Door_<i>")
    wall: StrictInt = Field(ge=0, description="index of the outline edge (from outline[i] to outline[i+1])")
    offset: Finite = Field(ge=0, le=MAX_LAYOUT_ROOM_SIDE_M, description="start of the opening along the edge, metres")
    width: Finite = Field(gt=0.5, le=2.0)
    height: Finite = Field(default=2.1, gt=1.5, le=3.0)
    swing_clearance: Finite = Field(default=0.9, ge=0, description="depth into the room that must stay free")
    hinge: Literal["start", "end"] = "start"


class LayoutWindow(_Model):
    """A window opening on outline edge `wall`: wall below `sill_height` and above `sill_height + height`."""

    id: Id | None = Field(default=None, description="default: Window_<i>")
    wall: StrictInt = Field(ge=0)
    offset: Finite = Field(ge=0, le=MAX_LAYOUT_ROOM_SIDE_M)
    width: Side
    sill_height: Side = 0.9
    height: Side = 1.2


class LayoutZone(_Model):
    """A named part of the floor (a kitchen's work and dining zones)."""

    name: Id
    polygon: tuple[Vec2, ...] = Field(min_length=3, max_length=1_000)


class LayoutRoom(_Model):
    """The room: its type, floor outline, walls' height and thickness, doors and windows.

    `fixture_plan` (a `luminous-room/1` fixture plan) and `zones` are kept for Luminous rooms; other
    layouts give their fixtures as objects and leave them out.
    """

    name: str = Field(pattern=r"^[A-Za-z0-9_\-]+$", max_length=256)
    room_type: RoomType
    outline: tuple[Vec2, ...] = Field(min_length=3, max_length=1_000, description="counter-clockwise, metres")
    wall_height: Finite = Field(default=2.6, ge=2.0, le=4.0)
    wall_thickness: Finite = Field(default=0.1, ge=0.05, le=0.5)
    doors: tuple[LayoutDoor, ...] = ()
    windows: tuple[LayoutWindow, ...] = ()
    zones: tuple[LayoutZone, ...] = ()
    shape: Literal["rect", "L", "two_zone", "rectilinear", "polygon"] | None = None
    """None: inferred from the outline."""
    fixture_plan: FixturePlan | None = None
    source: str = ""

    @model_validator(mode="after")
    def _extent(self) -> LayoutRoom:
        for axis, name in ((0, "x"), (1, "y")):
            values = [p[axis] for p in self.outline]
            if max(values) - min(values) > MAX_LAYOUT_ROOM_SIDE_M:
                raise ValueError(f"outline: spans {max(values) - min(values):g} m along {name}; a room may span "
                                 f"at most {MAX_LAYOUT_ROOM_SIDE_M:g} m (luminous_sim.limits.MAX_LAYOUT_ROOM_SIDE_M)")
        return self


class LayoutObject(_Model):
    """One object: a category, an oriented box, and optionally what supports it."""

    id: Id = Field(description="unique within the layout")
    category: Id = Field(description="an ALFRED object type, or the source method's class label")
    size: tuple[Side, Side, Side] = Field(description="width (own x), depth (own y), height; metres")
    position: Vec3 = Field(description="centre of the bounding box, metres")
    yaw: Angle = Field(default=0.0, description="radians about z; the front faces the object's own +y")
    parent: Id | None = Field(default=None, description="id of the object it stands on or in")
    region: Id | None = Field(default=None, description="the parent's region (a shelf, a drawer)")
    asset: Id | None = Field(default=None, description="catalog asset id (else matched by category and size)")
    scale: Annotated[float, Field(strict=True, gt=0, le=100, allow_inf_nan=False)] | None = Field(
        default=None, description="uniform scale of `asset`")
    layer: Literal["structure", "fixture", "furniture", "object", "decoration"] | None = None
    fixed: StrictBool | None = None
    name: Id | None = None
    states: dict[StateKey, StrictBool] = Field(default_factory=dict, description="initial object states")
    color: tuple[Unit, Unit, Unit] | None = Field(default=None, description="RGB, each 0..1")
    color_seed: StrictInt | None = Field(default=None, ge=0)

    @model_validator(mode="after")
    def _states_fit(self) -> LayoutObject:
        if not self.states:
            return self
        from luminous_sim.cdf.affordances import has_ability
        from luminous_sim.cdf.validate import STATE_ABILITY
        from luminous_sim.vocab import ALL_TYPES

        if self.category not in ALL_TYPES:
            raise ValueError(f"states: {self.category!r} is not an ALFRED object type; expected states only on "
                             "objects whose category is one (their abilities say which states apply)")
        for key, value in self.states.items():
            ability = STATE_ABILITY[key]
            if value and not has_ability(self.category, ability):
                raise ValueError(f"states.{key}: {self.category} is not {ability}; expected {key} only on "
                                 f"{ability} types")
        return self


class Provenance(_Model):
    """What made the layout: a method name, its seed, the input it came from, free-form notes."""

    generator: str = "unknown"
    seed: StrictInt = Field(default=0, ge=0)
    source: str = ""
    notes: dict[str, Any] = Field(default_factory=dict)


class Layout(_Model):
    """A furnished room in the one layout format."""

    format: Literal["luminous-layout/1"] = LAYOUT_FORMAT
    room: LayoutRoom
    objects: tuple[LayoutObject, ...] = ()
    provenance: Provenance = Provenance()

    @model_validator(mode="after")
    def _check_refs(self) -> Layout:
        ids = [o.id for o in self.objects]
        dup = sorted(i for i, n in Counter(ids).items() if n > 1)
        if dup:
            raise ValueError(f"objects: duplicate ids {', '.join(dup)}")
        index = {o.id: i for i, o in enumerate(self.objects)}
        for i, o in enumerate(self.objects):
            if o.parent is not None and o.parent not in index:
                raise ValueError(f"objects[{i}] ({o.id}): parent {o.parent!r} is not an object of the layout")
            if o.region is not None and o.parent is None:
                raise ValueError(f"objects[{i}] ({o.id}): region {o.region!r} without a parent; expected a parent "
                                 "whose region it is")
        for i, o in enumerate(self.objects):
            seen = {o.id}
            up = o.parent
            while up is not None:
                if up in seen:
                    raise ValueError(f"objects[{i}] ({o.id}): parent {o.parent!r} leads back to {up!r}; expected "
                                     "parents that end at an object standing on the floor")
                seen.add(up)
                up = self.objects[index[up]].parent
        n = len(self.room.outline)
        openings: list[tuple[str, int, int]] = [("doors", i, d.wall) for i, d in enumerate(self.room.doors)]
        openings += [("windows", i, w.wall) for i, w in enumerate(self.room.windows)]
        for kind, i, wall in openings:
            if wall >= n:
                raise ValueError(f"room.{kind}[{i}]: wall {wall} is not an outline edge (0..{n - 1})")
        return self

    def to_json(self) -> str:
        """Deterministic JSON text (sorted keys)."""
        return json.dumps(self.model_dump(mode="json", exclude_none=True), indent=1, sort_keys=True) + "\n"

    def save(self, path: Path) -> None:
        from luminous_sim.fileio import write_atomic

        write_atomic(Path(path), self.to_json())


MAX_REPORTED = 5
"""Problems named in one error line; the rest are counted."""


def problems(exc: ValidationError, where: str) -> LayoutError:
    """One line naming `where` and the first MAX_REPORTED problems pydantic found in a layout."""
    issues = from_validation_error(exc, where, Layout).issues
    text = "; ".join(f"{i.path}: {i.message}" if i.path else i.message for i in issues[:MAX_REPORTED])
    more = f" (and {len(issues) - MAX_REPORTED} more)" if len(issues) > MAX_REPORTED else ""
    return LayoutError(f"{where}: {text}{more}")


def room_problem(exc: ValidationError) -> str:
    """What is wrong with a LayoutRoom an importer built (its first problem, without pydantic's prefix)."""
    err = exc.errors(include_url=False)[0]
    where = ".".join(str(p) for p in err["loc"])
    msg = err["msg"].removeprefix("Value error, ")
    return f"{where}: {msg}" if where else msg


def loads(text: str, where: str = "layout") -> Layout:
    """A layout from JSON text; LayoutError names `where` and the first bad fields."""
    try:
        data = json.loads(text)
    except RecursionError:
        raise LayoutError(f"{where}: not JSON (nested too deeply)") from None
    except ValueError as exc:
        raise LayoutError(f"{where}: not JSON ({exc})") from None
    return from_data(data, where)


def from_data(data: Any, where: str = "layout") -> Layout:
    """A layout from parsed JSON; LayoutError names `where` and each bad field (one line)."""
    if not isinstance(data, dict):
        raise LayoutError(f"{where}: expected a JSON object (a luminous-layout/1 layout), got {type(data).__name__}")
    if data.get("format", LAYOUT_FORMAT) != LAYOUT_FORMAT:
        raise LayoutError(f"{where}: format: expected {LAYOUT_FORMAT!r}, got {data.get('format')!r}")
    objects = data.get("objects")
    if isinstance(objects, list) and len(objects) > MAX_LAYOUT_OBJECTS:
        raise LayoutError(f"{where}: objects: {len(objects)} objects; a layout may hold at most {MAX_LAYOUT_OBJECTS} "
                          "(luminous_sim.limits.MAX_LAYOUT_OBJECTS)")
    try:
        return Layout.model_validate(data)
    except ValidationError as exc:
        raise problems(exc, where) from None
    except RecursionError:
        raise LayoutError(f"{where}: nested too deeply") from None


def load(path: Path) -> Layout:
    """A layout file (a regular file within limits.MAX_INPUT_BYTES); LayoutError names the file and field."""
    return from_data(read_json(path, "a luminous-layout/1 JSON file"), str(path))
