"""A small house generated, built and walked: each room furnished in its own floor, the house's reachable
grid spanning its doorways, the simulator's navigation grid the same, and the oracle solving a task whose
object and receptacle are in different rooms."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.cssg import HouseGenerated, empty_cdf, generate, generate_house
from luminous_sim.errors import CDFError
from luminous_sim.scene import scene_reachable_grid

SMALL = """
cdf_version: 2
name: small_house
scene:
  house:
    size: {width: 8, depth: 5.5}
    rooms:
      - {name: kitchen, type: Kitchen}
      - {name: living, type: LivingRoom}
      - {name: bedroom, type: Bedroom}
    adjacency: [[kitchen, living]]
"""


@pytest.fixture(scope="module")
def house() -> HouseGenerated:
    return generate_house(cdf.loads(SMALL), seed=0)


def test_each_room_is_furnished_inside_its_floor(house: HouseGenerated) -> None:
    shell = house.scene.room
    assert shell.house is not None and house.report.ok
    assert set(house.report.rooms) == {"kitchen", "living", "bedroom"}
    by_room: dict[str, set[str]] = {}
    for o in house.scene.objects:
        room = shell.room_at(o.position[0], o.position[1])
        assert room is not None, o.id
        by_room.setdefault(room, set()).add(o.type)
    assert {"Fridge", "StoveBurner"} <= by_room["kitchen"]
    assert "Bed" in by_room["bedroom"] and "Sofa" in by_room["living"]
    assert len({o.id for o in house.scene.objects}) == len(house.scene.objects)


def test_the_reachable_grid_spans_every_room(house: HouseGenerated) -> None:
    grid = scene_reachable_grid(house.scene)
    shell = house.scene.room
    assert {shell.room_at(x, y) for x, y in grid} == {"kitchen", "living", "bedroom"}
    assert all(house.report.rooms_reached.values()) and house.report.reachable_points == len(grid)


def test_same_cdf_and_seed_give_the_same_house_byte_for_byte(house: HouseGenerated) -> None:
    again = generate_house(cdf.loads(SMALL), seed=0)
    assert again.scene.to_json() == house.scene.to_json()


def test_a_room_of_the_house_is_the_room_cssg_makes_alone(house: HouseGenerated) -> None:
    """The house's kitchen is CSSG's kitchen in the kitchen's shell, with the seed the report names."""
    alone = generate(empty_cdf("Kitchen"), seed=house.report.room_seeds["kitchen"], room=house.plan.rooms[0])
    ids = {o.id for o in house.scene.objects}
    assert {o.id for o in alone.scene.objects} <= ids


def test_generate_refuses_a_house_cdf() -> None:
    with pytest.raises(CDFError, match="generate_house"):
        generate(cdf.loads(SMALL), seed=0)


def test_the_world_builds_interior_walls_and_navigates_across_doorways(house: HouseGenerated) -> None:
    from luminous_sim.planning.navigation import NavGraph
    from luminous_sim.world import World
    from luminous_sim.world.agent import AgentPose

    with World(house.scene) as world:
        pts = world.nav.points()
        assert len(pts) == len(scene_reachable_grid(house.scene))
        shell = house.scene.room
        far: dict[str | None, tuple[float, float]] = {}
        for x, y in pts:
            far.setdefault(shell.room_at(x, y), (x, y))
        graph = NavGraph(world.nav)
        (ax, ay), (bx, by) = far["kitchen"], far["bedroom"]
        path = graph.path(AgentPose(ax, ay, 0, 30), AgentPose(bx, by, 0, 30))
        assert path and "MoveAhead" in path
        assert len(world.built.walls) == len(shell.wall_boxes()) > len(shell.interior_pieces())


def test_the_oracle_solves_a_task_across_rooms(house: HouseGenerated) -> None:
    from luminous_sim.episode import run_episode
    from luminous_sim.tasks import object_rooms

    result, record = run_episode(house.scene, "pick_and_place_simple", 0, record_frames=False, cross_room=True)
    assert result.success, result.failure
    rooms = object_rooms(house.scene)
    p = record.task.params
    here = {rooms[o.id] for o in house.scene.objects if o.type == p.object_target and o.id in rooms}
    there = {rooms[o.id] for o in house.scene.objects if o.type == p.parent_target and o.id in rooms}
    assert here and there and not here & there


