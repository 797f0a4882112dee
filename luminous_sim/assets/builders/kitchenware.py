"""Kitchenware and tableware: vessels, cutlery, utensils, bottles (small, pickupable).

Vessels with a cavity (mugs, cups, bowls, plates, pots, pans) are single revolved meshes decomposed by
coacd; everything else is built from convex pieces (boxes, cylinders, frusta, extruded outlines) so that
the collision shape is exact and free. Utensils are built lying on the floor along x: blades and flat
handles on z = 0, spoon and ladle bowls on a small flat spot with the handle sloping down to touch the
floor at its end. Dirtyable vessels carry a "dirty" state visual of food residue and grime.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, robust_mass, surface
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part, Region

add_palettes(
    kw_sponge=hex_colours("f2d43d", "f5c542", "8fd14f", "f29bb0"),
    kw_scrubber=hex_colours("2f7d3a", "1f5f8b", "3a3a3a"),
    kw_soap=hex_colours("7cc4b0", "e8a0b4", "f0c75e", "9fc5e8", "f4f1e8"),
    kw_pump=hex_colours("f4f4f4", "222222", "c0c4c8"),
    kw_wine_glass=hex_colours("1f3d25", "4a3016", "16261b", "5b6b3a"),
    kw_label=hex_colours("f3ecd8", "efe6cc", "faf6ea", "e9dcc0", "1d1d1d"),
    kw_foil=hex_colours("7a1f2b", "c9a44a", "1a1a1a", "d8d8d8"),
    kw_cardboard=hex_colours("b08d5e", "9c7b4f"),
    kw_nonstick=hex_colours("3c3f44", "45484d", "33363a"),
    kw_enamel=hex_colours("c0392b", "2e5e8c", "3f7d5a", "e0b43a"),
    kw_silicone=hex_colours("d64545", "3f88c5", "f2f2f2", "5aa469"),
    kw_paper_shade=hex_colours("e2ddd0", "d8d2c2"),
)

Pt = Sequence[float]


# --------------------------------------------------------------------------------------------------
# helpers


def _link(parts: list[Part], mass: float) -> list[Link]:
    """The single base link of a small object, its mass kept clear of PyBullet's inertia check."""
    return [Link("base", parts, robust_mass(parts, mass))]


def _profile_r(profile: Sequence[tuple[float, float]], z: float) -> tuple[float, float]:
    """Outer radius of a vessel profile at height z, and the wall's slope dr/dz there."""
    rs = np.array([p[0] for p in profile])
    zs = np.array([p[1] for p in profile])
    r = float(np.interp(z, zs, rs))
    i = int(np.clip(np.searchsorted(zs, z), 1, len(zs) - 1))
    slope = float((rs[i] - rs[i - 1]) / max(zs[i] - zs[i - 1], 1e-6))
    return r, slope


def _wall_stain(profile: Sequence[tuple[float, float]], wall: float, z: float, angle: float, w: float, h: float,
                inside: bool) -> trimesh.Trimesh:
    """A smear lying on a vessel wall (inside or outside) at height z and polar angle `angle`."""
    r, slope = _profile_r(profile, z)
    r = r - wall if inside else r
    return g.oval_patch((h, w, 0.0012), (r * np.cos(angle), r * np.sin(angle), z), yaw=angle,
                        pitch=float(np.arctan2(slope, 1.0)) - np.pi / 2)


def _floor_stains(r_in: float, z: float, seed: int, n: int = 5) -> list[trimesh.Trimesh]:
    """Food residue on a vessel floor of inner radius r_in: one off-centre smear and some blobs."""
    rng = np.random.default_rng(seed)
    out = [g.transformed(g.cylinder(0.55 * r_in, 0.0012, sections=14), offset=(0.18 * r_in, -0.1 * r_in, z + 0.0006))]
    for k in range(n):
        a = 2 * np.pi * k / n + round(float(rng.uniform(0, 0.6)), 3)
        rho = round(float(rng.uniform(0.35, 0.7)), 3) * r_in
        size = round(float(rng.uniform(0.1, 0.18)), 3) * r_in
        out.append(g.oval_patch((size, 0.6 * size, max(0.0015, 0.2 * size)), (rho * np.cos(a), rho * np.sin(a),
                                                                              z + 0.0008),
                                yaw=a))
    return out


def _vessel_dirt(profile: Sequence[tuple[float, float]], wall: float, bottom: float, seed: int,
                 outside: bool = True) -> list[Part]:
    """A dirty vessel: residue on the floor, smears on the inner wall and (optionally) drips outside."""
    r_floor = _profile_r(profile, bottom)[0] - wall
    meshes = _floor_stains(r_floor, bottom, seed)
    h = profile[-1][1]
    for zf, a in [(0.55, 0.4), (0.7, 2.3), (0.4, 4.0)]:
        z = bottom + zf * (h - bottom)
        meshes.append(_wall_stain(profile, wall + 0.0004, z, a + np.pi / 2, 0.14 * r_floor + 0.006,
                                  0.12 * (h - bottom) + 0.004, inside=True))
    if outside:
        for zf, a in [(0.45, 0.9), (0.3, 1.5)]:
            z = zf * h
            meshes.append(_wall_stain(profile, 0.0, z, a, 0.0045, 0.1 * h, inside=False))
    return [Part(m, "dirt", state="dirty") for m in meshes]


def _volume(r_in: float, bottom: float, top: float) -> Region:
    """The interior of a round vessel: a box inside its inner radius from the floor to the rim."""
    return Region("inside", "volume", (0.0, 0.0, round((bottom + top) / 2, 4)),
                  (round(1.4 * r_in, 4), round(1.4 * r_in, 4), round(top - bottom, 4)))


def _centered_x(parts: list[Part]) -> list[Part]:
    """Shift a lying utensil so its collision footprint is centred on x = 0 and its bottom is at z = 0."""
    bounds = np.array([p.mesh.bounds for p in parts if p.collide])
    lo, hi = bounds[:, 0].min(axis=0), bounds[:, 1].max(axis=0)
    shift = (-(lo[0] + hi[0]) / 2, 0.0, -lo[2])
    for p in parts:
        p.mesh.apply_translation(shift)
    return parts


# --------------------------------------------------------------------------------------------------
# Vessels


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
    # coffee drips down the outside and a tide line inside the rim: dirt that shows from any side
    out_r = max(p[0] for p in profile) + 0.0015
    for k, a in enumerate(np.linspace(0.4, 2 * np.pi + 0.4, 5, endpoint=False)):
        drip = g.ellipsoid((0.006, 0.0025, 0.012 + 0.004 * (k % 2)), (0, 0, 0))
        parts.append(Part(g.transformed(drip, yaw=float(a), offset=(out_r * np.cos(a), out_r * np.sin(a),
                                                                       h * (0.62 + 0.08 * (k % 3)))), "dirt",
                          state="dirty"))
    ring = g.container([(min(p[0] for p in profile) - 0.0045, h * 0.72), (min(p[0] for p in profile) - 0.0045,
                                                                        h * 0.8)], wall=0.001, bottom=0.0,
                       sections=20)
    parts.append(Part(ring, "dirt", state="dirty"))
    inner = min(p[0] for p in profile) - 0.006
    return AssetSpec(
        "Mug", v, "small", [Link("base", parts, 0.3)],
        regions=[Region("inside", "volume", (0.0, 0.0, 0.008 + (h - 0.008) / 2), (inner * 1.4, inner * 1.4,
                                                                                  h - 0.008))],
        description="ceramic mug with a handle and a cavity",
    )


