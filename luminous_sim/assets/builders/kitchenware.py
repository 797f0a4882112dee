"""Kitchenware and tableware: vessels, cutlery, utensils, bottles (small, pickupable)."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part, Region


@register("Mug", variants=4, category="small")
def mug(v: int, rng: np.random.Generator) -> AssetSpec:
    """A mug: a thick-walled cylinder (straight, tapered, barrel or tall) with a side handle."""
    r = pick(rng, 0.037, 0.045)
    h = [0.095, 0.09, 0.1, 0.12][v]
    flare = [1.0, 1.15, 0.92, 1.0][v]
    profile = [(r, 0.0), (r * (1 + flare) / 2 * 1.0, h * 0.5), (r * flare, h)]
    if v == 2:  # barrel: widest in the middle
        profile = [(r * 0.9, 0.0), (r * 1.05, h * 0.5), (r * 0.9, h)]
    body = g.container(profile, wall=0.005, bottom=0.008, sections=24)
    handle = g.torus_arc(0.026, 0.0065, (r * max(flare, 1.0) + 0.004, 0.0, h * 0.52), plane="xz",
                         start=-np.pi / 2, end=np.pi / 2, sections=10)
    parts = [Part(body, "ceramic", convex=False), Part(handle, "ceramic", convex=False)]
    stain = g.cylinder(r * 0.85, 0.002, (0, 0, 0.009), sections=16)
    parts.append(Part(stain, "dirt", state="dirty"))
    inner = min(p[0] for p in profile) - 0.006
    return AssetSpec(
        "Mug", v, "small", [Link("base", parts, 0.3)],
        regions=[Region("inside", "volume", (0.0, 0.0, 0.008 + (h - 0.008) / 2), (inner * 1.4, inner * 1.4, h - 0.008))],
        description="ceramic mug with a handle and a cavity",
    )
