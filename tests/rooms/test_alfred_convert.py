"""The ALFRED layout converter, on synthetic layouts and (when present) the real ALFRED data."""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path

import numpy as np
import pytest
import shapely

from luminous_sim.errors import RoomError
from luminous_sim.rooms.alfred_convert import (
    ALFRED_SPLITS,
    AlfredLayout,
    convert_all,
    convert_layout,
    read_layout,
    scene_numbers,
    scene_room_type,
    scene_split,
    splits_document,
)
from luminous_sim.rooms.checks import shell_problems
from luminous_sim.rooms.library import SHIPPED_DIR
from luminous_sim.rooms.shell import load_shell

SAMPLE = (1, 10, 25, 201, 219, 301, 308, 401, 424)
SHIPPED = SHIPPED_DIR / "alfred"


@cache
def _converted(layouts: Path, scene: int):
    layout = read_layout(layouts, scene)
    return layout, convert_layout(layout)


def _grid(x0: float, x1: float, y0: float, y1: float) -> np.ndarray:
    xs, ys = np.meshgrid(
        np.arange(x0, x1 + 1e-9, 0.25), np.arange(y0, y1 + 1e-9, 0.25), indexing="ij"
    )
    return np.stack([xs.ravel(), ys.ravel()], axis=1)


def _write_layout(
    folder, scene: int, points: np.ndarray, objects: list[str], openable: dict | None = None
):
    folder.mkdir(parents=True, exist_ok=True)
    np.save(folder / f"FloorPlan{scene}-layout.npy", points)
    (folder / f"FloorPlan{scene}-objects.json").write_text(json.dumps(objects))
    if openable is not None:
        (folder / f"FloorPlan{scene}-openable.json").write_text(json.dumps(openable))


def _check_converted(shell, layout: AlfredLayout) -> None:
    pts = layout.points
    floor = shell.polygon()
    assert shapely.contains_xy(floor, pts[:, 0], pts[:, 1]).all(), (
        "every reachable point inside the outline"
    )
    grid = {tuple(p) for p in np.round(shell.grid_points(avoid_fixtures=False), 3)}
    assert all(tuple(p) in grid for p in np.round(pts, 3)), (
        "every reachable point is an agent grid point"
    )
    reach = len(pts) * 0.25 * 0.25
    assert reach <= shell.area <= 6 * reach
    assert shell_problems(shell) == []
    assert all(abs(x - round(x / 0.05) * 0.05) < 1e-6 for v in shell.outline for x in v)
    assert all(abs(w.direction[0]) in (0.0, 1.0) for w in shell.walls), "rectilinear"
    assert len(shell.doors) == 1
    assert len(shell.windows) <= (1 if "Window" in layout.objects else 0)


def test_scene_numbers_types_and_splits():
    assert len(scene_numbers()) == 120
    assert [scene_room_type(n) for n in (1, 30, 201, 230, 301, 330, 401, 430)] == [
        "Kitchen",
        "Kitchen",
        "LivingRoom",
        "LivingRoom",
        "Bedroom",
        "Bedroom",
        "Bathroom",
        "Bathroom",
    ]
    for bad in (0, 31, 200, 431, 500):
        with pytest.raises(RoomError):
            scene_room_type(bad)
    assert [n for n in scene_numbers() if scene_split(n) == "valid_unseen"] == [10, 219, 308, 424]
    assert sorted(ALFRED_SPLITS["tests_unseen"]) == [9, 29, 215, 226, 315, 325, 404, 425]
    doc = splits_document()
    assert len(doc["splits"]["seen"]) == 108
    assert doc["scene_split"]["FloorPlan424"] == "valid_unseen"