@register("Cup", variants=3, category="small")
def cup(v: int, rng: np.random.Generator) -> AssetSpec:
    """A drinking glass: a straight tumbler, a tall tapered pint glass or a heavy-based rocks glass."""
    if v == 0:
        r, h = pick(rng, 0.034, 0.037), pick(rng, 0.1, 0.11)
        profile = [(0.9 * r, 0.0), (0.95 * r, 0.5 * h), (r, h)]
        bottom = 0.008
    elif v == 1:
        r, h = pick(rng, 0.04, 0.043), pick(rng, 0.14, 0.15)
        profile = [(0.68 * r, 0.0), (0.72 * r, 0.01), (0.93 * r, 0.75 * h), (r, 0.9 * h), (0.99 * r, h)]
        bottom = 0.01
    else:
        r, h = pick(rng, 0.041, 0.044), pick(rng, 0.078, 0.085)
        profile = [(r - 0.003, 0.0), (r, 0.004), (r, h)]
        bottom = 0.016
    wall = 0.004
    body = g.container(profile, wall=wall, bottom=bottom, sections=24)
    parts = [Part(body, "glass", convex=False)]
    parts += _vessel_dirt(profile, wall, bottom, seed=10 + v)
    ring = g.torus_arc(_profile_r(profile, 0.6 * h)[0] - wall, 0.0012, (0, 0, 0.6 * h), plane="xy",
                       start=0.0, end=2 * np.pi, sections=20, minor_sections=4)
    parts.append(Part(ring, "dirt", state="dirty"))
    r_in = min(p[0] for p in profile) - wall
    return AssetSpec("Cup", v, "small", [Link("base", parts, 0.25)], regions=[_volume(r_in, bottom, h)],
                     description=["glass tumbler", "pint glass", "rocks glass"][v])


@register("Bowl", variants=3, category="small")
def bowl(v: int, rng: np.random.Generator) -> AssetSpec:
    """A bowl on a foot ring: a rounded cereal bowl, a wide flared serving bowl or a deep noodle bowl."""
    if v == 0:
        rt, h, rf = pick(rng, 0.072, 0.078), pick(rng, 0.055, 0.062), 0.036
        curve = [(rf + 0.006 + (rt - rf - 0.006) * np.sin(a), 0.008 + (h - 0.008) * (1 - np.cos(a)))
                 for a in np.linspace(0.25, np.pi / 2, 6)]
    elif v == 1:
        rt, h, rf = pick(rng, 0.105, 0.115), pick(rng, 0.07, 0.078), 0.05
        curve = [(rf + 0.01, 0.01), (rf + 0.045, 0.035), (rt - 0.006, h - 0.006), (rt, h)]
    else:
        rt, h, rf = pick(rng, 0.082, 0.09), pick(rng, 0.08, 0.088), 0.034
        curve = [(rf + 0.008 + (rt - rf - 0.008) * np.sin(a) ** 0.8, 0.012 + (h - 0.012) * (1 - np.cos(a)) ** 0.9)
                 for a in np.linspace(0.3, np.pi / 2, 6)]
    profile = [(rf, 0.0), (rf, 0.006)] + [(float(x), float(z)) for x, z in curve]
    wall, bottom = 0.005, 0.009
    body = g.container(profile, wall=wall, bottom=bottom, sections=24)
    parts = [Part(body, "ceramic", convex=False)] + _vessel_dirt(profile, wall, bottom, seed=20 + v)
    r_in = _profile_r(profile, bottom + 0.3 * (h - bottom))[0] - wall
    return AssetSpec("Bowl", v, "small", [Link("base", parts, 0.35)],
                     regions=[_volume(max(r_in, 0.6 * rt), bottom, h)],
                     description=["cereal bowl", "serving bowl", "noodle bowl"][v])


@register("Plate", variants=3, category="small")
def plate(v: int, rng: np.random.Generator) -> AssetSpec:
    """A plate with a flat well and a raised rim: a dinner plate, a deep-rimmed side plate, a square plate."""
    parts: list[Part] = []
    if v < 2:
        big_r = pick(rng, 0.125, 0.135) if v == 0 else pick(rng, 0.095, 0.105)
        rim_h = 0.022 if v == 0 else 0.028
        well = (0.64 if v == 0 else 0.55) * big_r
        foot, t = 0.45 * big_r, 0.007
        pts = [(0.0, 0.0), (foot, 0.0), (foot + 0.004, 0.004), (well + 0.01, 0.007), (big_r, rim_h - 0.004),
               (big_r, rim_h), (big_r - 0.005, rim_h), (well, t + 0.001), (well - 0.01, t), (0.0, t)]
        parts.append(Part(g.revolve(pts, sections=28), "ceramic", convex=False))
        top_w = max(2 * well * 0.72, 1.05 * big_r)  # room for an apple or a mug on a side plate
    else:
        side = pick(rng, 0.21, 0.23)
        well, t, rise, th = 0.66 * side, 0.008, 0.014, 0.005
        parts.append(Part(g.extrude(g.rounded_outline(well, well, 0.01), t), "ceramic", convex=True))
        for k in range(4):  # four mitred rim pieces rising from the well's edges to the outer edge
            corners = []
            for dz in (0.0, th):
                corners += [(-well / 2, well / 2 - 0.002, t - th + dz), (well / 2, well / 2 - 0.002, t - th + dz),
                            (-side / 2, side / 2, t - th + rise + dz), (side / 2, side / 2, t - th + rise + dz)]
            rim = trimesh.convex.convex_hull(np.array(corners))
            parts.append(Part(g.transformed(rim, yaw=k * np.pi / 2), "ceramic", convex=True))
        well = 0.5 * well
        top_w = 2 * well * 0.9
    # dirty: sauce smears and crumbs on the well
    rng_d = np.random.default_rng(30 + v)
    dirt = [g.transformed(g.cylinder(0.45 * well, 0.001, sections=14), offset=(0.2 * well, 0.1 * well, t + 0.0005))]
    for k in range(7):
        a = 2 * np.pi * k / 7 + round(float(rng_d.uniform(0, 0.5)), 3)
        rho = round(float(rng_d.uniform(0.25, 0.8)), 3) * well
        s = round(float(rng_d.uniform(0.05, 0.12)), 3) * well
        dirt.append(g.oval_patch((s * 1.6, s, 0.002), (rho * np.cos(a), rho * np.sin(a), t + 0.0008), yaw=a))
    parts += [Part(m, "dirt", state="dirty") for m in dirt]
    return AssetSpec("Plate", v, "small", [Link("base", parts, 0.4)],
                     regions=[surface("top", top_w, top_w, t, 0.35, margin=0.0)],
                     description=["dinner plate", "side plate", "square plate"][v])


