"""Small bathroom things: plungers, scrub brushes, soap bars, spray bottles, tissue boxes, toilet paper.

Built in their natural resting pose (a roll on its end, a bar flat) so that they settle upright when
dropped. Sizes are real-world metres.
"""

from __future__ import annotations

import itertools

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, small_asset, solid, visual
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Part

add_palettes(
    hh_plunger=hex_colours("b3261e", "1e1e1e", "c0392b"),
    hh_soap=hex_colours("f3e9dc", "f7d6e0", "d5ecd4", "fff5c2", "cfe3f2"),
    hh_bottle=hex_colours("7fb8e6", "f2f2f2", "5aa469", "f2c14e", "e7e1f5"),
    hh_tissuebox=hex_colours("9fb6a2", "bcd4e6", "e8d9b5", "d9a6a0"),
    hh_tissue=hex_colours("fafafa", "f6f6f2"),
    hh_cardboard=hex_colours("c8a97e", "b8976a", "d4b892"),
)

PI = float(np.pi)


# ---------------------------------------------------------------------------------------------- bathroom

@register("Plunger", variants=3, category="small")
def plunger(v: int, rng: np.random.Generator) -> AssetSpec:
    """A plunger standing on its rubber cup: classic dome cup, flange cup with a T-handle, accordion."""
    ln = pick(rng, 0.4, 0.46)
    cups = [
        [(0, 0), (0.072, 0), (0.07, 0.02), (0.06, 0.045), (0.04, 0.065), (0.018, 0.075), (0, 0.076)],
        [(0, 0), (0.045, 0), (0.05, 0.012), (0.068, 0.02), (0.07, 0.035), (0.058, 0.06), (0.035, 0.078),
         (0.015, 0.085), (0, 0.085)],
        [(0, 0), (0.05, 0), (0.058, 0.012), (0.048, 0.022), (0.058, 0.034), (0.048, 0.044), (0.058, 0.056),
         (0.045, 0.066), (0.05, 0.078), (0.022, 0.095), (0, 0.1)],
    ]
    cup = cups[v]
    top = cup[-1][1]
    parts = [solid(g.revolve(cup, sections=20), "hh_plunger" if v != 2 else "plastic")]
    parts.append(solid(g.cylinder(0.017, 0.02, (0, 0, top + 0.006), sections=12),
                       "hh_plunger" if v != 2 else "plastic"))
    handle_slot = ["wood", "dark_metal", "porcelain"][v]
    parts.append(solid(g.cylinder(0.0115, ln, (0, 0, top + ln / 2), sections=12), handle_slot))
    z_end = top + ln
    if v == 0:
        parts.append(visual(g.sphere(0.0125, (0, 0, z_end), subdivisions=1), handle_slot))
    elif v == 1:
        parts.append(solid(g.cylinder(0.013, 0.11, (0, 0, z_end), axis="x", sections=12), "hh_plunger"))
    else:
        parts.append(visual(g.torus_arc(0.016, 0.004, (0, 0, z_end), plane="xz", start=0.0, end=PI, sections=10,
                                        minor_sections=6), handle_slot))
    return small_asset("Plunger", v, parts, [0.45, 0.5, 0.4][v], "toilet plunger standing on its cup")


