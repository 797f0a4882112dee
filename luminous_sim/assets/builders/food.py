"""Food: fruit, vegetables, bread and eggs, with their slices (small, pickupable)."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick
from luminous_sim.assets.registry import register, variant_rng
from luminous_sim.assets.spec import AssetSpec, Link, Part, SliceSpec

APPLE_SLICES = 6


def _apple_radius(v: int) -> float:
    return pick(variant_rng("Apple", v), 0.036, 0.045)


@register("Apple", variants=3, category="small")
def apple(v: int, rng: np.random.Generator) -> AssetSpec:
    """A round apple, slightly flattened, with a dimple, a stem and (variant 2) a leaf."""
    r = _apple_radius(v)
    squash = [0.9, 0.95, 0.86][v]
    body = g.ellipsoid((r, r, r * squash), (0, 0, r * squash), subdivisions=3)
    stem = g.cylinder(0.003, 0.018, (0, 0, 2 * r * squash + 0.004), sections=6)
    parts = [Part(body, "apple"), Part(stem, "stem", collide=False)]
    if v == 2:
        leaf = g.ellipsoid((0.012, 0.005, 0.0015), (0.01, 0, 2 * r * squash + 0.01))
        parts.append(Part(leaf, "plant", collide=False))
    ring = 0.62 * r
    poses = [(ring * np.cos(a), ring * np.sin(a), 0.0, float(a)) for a in np.linspace(0, 2 * np.pi, APPLE_SLICES,
                                                                                     endpoint=False)]
    return AssetSpec(
        "Apple", v, "small", [Link("base", parts, 0.18)],
        slices=SliceSpec("AppleSliced", APPLE_SLICES, [tuple(round(float(x), 4) for x in p) for p in poses]),
        description="apple",
    )


@register("AppleSliced", variants=3, category="small")
def apple_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """One wedge of the matching Apple variant, lying skin-down-outwards; origin at its bottom centre."""
    r = _apple_radius(v)
    squash = [0.9, 0.95, 0.86][v]
    half = np.pi / APPLE_SLICES
    # a wedge: a fan of the apple's outline between -half and +half, extruded radially (pointing +x)
    n = 6
    angles = np.linspace(-half, half, n)
    outline = [(0.0, 0.0)] + [(r * np.cos(a), r * np.sin(a)) for a in angles]
    wedge = g.extrude(outline, 2 * r * squash * 0.9)
    wedge.apply_translation((-0.62 * r, 0, 0))
    return AssetSpec("AppleSliced", v, "small", [Link("base", [Part(wedge, "apple_flesh", convex=True)],
                                                      0.18 / APPLE_SLICES)], description="apple wedge")