@register("Pot", variants=3, category="small")
def pot(v: int, rng: np.random.Generator) -> AssetSpec:
    """An open cooking pot with two side handles: a tall stock pot, an enamelled Dutch oven, a saucepot."""
    if v == 0:
        r, h = pick(rng, 0.105, 0.115), pick(rng, 0.16, 0.18)
        profile = [(r - 0.005, 0.0), (r, 0.005), (r, h)]
        body_slot, handle_slot = "metal", "metal"
    elif v == 1:
        r, h = pick(rng, 0.115, 0.125), pick(rng, 0.095, 0.105)
        profile = [(r - 0.018, 0.0), (r - 0.006, 0.004), (r - 0.001, 0.014), (r, 0.03), (r, h)]
        body_slot, handle_slot = "kw_enamel", "kw_enamel"
    else:
        r, h = pick(rng, 0.085, 0.095), pick(rng, 0.105, 0.115)
        profile = [(r - 0.006, 0.0), (r, 0.006), (r, h - 0.006), (r + 0.004, h)]
        body_slot, handle_slot = "metal", "dark_plastic"
    wall, bottom = 0.005, 0.007
    parts = [Part(g.container(profile, wall=wall, bottom=bottom, sections=24), body_slot, convex=False)]
    for s in (-1, 1):
        if v == 0:  # horizontal loops riveted to the wall
            a0 = -np.pi / 2 if s > 0 else np.pi / 2
            loop = g.torus_arc(0.03, 0.0055, (s * (r - 0.004), 0.0, h - 0.028), plane="xy", start=a0,
                               end=a0 + np.pi, sections=10)
            parts.append(Part(loop, handle_slot, convex=False))
        elif v == 1:  # cast lugs
            lug = g.extrude(g.rounded_outline(0.04, 0.07, 0.012), 0.012, h - 0.03)
            lug.apply_translation((s * (r + 0.012), 0.0, 0.0))
            parts.append(Part(lug, handle_slot, convex=True))
        else:  # vertical loops, like a mug's handle
            a0 = -np.pi / 2 if s > 0 else np.pi / 2
            loop = g.torus_arc(0.022, 0.006, (s * (r - 0.002), 0.0, h - 0.035), plane="xz", start=a0,
                               end=a0 + np.pi, sections=10)
            parts.append(Part(loop, handle_slot, convex=False))
    parts += _vessel_dirt(profile, wall, bottom, seed=40 + v)
    tide = g.torus_arc(r - wall, 0.0018, (0, 0, bottom + 0.45 * (h - bottom)), plane="xy", start=0.0,
                       end=2 * np.pi, sections=20, minor_sections=4)
    parts.append(Part(tide, "dirt", state="dirty"))
    r_in = min(p[0] for p in profile[1:]) - wall
    return AssetSpec("Pot", v, "small", [Link("base", parts, 1.5)], regions=[_volume(r_in, bottom, h)],
                     description=["stock pot", "Dutch oven", "saucepot"][v])


@register("Pan", variants=3, category="small")
def pan(v: int, rng: np.random.Generator) -> AssetSpec:
    """A frying pan with a long handle along +x: a flared skillet, a straight-sided saute pan, a crepe pan."""
    if v == 0:
        rb, h = pick(rng, 0.09, 0.1), pick(rng, 0.042, 0.048)
        rt = rb + 0.03
        profile = [(rb - 0.006, 0.0), (rb, 0.005), (rt, h)]
        wall, bottom = 0.004, 0.005
    elif v == 1:
        rb, h = pick(rng, 0.115, 0.125), pick(rng, 0.06, 0.068)
        rt = rb + 0.003
        profile = [(rb - 0.008, 0.0), (rb, 0.007), (rt, h)]
        wall, bottom = 0.004, 0.006
    else:
        rb, h = pick(rng, 0.115, 0.125), 0.02
        rt = rb + 0.012
        profile = [(rb - 0.004, 0.0), (rb, 0.003), (rt, h)]
        wall, bottom = 0.0035, 0.004
    parts = [Part(g.container(profile, wall=wall, bottom=bottom, sections=28), "metal", convex=False)]
    coat = g.cylinder(rb - wall - 0.001, 0.0008, (0, 0, bottom + 0.0004), sections=28)
    parts.append(Part(coat, "kw_nonstick", collide=False))
    # the handle: a riveted bracket on the rim and a long grip rising gently away from the pan
    x0 = rt - 0.004
    z0 = h - 0.012 if v != 2 else h - 0.006
    if v == 0:
        parts.append(Part(g.box_at((x0 - 0.004, -0.013, z0 - 0.012), (x0 + 0.03, 0.013, z0 + 0.006)), "metal",
                          convex=True))
        parts.append(Part(g.tapered_rod((x0 + 0.02, 0, z0), (x0 + 0.2, 0, z0 + 0.03), 0.011, 0.013, 12),
                          "dark_plastic", convex=True))
    elif v == 1:
        grip = [(0.0, -0.011), (0.2, -0.015), (0.21, -0.01), (0.21, 0.01), (0.2, 0.015), (0.0, 0.011)]
        parts.append(Part(g.box_at((x0 - 0.004, -0.012, z0 - 0.014), (x0 + 0.025, 0.012, z0 + 0.004)), "metal",
                          convex=True))
        parts.append(Part(g.tilted_plate(grip, 0.014, (x0 + 0.015, 0.0, z0 - 0.012), x0 + 0.22, z0 + 0.02),
                          "metal", convex=True))
        helper = g.torus_arc(0.02, 0.005, (-(rt - 0.002), 0.0, h - 0.014), plane="xy", start=np.pi / 2,
                             end=1.5 * np.pi, sections=8)
        parts.append(Part(helper, "metal", convex=False))
    else:
        parts.append(Part(g.box_at((x0 - 0.004, -0.009, 0.004), (x0 + 0.03, 0.009, 0.014)), "metal", convex=True))
        parts.append(Part(g.tapered_rod((x0 + 0.025, 0, 0.012), (x0 + 0.045, 0, 0.016), 0.009, 0.009, 10), "metal",
                          convex=True))
        parts.append(Part(g.tapered_rod((x0 + 0.045, 0, 0.016), (x0 + 0.21, 0, 0.036), 0.0095, 0.012, 10), "wood",
                          convex=True))
    parts += _vessel_dirt(profile, wall, bottom, seed=50 + v, outside=False)
    return AssetSpec("Pan", v, "small", [Link("base", parts, 1.0)], regions=[_volume(rb - wall, bottom, h)],
                     description=["frying pan", "saute pan", "crepe pan"][v])