@register("ScrubBrush", variants=3, category="small")
def scrub_brush(v: int, rng: np.random.Generator) -> AssetSpec:
    """A toilet brush standing in its holder: round ceramic pot, square caddy, tall tapered holder with collar."""
    parts: list[Part] = []
    if v == 0:
        r, h = pick(rng, 0.048, 0.055), pick(rng, 0.1, 0.12)
        parts.append(solid(g.container([(r * 0.92, 0), (r, 0.02), (r * 0.96, h)], wall=0.005, bottom=0.01, sections=20),
                           "ceramic"))
        parts.append(visual(g.cylinder(r * 0.8, 0.02, (0, 0, h - 0.03), sections=16), "hh_dark"))
        top = pick(rng, 0.36, 0.4)
        parts.append(solid(g.cylinder(0.0085, top - 0.05, (0, 0, 0.05 + (top - 0.05) / 2), sections=10), "plastic"))
        parts.append(visual(g.sphere(0.014, (0, 0, top), subdivisions=1), "plastic"))
    elif v == 1:
        s, h, t = pick(rng, 0.09, 0.1), pick(rng, 0.11, 0.13), 0.005
        walls = [g.box_at((-s / 2, -s / 2, 0), (s / 2, s / 2, 0.01)),
                 g.box_at((-s / 2, -s / 2, 0), (s / 2, -s / 2 + t, h)),
                 g.box_at((-s / 2, s / 2 - t, 0), (s / 2, s / 2, h)),
                 g.box_at((-s / 2, -s / 2, 0), (-s / 2 + t, s / 2, h)),
                 g.box_at((s / 2 - t, -s / 2, 0), (s / 2, s / 2, h))]
        parts += [solid(m, "plastic") for m in walls]
        parts.append(visual(g.box((s - 2 * t, s - 2 * t, 0.002), (0, 0, h - 0.025)), "hh_dark"))
        top = pick(rng, 0.36, 0.4)
        parts.append(solid(g.cylinder(0.008, top - 0.05, (0, 0, 0.05 + (top - 0.05) / 2), sections=10), "metal"))
        parts.append(solid(g.rounded_slab_y(0.032, 0.045, 0.012, 0.01, (0, 0, top)), "plastic"))
    else:
        r, h = pick(rng, 0.05, 0.056), pick(rng, 0.15, 0.17)
        parts.append(solid(g.container([(r, 0), (r * 0.72, h)], wall=0.004, bottom=0.01, sections=20), "metal"))
        collar = g.revolve([(0.011, 0), (r * 0.74, 0), (r * 0.74, 0.012), (0.011, 0.012), (0.011, 0)], sections=20)
        collar.apply_translation((0, 0, h - 0.006))
        parts.append(solid(collar, "dark_metal"))
        top = pick(rng, 0.4, 0.44)
        parts.append(solid(g.cylinder(0.007, top - 0.05, (0, 0, 0.05 + (top - 0.05) / 2), sections=10), "dark_metal"))
        parts.append(visual(g.torus_arc(0.014, 0.0035, (0, 0, top + 0.002), plane="xz", start=-0.2, end=PI + 0.2,
                                        sections=10, minor_sections=6), "dark_metal"))
    return small_asset("ScrubBrush", v, parts, [0.6, 0.5, 0.55][v], "toilet brush in its holder")


@register("SoapBar", variants=3, category="small")
def soap_bar(v: int, rng: np.random.Generator) -> AssetSpec:
    """A rounded bar of soap lying flat: rectangular with an embossed oval, oval bar, small hotel soap."""
    a, b, c, e1, e2 = [(pick(rng, 0.043, 0.048), pick(rng, 0.028, 0.032), 0.014, 0.45, 0.35),
                       (pick(rng, 0.048, 0.053), pick(rng, 0.03, 0.034), 0.015, 0.6, 1.0),
                       (0.03, 0.021, 0.0085, 0.5, 0.55)][v]
    body = g.clip_below(g.superquadric((a, b, c), e1, e2, (0, 0, 0), nu=10, nv=24), -0.85 * c)
    parts = [solid(body, "hh_soap")]
    top = float(body.bounds[1][2])
    if v == 0:
        parts.append(visual(g.ellipsoid((a * 0.55, b * 0.45, 0.002), (0, 0, top - 0.0008), 2), "hh_soap"))
    elif v == 1:
        parts.append(visual(g.torus_ring(b * 0.5, 0.0012, (0, 0, top - 0.0006), n=20, m=4), "hh_soap"))
    else:
        parts.append(visual(g.flat_decal(a * 0.8, b * 0.25, top - 0.0009, 0, 0, t=0.0012, r=0.002), "hh_soap"))
    return small_asset("SoapBar", v, parts, [0.11, 0.12, 0.03][v], "bar of soap")


