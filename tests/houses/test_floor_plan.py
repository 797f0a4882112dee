"""Floor plans: the partition tiles the outline, rooms have usable sizes, doorways join every room (on the
agent's grid), windows are on outside walls, and the same seed gives the same plan."""

from __future__ import annotations

import itertools

import networkx as nx
import numpy as np
import pytest
import shapely

from luminous_sim.errors import RoomError
from luminous_sim.rooms import RoomShell, generate_shell
from luminous_sim.rooms.house import MIN_SIDE, WALL_THICKNESS, FloorPlan, RoomRequest, plan_house
from luminous_sim.scene import largest_component

TYPES = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom", "Bedroom", "Bathroom", "Bedroom", "LivingRoom")


def _plan(n: int, seed: int, **kw) -> FloorPlan:
    rooms = [RoomRequest(f"r{i}", TYPES[i]) for i in range(n)]
    return plan_house(rooms, np.random.default_rng(seed), **kw)


PLANS = [(n, s) for n in (2, 3, 5, 8) for s in (0, 1)]


@pytest.mark.parametrize(("n", "seed"), PLANS)
def test_rooms_tile_the_outline_without_overlap(n: int, seed: int) -> None:
    house = _plan(n, seed).shell
    assert house.house is not None and len(house.house.rooms) == n
    outline = house.polygon()
    polys = [r.polygon() for r in house.house.rooms]
    for a, b in itertools.combinations(polys, 2):
        assert a.intersection(b).area < 1e-9
    for p in polys:
        assert outline.buffer(1e-6).contains(p)
        x0, y0, x1, y1 = p.bounds
        assert min(x1 - x0, y1 - y0) >= MIN_SIDE - 1e-9
    walls = shapely.union_all(house.interior_footprints() + [p for p in polys])
    # what is not a room's floor is interior wall (or a doorway in one): the rooms fill the outline
    assert outline.area - shapely.union_all(polys).area <= sum(
        w.wall.length for w in house.house.walls) * WALL_THICKNESS + 1e-6
    assert walls.area <= outline.area + 1e-6


@pytest.mark.parametrize(("n", "seed"), PLANS)
def test_doorways_join_every_room_and_the_agent_grid_passes_them(n: int, seed: int) -> None:
    house = _plan(n, seed).shell
    assert house.house is not None
    g = nx.Graph()
    g.add_nodes_from(r.name for r in house.house.rooms)
    g.add_edges_from(d.rooms for d in house.house.doors)
    assert nx.is_connected(g)
    pts = house.grid_points(0.25, clearance=0.2, avoid_fixtures=False)
    assert largest_component(pts).all(), "the empty house's floor is one connected part"
    rooms_hit = {house.room_at(x, y) for x, y in pts}
    assert rooms_hit == {r.name for r in house.house.rooms}
    for d in house.house.doors:  # jambs on the world's 0.25 m grid
        wall = next(w for w in house.house.walls if w.id == d.wall)
        for u in d.span:
            assert np.allclose(np.array(wall.wall.point(u)) / 0.25, np.round(np.array(wall.wall.point(u)) / 0.25))


def test_asked_for_adjacency_gets_a_door() -> None:
    rooms = [RoomRequest("k", "Kitchen"), RoomRequest("l", "LivingRoom"), RoomRequest("b", "Bedroom"),
             RoomRequest("t", "Bathroom")]
    for seed in range(3):
        house = plan_house(rooms, np.random.default_rng(seed), adjacency=[("k", "t"), ("b", "l")]).shell
        assert house.house is not None
        pairs = {frozenset(d.rooms) for d in house.house.doors}
        assert {frozenset(("k", "t")), frozenset(("b", "l"))} <= pairs