@register("Kettle", variants=3, category="small")
def kettle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A kettle with a spout towards -x: a stovetop kettle with a top handle, an electric jug kettle on its
    power base, a slim gooseneck pour-over kettle."""
    parts: list[Part] = []
    if v == 0:
        rb, h = pick(rng, 0.09, 0.1), pick(rng, 0.14, 0.155)
        body = [(0.0, 0.0), (rb - 0.006, 0.0), (rb, 0.008), (rb * 0.98, 0.04), (rb * 0.84, 0.09 * h / 0.15),
                (rb * 0.63, h - 0.01), (rb * 0.55, h), (0.0, h)]
        parts.append(Part(g.revolve(body, sections=24), "metal", convex=True))
        lid = [(0.0, 0.0), (rb * 0.56, 0.0), (rb * 0.5, 0.008), (rb * 0.3, 0.017), (0.0, 0.02)]
        parts.append(Part(g.revolve(lid, (0, 0, h), sections=20), "metal", convex=True))
        parts.append(Part(g.sphere(0.011, (0, 0, h + 0.026), subdivisions=1), "dark_plastic", convex=True))
        spout0, spout1 = (-rb * 0.7, 0, 0.045), (-rb - 0.05, 0, h - 0.01)
        parts.append(Part(g.tapered_rod(spout0, spout1, 0.017, 0.008), "metal", convex=True))
        parts.append(Part(g.tapered_rod(spout1, (spout1[0] - 0.01, 0, spout1[2] + 0.006), 0.009, 0.009, 10),
                          "dark_plastic", convex=True))
        top = h + 0.085
        for s in (-1, 1):  # two posts from the shoulder and a grip across the top
            parts.append(Part(g.rod((s * rb * 0.6, 0, h - 0.012), (s * 0.045, 0, top), 0.005, 8), "metal",
                              convex=True))
        parts.append(Part(g.cylinder(0.011, 0.1, (0, 0, top), axis="x", sections=12), "dark_plastic", convex=True))
    elif v == 1:
        rb, h = pick(rng, 0.075, 0.08), pick(rng, 0.21, 0.23)
        parts.append(Part(g.cylinder(rb + 0.01, 0.022, (0, 0, 0.011), sections=24), "dark_plastic", convex=True))
        body = [(0.0, 0.022), (rb, 0.022), (rb * 0.94, h - 0.015), (rb * 0.88, h), (0.0, h)]
        parts.append(Part(g.revolve(body, sections=24), "appliance", convex=True))
        parts.append(Part(g.cylinder(rb * 0.7, 0.01, (0, 0, h + 0.005), sections=20), "dark_plastic", convex=True))
        parts.append(Part(g.box((0.02, 0.03, 0.008), (0, 0, h + 0.013)), "appliance", convex=True))
        beak = trimesh.convex.convex_hull(np.array([
            (-rb * 0.8, -0.022, h - 0.04), (-rb * 0.8, 0.022, h - 0.04), (-rb * 0.8, -0.028, h + 0.002),
            (-rb * 0.8, 0.028, h + 0.002), (-rb - 0.03, -0.008, h + 0.008), (-rb - 0.03, 0.008, h + 0.008)]))
        parts.append(Part(beak, "appliance", convex=True))
        window = g.box((0.004, 0.022, 0.12), (-rb * 0.96, rb * 0.28, 0.04 + 0.07))
        parts.append(Part(g.transformed(window, yaw=-0.3), "glass", collide=False))
        hx = rb + 0.045
        parts.append(Part(g.rod((hx, 0, 0.06), (hx - 0.008, 0, h - 0.02), 0.012, 10), "dark_plastic", convex=True))
        parts.append(Part(g.box_at((rb * 0.85, -0.011, h - 0.035), (hx + 0.005, 0.011, h - 0.005)), "dark_plastic",
                          convex=True))
        parts.append(Part(g.box_at((rb * 0.9, -0.011, 0.045), (hx + 0.008, 0.011, 0.07)), "dark_plastic",
                          convex=True))
    else:
        rb, h = pick(rng, 0.065, 0.07), pick(rng, 0.11, 0.12)
        body = [(0.0, 0.0), (rb - 0.004, 0.0), (rb, 0.005), (rb * 0.9, h - 0.012), (rb * 0.72, h), (0.0, h)]
        parts.append(Part(g.revolve(body, sections=24), "dark_metal", convex=True))
        parts.append(Part(g.cylinder(rb * 0.68, 0.008, (0, 0, h + 0.004), sections=20), "dark_metal", convex=True))
        parts.append(Part(g.cylinder(0.008, 0.02, (0, 0, h + 0.016), sections=10), "wood", convex=True))
        neck = [(-rb * 0.8, 0, 0.02), (-rb - 0.03, 0, 0.035), (-rb - 0.045, 0, h - 0.01),
                (-rb - 0.09, 0, h + 0.005)]
        radii = [(0.011, 0.008), (0.008, 0.0065), (0.0065, 0.005)]
        for (a, b_), (r0, r1) in zip(itertools.pairwise(neck), radii):
            parts.append(Part(g.tapered_rod(a, b_, r0, r1, 10), "dark_metal", convex=True))
            parts.append(Part(g.sphere(r1, b_, subdivisions=1), "dark_metal", convex=True))
        hx = rb + 0.04
        parts.append(Part(g.rod((rb * 0.9, 0, h - 0.015), (hx, 0, h - 0.01), 0.007, 8), "wood", convex=True))
        parts.append(Part(g.rod((hx, 0, h - 0.01), (hx - 0.01, 0, 0.03), 0.01, 10), "wood", convex=True))
        parts.append(Part(g.rod((hx - 0.01, 0, 0.03), (rb * 0.95, 0, 0.02), 0.006, 8), "wood", convex=True))
    return AssetSpec("Kettle", v, "small", _link(parts, 1.0),
                     description=["stovetop kettle", "electric kettle", "gooseneck kettle"][v])


# --------------------------------------------------------------------------------------------------
# Knives and cutlery (lying flat along x)


@register("Knife", variants=4, category="small")
def knife(v: int, rng: np.random.Generator) -> AssetSpec:
    """A kitchen knife lying flat: a chef's knife, a bread knife, a paring knife, a cleaver."""
    if v == 0:
        lb, hb, lh = pick(rng, 0.19, 0.21), pick(rng, 0.042, 0.048), 0.12
        blade = [(0.0, -hb / 2), (0.6 * lb, -hb / 2), (0.85 * lb, -0.3 * hb), (0.97 * lb, 0.05 * hb),
                 (lb, 0.25 * hb), (0.8 * lb, hb / 2), (0.0, hb / 2)]
    elif v == 1:
        lb, hb, lh = pick(rng, 0.21, 0.23), pick(rng, 0.027, 0.03), 0.125
        blade = [(0.0, -hb / 2), (lb - 0.012, -hb / 2), (lb - 0.004, -hb / 2 + 0.004), (lb, 0.0), (lb - 0.004,
                                                                                                   hb / 2 - 0.004),
                 (lb - 0.012, hb / 2), (0.0, hb / 2)]
    elif v == 2:
        lb, hb, lh = pick(rng, 0.085, 0.095), pick(rng, 0.019, 0.022), 0.1
        blade = [(0.0, -hb / 2), (0.55 * lb, -hb / 2), (0.9 * lb, -0.1 * hb), (lb, 0.3 * hb), (0.0, hb / 2)]
    else:
        lb, hb, lh = pick(rng, 0.17, 0.19), pick(rng, 0.08, 0.09), 0.12
        blade = [(0.0, -hb / 2), (lb - 0.004, -hb / 2), (lb, -hb / 2 + 0.006), (lb, hb / 2), (0.0, hb / 2)]
    t = 0.0025
    y_spine = hb / 2
    grip_r = [0.0095, 0.0095, 0.0075, 0.011][v]
    yh = y_spine - grip_r  # the handle runs in line with the spine
    parts = [Part(g.extrude(blade, t), "metal", convex=True)]
    if v == 3:  # hanging hole
        parts.append(Part(g.cylinder(0.007, 0.0008, (lb - 0.025, hb / 2 - 0.02, t + 0.0004), sections=12),
                          "dark_metal", collide=False))
    handle = g.capsule(grip_r, lh - 2 * grip_r, (-lh / 2, yh, 0.0), axis="x")
    handle.apply_scale((1.0, 1.0, 0.85))
    handle.apply_translation((0, 0, grip_r * 0.85))
    slot = ["dark_plastic", "wood", "dark_wood", "dark_plastic"][v]
    parts.append(Part(handle, slot, convex=True))
    parts.append(Part(g.box_at((-0.012, yh - grip_r, 0.0), (0.004, y_spine, 2 * grip_r * 0.85)), "metal",
                      convex=True))
    for k in (0.3, 0.7):  # rivets
        parts.append(Part(g.cylinder(0.0022, 0.001, (-lh * k, yh, 2 * grip_r * 0.85 + 0.0003), sections=8),
                          "metal", collide=False))
    return AssetSpec("Knife", v, "small", _link(_centered_x(parts), 0.1),
                     description=["chef's knife", "bread knife", "paring knife", "cleaver"][v])