@register("SprayBottle", variants=3, category="small")
def spray_bottle(v: int, rng: np.random.Generator) -> AssetSpec:
    """A trigger spray bottle (nozzle towards +y): round bottle, flat oval bottle, waisted grip bottle."""
    h = pick(rng, 0.18, 0.2)
    if v == 2:
        r = 0.045
        prof = [(0, 0), (r, 0), (r, h * 0.3), (r * 0.78, h * 0.46), (r * 0.93, h * 0.66), (r * 0.9, h * 0.8),
                (0.016, h * 0.92), (0.016, h), (0, h)]
    else:
        r = 0.042
        prof = [(0, 0), (r, 0), (r * 1.03, 0.005), (r * 1.03, h * 0.78), (r * 0.82, h * 0.88), (0.016, h * 0.94),
                (0.016, h), (0, h)]
    body = g.revolve(prof, sections=20)
    label = g.cylinder(r * 1.03 + 0.0008, h * 0.32, (0, 0, h * 0.42), sections=20)
    if v == 1:
        body.apply_scale((1.0, 0.62, 1.0))
        label.apply_scale((1.0, 0.62, 1.0))
    parts = [solid(body, "hh_bottle")]
    if v != 2:
        parts.append(visual(label, "hh_face"))
    zt = h
    parts.append(solid(g.cylinder(0.019, 0.018, (0, 0, zt + 0.009), sections=14), "plastic"))
    zt += 0.018
    head = [(-0.02, 0), (0.03, 0), (0.055, 0.016), (0.055, 0.03), (-0.016, 0.036), (-0.022, 0.02)]
    parts.append(solid(g.extrude_yz([(y, z + zt) for y, z in head], 0.028), "plastic"))
    parts.append(solid(g.cylinder(0.0065, 0.012, (0, 0.061, zt + 0.023), axis="y", sections=10), "hh_ink"))
    trig = [(0.02, 0.002), (0.034, 0.002), (0.04, -0.04), (0.03, -0.046)]
    parts.append(solid(g.extrude_yz([(y, z + zt) for y, z in trig], 0.016), "plastic"))
    return small_asset("SprayBottle", v, parts, [0.45, 0.4, 0.45][v], "trigger spray bottle")


@register("TissueBox", variants=3, category="small")
def tissue_box(v: int, rng: np.random.Generator) -> AssetSpec:
    """A box of tissues with one sticking out: long box, cube box, soft pocket pack."""
    w, d, h = [(pick(rng, 0.22, 0.25), pick(rng, 0.11, 0.125), pick(rng, 0.08, 0.095)),
               (pick(rng, 0.11, 0.125), pick(rng, 0.11, 0.125), pick(rng, 0.125, 0.135)),
               (0.11, 0.055, 0.026)][v]
    parts: list[Part] = []
    if v == 2:
        pack = g.superquadric((w / 2, d / 2, h / 2), 0.35, 0.2, (0, 0, 0), nu=8, nv=20)
        parts.append(solid(g.clip_below(pack, -0.42 * h), "plastic"))
        parts[-1].mesh.apply_translation((0, 0, 0.42 * h))
        h = float(parts[-1].mesh.bounds[1][2])
        parts.append(visual(g.flat_decal(w * 0.55, 0.004, h - 0.0003, r=0.0015), "hh_dark"))
        sheet_w, sheet_h = 0.045, 0.014
    else:
        parts.append(solid(g.box_at((-w / 2, -d / 2, 0), (w / 2, d / 2, h)), "hh_tissuebox"))
        if v == 0:
            hole = g.cylinder(1.0, 0.0006, (0, 0, 0), sections=20)
            hole.apply_scale((w * 0.28, d * 0.2, 1.0))
            hole.apply_translation((0, 0, h + 0.0003))
            for sx in (-1, 1):
                parts.append(visual(g.box((0.01, d + 0.001, h + 0.001), (sx * w * 0.3, 0, h / 2)), "hh_art"))
        else:
            hole = g.flat_disc(w * 0.24, h, n=20, t=0.0006)
            parts.append(visual(g.box((w + 0.001, d + 0.001, 0.02), (0, 0, h * 0.2)), "hh_art"))
        parts.append(visual(hole, "hh_dark"))
        sheet_w, sheet_h = 0.08, 0.045
    # the tissue: two thin, slightly twisted fins rising out of the opening
    for k, (yaw, lean) in enumerate(((0.12, 0.18), (-0.35, -0.12))):
        s = 1.0 if k == 0 else 0.75
        outline = [(-sheet_w / 2 * s, -0.008), (sheet_w / 2 * s, -0.008),
                   (sheet_w * 0.32 * s, sheet_h * 0.7 * s), (sheet_w * 0.05, sheet_h * s),
                   (-sheet_w * 0.2 * s, sheet_h * 0.85 * s), (-sheet_w * 0.4 * s, sheet_h * 0.4)]
        fin = g.extrude(outline, 0.003, -0.0015)
        g.rotate_x(fin, PI / 2 + lean)
        g.rotate_z(fin, yaw)
        fin.apply_translation((0, 0, h))
        parts.append(solid(fin, "hh_tissue"))
    return small_asset("TissueBox", v, parts, [0.2, 0.18, 0.03][v], "box of tissues")


