"""Lamps, electronics on display, decorations and room structure pieces (windows, blinds, paintings...)."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part


@register("DeskLamp", variants=3, category="small")
def desk_lamp(v: int, rng: np.random.Generator) -> AssetSpec:
    """A desk lamp: weighted base, stem, conical shade; the bulb glows when switched on."""
    base_r = pick(rng, 0.07, 0.09)
    stem_h = [0.3, 0.36, 0.26][v]
    parts = [Part(g.cylinder(base_r, 0.025, (0, 0, 0.0125), sections=20), "dark_metal")]
    parts.append(Part(g.cylinder(0.01, stem_h, (0, 0, 0.025 + stem_h / 2), sections=8), "metal"))
    top = 0.025 + stem_h
    shade_h = 0.14
    rb, rt = [(0.1, 0.06), (0.09, 0.09), (0.11, 0.04)][v]
    shade = g.container([(rb, 0.0), (rt, shade_h)], wall=0.006, bottom=0.004, sections=20)
    shade.apply_transform(np.diag([1, 1, -1, 1]))  # opening faces down
    shade.apply_translation((0, 0, top + shade_h - 0.02))
    shade.invert()
    parts.append(Part(shade, "fabric", convex=True))
    bulb = g.sphere(0.03, (0, 0, top + 0.02))
    parts.append(Part(bulb, "porcelain", state="off"))
    parts.append(Part(g.sphere(0.032, (0, 0, top + 0.02)), "glow", state="on"))
    parts.append(Part(g.frustum(rb * 0.98, rt * 0.98, shade_h * 0.9, (0, 0, top - 0.01)), "glow", state="on"))
    return AssetSpec("DeskLamp", v, "small", [Link("base", parts, 1.5)], description="desk lamp that lights up")