def _strip(length: float, w0: float, w1: float, end_round: bool = True) -> list[tuple[float, float]]:
    """A flat handle outline from x = 0 (width w0) to x = length (width w1), its far end rounded."""
    pts = [(0.0, -w0 / 2), (length - w1 / 2, -w1 / 2)]
    if end_round:
        pts += [(length - w1 / 2 + w1 / 2 * np.sin(a), -w1 / 2 * np.cos(a)) for a in np.linspace(0.4, np.pi - 0.4, 5)]
    else:
        pts += [(length, -w1 / 2), (length, w1 / 2)]
    pts += [(length - w1 / 2, w1 / 2), (0.0, w0 / 2)]
    return [(float(x), float(y)) for x, y in pts]


@register("ButterKnife", variants=3, category="small")
def butter_knife(v: int, rng: np.random.Generator) -> AssetSpec:
    """A table knife lying flat: a classic round-tipped knife, a wide spreader, a pointed dinner knife."""
    lh = [0.11, 0.095, 0.115][v]
    lb = [pick(rng, 0.095, 0.105), pick(rng, 0.065, 0.075), pick(rng, 0.1, 0.11)][v]
    wb = [0.019, 0.026, 0.018][v]
    if v == 0:
        blade = [(0.0, -0.004), (lb - wb / 2, -wb / 2)] + [
            (lb - wb / 2 + wb / 2 * np.sin(a), -wb / 2 * np.cos(a)) for a in np.linspace(0.3, np.pi - 0.3, 6)
        ] + [(lb - wb / 2, wb / 2), (0.0, 0.004)]
    elif v == 1:
        blade = [(0.0, -0.005), (0.02, -wb / 2), (lb - 0.01, -wb / 2), (lb, -wb / 2 + 0.01), (lb, wb / 2 - 0.004),
                 (lb - 0.006, wb / 2), (0.0, 0.005)]
    else:
        blade = [(0.0, -0.004), (0.02, -wb / 2), (0.75 * lb, -0.4 * wb), (lb, 0.2 * wb), (0.8 * lb, wb / 2),
                 (0.0, wb / 2)]
    blade = [(float(x), float(y)) for x, y in blade]
    parts = [Part(g.extrude(blade, 0.002), "metal", convex=True)]
    handle = _strip(lh, 0.008, [0.018, 0.02, 0.016][v])
    parts.append(Part(g.extrude([(-x, y) for x, y in handle][::-1], 0.0045), "metal", convex=True))
    return AssetSpec("ButterKnife", v, "small", _link(_centered_x(parts), 0.05),
                     description=["butter knife", "spreader", "table knife"][v])


@register("Fork", variants=3, category="small")
def fork(v: int, rng: np.random.Generator) -> AssetSpec:
    """A fork lying flat, tines towards +x: a dinner fork, a salad fork, a two-pronged carving fork."""
    lh = [pick(rng, 0.12, 0.13), pick(rng, 0.105, 0.115), pick(rng, 0.13, 0.14)][v]
    head_w = [0.025, 0.024, 0.02][v]
    tine_l = [0.036, 0.028, 0.065][v]
    n_tines = [4, 4, 2][v]
    parts: list[Part] = []
    if v == 2:  # wooden grip and a steel shank
        parts.append(Part(g.capsule(0.009, lh - 0.035, (-lh / 2 - 0.005, 0, 0.0), axis="x"), "wood", convex=True))
        parts[-1].mesh.apply_scale((1, 1, 0.8))
        parts[-1].mesh.apply_translation((0, 0, 0.0072))
        parts.append(Part(g.box_at((-0.01, -0.004, 0.0), (0.03, 0.004, 0.004)), "metal", convex=True))
        neck_x = 0.03
    else:
        handle = _strip(lh, 0.006, [0.02, 0.018][v])
        parts.append(Part(g.extrude([(-x, y) for x, y in handle][::-1], 0.0035), "metal", convex=True))
        neck_x = 0.0
    head = [(neck_x, -0.003), (neck_x + 0.018, -head_w / 2), (neck_x + 0.026, -head_w / 2),
            (neck_x + 0.026, head_w / 2), (neck_x + 0.018, head_w / 2), (neck_x, 0.003)]
    parts.append(Part(g.extrude(head, 0.0025), "metal", convex=True))
    tw = 0.0032 if n_tines == 4 else 0.004
    for k in range(n_tines):
        y = (k - (n_tines - 1) / 2) * (head_w - tw) / (n_tines - 1)
        x0 = neck_x + 0.024
        tine = [(x0, y - tw / 2), (x0 + tine_l - 0.004, y - tw / 2), (x0 + tine_l, y - 0.0007),
                (x0 + tine_l, y + 0.0007), (x0 + tine_l - 0.004, y + tw / 2), (x0, y + tw / 2)]
        parts.append(Part(g.extrude(tine, 0.0022), "metal", convex=True))
    return AssetSpec("Fork", v, "small", _link(_centered_x(parts), 0.05),
                     description=["dinner fork", "salad fork", "carving fork"][v])


def _lying_bowl(rx: float, ry: float, depth: float, flat: float, wall: float = 0.0015) -> trimesh.Trimesh:
    """An open oval bowl (spoon, ladle) standing on a small flat spot, opening up, centred at the origin."""
    profile = [(flat, 0.0)] + [(flat + (ry - flat) * np.sin(a), depth * (1 - np.cos(a))) for a in
                               np.linspace(0.35, np.pi / 2, 5)]
    mesh = g.container([(float(r), float(z)) for r, z in profile], wall=wall, bottom=wall, sections=20)
    mesh.apply_scale((rx / ry, 1.0, 1.0))
    return mesh


@register("Spoon", variants=4, category="small")
def spoon(v: int, rng: np.random.Generator) -> AssetSpec:
    """A spoon lying on its bowl with the handle sloping down to the floor: a tablespoon, a teaspoon,
    a round soup spoon, a wooden cooking spoon."""
    rx = [pick(rng, 0.029, 0.032), pick(rng, 0.021, 0.023), 0.026, pick(rng, 0.03, 0.034)][v]
    ry = [0.02, 0.0145, 0.024, 0.023][v]
    depth = [0.009, 0.007, 0.01, 0.008][v]
    lh = [0.135, 0.1, 0.13, 0.22][v]
    slot = "wood" if v == 3 else "metal"
    wall = 0.0035 if v == 3 else 0.0015
    parts = [Part(_lying_bowl(rx, ry, depth, 0.35 * ry, wall), slot, convex=True)]
    th = 0.006 if v == 3 else 0.003
    grip = _strip(lh, 0.007 if v != 3 else 0.012, [0.018, 0.013, 0.018, 0.02][v])
    parts.append(Part(g.tilted_plate(grip, th, (rx - 0.004, 0.0, depth - th), rx + lh, 0.0), slot, convex=True))
    return AssetSpec("Spoon", v, "small", _link(_centered_x(parts), 0.05),
                     description=["tablespoon", "teaspoon", "soup spoon", "wooden spoon"][v])