def test_each_room_shell_has_its_doors_fixtures_and_outside_windows() -> None:
    plan = _plan(4, 3)
    house = plan.shell
    assert house.house is not None
    for shell, room in zip(plan.rooms, house.house.rooms, strict=True):
        assert shell.outline == room.outline and shell.room_type == room.room_type
        front = int(room.name == "r0")  # the first room holds the front door
        assert len(shell.doors) == sum(room.name in d.rooms for d in house.house.doors) + front
        edge = house.polygon().exterior
        for w in shell.windows:
            wall = shell.wall(w.wall)
            assert edge.distance(shapely.Point(wall.point(w.offset + w.width / 2))) < 1e-6
    assert len(house.windows) == sum(len(s.windows) for s in plan.rooms)
    kitchen = plan.rooms[0]
    assert kitchen.fixtures.slot("Sink") is not None and kitchen.fixtures.slot("Fridge") is not None


def test_interior_walls_do_not_overlap_each_other() -> None:
    house = _plan(8, 0).shell
    feet = house.interior_footprints()
    for a, b in itertools.combinations(feet, 2):
        assert a.intersection(b).area < 1e-9
    boxes = [b for b in house.wall_boxes() if b.wall.startswith("iw")]
    assert boxes and all(b.size[1] == WALL_THICKNESS for b in boxes)


def test_same_seed_same_plan_and_json_round_trip() -> None:
    a, b = _plan(5, 7), _plan(5, 7)
    assert a.shell.to_json() == b.shell.to_json()
    assert RoomShell.from_json(a.shell.to_json()) == a.shell
    assert _plan(5, 8).shell.to_json() != a.shell.to_json()


def test_a_single_room_json_has_no_house_key() -> None:
    shell = generate_shell("Kitchen", np.random.default_rng(0))
    assert shell.house is None and '"house"' not in shell.to_json() and "house" not in shell.model_dump()
    assert shell.room_types == ("Kitchen",) and shell.room_at(1.0, 1.0) is None


def test_bad_requests_are_refused() -> None:
    with pytest.raises(RoomError, match="at least 2 rooms"):
        plan_house([RoomRequest("a", "Kitchen")], np.random.default_rng(0))
    with pytest.raises(RoomError, match="unknown room 'z'"):
        plan_house([RoomRequest("a", "Kitchen"), RoomRequest("b", "Bedroom")], np.random.default_rng(0),
                   adjacency=[("a", "z")])
    with pytest.raises(RoomError, match="no floor plan"):
        plan_house([RoomRequest("a", "LivingRoom"), RoomRequest("b", "LivingRoom")], np.random.default_rng(0),
                   size=(4.0, 4.0))


@pytest.mark.parametrize(("n", "seed", "front"), [(3, 0, None), (5, 1, "r2"), (8, 0, "r5")])
def test_one_front_door_on_an_outside_wall_of_its_room_with_jambs_on_the_grid(n: int, seed: int,
                                                                                front: str | None) -> None:
    plan = _plan(n, seed, front_door=front)
    house = plan.shell
    assert house.house is not None
    (door,) = house.doors
    assert door.id == "FrontDoor"
    wall = house.wall(door.wall)
    ends = np.array([wall.point(door.offset), wall.point(door.offset + door.width)])
    assert np.allclose(ends / 0.25, np.round(ends / 0.25))
    inside = wall.point(door.offset + door.width / 2, 0.3)
    assert house.room_at(*inside) == (front or "r0")
    room = next(s for s in plan.rooms if s.name == (front or "r0"))
    (mine,) = [d for d in room.doors if d.id == "FrontDoor"]
    own = np.array([room.wall(mine.wall).point(mine.offset), room.wall(mine.wall).point(mine.offset + 1.0)])
    assert np.allclose(sorted(map(tuple, own)), sorted(map(tuple, ends)))
    assert not any(d.id == "FrontDoor" for s in plan.rooms if s.name != room.name for d in s.doors)
    # the grid passes the doorway's inside: a point 0.25 m in from the door's middle
    grid = house.grid_points()
    assert np.linalg.norm(grid - np.array(wall.point(door.offset + door.width / 2, 0.25)), axis=1).min() < 0.2


def test_an_unknown_front_door_room_is_refused() -> None:
    with pytest.raises(RoomError, match="front door: unknown room 'r9'"):
        _plan(3, 0, front_door="r9")