@register("ToiletPaper", variants=3, category="small")
def toilet_paper(v: int, rng: np.random.Generator) -> AssetSpec:
    """A toilet paper roll standing on its end: with the loose sheet lying out, a fat roll, a nearly used roll."""
    ri = 0.021
    ro, h = [(pick(rng, 0.054, 0.058), 0.1), (pick(rng, 0.064, 0.068), 0.105), (pick(rng, 0.032, 0.036), 0.099)][v]
    parts = [solid(g.hollow_cylinder(ri, ro, h, 0.003), "hh_tissue"),
             visual(g.hollow_cylinder(ri - 0.0015, ri + 0.0003, h + 0.0006, 0.0, 20), "hh_cardboard")]
    parts[-1].mesh.apply_translation((0, 0, -0.0003))
    if v == 0:
        sheet_l = pick(rng, 0.08, 0.1)
        sheet = g.box_at((-0.05, ro - 0.02, 0), (0.05, ro + sheet_l, 0.0015))
        parts.append(solid(sheet, "hh_tissue"))
        flap = g.hollow_cylinder(ro - 0.0005, ro + 0.0009, h - 0.002, 0.0, 6, angle=0.9)
        g.rotate_z(flap, PI / 2 - 0.45)
        parts.append(visual(flap, "hh_tissue"))
        for k in range(1, 3):
            parts.append(visual(g.flat_decal(0.1, 0.0012, 0.0015, 0, ro + k * 0.034 - 0.01, t=0.0002), "hh_print"))
    elif v == 1:
        for z in (0.03, 0.075):
            parts.append(visual(g.torus_ring(ro + 0.0002, 0.0009, (0, 0, z), n=28, m=4), "hh_print"))
    else:
        flap = g.hollow_cylinder(ro - 0.0005, ro + 0.0008, h * 0.9, 0.0, 6, angle=0.9)
        g.rotate_z(flap, PI / 2 - 0.45)
        parts.append(visual(flap, "hh_tissue"))
    return small_asset("ToiletPaper", v, parts, [0.12, 0.16, 0.05][v], "toilet paper roll")


@register("ToiletPaperRoll", variants=3, category="small")
def toilet_paper_roll(v: int, rng: np.random.Generator) -> AssetSpec:
    """An empty cardboard tube standing on end: plain, with a few sheets left on it, slightly squashed."""
    r, h = 0.0215, pick(rng, 0.097, 0.1)
    tube = g.hollow_cylinder(r - 0.0013, r, h, 0.0, 20)
    parts = [solid(tube, "hh_cardboard")]
    if v == 2:
        tube.apply_scale((1.22, 0.82, 1.0))
    # the spiral seam of the wound cardboard
    pts = [((r + 0.0002) * np.cos(t), (r + 0.0002) * np.sin(t), 0.004 + (h - 0.008) * t / (2.2 * PI))
           for t in np.linspace(0, 2.2 * PI, 13)]
    for p0, p1 in itertools.pairwise(pts):
        seam = g.rod(p0, p1, 0.0006, sections=4)
        if v == 2:
            seam.apply_scale((1.22, 0.82, 1.0))
        parts.append(visual(seam, "hh_print"))
    if v == 1:
        parts.append(solid(g.hollow_cylinder(r, r + 0.003, h - 0.004, 0.001, 20), "hh_tissue"))
        parts[-1].mesh.apply_translation((0, 0, 0.002))
        flap = g.hollow_cylinder(r + 0.0025, r + 0.0035, h - 0.006, 0.0, 6, angle=1.0)
        flap.apply_translation((0, 0, 0.003))
        parts.append(visual(flap, "hh_tissue"))
    return small_asset("ToiletPaperRoll", v, parts, [0.01, 0.02, 0.01][v], "empty toilet paper tube")
