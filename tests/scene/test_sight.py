"""Keeping small objects where the agent can see them: the closed-form sight test on region boxes, and
generated scenes whose objects the built scene's ray test sees."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import generate
from luminous_sim.scene.sight import BOARD, MARGIN, Box2, Shade, in_sight, shades
from luminous_sim.vocab import abilities
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples"


def _entry(asset_id: str):
    return default_catalog().get(asset_id)


def _region(entry, name: str) -> dict:
    return next(r for r in entry.regions if r["name"] == name)


def test_a_shelf_under_a_table_top_has_that_top_as_its_roof():
    entry = _entry("CoffeeTable_00")
    got = shades(entry)
    assert got["top"].roof is None and got["top"].rim is not None
    roof = got["shelf"].roof
    assert roof is not None
    top = _region(entry, "top")
    assert roof[1] == pytest.approx(entry.link_origins[top["link"]][2] + top["center"][2] - BOARD - MARGIN)


def test_regions_behind_doors_have_no_shade():
    entry = default_catalog().of_type("Fridge")[0]
    assert all(s == Shade() for name, s in shades(entry).items() if _region(entry, name).get("requires_open"))


def _shelf() -> Shade:
    """A 1 m x 0.4 m shelf 0.5 m off the floor, under one 0.85 m off the floor, front edge at y = 0.2."""
    box = Box2(0.0, 0.0, 0.5, 0.2)
    return Shade(roof=(box, 0.85), rim=(box, 0.5))


OBJECT = (0.55, 0.6)
"""Heights of the sight targets of a 10 cm object on that shelf."""


def test_the_front_of_a_covered_shelf_is_seen_and_its_back_is_not():
    eyes = np.array([[0.0, 0.6], [0.25, 0.6], [-0.25, 0.6]])
    assert in_sight(_shelf(), (0.0, 0.0), 0.0, (0.0, 0.17), OBJECT, eyes)
    assert not in_sight(_shelf(), (0.0, 0.0), 0.0, (0.0, -0.17), OBJECT, eyes)
    # with nothing above, the back is seen from there too
    assert in_sight(Shade(rim=_shelf().rim), (0.0, 0.0), 0.0, (0.0, -0.17), OBJECT, eyes)


def test_a_covered_shelf_is_seen_through_its_front_only():
    behind = np.array([[0.0, -0.6]])
    assert not in_sight(_shelf(), (0.0, 0.0), 0.0, (0.0, -0.17), OBJECT, behind)


def test_the_host_pose_turns_the_shelf():
    # turned a quarter (yaw +90 degrees: local +y points to world -x), the front faces -x
    eyes = np.array([[-0.6, 0.0]])
    assert in_sight(_shelf(), (0.0, 0.0), math.pi / 2, (-0.17, 0.0), OBJECT, eyes)
    assert not in_sight(_shelf(), (0.0, 0.0), math.pi / 2, (0.17, 0.0), OBJECT, eyes)


def test_the_bottom_of_a_can_is_hidden_by_its_rim_and_what_sticks_out_is_not():
    box = Box2(0.0, 0.0, 0.1, 0.1)
    can = Shade(rim=(box, 0.3 + MARGIN))
    eyes = np.array([[0.0, 0.5]])
    assert not in_sight(can, (0.0, 0.0), 0.0, (0.0, 0.0), (0.05, 0.08), eyes)
    assert in_sight(can, (0.0, 0.0), 0.0, (0.0, 0.0), (0.4,), eyes)


def test_the_back_of_a_shelf_above_the_eye_is_hidden_by_its_edge():
    box = Box2(0.0, 0.0, 0.4, 0.15)
    high = Shade(rim=(box, 1.9))
    eyes = np.array([[0.0, 0.6]])
    assert in_sight(high, (0.0, 0.0), 0.0, (0.0, 0.14), (1.95, 2.0), eyes)
    assert not in_sight(high, (0.0, 0.0), 0.0, (0.0, -0.14), (1.95, 2.0), eyes)


def test_reach_is_measured_from_the_eye():
    floor_level = Shade()
    eyes = np.array([[0.0, 0.5]])
    assert not in_sight(floor_level, (0.0, 0.0), 0.0, (0.0, 0.0), (0.05,), eyes)
    assert in_sight(floor_level, (0.0, 0.0), 0.0, (0.0, 0.0), (CAMERA_HEIGHT - 0.5,), eyes)
    assert not in_sight(floor_level, (0.0, 0.0), 0.0, (0.0, 0.0), (1.0,), np.zeros((0, 2)))


def test_no_object_is_put_in_a_drawer_the_agent_cannot_open():
    doc = cdf.load(EXAMPLES / "bedroom_reading_desk.yaml")
    catalog = default_catalog()
    drawers = 0  # drawers of furniture ALFRED cannot open (dressers, side tables, desks) in these scenes
    for seed in range(6):
        scene = generate(doc, seed=seed, catalog=catalog).scene
        by_id = {o.id: o for o in scene.objects}
        drawers += sum(1 for o in scene.objects if not abilities(o.type).openable
                       for r in catalog.for_object(o).regions if r.get("requires_open"))
        for o in scene.objects:
            host = by_id.get(o.parent or "")
            if host is not None and o.region is not None:
                gated = _region(catalog.for_object(host), o.region).get("requires_open")
                assert not gated or abilities(host.type).openable, (seed, o.id, host.id, o.region)
    assert drawers > 0


@pytest.mark.parametrize(("example", "seed"), [("livingroom_painting_sofa", 0), ("bedroom_reading_desk", 2),
                                               ("bathroom_soap", 1)])
def test_every_object_to_interact_with_is_seen_in_the_built_scene(example, seed):
    from luminous_sim.world.physics_check import check_physics

    scene = generate(cdf.load(EXAMPLES / f"{example}.yaml"), seed=seed).scene
    assert check_physics(scene).unseeable == []
