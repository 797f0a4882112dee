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
from typing import Annotated, Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from luminous_sim.errors import LuminousError
from luminous_sim.limits import MAX_INPUT_BYTES, MAX_LAYOUT_OBJECTS
from luminous_sim.rooms.shell import FixturePlan, RoomType

LAYOUT_FORMAT: Final = "luminous-layout/1"
"""The value of every layout file's `format` key (the `/1` is the format's version)."""

Finite = Annotated[float, Field(allow_inf_nan=False)]
Positive = Annotated[float, Field(gt=0, allow_inf_nan=False)]
Vec2 = tuple[Finite, Finite]
Vec3 = tuple[Finite, Finite, Finite]


class LayoutError(LuminousError):
    """A layout file (or an input to an importer) that cannot be read: the message names the file and field."""


class _Model(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class LayoutDoor(_Model):
    """A door opening on outline edge `wall`, `offset` metres from the edge's start; it swings into the room."""

    id: str | None = Field(default=None, description="default: Door_<i>")
    wall: int = Field(ge=0, description="index of the outline edge (from outline[i] to outline[i+1])")
    offset: Finite = Field(ge=0, description="start of the opening along the edge, metres")
    width: Finite = Field(gt=0.5, le=2.0)
    height: Finite = Field(default=2.1, gt=1.5, le=3.0)
    swing_clearance: Finite = Field(default=0.9, ge=0, description="depth into the room that must stay free")
    hinge: Literal["start", "end"] = "start"


class LayoutWindow(_Model):
    """A window opening on outline edge `wall`: wall below `sill_height` and above `sill_height + height`."""

    id: str | None = Field(default=None, description="default: Window_<i>")
    wall: int = Field(ge=0)
    offset: Finite = Field(ge=0)
    width: Positive
    sill_height: Positive = 0.9
    height: Positive = 1.2


class LayoutZone(_Model):
    """A named part of the floor (a kitchen's work and dining zones)."""

    name: str
    polygon: tuple[Vec2, ...] = Field(min_length=3)


class LayoutRoom(_Model):
    """The room: its type, floor outline, walls' height and thickness, doors and windows.

    `fixture_plan` (a `luminous-room/1` fixture plan) and `zones` are kept for Luminous rooms; other
    layouts give their fixtures as objects and leave them out.
    """

    name: str = Field(pattern=r"^[A-Za-z0-9_\-]+$")
    room_type: RoomType
    outline: tuple[Vec2, ...] = Field(min_length=3, description="counter-clockwise, metres")
    wall_height: Finite = Field(default=2.6, ge=2.0, le=4.0)
    wall_thickness: Finite = Field(default=0.1, ge=0.05, le=0.5)
    doors: tuple[LayoutDoor, ...] = ()
    windows: tuple[LayoutWindow, ...] = ()
    zones: tuple[LayoutZone, ...] = ()
    shape: Literal["rect", "L", "two_zone", "rectilinear", "polygon"] | None = None
    """None: inferred from the outline."""
    fixture_plan: FixturePlan | None = None
    source: str = ""


class LayoutObject(_Model):
    """One object: a category, an oriented box, and optionally what supports it."""

    id: str = Field(min_length=1, description="unique within the layout")
    category: str = Field(min_length=1, description="an ALFRED object type, or the source method's class label")
    size: tuple[Positive, Positive, Positive] = Field(description="width (own x), depth (own y), height; metres")
    position: Vec3 = Field(description="centre of the bounding box, metres")
    yaw: Finite = Field(default=0.0, description="radians about z; the front faces the object's own +y")
    parent: str | None = Field(default=None, description="id of the object it stands on or in")
    region: str | None = Field(default=None, description="the parent's region (a shelf, a drawer)")
    asset: str | None = Field(default=None, description="catalog asset id (else matched by category and size)")
    scale: Positive | None = Field(default=None, description="uniform scale of `asset`")
    layer: Literal["structure", "fixture", "furniture", "object", "decoration"] | None = None
    fixed: bool | None = None
    name: str | None = None
    states: dict[str, bool] = Field(default_factory=dict)
    color: tuple[Finite, Finite, Finite] | None = None
    color_seed: int | None = None


class Provenance(_Model):
    """What made the layout: a method name, its seed, the input it came from, free-form notes."""

    generator: str = "unknown"
    seed: int = 0
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
        known = set(ids)
        for i, o in enumerate(self.objects):
            if o.parent is not None and o.parent not in known:
                raise ValueError(f"objects[{i}] ({o.id}): parent {o.parent!r} is not an object of the layout")
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
        from luminous_sim.assets.objio import write_atomic

        write_atomic(Path(path), self.to_json())


def _where(loc: tuple[Any, ...]) -> str:
    return ".".join(f"[{p}]" if isinstance(p, int) else str(p) for p in loc).replace(".[", "[") or "(top level)"


def loads(text: str, where: str = "layout") -> Layout:
    """A layout from JSON text; LayoutError names `where` and the first bad field."""
    try:
        data = json.loads(text)
    except ValueError as exc:
        raise LayoutError(f"{where}: not JSON ({exc})") from None
    return from_data(data, where)


def from_data(data: Any, where: str = "layout") -> Layout:
    """A layout from parsed JSON; LayoutError names `where` and each bad field."""
    if isinstance(data, dict) and data.get("format", LAYOUT_FORMAT) != LAYOUT_FORMAT:
        raise LayoutError(f"{where}: format: expected {LAYOUT_FORMAT!r}, got {data.get('format')!r}")
    objects = data.get("objects") if isinstance(data, dict) else None
    if isinstance(objects, list) and len(objects) > MAX_LAYOUT_OBJECTS:
        raise LayoutError(f"{where}: objects: {len(objects)} objects; a layout may hold at most {MAX_LAYOUT_OBJECTS} "
                          "(luminous_sim.limits.MAX_LAYOUT_OBJECTS)")
    try:
        return Layout.model_validate(data)
    except ValidationError as exc:
        problems = "; ".join(f"{_where(e['loc'])}: {e['msg']}" for e in exc.errors()[:5])
        raise LayoutError(f"{where}: {problems}") from None


def load(path: Path) -> Layout:
    """A layout file; LayoutError names the file and field."""
    path = Path(path)
    if not path.exists():
        raise LayoutError(f"{path}: no such layout file")
    if path.is_dir():
        raise LayoutError(f"{path}: a folder; expected a layout file")
    if not path.is_file():
        raise LayoutError(f"{path}: not a regular file (a device or a pipe?); expected a layout file")
    size = path.stat().st_size
    if size > MAX_INPUT_BYTES:
        raise LayoutError(f"{path}: {size} bytes; a layout file may hold at most {MAX_INPUT_BYTES} "
                          "(luminous_sim.limits.MAX_INPUT_BYTES)")
    return loads(path.read_text(encoding="utf-8"), where=str(path))
