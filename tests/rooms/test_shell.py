"""RoomShell: validation, JSON round trip, and its geometry queries."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import shapely
from shapely.geometry import Point, Polygon

from luminous_sim.errors import RoomError
from luminous_sim.rooms.checks import shell_problems
from luminous_sim.rooms.shell import (
    Door,
    RoomShell,
    load_shell,
    make_shell,
    save_shell,
    walls_from_outline,
)
from tests.rooms.conftest import rect_shell


def _inside_box(box, p: tuple[float, float, float]) -> bool:
    c, s = math.cos(box.yaw), math.sin(box.yaw)
    dx, dy, dz = p[0] - box.center[0], p[1] - box.center[1], p[2] - box.center[2]
    u, v = dx * c + dy * s, -dx * s + dy * c
    return (
        abs(u) <= box.size[0] / 2 + 1e-9
        and abs(v) <= box.size[1] / 2 + 1e-9
        and abs(dz) <= box.size[2] / 2 + 1e-9
    )


def _footprint(box) -> Polygon:
    c, s = math.cos(box.yaw), math.sin(box.yaw)
    hx, hy = box.size[0] / 2, box.size[1] / 2
    pts = [
        (box.center[0] + a * c - b * s, box.center[1] + a * s + b * c)
        for a, b in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))
    ]
    return Polygon(pts)


def test_basic_geometry(rect):
    assert rect.area == pytest.approx(12.0)
    assert rect.bounds == (0.0, 0.0, 4.0, 3.0)
    assert isinstance(rect.polygon(), Polygon) and rect.polygon().is_valid
    assert [w.id for w in rect.walls] == ["w0", "w1", "w2", "w3"]
    centre = rect.polygon().centroid
    for w in rect.walls:
        mid = w.point(w.length / 2)
        inward = (mid[0] + 0.1 * w.normal[0], mid[1] + 0.1 * w.normal[1])
        assert rect.polygon().contains(Point(inward)), w.id
        assert math.hypot(*w.normal) == pytest.approx(1.0)
        assert (centre.x - mid[0]) * w.normal[0] + (centre.y - mid[1]) * w.normal[1] > 0


def test_make_shell_canonicalises_clockwise_outline():
    shell = rect_shell(outline=[(0, 3), (4, 3), (4, 0), (0, 0), (0, 0)])
    assert shell.outline == ((0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0))


def test_json_round_trip_and_determinism(tmp_path, kitchen_rect):
    text = kitchen_rect.to_json()
    assert RoomShell.from_json(text) == kitchen_rect
    assert RoomShell.from_json(text).to_json() == text
    data = json.loads(text)
    assert list(data) == sorted(data)
    path = save_shell(kitchen_rect, tmp_path / "sub" / "room.json")
    assert path.read_text() == text
    assert load_shell(path) == kitchen_rect


def test_floats_rounded_to_4_decimals():
    shell = rect_shell(
        wall_height=2.555555, outline=[(0, -0.000001), (4.123456789, 0), (4.123456789, 3), (0, 3)]
    )
    assert shell.wall_height == 2.5556
    assert shell.outline[0] == (0.0, 0.0)
    assert "-0.0" not in shell.to_json()
    assert shell.outline[1] == (4.1235, 0.0)


@pytest.mark.parametrize(
    "change, fragment",
    [
        (
            {
                "doors": [
                    {
                        "id": "d",
                        "wall": "w9",
                        "offset": 0.5,
                        "width": 0.9,
                        "height": 2.0,
                        "swing_clearance": 1,
                    }
                ]
            },
            "unknown wall",
        ),
        (
            {
                "doors": [
                    {
                        "id": "d",
                        "wall": "w0",
                        "offset": 3.5,
                        "width": 0.9,
                        "height": 2.0,
                        "swing_clearance": 1,
                    }
                ]
            },
            "outside wall",
        ),
        (
            {
                "windows": [
                    {
                        "id": "x",
                        "wall": "w0",
                        "offset": 1,
                        "width": 1,
                        "sill_height": 2.0,
                        "height": 1.0,
                    }
                ]
            },
            "above the wall",
        ),
        ({"outline": [[0, 0], [0, 3], [4, 3], [4, 0]]}, "counter-clockwise"),
        ({"wall_height": 9.0}, "wall_height"),
        ({"name": "../evil"}, "name"),
        ({"extra_key": 1}, "extra_key"),
    ],
)
def test_validation_errors_name_the_key(rect, change, fragment):
    data = rect.to_dict()
    data.update(change)
    with pytest.raises(RoomError) as err:
        RoomShell.from_dict(data, where="rooms/x.json")
    assert "rooms/x.json" in str(err.value) and fragment in str(err.value)


def test_bad_json_and_missing_file(tmp_path):
    with pytest.raises(RoomError, match="not valid JSON"):
        RoomShell.from_json("{", where="f.json")
    with pytest.raises(RoomError, match="cannot read"):
        load_shell(tmp_path / "nope.json")


def test_walls_must_match_outline(rect):
    data = rect.to_dict()
    data["walls"][1]["start"] = [4.0, 0.5]
    with pytest.raises(RoomError, match="does not match outline"):
        RoomShell.from_dict(data)


def test_wall_boxes_cut_door_and_window(rect):
    boxes = rect.wall_boxes()
    door, win = rect.doors[0], rect.windows[0]
    w0, w2 = rect.wall("w0"), rect.wall("w2")
    t = rect.wall_thickness
    x, y = w0.point(door.offset + door.width / 2, -t / 2)
    for z in (0.01, 1.0, door.height - 0.01):  # open to the floor
        assert not any(_inside_box(b, (x, y, z)) for b in boxes)
    assert any(_inside_box(b, (x, y, door.height + 0.1)) and b.kind == "lintel" for b in boxes)
    x, y = w2.point(win.offset + win.width / 2, -t / 2)
    assert any(_inside_box(b, (x, y, win.sill_height / 2)) and b.kind == "sill" for b in boxes)
    assert not any(_inside_box(b, (x, y, win.sill_height + win.height / 2)) for b in boxes)
    assert any(
        _inside_box(b, (x, y, win.sill_height + win.height + 0.1)) and b.kind == "head"
        for b in boxes
    )
    for b in boxes:
        assert (
            b.center[2] - b.size[2] / 2 >= -1e-9
            and b.center[2] + b.size[2] / 2 <= rect.wall_height + 1e-9
        )
        assert b.size[1] == pytest.approx(t)


@pytest.mark.parametrize("fixture_name", ["rect", "l_shell"])
def test_wall_boxes_tile_the_wall_ring_without_overlap(request, fixture_name):
    shell = request.getfixturevalue(fixture_name)
    shell = shell.model_copy(update={"doors": (), "windows": ()})
    feet = [_footprint(b) for b in shell.wall_boxes()]
    ring = (
        shell.polygon().buffer(shell.wall_thickness, join_style="mitre").difference(shell.polygon())
    )
    union = shapely.union_all(feet)
    assert union.symmetric_difference(ring).area < 1e-5
    assert sum(f.area for f in feet) == pytest.approx(ring.area, abs=1e-5)


def test_free_floor_and_footprints(kitchen_rect):
    feet = kitchen_rect.fixture_footprints()
    assert set(feet) == {"CounterTop_0", "Sink_0"}
    assert feet["CounterTop_0"].area == pytest.approx(2.6 * 0.6)
    assert feet["Sink_0"].within(feet["CounterTop_0"].buffer(1e-9))
    assert kitchen_rect.free_floor().area == pytest.approx(12.0 - 2.6 * 0.6)
    minx, _, maxx, _ = feet["CounterTop_0"].bounds
    assert (minx, maxx) == pytest.approx((3.4, 4.0))


def test_door_clearance_zone(rect):
    (zone,) = rect.door_clearance_zones()
    assert zone.bounds == pytest.approx((1.0, 0.0, 1.9, 1.0))
    assert zone.within(rect.polygon())


def test_grid_points(kitchen_rect):
    pts = kitchen_rect.grid_points()
    assert pts.shape[1] == 2 and len(pts) > 0
    assert np.allclose(pts / 0.25, np.round(pts / 0.25))
    boundary = kitchen_rect.polygon().exterior
    d_wall = shapely.distance(boundary, shapely.points(pts))
    assert d_wall.min() >= 0.2 - 1e-9
    counter = kitchen_rect.fixture_footprints()["CounterTop_0"]
    assert shapely.distance(counter, shapely.points(pts)).min() >= 0.2 - 1e-9
    every = kitchen_rect.grid_points(avoid_fixtures=False)
    assert len(every) > len(pts)
    assert len(kitchen_rect.grid_points(step=0.5)) < len(pts)


def test_walls_from_outline_normals():
    walls = walls_from_outline([(0, 0), (2, 0), (2, 1), (0, 1)])
    assert [w.normal for w in walls] == [(0.0, 1.0), (-1.0, 0.0), (0.0, -1.0), (1.0, 0.0)]


def test_problems_report_overlaps(rect):
    assert shell_problems(rect) == []
    bad = rect.model_copy(
        update={
            "doors": rect.doors
            + (
                Door(
                    id="Door_1", wall="w0", offset=1.5, width=0.9, height=2.0, swing_clearance=1.0
                ),
            )
        }
    )
    assert any("overlaps" in p for p in shell_problems(bad))
    assert "no door" in shell_problems(rect.model_copy(update={"doors": ()}))


def test_make_shell_error_is_room_error():
    with pytest.raises(RoomError):
        make_shell(
            name="x",
            room_type="Kitchen",
            shape="rect",
            outline=[(0, 0), (1, 0), (0, 1), (1, 1)],
            wall_height=2.5,
            wall_thickness=0.1,
        )


def test_model_copy_drops_cached_geometry(rect):
    assert rect.area == pytest.approx(12.0) and rect.walls[0].length == pytest.approx(4.0)
    copy = rect.model_copy(update={"outline": ((0, 0), (1, 0), (1, 1), (0, 1))})
    assert copy.area == pytest.approx(1.0)
    assert rect.walls[0].model_copy(update={"end": (2.0, 0.0)}).length == pytest.approx(2.0)


def test_with_changes_validates(rect):
    from luminous_sim.rooms.shell import with_changes

    assert with_changes(rect, wall_height=2.7).wall_height == 2.7
    with pytest.raises(RoomError, match="wall_height"):
        with_changes(rect, wall_height=1.0)
