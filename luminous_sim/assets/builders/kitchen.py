"""Kitchen appliances and fixtures: fridge, microwave, counters, sink, faucet, stove, toaster, coffee machine."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import carcass, hinged_door, pick
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part, Region


@register("Fridge", variants=4, category="appliance")
def fridge(v: int, rng: np.random.Generator) -> AssetSpec:
    """A fridge: an insulated body with glass shelves and a hinged door carrying door shelves.

    Variants: single door left/right hinge, tall or short, white/steel/black.
    """
    w = pick(rng, 0.6, 0.75)
    d = pick(rng, 0.62, 0.72)
    h = [1.75, 1.8, 1.55, 1.85][v]
    t = 0.05
    slot = "appliance"
    parts = carcass(w, d - 0.04, h, t, slot)
    for p in parts:
        p.mesh.apply_translation((0, -0.02, 0))
    y_front = d / 2 - 0.04
    shelf_zs = [round(z, 3) for z in np.linspace(t + 0.35, h - t - 0.3, 3)]
    inner_w, inner_d = w - 2 * t, d - 0.04 - t
    for z in shelf_zs:
        parts.append(Part(g.box((inner_w, inner_d - 0.02, 0.01), (0, -0.02 + t / 2 - 0.01, z)), "glass"))
    parts.append(Part(g.box((w, 0.03, 0.03), (0, y_front, h - 0.03)), "dark_plastic"))
    hinge = "left" if v % 2 == 0 else "right"
    sign = 1 if hinge == "left" else -1
    door_shelves = []
    for z in (0.45, 0.85, 1.25):
        x0, x1 = sorted((sign * 0.06, sign * (w - 0.06)))
        door_shelves.append(Part(g.box_at((x0, -0.09, z), (x1, 0.0, z + 0.012)), "glass"))
        door_shelves.append(Part(g.box_at((x0, -0.09, z), (x1, -0.08, z + 0.06)), "glass"))
    door, joint = hinged_door("door", "base", -w / 2, w / 2, y_front, 0.02, h - 0.04, hinge, slot,
                              thickness=0.05, extra=door_shelves, mass=8.0)
    regions = []
    levels = [t] + shelf_zs
    tops = shelf_zs + [h - t]
    for i, (z0, z1) in enumerate(zip(levels, tops)):
        z0 = z0 + (0.01 if i else 0.0)
        regions.append(Region(f"shelf_{i}", "volume", (0.0, -0.02 + t / 2, (z0 + z1) / 2),
                              (inner_w - 0.02, inner_d - 0.04, z1 - z0 - 0.01), requires_open=joint.name))
    return AssetSpec(
        "Fridge", v, "appliance", [Link("base", parts, 60.0), door], joints=[joint], regions=regions,
        description="fridge with shelves and a hinged door with door shelves",
    )