@register("Ladle", variants=3, category="small")
def ladle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A ladle resting on its bowl, the long handle sloping down to the floor: a steel soup ladle, a small
    sauce ladle, a wide nylon ladle."""
    r = [pick(rng, 0.043, 0.047), pick(rng, 0.028, 0.032), pick(rng, 0.04, 0.044)][v]
    depth = [0.036, 0.024, 0.026][v]
    lh = [0.24, 0.19, 0.23][v]
    slot = "dark_plastic" if v == 2 else "metal"
    wall = 0.003 if v == 2 else 0.002
    parts = [Part(_lying_bowl(r, r, depth, 0.4 * r, wall), slot, convex=True)]
    th = 0.006 if v == 2 else 0.004
    grip = _strip(lh, 0.012, 0.022 if v != 1 else 0.016)
    parts.append(Part(g.tilted_plate(grip, th, (r - 0.006, 0.0, depth - th), r + lh, 0.0), slot, convex=True))
    return AssetSpec("Ladle", v, "small", _link(_centered_x(parts), 0.15),
                     description=["soup ladle", "sauce ladle", "nylon ladle"][v])


@register("Spatula", variants=3, category="small")
def spatula(v: int, rng: np.random.Generator) -> AssetSpec:
    """A spatula lying flat: a slotted steel turner, a silicone scraper, a wooden spatula."""
    parts: list[Part] = []
    if v == 0:
        bl, bw = pick(rng, 0.085, 0.095), pick(rng, 0.07, 0.078)
        blade = [(0.0, -0.012), (0.012, -bw / 2), (bl, -bw / 2), (bl, bw / 2), (0.012, bw / 2), (0.0, 0.012)]
        parts.append(Part(g.extrude(blade, 0.0025), "metal", convex=True))
        for k in range(4):
            y = (k - 1.5) * bw * 0.2
            parts.append(Part(g.box((bl * 0.55, 0.005, 0.0008), (0.02 + bl * 0.3, y, 0.0029)), "dark_metal",
                              collide=False))
        parts.append(Part(g.rod((0.004, 0, 0.0012), (-0.04, 0, 0.02), 0.004, 8), "metal", convex=True))
        grip = _strip(0.17, 0.016, 0.022)
        parts.append(Part(g.tilted_plate(grip, 0.01, (-0.04, 0.0, 0.014), -0.2, 0.0),
                          "dark_plastic", convex=True))
    elif v == 1:
        bl, bw = pick(rng, 0.09, 0.1), pick(rng, 0.05, 0.056)
        parts.append(Part(g.extrude(g.rounded_outline(bl, bw, 0.012), 0.006, 0.0), "kw_silicone", convex=True))
        parts[-1].mesh.apply_translation((bl / 2, 0, 0))
        parts.append(Part(g.cylinder(0.0075, 0.2, (-0.1 + 0.004, 0, 0.0075), axis="x", sections=12), "wood",
                          convex=True))
    else:
        bl, bw = pick(rng, 0.1, 0.11), pick(rng, 0.055, 0.062)
        blade = [(0.0, -0.014), (0.03, -bw / 2), (bl - 0.01, -bw / 2), (bl, -bw / 2 + 0.01), (bl, bw / 2 - 0.01),
                 (bl - 0.01, bw / 2), (0.03, bw / 2), (0.0, 0.014)]
        parts.append(Part(g.extrude(blade, 0.007), "wood", convex=True))
        grip = _strip(0.2, 0.028, 0.03)
        parts.append(Part(g.extrude([(-x, y) for x, y in grip][::-1], 0.009), "wood", convex=True))
    return AssetSpec("Spatula", v, "small", _link(_centered_x(parts), 0.1),
                     description=["slotted turner", "silicone spatula", "wooden spatula"][v])


# --------------------------------------------------------------------------------------------------
# Shakers, sponge, bottles, paper


def _holes(z: float, n: int, ring: float) -> list[Part]:
    """Pour holes on a shaker's top at height z."""
    pts = [(0.0, 0.0)] + [(ring * np.cos(a), ring * np.sin(a)) for a in np.linspace(0, 2 * np.pi, n - 1,
                                                                                    endpoint=False)]
    return [Part(g.cylinder(0.0014, 0.0008, (x, y, z + 0.0003), sections=6), "dark_plastic", collide=False)
            for x, y in pts]


@register("SaltShaker", variants=3, category="small")
def salt_shaker(v: int, rng: np.random.Generator) -> AssetSpec:
    """A glass salt shaker with a steel cap: a cylinder with a dome cap, a square one, a tapered diner one."""
    parts: list[Part] = []
    if v == 0:
        r, h = pick(rng, 0.019, 0.021), pick(rng, 0.062, 0.068)
        parts.append(Part(g.cylinder(r, h, (0, 0, h / 2), sections=20), "glass", convex=True))
        cap = [(0.0, 0.0), (r + 0.0008, 0.0), (r + 0.0008, 0.008), (r * 0.8, 0.015), (0.0, 0.018)]
        parts.append(Part(g.revolve(cap, (0, 0, h), sections=20), "metal", convex=True))
        parts += _holes(h + 0.0175, 5, 0.006)
    elif v == 1:
        s, h = pick(rng, 0.032, 0.036), pick(rng, 0.058, 0.064)
        parts.append(Part(g.extrude(g.rounded_outline(s, s, 0.004, 3), h), "glass", convex=True))
        parts.append(Part(g.cylinder(0.016, 0.014, (0, 0, h + 0.007), sections=18), "metal", convex=True))
        parts += _holes(h + 0.014, 7, 0.008)
    else:
        r, h = pick(rng, 0.024, 0.026), pick(rng, 0.07, 0.076)
        body = [(0.0, 0.0), (r, 0.0), (r * 0.78, h), (0.0, h)]
        parts.append(Part(g.revolve(body, sections=16), "glass", convex=True))
        cap = [(0.0, 0.0), (r * 0.8, 0.0), (r * 0.8, 0.006), (r * 0.62, 0.022), (0.0, 0.024)]
        parts.append(Part(g.revolve(cap, (0, 0, h), sections=16), "metal", convex=True))
        parts += _holes(h + 0.0235, 5, 0.0045)
    return AssetSpec("SaltShaker", v, "small", _link(parts, 0.1),
                     description=["salt shaker", "square salt shaker", "diner salt shaker"][v])


@register("PepperShaker", variants=3, category="small")
def pepper_shaker(v: int, rng: np.random.Generator) -> AssetSpec:
    """A pepper shaker or mill: a waisted wooden mill, a round ceramic shaker, a steel grinder."""
    parts: list[Part] = []
    if v == 0:
        rb, h = pick(rng, 0.025, 0.028), pick(rng, 0.14, 0.16)
        parts.append(Part(g.frustum(rb, rb * 0.72, 0.45 * h, sections=18), "dark_wood", convex=True))
        parts.append(Part(g.frustum(rb * 0.72, rb * 0.95, 0.35 * h, (0, 0, 0.45 * h), sections=18), "dark_wood",
                          convex=True))
        top = [(0.0, 0.0), (rb * 0.95, 0.0), (rb * 0.9, 0.08 * h), (rb * 0.5, 0.18 * h), (0.0, 0.19 * h)]
        parts.append(Part(g.revolve(top, (0, 0, 0.8 * h), sections=18), "dark_wood", convex=True))
        parts.append(Part(g.sphere(0.007, (0, 0, 0.99 * h + 0.004), subdivisions=1), "metal", convex=True))
    elif v == 1:
        r, h = pick(rng, 0.024, 0.027), pick(rng, 0.07, 0.078)
        prof = [(0.0, 0.0), (r * 0.75, 0.0)] + [(r * np.sin(a), 0.5 * h * (1 - np.cos(a)) + 0.0)
                                                 for a in np.linspace(0.9, np.pi / 2, 3)]
        prof += [(r * 0.9, 0.75 * h), (r * 0.6, 0.95 * h), (r * 0.45, h), (0.0, h)]
        parts.append(Part(g.revolve([(float(a), float(b)) for a, b in prof], sections=18), "ceramic", convex=True))
        parts.append(Part(g.cylinder(r * 0.45, 0.001, (0, 0, h + 0.0003), sections=14), "dark_plastic",
                          collide=False))
        for k in range(5):
            a = 2 * np.pi * k / 5
            parts.append(Part(g.cylinder(0.0013, 0.0008, (0.005 * np.cos(a), 0.005 * np.sin(a), h + 0.001),
                                         sections=6), "porcelain", collide=False))
    else:
        r, h = pick(rng, 0.021, 0.023), pick(rng, 0.1, 0.11)
        parts.append(Part(g.cylinder(r, 0.72 * h, (0, 0, 0.36 * h), sections=20), "metal", convex=True))
        parts.append(Part(g.cylinder(r * 1.02, 0.22 * h, (0, 0, 0.83 * h), sections=20), "dark_plastic",
                          convex=True))
        parts.append(Part(g.cylinder(r * 0.55, 0.06 * h, (0, 0, 0.97 * h), sections=14), "dark_plastic",
                          convex=True))
        for k in range(6):  # grip ribs on the cap
            a = 2 * np.pi * k / 6
            parts.append(Part(g.box((0.003, 0.003, 0.18 * h), (r * 1.02 * np.cos(a), r * 1.02 * np.sin(a), 0.83 * h)),
                              "dark_plastic", collide=False))
    return AssetSpec("PepperShaker", v, "small", _link(parts, 0.1),
                     description=["wooden pepper mill", "ceramic pepper shaker", "steel pepper grinder"][v])