def test_rooms_apart_needs_a_house() -> None:
    from luminous_sim.tasks import TaskError, rooms_apart, state_from_scene

    scene = generate(empty_cdf("Bedroom"), seed=0).scene
    with pytest.raises(TaskError, match="single room"):
        rooms_apart(scene, state_from_scene(scene))


def test_rooms_apart_keeps_only_tasks_across_rooms(house: HouseGenerated) -> None:
    from luminous_sim.tasks import object_rooms, rooms_apart, sample_task, state_from_scene

    state = state_from_scene(house.scene)
    keep = rooms_apart(house.scene, state)
    rooms = object_rooms(house.scene)
    for seed in range(5):
        task = sample_task(house.scene, state, "pick_and_place_simple", np.random.default_rng(seed), keep=keep)
        p = task.params
        here = {rooms[i] for i, o in state.objects.items() if o.object_type == p.object_target and i in rooms}
        there = {rooms[i] for i, o in state.objects.items() if o.object_type == p.parent_target and i in rooms}
        assert here and there and not here & there


def test_a_plan_with_a_room_cssg_cannot_furnish_is_drawn_again(monkeypatch: pytest.MonkeyPatch) -> None:
    import luminous_sim.cssg.house as house_mod
    from luminous_sim.errors import InfeasibleSceneError

    real = house_mod.generate
    calls = {"n": 0}

    def first_fails(*args, **kwargs):
        calls["n"] += 1
        if calls["n"] == 1:
            raise InfeasibleSceneError("no valid layout")
        return real(*args, **kwargs)

    monkeypatch.setattr(house_mod, "generate", first_fails)
    got = generate_house(cdf.loads(SMALL), seed=0)
    assert got.report.plan_redraws == 1 and got.scene.notes["plan_redraws"] == 1 and got.report.ok

    def always_fails(*args, **kwargs):
        raise InfeasibleSceneError("no valid layout")

    monkeypatch.setattr(house_mod, "generate", always_fails)
    with pytest.raises(InfeasibleSceneError, match="no floor plan of 4 could be furnished"):
        generate_house(cdf.loads(SMALL), seed=0)


def test_ray_batches_fit_pybullets_limit() -> None:
    """A house's sight-line check casts more rays than one rayTestBatch takes; a batch of 16,384 would come
    back empty."""
    from luminous_sim.world.client import new_client
    from luminous_sim.world.sightlines import RAY_BATCH

    client = new_client()
    try:
        froms = [(0.0, 0.0, 1.0)] * RAY_BATCH
        tos = [(0.0, 0.0, -1.0)] * RAY_BATCH
        assert len(client.rayTestBatch(froms, tos)) == RAY_BATCH
    finally:
        client.disconnect()


def test_the_front_door_is_an_opening_in_the_outer_wall_shown_in_the_top_down_picture(house: HouseGenerated) -> None:
    from luminous_sim.world import World
    from luminous_sim.world.views import _room_labels, top_down

    shell = house.scene.room
    (door,) = shell.doors
    wall = shell.wall(door.wall)
    assert shell.room_at(*wall.point(door.offset + door.width / 2, 0.3)) == "kitchen"  # the first room
    assert not [b for b in shell.wall_boxes() if b.wall == door.wall and b.kind == "solid"
                and abs(np.dot(np.subtract(b.center[:2], wall.start), wall.direction) - (door.offset + 0.5)) < 0.5]
    grid = scene_reachable_grid(house.scene)
    assert np.linalg.norm(grid - np.array(wall.point(door.offset + door.width / 2, 0.25)), axis=1).min() < 0.2
    with World(house.scene) as world:
        labels = [text for text, _ in _room_labels(world.built, lambda p: (float(p[0]), float(p[1])))]
        assert labels.count("front door") == 1
        assert top_down(world.built, px_per_m=40).size[0] > 0
