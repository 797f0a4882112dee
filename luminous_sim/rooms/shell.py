"""The `RoomShell` model: a room's fixed structure (floor, walls, doors, windows, zones, fixtures).

Coordinates are the project's world frame: metres, x/y on the floor (z = 0), z up. The outline is
the inside face of the walls, counter-clockwise; wall `w<i>` runs from outline vertex i to vertex
i+1, so the room lies on its left and its inward normal is the direction turned 90 degrees left.
Walls are `wall_thickness` thick, outside the outline. Positions along a wall (`offset`, `start`,
`end`) are metres from the wall's start vertex.

Every float is rounded to 4 decimals when a model is built, so
`RoomShell.from_json(s.to_json()) == s` and `to_json` is byte-for-byte deterministic (sorted keys).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Annotated, Any, Final, Literal, Self

import numpy as np
import shapely
from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    SerializerFunctionWrapHandler,
    ValidationError,
    model_serializer,
    model_validator,
)
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from luminous_sim.errors import RoomError
from luminous_sim.rooms.geometry import EPS, canonical_ring, is_convex_vertex, r4, signed_area

FORMAT: Final = "luminous-room/1"
"""The value of every room file's `format` key."""

R4 = Annotated[float, AfterValidator(r4)]
Vec2 = tuple[R4, R4]
RoomType = Literal["Kitchen", "LivingRoom", "Bedroom", "Bathroom"]
Shape = Literal["rect", "L", "two_zone", "rectilinear", "polygon"]
SlotType = Literal["Sink", "StoveBurner", "Fridge", "Toilet", "Bathtub", "Shower"]
"""Fixture slot types: ALFRED object types, and `Shower`, a stall (ShowerGlass/ShowerDoor)."""
NAME_PATTERN = r"^[A-Za-z0-9_\-]+$"


