"""L-shaped rooms in houses: the floor planner cuts a corner of the outline out of an L room's rectangle;
walls, doorways, the reachable grid and CSSG's placement work in it."""

from __future__ import annotations

import networkx as nx
import numpy as np
import pytest
import shapely

from luminous_sim import cdf
from luminous_sim.rooms.house import L_ARM, RoomRequest, plan_house
from luminous_sim.scene import largest_component

TYPES = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom")


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_an_l_room_is_its_rectangle_less_a_corner_of_the_outline(seed: int) -> None:
    rooms = [RoomRequest(f"r{i}", t, shape="L" if i in (1, 2) else "rect") for i, t in enumerate(TYPES)]
    plan = plan_house(rooms, np.random.default_rng(seed))
    house = plan.shell
    assert house.house is not None
    shapes = {s.name: s.shape for s in plan.rooms}
    assert shapes == {"r0": "rect", "r1": "L", "r2": "L", "r3": "rect"}
    outline = house.polygon()
    assert len(house.outline) == 8  # two notches at two corners of the rectangle
    for s in plan.rooms:
        poly = s.polygon()
        assert outline.buffer(1e-6).contains(poly)
        if s.shape == "L":
            assert len(s.outline) == 6 and poly.area < poly.envelope.area - L_ARM ** 2 + 1e-6
            # the notch is outside the house: its corner of the room's box lies off the outline
            assert poly.envelope.difference(poly).intersection(outline).area < 1e-6
    # every room reachable through its doorways on the house's grid
    pts = house.grid_points()
    keys = {(round(x * 4), round(y * 4)) for x, y in pts[largest_component(pts)]}
    for s in plan.rooms:
        assert any((round(x * 4), round(y * 4)) in keys for x, y in s.grid_points()), s.name


def test_a_house_without_l_rooms_is_drawn_as_before() -> None:
    plain = [RoomRequest(f"r{i}", t) for i, t in enumerate(TYPES)]
    shaped = [RoomRequest(f"r{i}", t, shape="rect") for i, t in enumerate(TYPES)]
    a = plan_house(plain, np.random.default_rng(5)).shell
    b = plan_house(shaped, np.random.default_rng(5)).shell
    assert a.to_json() == b.to_json() and a.shape == "rect" and len(a.outline) == 4


HOUSE = """
cdf_version: 2
name: l_flat
scene:
  house:
    rooms:
      - {name: kitchen, type: Kitchen}
      - name: living
        type: LivingRoom
        shape: L
        objects: [{name: sofa, type: Sofa}, {name: coffee, type: CoffeeTable}]
        relations: [{subject: coffee, relation: in_front_of, target: sofa}]
      - {name: bedroom, type: Bedroom}
    adjacency: [[kitchen, living], [bedroom, living]]
"""


def test_cssg_furnishes_an_l_room_of_a_house_inside_its_floor() -> None:
    from luminous_sim.cssg import generate_house
    from luminous_sim.scene import scene_reachable_grid

    generated = generate_house(cdf.loads(HOUSE), seed=0)
    assert generated.report.ok
    scene = generated.scene
    assert scene.room.house is not None
    living = scene.room.house.room("living")
    assert len(living.outline) == 6
    floor = living.polygon().buffer(0.06)  # wall-hung things sit in the wall, half its thickness out
    placed = [o for o in scene.objects if scene.room.room_at(*o.position[:2]) == "living" and o.parent is None]
    assert {"sofa", "coffee"} <= {o.name for o in placed}
    assert all(floor.contains(shapely.Point(o.position[:2])) for o in placed)
    grid = scene_reachable_grid(scene)
    graph = nx.Graph()
    keys = {(round(x * 4), round(y * 4)) for x, y in grid}
    graph.add_nodes_from(keys)
    graph.add_edges_from((k, (k[0] + dx, k[1] + dy)) for k in keys for dx, dy in ((1, 0), (0, 1))
                         if (k[0] + dx, k[1] + dy) in keys)
    assert nx.is_connected(graph)
    assert sum(living.polygon().contains(shapely.Point(x, y)) for x, y in grid) > 20