@register("DishSponge", variants=3, category="small")
def dish_sponge(v: int, rng: np.random.Generator) -> AssetSpec:
    """A kitchen sponge: a soft foam block with a scouring layer on top (rectangular, oval, square)."""
    if v == 0:
        outline = g.rounded_outline(pick(rng, 0.09, 0.1), pick(rng, 0.06, 0.068), 0.006)
        t_foam, t_scour = 0.022, 0.007
    elif v == 1:
        outline = g.ellipse_points(pick(rng, 0.05, 0.055), pick(rng, 0.034, 0.038), 18)
        t_foam, t_scour = 0.026, 0.006
    else:
        s = pick(rng, 0.075, 0.082)
        outline = g.rounded_outline(s, s, 0.012)
        t_foam, t_scour = 0.03, 0.005
    foam = g.extrude(outline, t_foam)
    scour = g.extrude(outline, t_scour, t_foam)
    return AssetSpec("DishSponge", v, "small",
                     _link([Part(foam, "kw_sponge", convex=True), Part(scour, "kw_scrubber", convex=True)], 0.02),
                     description=["dish sponge", "oval sponge", "square scrub sponge"][v])


def _pump(z: float, x_collar: float = 0.0, r_collar: float = 0.014) -> list[Part]:
    """A soap pump on a bottle neck at height z: collar, stem, head and a nozzle pointing to -x."""
    return [
        Part(g.cylinder(r_collar, 0.014, (x_collar, 0, z + 0.007), sections=16), "kw_pump", convex=True),
        Part(g.cylinder(0.0045, 0.022, (x_collar, 0, z + 0.025), sections=10), "kw_pump", convex=True),
        Part(g.cylinder(0.012, 0.012, (x_collar, 0, z + 0.042), sections=14), "kw_pump", convex=True),
        Part(g.rod((x_collar, 0, z + 0.043), (x_collar - 0.032, 0, z + 0.04), 0.004, 8), "kw_pump", convex=True),
    ]


@register("SoapBottle", variants=3, category="small")
def soap_bottle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A pump bottle of liquid soap with a label: round, flat oval, square."""
    parts: list[Part] = []
    if v == 0:
        r, h = pick(rng, 0.03, 0.033), pick(rng, 0.13, 0.145)
        body = [(0.0, 0.0), (r - 0.003, 0.0), (r, 0.004), (r, 0.8 * h), (0.7 * r, 0.95 * h), (0.45 * r, h), (0.0, h)]
        parts.append(Part(g.revolve(body, sections=20), "kw_soap", convex=True))
        parts.append(Part(g.cylinder(r + 0.0006, 0.05, (0, 0, 0.4 * h), sections=20), "kw_label", collide=False))
    elif v == 1:
        r, h = pick(rng, 0.038, 0.042), pick(rng, 0.15, 0.165)
        body = [(0.0, 0.0), (r - 0.004, 0.0), (r, 0.006), (r, 0.78 * h), (0.75 * r, 0.93 * h), (0.35 * r, h), (0.0, h)]
        mesh = g.revolve(body, sections=20)
        mesh.apply_scale((1.0, 0.55, 1.0))
        parts.append(Part(mesh, "kw_soap", convex=True))
        label = g.box((0.045, 0.001, 0.06), (0, r * 0.55 + 0.0002, 0.4 * h))
        parts.append(Part(label, "kw_label", collide=False))
    else:
        s, h = pick(rng, 0.058, 0.064), pick(rng, 0.12, 0.13)
        parts.append(Part(g.extrude(g.rounded_outline(s, s, 0.008), 0.85 * h), "kw_soap", convex=True))
        shoulder = trimesh.convex.convex_hull(np.vstack([
            np.array([(x, y, 0.85 * h) for x, y in g.rounded_outline(s, s, 0.008)]),
            np.array([(x, y, h) for x, y in g.ellipse_points(0.016, 0.016, 12)])]))
        parts.append(Part(shoulder, "kw_soap", convex=True))
        parts.append(Part(g.box((s * 0.7, 0.001, 0.055), (0, s / 2 + 0.0002, 0.42 * h)), "kw_label", collide=False))
    parts += _pump(h)
    return AssetSpec("SoapBottle", v, "small", _link(parts, 0.4),
                     description=["round soap pump bottle", "oval soap pump bottle", "square soap pump bottle"][v])


def _bottle(r: float, body_h: float, shoulder: Sequence[tuple[float, float]], neck_r: float, neck_top: float,
            slot: str, lip: bool = True) -> list[Part]:
    """A round bottle: body with shoulder (radius, height pairs ending at the neck), neck and lip."""
    prof = [(0.0, 0.0), (r - 0.004, 0.0), (r, 0.005), (r, body_h)] + list(shoulder)
    prof.append((0.0, prof[-1][1]))
    parts = [Part(g.revolve([(float(a), float(b)) for a, b in prof], sections=20), slot, convex=True)]
    z0 = prof[-1][1] - 0.004
    parts.append(Part(g.cylinder(neck_r, neck_top - z0, (0, 0, (z0 + neck_top) / 2), sections=14), slot,
                      convex=True))
    if lip:
        parts.append(Part(g.cylinder(neck_r + 0.002, 0.006, (0, 0, neck_top - 0.003), sections=14), slot,
                          convex=True))
    return parts


@register("Glassbottle", variants=3, category="small")
def glass_bottle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A clear glass bottle: a round bottle with a long neck, a square bottle with a cork, a milk bottle."""
    if v == 0:
        r, hb = pick(rng, 0.033, 0.036), pick(rng, 0.15, 0.17)
        parts = _bottle(r, hb, [(0.9 * r, hb + 0.02), (0.6 * r, hb + 0.04), (0.4 * r, hb + 0.05)], 0.012,
                        hb + 0.11, "glass")
        parts.append(Part(g.cylinder(0.0145, 0.012, (0, 0, hb + 0.116), sections=14), "metal", convex=True))
    elif v == 1:
        s, hb = pick(rng, 0.06, 0.066), pick(rng, 0.14, 0.15)
        body = g.extrude(g.rounded_outline(s, s, 0.006), hb)
        shoulder = trimesh.convex.convex_hull(np.vstack([
            np.array([(x, y, hb) for x, y in g.rounded_outline(s, s, 0.006)]),
            np.array([(x, y, hb + 0.03) for x, y in g.ellipse_points(0.015, 0.015, 12)])]))
        parts = [Part(body, "glass", convex=True), Part(shoulder, "glass", convex=True),
                 Part(g.cylinder(0.013, 0.05, (0, 0, hb + 0.05), sections=14), "glass", convex=True),
                 Part(g.frustum(0.011, 0.014, 0.022, (0, 0, hb + 0.07), sections=12), "wood", convex=True)]
    else:
        r, hb = pick(rng, 0.042, 0.046), pick(rng, 0.12, 0.13)
        parts = _bottle(r, hb, [(0.94 * r, hb + 0.02), (0.78 * r, hb + 0.045), (0.6 * r, hb + 0.065)], 0.6 * r - 0.002,
                        hb + 0.085, "glass")
    return AssetSpec("Glassbottle", v, "small", _link(parts, 0.5),
                     description=["glass bottle", "square glass bottle", "milk bottle"][v])


