"""CDF attributes reach the scene and the simulator: size scales the asset, material picks the variant,
colour paints the main material."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim import cdf
from luminous_sim.assets.catalog import default_catalog, scaled
from luminous_sim.cssg.attributes import candidates, parse_colour
from luminous_sim.cssg.pipeline import generate
from luminous_sim.errors import CDFError

DOC = """
cdf_version: 2
name: attributes
scene:
  room_type: Bedroom
  objects:
    - {name: desk, type: Desk, attributes: {material: oak}}
    - {name: table, type: SideTable}
    - {name: apple, type: Apple, attributes: {size: 1.5, colour: green}}
    - {name: chair, type: Chair, attributes: {size: {width: 0.6, depth: 0.6, height: 1.0}}}
  relations:
    - {subject: apple, relation: on, target: table}
"""


def test_scaled_entry_scales_geometry():
    e = default_catalog().of_type("Mug")[0]
    big = scaled(e, 2.0)
    assert big.scale == 2.0 and big.dims == pytest.approx([2 * d for d in e.dims], abs=1e-4)
    assert big.regions[0]["size"] == pytest.approx([2 * s for s in e.regions[0]["size"]], abs=1e-4)
    assert big.mass == pytest.approx(8 * e.mass, rel=1e-3)


def test_material_and_size_choose_and_scale_variants():
    cat = default_catalog()
    oak = candidates(cat.of_type("Desk"), {"material": "oak"})
    assert oak and all(any(v["slot"] in ("wood",) for v in e.visuals) for e in oak)
    chairs = candidates(cat.of_type("Chair"), {"size": {"width": 0.6, "depth": 0.6, "height": 1.0}})
    assert all(0.3 <= e.scale <= 3.0 and e.scale != 1.0 for e in chairs)


def test_attributes_reach_the_scene_and_the_world():
    from luminous_sim.world.scene_builder import build_scene

    scene = generate(cdf.loads(DOC, source="attributes.yaml"), seed=0).scene
    by = {o.name: o for o in scene.objects if o.name}
    assert by["apple"].scale == 1.5 and by["apple"].color == parse_colour("green")
    assert by["chair"].scale != 1.0
    built = build_scene(scene, settle_steps=10)
    try:
        body = built.objects[by["apple"].id].body
        lo, hi = map(np.array, built.client.getAABB(body, -1))
        base = default_catalog().get(by["apple"].asset)
        assert (hi - lo)[0] == pytest.approx(1.5 * base.dims[0], rel=0.15)
        from luminous_sim.world.camera import render

        top = (lo + hi) / 2
        frame = render(built.client, top + [0, 0, 0.35], top, up=(0, 1, 0), width=64, height=64, fov=30)
        centre = frame.rgb[28:36, 28:36].reshape(-1, 3).mean(axis=0)
        assert centre[1] > centre[0] + 20 and centre[1] > centre[2] + 20, f"apple is not green: {centre}"
    finally:
        built.client.disconnect()


def test_unknown_colour_is_a_cdf_error():
    with pytest.raises(CDFError, match="unknown colour 'blurple'"):
        parse_colour("blurple")
