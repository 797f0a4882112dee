"""Between the layout format and the project's own models: a room shell and a layout room, a scene and a layout.

A scene exports every object with its asset, scale and the rest of its scene fields, so that loading the
layout back gives the same scene; the box (`position` at the box centre, `size`) is written from the
scaled asset's bounding box, so that other tools can read the layout without the catalog.
"""

from __future__ import annotations

import math

from pydantic import ValidationError

from luminous_sim.assets.catalog import AssetEntry, Catalog
from luminous_sim.layouts.model import (
    Layout,
    LayoutDoor,
    LayoutError,
    LayoutObject,
    LayoutRoom,
    LayoutWindow,
    LayoutZone,
    Provenance,
    problems,
    room_problem,
)
from luminous_sim.rooms.shell import Door, FixturePlan, RoomShell, Window, Zone, walls_from_outline
from luminous_sim.scene import Scene, local_to_world

DIGITS = 6
"""Decimals kept for box centres and yaws: enough that a scene's 4-decimal origins come back exactly."""


def _wall_index(shell: RoomShell, wall_id: str) -> int:
    return [w.id for w in shell.walls].index(wall_id)


def room_of_shell(shell: RoomShell) -> LayoutRoom:
    """The layout room of a Luminous room shell (nothing left out)."""
    return LayoutRoom(
        name=shell.name, room_type=shell.room_type, outline=shell.outline, wall_height=shell.wall_height,
        wall_thickness=shell.wall_thickness, shape=shell.shape, source=shell.source,
        doors=tuple(LayoutDoor(id=d.id, wall=_wall_index(shell, d.wall), offset=d.offset, width=d.width,
                               height=d.height, swing_clearance=d.swing_clearance, hinge=d.hinge) for d in shell.doors),
        windows=tuple(LayoutWindow(id=w.id, wall=_wall_index(shell, w.wall), offset=w.offset, width=w.width,
                                   sill_height=w.sill_height, height=w.height) for w in shell.windows),
        zones=tuple(LayoutZone(name=z.name, polygon=z.polygon) for z in shell.zones),
        fixture_plan=None if shell.fixtures == FixturePlan() else shell.fixtures,
    )


def _shape(outline: tuple[tuple[float, float], ...]) -> str:
    square = all(abs(a[0] - b[0]) < 1e-6 or abs(a[1] - b[1]) < 1e-6
                 for a, b in zip(outline, outline[1:] + outline[:1]))
    if square:
        return "rect" if len(outline) == 4 else "rectilinear"
    return "polygon"


def shell_of_room(room: LayoutRoom, where: str = "layout") -> RoomShell:
    """The room shell of a layout room; LayoutError names `where` and what is wrong with the room."""
    walls = walls_from_outline(room.outline)
    try:
        return RoomShell(
            name=room.name, room_type=room.room_type, shape=room.shape or _shape(tuple(room.outline)),
            source=room.source, outline=room.outline, wall_height=room.wall_height,
            wall_thickness=room.wall_thickness, walls=walls,
            doors=tuple(Door(id=d.id or f"Door_{i}", wall=walls[d.wall].id, offset=d.offset, width=d.width,
                             height=d.height, swing_clearance=d.swing_clearance, hinge=d.hinge)
                        for i, d in enumerate(room.doors)),
            windows=tuple(Window(id=w.id or f"Window_{i}", wall=walls[w.wall].id, offset=w.offset, width=w.width,
                                 sill_height=w.sill_height, height=w.height) for i, w in enumerate(room.windows)),
            zones=tuple(Zone(name=z.name, polygon=z.polygon) for z in room.zones),
            fixtures=room.fixture_plan or FixturePlan(),
        )
    except (ValidationError, ValueError) as exc:
        errors = exc.errors() if isinstance(exc, ValidationError) else [{"loc": (), "msg": str(exc)}]
        msg = "; ".join(f"{'.'.join(map(str, e['loc'])) or 'outline'}: {e['msg']}" for e in errors[:3])
        raise LayoutError(f"{where}: room: not a valid room ({msg})") from None


def box_centre(entry: AssetEntry, x: float, y: float, z: float, yaw: float) -> tuple[float, float, float]:
    """World centre of an asset's bounding box with its origin at (x, y, z) and heading `yaw`."""
    cx = (entry.bbox_min[0] + entry.bbox_max[0]) / 2
    cy = (entry.bbox_min[1] + entry.bbox_max[1]) / 2
    wx, wy = local_to_world(x, y, yaw, (cx, cy))
    return wx, wy, z + (entry.bbox_min[2] + entry.bbox_max[2]) / 2


def origin_of(entry: AssetEntry, centre: tuple[float, float, float], yaw: float) -> tuple[float, float, float]:
    """The asset origin that puts its bounding box's centre at `centre` (the inverse of `box_centre`)."""
    cx = (entry.bbox_min[0] + entry.bbox_max[0]) / 2
    cy = (entry.bbox_min[1] + entry.bbox_max[1]) / 2
    c, s = math.cos(yaw), math.sin(yaw)
    return (centre[0] - (c * cx - s * cy), centre[1] - (s * cx + c * cy),
            centre[2] - (entry.bbox_min[2] + entry.bbox_max[2]) / 2)


def _r(v: float) -> float:
    return round(float(v), DIGITS) + 0.0


def layout_of_scene(scene: Scene, catalog: Catalog, where: str = "scene") -> Layout:
    """The layout of a scene: its room and every object, with asset, scale and scene fields.

    Raises:
        LayoutError: one line naming `where` and the object or field the layout format refuses.
    """
    objects = []
    for i, o in enumerate(scene.objects):
        entry = catalog.for_object(o)
        centre = box_centre(entry, *o.position, o.yaw)
        try:
            objects.append(LayoutObject(
                id=o.id, category=o.type, size=tuple(_r(d) for d in entry.dims),
                position=tuple(_r(c) for c in centre), yaw=_r(o.yaw), parent=o.parent, region=o.region,
                asset=o.asset, scale=o.scale, layer=o.layer, fixed=o.fixed, name=o.name, states=o.states,
                color=o.color, color_seed=o.color_seed,
            ))
        except ValidationError as exc:
            raise LayoutError(f"{where}: objects[{i}] ({o.id}): {room_problem(exc)}") from None
    try:
        return Layout(room=room_of_shell(scene.room), objects=tuple(objects),
                      provenance=Provenance(generator=scene.generator, seed=scene.seed, source=scene.source,
                                            notes=scene.notes))
    except ValidationError as exc:
        raise problems(exc, where) from None