def test_synthetic_kitchen(tmp_path):
    pts = _grid(0.0, 3.0, 0.75, 3.5)
    openable = {
        "Fridge|+03.60|+00.00|+00.40": [3.0, 0.75, 90, 0],
        "Sink|+01.50|+00.90|+00.10|SinkBasin": [1.5, 0.75, 180, 30],
        "Cabinet|+00.50|+00.40|+00.10": [0.5, 0.75, 180, 30],
        "Cabinet|+02.50|+00.40|+00.10": [2.5, 0.75, 180, 30],
    }
    _write_layout(
        tmp_path,
        5,
        pts,
        ["CounterTop", "Sink", "Fridge", "StoveBurner", "Cabinet", "Window"],
        openable,
    )
    layout = read_layout(tmp_path, 5)
    shell = convert_layout(layout)
    _check_converted(shell, layout)
    assert (
        shell.room_type == "Kitchen"
        and shell.name == "FloorPlan5"
        and shell.source == "alfred:FloorPlan5"
    )
    assert {s.type for s in shell.fixtures.slots} == {
        "Sink",
        "StoveBurner",
        "Fridge",
    } and shell.fixtures.counters
    sink = shell.footprint(shell.fixtures.slot("Sink"))
    assert sink.distance(shapely.Point(1.5, 0.1)) < 0.5, "the sink goes where ALFRED's sink is"
    assert len(shell.windows) == 1


def test_synthetic_bathroom_without_positions(tmp_path):
    pts = _grid(-2.0, -0.5, 1.0, 2.5)
    _write_layout(tmp_path, 410, pts, ["Toilet", "Sink", "CounterTop"])
    layout = read_layout(tmp_path, 410)
    shell = convert_layout(layout)
    _check_converted(shell, layout)
    assert sorted(s.type for s in shell.fixtures.slots) == ["Shower", "Sink", "Toilet"]
    assert shell.windows == ()


def test_bad_inputs(tmp_path):
    with pytest.raises(RoomError, match="no such layouts folder"):
        convert_all(tmp_path / "missing", tmp_path / "out")
    with pytest.raises(RoomError, match="no FloorPlan"):
        convert_all(tmp_path, tmp_path / "out")
    with pytest.raises(RoomError, match="no such layout file"):
        read_layout(tmp_path, 3)
    (tmp_path / "FloorPlan3-layout.npy").write_text("not numpy")
    with pytest.raises(RoomError, match="FloorPlan3-layout.npy"):
        read_layout(tmp_path, 3)


@pytest.mark.parametrize("scene", SAMPLE)
def test_real_layouts(shared_alfred, scene):
    layout, shell = _converted(shared_alfred / "layouts", scene)
    _check_converted(shell, layout)
    objects = set(layout.objects)
    if shell.room_type == "Kitchen":
        assert {"Sink", "StoveBurner", "Fridge"} <= {s.type for s in shell.fixtures.slots}
    if shell.room_type == "Bathroom":
        types = {s.type for s in shell.fixtures.slots}
        assert {"Toilet", "Sink"} <= types and ("Bathtub" in types) == ("Bathtub" in objects)
    if shell.room_type in ("LivingRoom", "Bedroom"):
        assert not shell.fixtures.slots and not shell.fixtures.counters


@pytest.mark.parametrize("scene", SAMPLE)
def test_shipped_rooms_equal_a_fresh_conversion(shared_alfred, scene):
    shipped = SHIPPED / f"FloorPlan{scene}.json"
    assert shipped.read_text() == _converted(shared_alfred / "layouts", scene)[1].to_json()


def test_shipped_library_is_complete():
    names = sorted(p.stem for p in SHIPPED.glob("FloorPlan*.json"))
    assert len(names) == 120
    assert json.loads((SHIPPED / "splits.json").read_text()) == splits_document()
    for scene in (2, 215, 325, 404):
        shell = load_shell(SHIPPED / f"FloorPlan{scene}.json")
        assert shell.room_type == scene_room_type(scene) and shell_problems(shell) == []


def test_convert_all_writes_files_and_splits(shared_alfred, tmp_path):
    written = convert_all(shared_alfred / "layouts", tmp_path, scenes=[301, 424])
    assert [p.name for p in written] == ["FloorPlan301.json", "FloorPlan424.json"]
    assert (tmp_path / "splits.json").is_file()
    assert written[1].read_text() == (SHIPPED / "FloorPlan424.json").read_text()
