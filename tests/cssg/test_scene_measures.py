"""The field's scene measures (PhyScene's collision, walkable and accessible rates; CKL on presence), each with a
negative control: a hand-made scene that violates it must be measured as violating it."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from shapely.geometry import Point

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import (
    alfred_reference,
    category_kl,
    ckl_figures,
    empty_cdf,
    floor_measures,
    generate,
    generate_house,
    group_rates,
    house_rooms,
    presence,
    reference_rooms,
    room_groups,
)
from luminous_sim.scene import Scene, SceneObject
from luminous_sim.world import scene_collisions


@pytest.fixture(scope="module")
def living() -> Scene:
    return generate(empty_cdf("LivingRoom"), seed=0).scene


def _with(scene: Scene, *extra: tuple[str, float, float, float]) -> Scene:
    """The scene with more floor pieces: (type, x, y, yaw)."""
    catalog = default_catalog()
    added = [SceneObject(id=f"{t}|extra{i}", type=t, asset=catalog.of_type(t)[0].id, position=(x, y, 0.0), yaw=yaw,
                         layer="furniture") for i, (t, x, y, yaw) in enumerate(extra)]
    return Scene(room=scene.room, seed=scene.seed, generator=scene.generator, objects=(*scene.objects, *added))


def test_a_cssg_room_is_walkable_and_collision_free(living):
    m = floor_measures(living)
    assert m.walkable_rate > 0.95 and m.doors == [d.id for d in living.room.doors]
    assert scene_collisions(living).colliding == []  # support and containment (a vase on its shelf) excluded


def test_two_pieces_in_one_place_collide(living):
    sofa = next(o for o in living.objects if o.parent is None and o.layer == "furniture")
    scene = _with(living, (sofa.type, sofa.position[0], sofa.position[1], sofa.yaw))
    got = scene_collisions(scene)
    assert {sofa.id, f"{sofa.type}|extra0"} <= set(got.colliding)
    assert got.rate == len(got.colliding) / got.objects > 0 and got.to_dict()["any"] is True


def test_a_blocked_door_leaves_nothing_walkable(living):
    blocks = []
    for door in living.room.doors:
        wall = living.room.wall(door.wall)
        x, y = wall.point(door.offset + door.width / 2, 0.3)
        blocks += [("Dresser", x, y, wall.yaw), ("Dresser", x, y, wall.yaw + math.pi / 2)]
    m = floor_measures(_with(living, *blocks))
    assert m.walkable_rate == 0.0 < m.walkable_area


def test_a_thing_under_the_bed_is_not_accessible():
    scene = generate(empty_cdf("Bedroom"), seed=2).scene
    assert floor_measures(scene).inaccessible == []
    bed = scene.of_type("Bed")[0]
    hidden = floor_measures(_with(scene, ("GarbageCan", bed.position[0], bed.position[1], 0.0)))
    assert hidden.inaccessible == ["GarbageCan|extra0"] and hidden.accessible_rate < 1.0


def test_a_wall_piece_hung_too_high_is_out_of_reach(living):
    """Wall pieces are measured by the agent's reach (1.5 m from its camera), not by PhyScene's floor contact: a
    painting hung on the middle of a wall at 1.4 m is reached; the same painting at 3.2 m is not."""
    catalog = default_catalog()
    assert floor_measures(living).out_of_reach == []
    wall = living.room.walls[0]
    x, y = wall.point(wall.length / 2, 0.01)
    painting = catalog.of_type("Painting")[0]
    for z, reached in ((1.4, True), (3.2, False)):
        hung = SceneObject(id="Painting|extra", type="Painting", asset=painting.id, position=(x, y, z), yaw=wall.yaw,
                           layer="decoration")
        scene = Scene(room=living.room, seed=0, generator="test", objects=(*living.objects, hung))
        m = floor_measures(scene, catalog)
        assert ("Painting|extra" not in m.out_of_reach) is reached, (z, m.out_of_reach)
        assert "Painting|extra" not in m.inaccessible  # a wall piece is not in PhyScene's floor population
    assert m.wall_reach_rate < 1.0


def test_a_region_cut_off_from_the_door_counts_against_walkable(living):
    # a row of sofas wall to wall across the room: the far side is free floor no one walks to from the door
    catalog = default_catalog()
    width = catalog.of_type("Sofa")[0].dims[0]
    x0, y0, x1, y1 = living.room.bounds
    door = living.room.wall(living.room.doors[0].wall)
    along_x = abs(door.normal[0]) > 0.5  # the row runs parallel to the door's wall
    row = [("Sofa", (x0 + x1) / 2, y0 + (i + 0.5) * width, math.pi / 2) if along_x else
           ("Sofa", x0 + (i + 0.5) * width, (y0 + y1) / 2, 0.0)
           for i in range(math.ceil(((y1 - y0) if along_x else (x1 - x0)) / width) + 1)]
    m = floor_measures(_with(living, *row))
    assert m.regions >= 2 and m.walkable_rate < 0.9


def test_ckl_is_zero_on_the_same_rooms_and_grows_with_the_wrong_ones():
    kitchens, baths = reference_rooms("Kitchen"), reference_rooms("Bathroom")
    assert len(kitchens) == len(baths) == 30
    assert category_kl(kitchens, kitchens) == 0.0
    assert category_kl(kitchens, baths) > 1.0 > category_kl(kitchens[:15], kitchens[15:]) > 0.0


def test_cssg_kitchens_sit_nearer_the_floor_than_the_ceiling():
    gen = [presence(generate(empty_cdf("Kitchen"), seed=s).scene) for s in range(15)]
    f = ckl_figures(reference_rooms("Kitchen"), gen, default_catalog().types(), draws=20)
    assert f.floor < f.generated < f.ceiling and f.generated - f.floor < f.ceiling - f.generated


def test_the_shipped_reference_is_what_the_converter_makes(shared_alfred):
    from importlib import resources

    shipped = json.loads(resources.files("luminous_sim.cssg").joinpath("data/alfred_rooms.json").read_text())
    made = alfred_reference(shared_alfred / "layouts", [shared_alfred / "valid_seen"])
    assert {rt: v["rooms"] for rt, v in made["room_types"].items()} == \
        {rt: v["rooms"] for rt, v in shipped["room_types"].items()}
    # the instances were counted over valid_seen and the 6,574 train trajectories (train.tar.xz, too big to unpack here)
    assert shipped["trajectories"] == made["trajectories"] + 6574 == 251 + 6574
    assert all(set(made["room_types"][rt]["instances"]) <= set(shipped["room_types"][rt]["instances"])
               for rt in made["room_types"])


def test_a_side_table_moved_from_the_bed_breaks_its_group():
    """Negative control of the functional groups: a bedroom's side table carried to the far corner is still
    held, and no longer met."""
    scene = next(s for seed in range(8) if (s := generate(empty_cdf("Bedroom"), seed=seed).scene)
                 and room_groups(s)["side tables at the bed's head"].met)
    bed = next(o for o in scene.objects if o.type == "Bed")
    far = max(scene.room.polygon().exterior.coords, key=lambda p: math.dist(p, bed.position[:2]))
    moved = tuple(o.model_copy(update={"position": (far[0] * 0.9 + 0.1, far[1] * 0.9 + 0.1, o.position[2])})
                  if o.type == "SideTable" else o for o in scene.objects)
    state = room_groups(Scene(room=scene.room, seed=scene.seed, generator=scene.generator, objects=moved))
    assert state["side tables at the bed's head"].held and not state["side tables at the bed's head"].met


def test_a_house_splits_into_its_rooms_and_keeps_their_groups():
    from luminous_sim import cdf

    doc = cdf.load(Path(__file__).resolve().parents[2] / "cdf" / "examples" / "houses" / "default_house.yaml")
    house = generate_house(doc, seed=0)
    rooms = house_rooms(house)
    assert sorted(rooms) == sorted(r.name for r in doc.scene.house.rooms)
    ids = [o.id for _, scene in rooms.values() for o in scene.objects]
    assert sorted(ids) == sorted(o.id for o in house.scene.objects)  # every thing in exactly one room
    for name, (room_type, scene) in rooms.items():
        assert room_type == next(r.type for r in doc.scene.house.rooms if r.name == name)
        shell = scene.room.polygon().buffer(0.5)
        assert all(shell.contains(Point(o.position[:2])) for o in scene.objects if o.parent is None)
    groups = group_rates(room_groups(s) for t, s in rooms.values() if t == "LivingRoom")
    assert groups["a sofa facing the TV or coffee table"] == {"rooms": 1, "held": 1, "met": 1}