@register("WineBottle", variants=3, category="small")
def wine_bottle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A wine bottle with label and foil capsule: Bordeaux (high shoulders), Burgundy (sloping shoulders),
    Riesling (tall and slim)."""
    if v == 0:
        r, hb = pick(rng, 0.036, 0.038), pick(rng, 0.19, 0.2)
        shoulder = [(0.93 * r, hb + 0.015), (0.7 * r, hb + 0.032), (0.45 * r, hb + 0.045)]
        neck_top = hb + 0.12
    elif v == 1:
        r, hb = pick(rng, 0.04, 0.042), pick(rng, 0.15, 0.16)
        shoulder = [(0.96 * r, hb + 0.025), (0.82 * r, hb + 0.05), (0.6 * r, hb + 0.075), (0.42 * r, hb + 0.09)]
        neck_top = hb + 0.16
    else:
        r, hb = pick(rng, 0.031, 0.033), pick(rng, 0.17, 0.18)
        shoulder = [(0.93 * r, hb + 0.03), (0.76 * r, hb + 0.065), (0.56 * r, hb + 0.1)]
        neck_top = hb + 0.17
    neck_r = 0.0145
    parts = _bottle(r, hb, shoulder, neck_r, neck_top, "kw_wine_glass")
    parts.append(Part(g.cylinder(neck_r + 0.0025, 0.05, (0, 0, neck_top - 0.022), sections=14), "kw_foil",
                      collide=False))
    label_h = [0.09, 0.08, 0.075][v]
    parts.append(Part(g.cylinder(r + 0.0006, label_h, (0, 0, 0.45 * hb + 0.01), sections=20), "kw_label",
                      collide=False))
    return AssetSpec("WineBottle", v, "small", _link(parts, 0.75),
                     description=["Bordeaux wine bottle", "Burgundy wine bottle", "Riesling wine bottle"][v])


@register("PaperTowelRoll", variants=3, category="small")
def paper_towel_roll(v: int, rng: np.random.Generator) -> AssetSpec:
    """A kitchen paper roll standing on end: on its own, on a wooden stand, on a steel stand."""
    r = [pick(rng, 0.056, 0.062), pick(rng, 0.056, 0.062), pick(rng, 0.05, 0.055)][v]
    h = [pick(rng, 0.27, 0.28), pick(rng, 0.26, 0.27), pick(rng, 0.22, 0.24)][v]
    z0 = [0.0, 0.016, 0.008][v]
    parts = [Part(g.cylinder(r, h, (0, 0, z0 + h / 2), sections=24), "paper", convex=True)]
    parts.append(Part(g.cylinder(0.022, 0.0008, (0, 0, z0 + h + 0.0004), sections=16), "kw_cardboard",
                      collide=False))
    # the free end of the sheet, a slightly proud flap along the roll
    flap = g.box((0.0012, 0.05, h * 0.98), (r - 0.0002, 0.0, z0 + h / 2))
    parts.append(Part(g.transformed(flap, yaw=1.2), "kw_paper_shade", collide=False))
    if v == 0:
        parts.append(Part(g.cylinder(0.017, 0.001, (0, 0, z0 + h + 0.0009), sections=16), "dark_plastic",
                          collide=False))
    elif v == 1:
        parts.append(Part(g.cylinder(r + 0.018, 0.016, (0, 0, 0.008), sections=24), "wood", convex=True))
        parts.append(Part(g.cylinder(0.012, h + 0.03, (0, 0, 0.016 + (h + 0.03) / 2), sections=12), "wood",
                          convex=True))
        parts.append(Part(g.sphere(0.016, (0, 0, 0.016 + h + 0.035), subdivisions=1), "wood", convex=True))
    else:
        parts.append(Part(g.cylinder(r + 0.02, 0.008, (0, 0, 0.004), sections=24), "metal", convex=True))
        parts.append(Part(g.cylinder(0.006, h + 0.06, (0, 0, 0.008 + (h + 0.06) / 2), sections=10), "metal",
                          convex=True))
        parts.append(Part(g.torus_arc(0.018, 0.004, (0, 0, 0.008 + h + 0.06 + 0.014), plane="xz", start=-np.pi / 2,
                                      end=1.5 * np.pi, sections=12, minor_sections=6), "metal", collide=False))
    return AssetSpec("PaperTowelRoll", v, "small", _link(parts, 0.2),
                     description=["paper towel roll", "paper towel roll on a wooden stand",
                                  "paper towel roll on a steel stand"][v])


@register("PaperTowel", variants=3, category="small")
def paper_towel(v: int, rng: np.random.Generator) -> AssetSpec:
    """Folded paper towels lying flat: a quarter-folded towel, a stack of z-fold towels, folded napkins."""
    parts: list[Part] = []
    if v == 0:
        s = pick(rng, 0.13, 0.14)
        parts.append(Part(g.extrude(g.rounded_outline(s, s, 0.004, 3), 0.004), "paper", convex=True))
        parts.append(Part(g.extrude(g.rounded_outline(s * 0.98, s * 0.98, 0.004, 3), 0.002, 0.004), "paper",
                          convex=True))
        parts[-1].mesh.apply_translation((0.003, -0.003, 0.0))
        parts.append(Part(g.box((s * 0.9, 0.0012, 0.0004), (0.003, -0.003, 0.0062)), "kw_paper_shade",
                          collide=False))
    elif v == 1:
        w, d = pick(rng, 0.22, 0.235), pick(rng, 0.1, 0.11)
        for k in range(5):
            off = 0.003 * ((k % 3) - 1)
            slot = "paper" if k % 2 == 0 else "kw_paper_shade"
            parts.append(Part(g.box((w, d, 0.003), (off, -off, 0.0015 + 0.003 * k)), slot, convex=True))
        parts.append(Part(g.box((w, 0.0014, 0.0004), (0.0, -d * 0.15, 0.0152)), "kw_paper_shade", collide=False))
    else:
        s = pick(rng, 0.15, 0.16)
        tri = [(-s / 2, -s / 2), (s / 2, -s / 2), (-s / 2, s / 2)]
        for k in range(3):
            slab = g.extrude([(x + 0.004 * k, y + 0.004 * k) for x, y in tri], 0.0035, 0.0035 * k)
            parts.append(Part(slab,
                              "paper" if k % 2 == 0 else "kw_paper_shade", convex=True))
    return AssetSpec("PaperTowel", v, "small", _link(parts, 0.05),
                     description=["folded paper towel", "stack of paper towels", "folded paper napkins"][v])