class _Model(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")

    def model_copy(self, *, update: Mapping[str, Any] | None = None, deep: bool = False) -> Self:
        """A copy with some fields replaced (not validated again), without stale cached values."""
        copy = super().model_copy(update=update, deep=deep)
        for name in dir(type(copy)):
            if isinstance(getattr(type(copy), name, None), cached_property):
                copy.__dict__.pop(name, None)
        return copy


class Wall(_Model):
    """A straight wall whose inside face runs from `start` to `end`; the room is on its left."""

    id: str
    start: Vec2
    end: Vec2
    normal: Vec2 = Field(description="unit normal pointing into the room")

    @cached_property
    def length(self) -> float:
        """Length of the inside face, metres."""
        return math.dist(self.start, self.end)

    @cached_property
    def direction(self) -> tuple[float, float]:
        """Unit vector from start to end."""
        n = self.length
        return ((self.end[0] - self.start[0]) / n, (self.end[1] - self.start[1]) / n)

    @property
    def yaw(self) -> float:
        """Angle of `direction` from +x, radians."""
        d = self.direction
        return math.atan2(d[1], d[0])

    def point(self, u: float, v: float = 0.0) -> tuple[float, float]:
        """World (x, y) of the point `u` along the wall and `v` into the room."""
        d, n = self.direction, self.normal
        return (self.start[0] + d[0] * u + n[0] * v, self.start[1] + d[1] * u + n[1] * v)

    def local(self, points: Any) -> np.ndarray:
        """(u, v) wall coordinates (along, into the room) of world points, shape (N, 2)."""
        p = np.asarray(points, dtype=float).reshape(-1, 2) - np.asarray(self.start)
        return np.stack([p @ np.asarray(self.direction), p @ np.asarray(self.normal)], axis=1)

    def rect(self, u0: float, u1: float, v0: float, v1: float) -> Polygon:
        """The rectangle [u0, u1] along the wall by [v0, v1] into the room, as a world polygon."""
        pts = [self.point(u0, v0), self.point(u1, v0), self.point(u1, v1), self.point(u0, v1)]
        if self.normal[0] == 0.0 or self.normal[1] == 0.0:  # axis-aligned: the fast constructor
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            return shapely.box(min(xs), min(ys), max(xs), max(ys))
        return Polygon(pts)


class Door(_Model):
    """A door opening in a wall, open down to the floor; it swings into the room."""

    id: str
    wall: str
    offset: R4 = Field(ge=0, description="start of the opening along the wall")
    width: R4 = Field(gt=0.5, le=2.0)
    height: R4 = Field(gt=1.5, le=3.0)
    swing_clearance: R4 = Field(ge=0, description="depth into the room that must stay free")
    hinge: Literal["start", "end"] = "start"

    @property
    def span(self) -> tuple[float, float]:
        return (self.offset, self.offset + self.width)


class Window(_Model):
    """A window opening: wall remains below `sill_height` and above `sill_height + height`."""

    id: str
    wall: str
    offset: R4 = Field(ge=0)
    width: R4 = Field(gt=0)
    sill_height: R4 = Field(gt=0)
    height: R4 = Field(gt=0)

    @property
    def span(self) -> tuple[float, float]:
        return (self.offset, self.offset + self.width)


class Zone(_Model):
    """A named part of the floor (e.g. a kitchen's `work` and `dining` zones)."""

    name: str
    polygon: tuple[Vec2, ...]

    def shape(self) -> Polygon:
        return Polygon(self.polygon)


class CounterRun(_Model):
    """A CounterTop run against a wall, from `start` to `end` along it; cabinets, drawers below."""

    id: str
    wall: str
    start: R4 = Field(ge=0)
    end: R4 = Field(gt=0)
    depth: R4 = Field(default=0.6, gt=0)
    height: R4 = Field(default=0.9, gt=0)
    below: tuple[str, ...] = ("Cabinet", "Drawer")

    @property
    def span(self) -> tuple[float, float]:
        return (self.start, self.end)


class FixtureSlot(_Model):
    """A fixed appliance's place: `width` along the wall from `offset`, `depth` into the room.

    `counter` names the CounterRun that holds it (a sink or stove built into a counter), if any.
    """

    id: str
    type: SlotType
    wall: str
    offset: R4 = Field(ge=0)
    width: R4 = Field(gt=0)
    depth: R4 = Field(gt=0)
    height: R4 = Field(gt=0)
    counter: str | None = None

    @property
    def span(self) -> tuple[float, float]:
        return (self.offset, self.offset + self.width)


class FixturePlan(_Model):
    """Kitchen and bathroom fixtures, kept with the structure (as LUMINOUS does for those rooms)."""

    layout: Literal["none", "I", "L", "U", "galley", "other"] = "none"
    counters: tuple[CounterRun, ...] = ()
    slots: tuple[FixtureSlot, ...] = ()

    def slot(self, slot_type: str) -> FixtureSlot | None:
        """The first slot of a type, or None."""
        return next((s for s in self.slots if s.type == slot_type), None)


@dataclass(frozen=True)
class WallBox:
    """A solid box of wall for building: centre (x, y, z), size (along, thickness, height), yaw."""

    wall: str
    kind: Literal["solid", "lintel", "sill", "head"]
    center: tuple[float, float, float]
    size: tuple[float, float, float]
    yaw: float


def walls_from_outline(outline: Any) -> tuple[Wall, ...]:
    """Walls `w0..w<n-1>` along a counter-clockwise outline, each with its inward normal."""
    pts = [tuple(map(float, p)) for p in outline]
    walls = []
    for i, a in enumerate(pts):
        b = pts[(i + 1) % len(pts)]
        n = math.dist(a, b)
        walls.append(
            Wall(id=f"w{i}", start=a, end=b, normal=(-(b[1] - a[1]) / n, (b[0] - a[0]) / n))
        )
    return tuple(walls)


class HouseRoom(_Model):
    """One room of a house: its name, type and floor outline (inside its walls, counter-clockwise)."""

    name: str = Field(pattern=NAME_PATTERN)
    room_type: RoomType
    outline: tuple[Vec2, ...]

    def polygon(self) -> Polygon:
        return Polygon(self.outline)


class InteriorWall(_Model):
    """A wall inside a house, `thickness` thick about the centre line from `start` to `end`."""

    id: str
    start: Vec2
    end: Vec2

    @cached_property
    def wall(self) -> Wall:
        """The centre line as a Wall (its `point(u, v)` and `rect` are in metres along and across it)."""
        n = math.dist(self.start, self.end)
        d = ((self.end[0] - self.start[0]) / n, (self.end[1] - self.start[1]) / n)
        return Wall(id=self.id, start=self.start, end=self.end, normal=(-d[1], d[0]))


class HouseDoor(_Model):
    """A doorway in an interior wall, joining two rooms; open down to the floor."""

    id: str
    wall: str
    offset: R4 = Field(ge=0, description="start of the opening along the wall")
    width: R4 = Field(gt=0.5, le=2.0)
    height: R4 = Field(gt=1.5, le=3.0)
    rooms: tuple[str, str]

    @property
    def span(self) -> tuple[float, float]:
        return (self.offset, self.offset + self.width)


class HousePlan(_Model):
    """The rooms of a house, the interior walls between them and the doorways in those walls."""

    rooms: tuple[HouseRoom, ...]
    walls: tuple[InteriorWall, ...] = ()
    doors: tuple[HouseDoor, ...] = ()

    def room(self, name: str) -> HouseRoom:
        """The room with this name."""
        for r in self.rooms:
            if r.name == name:
                return r
        raise RoomError(f"house: no room {name!r}")


class RoomShell(_Model):
    """A room's structure. Build it with `generate_shell`, the ALFRED converter, or a JSON file.

    A house is a shell too: its outline is the house's, and `house` lists its rooms, the interior walls
    between them and their doorways (the walls and doorways are built, and kept out of the agent's grid).
    """

    format: Literal["luminous-room/1"] = FORMAT
    name: str = Field(pattern=NAME_PATTERN)
    room_type: RoomType
    shape: Shape
    source: str = ""
    outline: tuple[Vec2, ...]
    wall_height: R4 = Field(ge=2.0, le=4.0)
    wall_thickness: R4 = Field(ge=0.05, le=0.5)
    walls: tuple[Wall, ...]
    doors: tuple[Door, ...] = ()
    windows: tuple[Window, ...] = ()
    zones: tuple[Zone, ...] = ()
    fixtures: FixturePlan = FixturePlan()
    house: HousePlan | None = None

    @model_serializer(mode="wrap")
    def _without_house(self, handler: SerializerFunctionWrapHandler) -> dict[str, Any]:
        # a single room's JSON has no `house` key, so that it stays byte for byte what it was
        data = handler(self)
        if data.get("house", 0) is None:
            del data["house"]
        return data

    @model_validator(mode="after")
    def _check_structure(self) -> RoomShell:
        ring = list(self.outline)
        if len(ring) < 3:
            raise ValueError("outline needs at least 3 vertices")
        if signed_area(ring) <= 0:
            raise ValueError("outline must be counter-clockwise with positive area")
        poly = Polygon(ring)
        if not poly.is_valid:
            raise ValueError(f"outline is not a simple polygon ({shapely.is_valid_reason(poly)})")
        if len(self.walls) != len(ring):
            raise ValueError(
                f"expected {len(ring)} walls (one per outline edge), got {len(self.walls)}"
            )
        for i, (wall, ref) in enumerate(zip(self.walls, walls_from_outline(ring))):
            if (
                wall.start != ref.start
                or wall.end != ref.end
                or math.dist(wall.normal, ref.normal) > 1e-3
            ):
                raise ValueError(f"walls[{i}] ({wall.id}) does not match outline edge {i}")
        lengths = {w.id: w.length for w in self.walls}
        ids = [w.id for w in self.walls]
        items: list[tuple[str, Any, float, float]] = []
        items += [("doors", d, d.offset, d.offset + d.width) for d in self.doors]
        items += [("windows", w, w.offset, w.offset + w.width) for w in self.windows]
        items += [("fixtures.counters", c, c.start, c.end) for c in self.fixtures.counters]
        items += [("fixtures.slots", s, s.offset, s.offset + s.width) for s in self.fixtures.slots]
        for field, item, a, b in items:
            if item.wall not in lengths:
                raise ValueError(f"{field} {item.id!r}: unknown wall {item.wall!r}")
            if not (a >= -EPS and b <= lengths[item.wall] + 1e-4 and b > a):
                raise ValueError(
                    f"{field} {item.id!r}: span [{a}, {b}] outside wall {item.wall} "
                    f"(length {lengths[item.wall]:.4f})"
                )
            ids.append(item.id)
        dup = sorted({i for i in ids if ids.count(i) > 1})
        if dup:
            raise ValueError(f"duplicate ids: {', '.join(dup)}")
        for d in self.doors:
            if d.height > self.wall_height:
                raise ValueError(f"door {d.id!r} is taller than the wall ({self.wall_height})")
        for w in self.windows:
            if w.sill_height + w.height > self.wall_height:
                raise ValueError(f"window {w.id!r} reaches above the wall ({self.wall_height})")
        counters = {c.id for c in self.fixtures.counters}
        for s in self.fixtures.slots:
            if s.counter is not None and s.counter not in counters:
                raise ValueError(f"slot {s.id!r}: unknown counter {s.counter!r}")
        names = [z.name for z in self.zones]
        if len(set(names)) != len(names):
            raise ValueError("zone names must be unique")
        for z in self.zones:
            if len(z.polygon) < 3 or not z.shape().is_valid:
                raise ValueError(f"zone {z.name!r} is not a simple polygon")
        if self.house is not None:
            self._check_house(self.house, poly)
        return self

    @staticmethod
    def _check_house(house: HousePlan, poly: Polygon) -> None:
        names = [r.name for r in house.rooms]
        if len(set(names)) != len(names):
            raise ValueError("house room names must be unique")
        for r in house.rooms:
            shape = r.polygon()
            if len(r.outline) < 3 or not shape.is_valid or signed_area(list(r.outline)) <= 0:
                raise ValueError(f"house room {r.name!r}: outline is not a counter-clockwise simple polygon")
            if not poly.buffer(1e-4).contains(shape):
                raise ValueError(f"house room {r.name!r} reaches outside the house outline")
        walls = {w.id: w for w in house.walls}
        for d in house.doors:
            if d.wall not in walls:
                raise ValueError(f"house door {d.id!r}: unknown wall {d.wall!r}")
            if d.offset + d.width > walls[d.wall].wall.length + 1e-4:
                raise ValueError(f"house door {d.id!r}: span beyond the end of wall {d.wall}")
            for name in d.rooms:
                if name not in names:
                    raise ValueError(f"house door {d.id!r}: unknown room {name!r}")

    # ----------------------------------------------------------------- geometry

    @cached_property
    def _polygon(self) -> Polygon:
        return Polygon(self.outline)

    def polygon(self) -> Polygon:
        """The floor outline as a shapely Polygon."""
        return self._polygon

    @property
    def area(self) -> float:
        """Floor area, square metres."""
        return float(self._polygon.area)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """(min_x, min_y, max_x, max_y) of the floor."""
        return tuple(float(v) for v in self._polygon.bounds)  # type: ignore[return-value]

    def wall(self, wall_id: str) -> Wall:
        """The wall with this id."""
        for w in self.walls:
            if w.id == wall_id:
                return w
        raise RoomError(f"room {self.name!r}: no wall {wall_id!r}")

    def zone(self, name: str) -> Zone:
        """The zone with this name."""
        for z in self.zones:
            if z.name == name:
                return z
        raise RoomError(f"room {self.name!r}: no zone {name!r}")

    def footprint(self, item: CounterRun | FixtureSlot) -> Polygon:
        """Floor polygon covered by a counter run or fixture slot."""
        a, b = item.span
        return self.wall(item.wall).rect(a, b, 0.0, item.depth)

    def fixture_footprints(self) -> dict[str, Polygon]:
        """Footprint of every counter run and fixture slot, by id."""
        items = list(self.fixtures.counters) + list(self.fixtures.slots)
        return {i.id: self.footprint(i) for i in items}

    @cached_property
    def _open_floor(self) -> BaseGeometry:
        walls = self.interior_footprints()
        return self._polygon.difference(shapely.union_all(walls)) if walls else self._polygon

    def free_floor(self) -> BaseGeometry:
        """The floor minus every fixture footprint and interior wall (Polygon or MultiPolygon)."""
        feet = list(self.fixture_footprints().values())
        if not feet:
            return self._open_floor
        return self._open_floor.difference(shapely.union_all(feet))

    def interior_pieces(self) -> list[tuple[InteriorWall, float, float]]:
        """A house's interior walls as solid pieces (wall, from, to along it), doorways left out."""
        if self.house is None:
            return []
        out = []
        edge = self._polygon.exterior
        half = self.wall_thickness / 2
        for w in self.house.walls:
            # an end on another interior wall stops at that wall's face, so that the two do not overlap
            u = 0.0 if edge.distance(shapely.Point(w.start)) < 1e-6 else half
            end = w.wall.length - (0.0 if edge.distance(shapely.Point(w.end)) < 1e-6 else half)
            for a, b in sorted(d.span for d in self.house.doors if d.wall == w.id):
                if a > u:
                    out.append((w, u, a))
                u = max(u, b)
            if end > u:
                out.append((w, u, end))
        return out

    def interior_footprints(self) -> list[Polygon]:
        """Floor footprints of a house's interior walls (doorways left open); empty for a single room."""
        t = self.wall_thickness
        return [w.wall.rect(a, b, -t / 2, t / 2) for w, a, b in self.interior_pieces()]

    @property
    def room_types(self) -> tuple[str, ...]:
        """The room types the shell holds: a house's rooms' types (in order, no repeats), else its own."""
        if self.house is None:
            return (self.room_type,)
        return tuple(dict.fromkeys(r.room_type for r in self.house.rooms))

    def room_at(self, x: float, y: float) -> str | None:
        """The name of the house room whose floor holds (x, y) (the nearest room within 0.5 m, for a point
        in a doorway); None for a single room or a point outside every room."""
        if self.house is None:
            return None
        p = shapely.Point(x, y)
        best = min(self.house.rooms, key=lambda r: (r.polygon().distance(p), r.name))
        return best.name if best.polygon().distance(p) <= 0.5 else None

    def door_clearance_zones(self) -> list[Polygon]:
        """For each door (in order), the rectangle in front of it that must stay free."""
        out = []
        for d in self.doors:
            out.append(self.wall(d.wall).rect(d.offset, d.offset + d.width, 0.0, d.swing_clearance))
        return out

    def grid_points(
        self, step: float = 0.25, clearance: float = 0.2, avoid_fixtures: bool = True
    ) -> np.ndarray:
        """Candidate agent positions: multiples of `step` at least `clearance` from walls.

        Args:
            step: grid spacing; the grid is aligned with the world origin, like AI2-THOR's.
            clearance: least distance to a wall (and to a fixture, with `avoid_fixtures`).
            avoid_fixtures: also keep `clearance` away from counters and fixture slots.

        Returns:
            Array of shape (N, 2), sorted by x then y.
        """
        area = self.free_floor() if avoid_fixtures else self._open_floor
        inner = area.buffer(-(clearance - 1e-6))
        if inner.is_empty:
            return np.zeros((0, 2))
        x0, y0, x1, y1 = inner.bounds
        xs = np.arange(math.ceil(x0 / step - 1e-9), math.floor(x1 / step + 1e-9) + 1) * step
        ys = np.arange(math.ceil(y0 / step - 1e-9), math.floor(y1 / step + 1e-9) + 1) * step
        gx, gy = np.meshgrid(xs, ys, indexing="ij")
        pts = np.stack([gx.ravel(), gy.ravel()], axis=1)
        keep = shapely.intersects_xy(inner, pts[:, 0], pts[:, 1])
        return np.round(pts[keep], 4) + 0.0

    def wall_boxes(self) -> list[WallBox]:
        """Boxes that build the walls, with door and window openings cut out.

        A door leaves the wall open from the floor to the door height (a lintel above); a window
        leaves a sill piece below and a head piece above. At a convex corner the wall ending there
        is lengthened by the thickness to close the corner; at a reflex corner it is shortened so
        that walls do not overlap. Openings should keep a thickness away from wall ends.
        """
        t, h = self.wall_thickness, self.wall_height
        ring = list(self.outline)
        boxes: list[WallBox] = []
        for i, wall in enumerate(self.walls):
            nxt = ring[(i + 2) % len(ring)]
            extend = t if is_convex_vertex(wall.start, wall.end, nxt) else -t
            u_end = wall.length + extend
            cuts: list[tuple[float, float, list[tuple[str, float, float]]]] = []
            for d in self.doors:
                if d.wall == wall.id:
                    cuts.append((d.offset, d.offset + d.width, [("lintel", d.height, h)]))
            for w in self.windows:
                if w.wall == wall.id:
                    top = w.sill_height + w.height
                    cuts.append(
                        (
                            w.offset,
                            w.offset + w.width,
                            [("sill", 0.0, w.sill_height), ("head", top, h)],
                        )
                    )
            cuts.sort()
            pieces: list[tuple[str, float, float, float, float]] = []
            u = 0.0
            for a, b, keep in cuts:
                if a > u:
                    pieces.append(("solid", u, a, 0.0, h))
                pieces += [(kind, a, b, z0, z1) for kind, z0, z1 in keep]
                u = max(u, b)
            if u_end > u:
                pieces.append(("solid", u, u_end, 0.0, h))
            for kind, a, b, z0, z1 in pieces:
                if b - a < 1e-6 or z1 - z0 < 1e-6:
                    continue
                cx, cy = wall.point((a + b) / 2, -t / 2)
                boxes.append(
                    WallBox(
                        wall=wall.id,
                        kind=kind,  # type: ignore[arg-type]
                        center=(round(cx, 6), round(cy, 6), round((z0 + z1) / 2, 6)),
                        size=(round(b - a, 6), round(t, 6), round(z1 - z0, 6)),
                        yaw=wall.yaw,
                    )
                )
        return boxes + self._interior_boxes()

    def _interior_boxes(self) -> list[WallBox]:
        """A house's interior walls: solid pieces full height, a lintel over each doorway."""
        if self.house is None:
            return []
        t, h = self.wall_thickness, self.wall_height
        pieces: list[tuple[InteriorWall, str, float, float, float, float]] = [
            (w, "solid", a, b, 0.0, h) for w, a, b in self.interior_pieces()]
        walls = {w.id: w for w in self.house.walls}
        pieces += [(walls[d.wall], "lintel", d.offset, d.offset + d.width, d.height, h) for d in self.house.doors]
        boxes = []
        for w, kind, a, b, z0, z1 in pieces:
            if b - a < 1e-6 or z1 - z0 < 1e-6:
                continue
            cx, cy = w.wall.point((a + b) / 2, 0.0)
            boxes.append(WallBox(wall=w.id, kind=kind,  # type: ignore[arg-type]
                                 center=(round(cx, 6), round(cy, 6), round((z0 + z1) / 2, 6)),
                                 size=(round(b - a, 6), round(t, 6), round(z1 - z0, 6)), yaw=w.wall.yaw))
        return boxes

    # ----------------------------------------------------------------- JSON

    def to_dict(self) -> dict[str, Any]:
        """Plain JSON-ready dict (lists for tuples)."""
        return self.model_dump(mode="json")

    def to_json(self) -> str:
        """Deterministic JSON text: sorted keys, floats rounded to 4 decimals, trailing newline."""
        return json.dumps(self.to_dict(), sort_keys=True, indent=1) + "\n"

    @classmethod
    def from_dict(cls, data: Any, where: str = "room") -> RoomShell:
        """Validate a dict into a RoomShell; a bad document raises RoomError naming `where`, key."""
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            err = exc.errors()[0]
            loc = ".".join(str(p) for p in err["loc"]) or "(document)"
            more = f" (and {exc.error_count() - 1} more problems)" if exc.error_count() > 1 else ""
            raise RoomError(f"{where}: {loc}: {err['msg']}{more}") from None

    @classmethod
    def from_json(cls, text: str, where: str = "room") -> RoomShell:
        """Parse and validate JSON text."""
        try:
            data = json.loads(text)
        except json.JSONDecodeError as exc:
            raise RoomError(f"{where}: not valid JSON ({exc})") from None
        return cls.from_dict(data, where)


def load_shell(path: str | Path) -> RoomShell:
    """Read a room file; errors name the file and the offending key."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as exc:
        raise RoomError(f"{p}: cannot read room file ({exc.strerror})") from None
    return RoomShell.from_json(text, where=str(p))


def save_shell(shell: RoomShell, path: str | Path) -> Path:
    """Write `shell.to_json()` to `path` (creating folders); returns the path."""
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    p.write_text(shell.to_json(), encoding="utf-8")
    return p


def make_shell(**fields: Any) -> RoomShell:
    """Build a RoomShell from an outline, deriving canonical vertex order and walls.

    `outline` may be any simple ring; it is made counter-clockwise, starting at its lowest-left
    vertex. Raises RoomError if the fields are inconsistent.
    """
    ring = canonical_ring(fields.pop("outline"))
    fields.setdefault("walls", walls_from_outline(ring))
    try:
        return RoomShell(outline=tuple(ring), **fields)
    except ValidationError as exc:
        err = exc.errors()[0]
        loc = ".".join(str(p) for p in err["loc"]) or "(room)"
        raise RoomError(f"room {fields.get('name', '?')!r}: {loc}: {err['msg']}") from None


def with_changes(shell: RoomShell, **changes: Any) -> RoomShell:
    """A copy of `shell` with some fields replaced, validated again."""
    data = shell.model_dump()
    data.update(changes)
    return RoomShell.from_dict(data, where=f"room {shell.name!r}")


def zone_polygon(poly: Polygon) -> tuple[tuple[float, float], ...]:
    """A polygon's exterior as a canonical zone vertex tuple."""
    return tuple(canonical_ring(poly.exterior.coords))
