"""Seating and beds: chairs, armchairs, sofas, ottomans, footstools, beds (furniture)."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import corner_legs, pick, surface
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part


@register("Chair", variants=4, category="furniture")
def chair(v: int, rng: np.random.Generator) -> AssetSpec:
    """A dining/desk chair: four legs, a seat and a back (slatted, solid, ladder or round-legged)."""
    w, d = pick(rng, 0.42, 0.5), pick(rng, 0.42, 0.5)
    seat_h = pick(rng, 0.44, 0.48)
    back_h = pick(rng, 0.4, 0.5)
    t = 0.035
    slot = ["wood", "dark_wood", "painted", "metal"][v]
    parts = corner_legs(w, d, seat_h - t, 0.03, 0.018, slot, square=v in (0, 1))
    parts.append(Part(g.box((w, d, t), (0, 0, seat_h - t / 2)), "cushion" if v == 2 else slot))
    back_y = -d / 2 + 0.02
    for sx in (-1, 1):  # back posts continue the rear legs
        parts.append(Part(g.box((0.035, 0.035, back_h), (sx * (w / 2 - 0.03), back_y, seat_h + back_h / 2)), slot))
    if v == 0:  # vertical slats
        for x in np.linspace(-w / 2 + 0.1, w / 2 - 0.1, 4):
            parts.append(Part(g.box((0.03, 0.018, back_h * 0.7), (x, back_y, seat_h + back_h * 0.45)), slot))
        parts.append(Part(g.box((w - 0.04, 0.025, 0.06), (0, back_y, seat_h + back_h - 0.03)), slot))
    elif v == 2:  # ladder back
        for z in np.linspace(seat_h + 0.12, seat_h + back_h - 0.04, 3):
            parts.append(Part(g.box((w - 0.06, 0.02, 0.05), (0, back_y, z)), slot))
    else:  # solid panel
        parts.append(Part(g.box((w - 0.05, 0.025, back_h * 0.75), (0, back_y, seat_h + back_h * 0.55)), slot))
    return AssetSpec(
        "Chair", v, "furniture", [Link("base", parts, 5.0)],
        regions=[surface("seat", w, d - 0.05, seat_h, 0.4, cy=0.025)],
        description="chair with four legs, a seat and a back",
    )
