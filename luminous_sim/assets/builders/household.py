"""Household small objects: books and papers, sports gear, boots, candles, desk things, ornaments, a watering can.

Everything here is built in its natural resting pose (flat things lie flat along x or y, round things
carry a small flat spot) so that it settles upright when dropped. Sizes are real-world metres.
Electronics, textiles and toiletries have their own modules.
"""

from __future__ import annotations

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, small_asset, solid, visual
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Part

add_palettes(
    hh_basketball=hex_colours("d9642b", "c8561f", "e07a3a", "cf6a32"),
    hh_alu=hex_colours("9aa0a6", "3a3d41", "c0392b", "1d3557"),
    hh_grip=hex_colours("222222", "f0f0f0", "3f88c5"),
    hh_boot=hex_colours("7b4a2a", "2d2420", "1f3b2c", "a0703c", "d94f4f"),
    hh_sole=hex_colours("2b2b2b", "4a3526", "1e1e1e"),
    hh_lace=hex_colours("c8a97e", "1e1e1e"),
    hh_disc=hex_colours("d8dde3", "e5e5e5", "c9ced4"),
    hh_wax=hex_colours("f4efe1", "e8d9b5", "c94c4c", "f2c14e", "9fb59a"),
    hh_wick=hex_colours("2a2a2a"),
    hh_card=hex_colours("1d4e89", "2a9d8f", "c1121f", "222222", "e9c46a"),
    hh_gold=hex_colours("d4af37", "c9a227"),
    hh_photo=hex_colours("8a8f94", "6f7b86", "a3a8ad"),
    hh_newsprint=hex_colours("e9e5da", "efece3", "e0dccf"),
    hh_pen=hex_colours("1d4ed8", "111111", "c1121f", "1f7a3a"),
    hh_pen_barrel=hex_colours("e6e9ec", "f0f0f0", "111111"),
    hh_pencil=hex_colours("f2c14e", "3f88c5", "c94c4c", "5aa469"),
    hh_pencil_wood=hex_colours("e8c89a", "dcb886"),
    hh_graphite=hex_colours("3a3a3a", "2f2f2f"),
    hh_eraser=hex_colours("f4a6a6", "f19a9a"),
    hh_bronze=hex_colours("8c6a3f", "a97d4a", "6e5230", "4a4a4a"),
    hh_fur=hex_colours("8b5a2b", "c8a06e", "e8d8c0", "5a3a22", "d9b38c"),
    hh_fur_light=hex_colours("d9b38c", "efe0c8", "fbf3e8", "a0744c", "f0dcc0"),
    hh_ribbon=hex_colours("c0392b", "3f88c5", "e76f98"),
    hh_strings=hex_colours("f0f0f0", "e8e25a", "f5f0dc"),
    hh_racket=hex_colours("1d3557", "c1121f", "2d2d2d", "a0703c"),
    hh_can=hex_colours("5aa469", "3f88c5", "b8bcc2", "f2c14e", "d94f4f"),
)

PI = float(np.pi)


# ------------------------------------------------------------------------------------------ sports gear

@register("BaseballBat", variants=4, category="small")
def baseball_bat(v: int, rng: np.random.Generator) -> AssetSpec:
    """A tapered bat lying along x (knob at -x) with a shaved flat under the barrel so it does not roll."""
    length = [0.84, 0.81, 0.71, 0.86][v] + pick(rng, -0.01, 0.01)
    rb = [0.033, 0.032, 0.029, 0.0305][v]
    rh = [0.0125, 0.012, 0.011, 0.013][v]
    rk = rh + 0.007
    prof = [(0, 0), (rk, 0), (rk, 0.007), (rh + 0.001, 0.02), (rh, 0.03), (rh, 0.33 * length),
            (rb * 0.7, 0.52 * length), (rb * 0.95, 0.66 * length), (rb, 0.75 * length), (rb, length - 0.012),
            (rb * 0.88, length - 0.003), (rb * 0.55, length), (0, length)]
    if v == 3:  # softball bat: longer straight barrel
        prof[6:9] = [(rb * 0.8, 0.45 * length), (rb, 0.55 * length)]
    # rest it as a real bat lies: on the knob and the barrel, the axis slightly inclined; shave both flat
    xb = 0.8 * length
    tilt = float(np.arctan2(rk - rb, xb))
    bat = g.lathe_x(prof, -length / 2, 0.0, sections=16)
    g.rotate_y(bat, tilt)
    bat = g.clip_below(bat, float(bat.bounds[0][2]) + 0.003)
    slot = ["wood", "hh_alu", "wood", "hh_alu"][v]
    parts = [solid(bat, slot)]
    if v in (1, 3):
        grip = g.prism_x(rh + 0.0012, 0.28 * length - 0.02, -length / 2 + 0.02, 0.0, sections=12)
        parts.append(visual(g.rotate_y(grip, tilt), "hh_grip"))
    else:
        band = g.torus_ring(rb * 0.97, 0.0012, (length * 0.3, 0, 0.0), plane="yz", n=16, m=4)
        parts.append(visual(g.rotate_y(band, tilt), "hh_ink"))
    return small_asset("BaseballBat", v, parts, [0.9, 0.85, 0.7, 0.8][v], "baseball bat lying on its side")


@register("BasketBall", variants=4, category="small")
def basket_ball(v: int, rng: np.random.Generator) -> AssetSpec:
    """A basketball (size 7, 6, 5, mini) with black seams and a tiny flat spot where it rests."""
    r = [0.121, 0.116, 0.11, 0.085][v]
    depth = 0.055 * r
    ball = g.clip_below(g.superquadric((r, r, r), 1.0, 1.0, (0, 0, r), nu=14, nv=28), depth)
    parts = [solid(ball, "hh_basketball")]
    ms = 0.0016 if v < 3 else 0.0013
    yaw = [0.0, PI / 4, PI / 2, PI / 6][v]
    delta = np.radians(28)
    seams = [g.torus_arc(r, ms, (0, 0, r), plane="yz", start=-PI / 2 + delta, end=3 * PI / 2 - delta,
                         sections=26, minor_sections=4),
             g.torus_ring(r, ms, (0, 0, r), plane="xy", n=28, m=4)]
    off = 0.58 * r
    rho = float(np.sqrt(r * r - off * off))
    for s in (-1, 1):
        seams.append(g.torus_ring(rho, ms, (s * off, 0, r), plane="yz", n=22, m=4))
    for m in seams:
        parts.append(visual(g.rotate_z(m, yaw, (0, 0, 0)), "hh_ink"))
    return small_asset("BasketBall", v, parts, [0.62, 0.57, 0.5, 0.3][v], "basketball")


@register("TennisRacket", variants=3, category="small")
def tennis_racket(v: int, rng: np.random.Generator) -> AssetSpec:
    """A racket lying flat: oval frame, string bed, throat and an octagonal grip along x."""
    total = [0.685, 0.69, 0.66][v]
    ha, hb = [(0.165, 0.125), (0.18, 0.14), (0.145, 0.11)][v]  # head semi-axes along x / y
    ft, fh = [(0.012, 0.022), (0.013, 0.026), (0.011, 0.017)][v]  # frame width / height
    grip_r = 0.0165
    zc = g.prism_axis_height(grip_r, 8)
    head_cx = total / 2 - ha
    path = [(head_cx + ha * np.cos(a), hb * np.sin(a)) for a in np.linspace(0, 2 * PI, 40, endpoint=False)]
    sec = [(-ft / 2, -fh / 2), (ft / 2, -fh / 2), (ft / 2, fh / 2), (-ft / 2, fh / 2)]
    slot = "hh_racket"
    parts = [solid(g.sweep_loop(path, sec, zc), slot)]
    # strings: mains along x, crosses along y, clipped to the inner oval
    ia, ib = ha - ft / 2, hb - ft / 2
    for k in range(-7, 8):
        y = k * 2 * ib / 16
        half = ia * np.sqrt(max(1 - (y / ib) ** 2, 0.0))
        parts.append(visual(g.box((2 * half, 0.0012, 0.0012), (head_cx, y, zc)), "hh_strings"))
    for k in range(-9, 10):
        x = k * 2 * ia / 20
        half = ib * np.sqrt(max(1 - (x / ia) ** 2, 0.0))
        parts.append(visual(g.box((0.0012, 2 * half, 0.0012), (head_cx + x, 0, zc)), "hh_strings"))
    # throat: two arms from the bottom of the head to the handle
    grip_len = 0.19
    x_grip = -total / 2 + grip_len
    x_head = head_cx - ha
    for s in (-1, 1):
        p0 = (x_head + 0.03, s * hb * 0.55, zc)
        p1 = (x_grip + 0.005, s * 0.006, zc)
        parts.append(solid(g.rod(p0, p1, fh / 2 * 0.8, sections=8), slot))
    parts.append(solid(g.box((0.012, hb * 1.0, fh * 0.8), (x_head + 0.045, 0, zc)), slot))
    grip = g.prism_x(grip_r, grip_len, -total / 2, zc, sections=8)
    parts.append(solid(grip, "hh_grip"))
    parts.append(visual(g.prism_x(grip_r + 0.001, 0.012, -total / 2 - 0.001, zc, sections=8), slot))
    if v == 1:  # wrap band on the grip
        parts.append(visual(g.prism_x(grip_r + 0.0008, 0.01, x_grip - 0.012, zc, sections=8), slot))
    return small_asset("TennisRacket", v, parts, [0.3, 0.31, 0.28][v], "tennis racket lying flat")


# ------------------------------------------------------------------------------------------ paper goods

@register("Book", variants=4, category="small")
def book(v: int, rng: np.random.Generator) -> AssetSpec:
    """A closed book lying flat, spine at -x: hardcover, paperback, thick dictionary, coffee-table book."""
    w, d, th = [
        (pick(rng, 0.15, 0.17), pick(rng, 0.22, 0.24), pick(rng, 0.025, 0.035)),
        (pick(rng, 0.11, 0.13), pick(rng, 0.175, 0.19), pick(rng, 0.012, 0.02)),
        (pick(rng, 0.17, 0.19), pick(rng, 0.24, 0.26), pick(rng, 0.055, 0.065)),
        (pick(rng, 0.29, 0.31), pick(rng, 0.23, 0.25), pick(rng, 0.02, 0.026)),
    ][v]
    parts: list[Part] = []
    cover = "book_cover"
    if v == 1:  # paperback: flush soft cover around the page block
        ct = 0.0012
        parts.append(solid(g.box_at((-w / 2 + ct, -d / 2, ct), (w / 2, d / 2, th - ct)), "paper"))
        parts.append(solid(g.box_at((-w / 2, -d / 2, 0), (w / 2, d / 2, ct)), cover))
        parts.append(solid(g.box_at((-w / 2, -d / 2, th - ct), (w / 2, d / 2, th)), cover))
        parts.append(solid(g.box_at((-w / 2, -d / 2, 0), (-w / 2 + ct, d / 2, th)), cover))
        parts.append(visual(g.flat_decal(w * 0.7, d * 0.3, th, 0.01, d * 0.12), "hh_face"))
        parts.append(visual(g.flat_decal(w * 0.5, d * 0.05, th, 0.01, -d * 0.3), "hh_ink"))
    else:  # hardcover: boards overhang the pages, rounded spine
        bt, oh = (0.003, 0.003) if v != 2 else (0.0035, 0.004)
        parts.append(solid(g.box_at((-w / 2 + 0.002, -d / 2, 0), (w / 2, d / 2, bt)), cover))
        parts.append(solid(g.box_at((-w / 2 + 0.002, -d / 2, th - bt), (w / 2, d / 2, th)), cover))
        spine = g.cylinder(th / 2, d, (0, 0, 0), axis="y", sections=16)
        spine.apply_scale((0.006 / (th / 2), 1.0, 1.0))
        spine.apply_translation((-w / 2 + 0.006, 0, th / 2))
        parts.append(solid(spine, cover))
        parts.append(solid(g.box_at((-w / 2 + 0.004, -d / 2 + oh, bt), (w / 2 - oh, d / 2 - oh, th - bt)), "paper"))
        for z in (th * 0.2, th * 0.8):
            band = g.box((0.0125, d + 0.0008, 0.002), (-w / 2 + 0.0045, 0, z))
            parts.append(visual(band, "hh_gold"))
        if v == 0:
            parts.append(visual(g.flat_decal(w * 0.55, d * 0.08, th, 0.01, d * 0.25), "hh_gold"))
            parts.append(visual(g.flat_decal(w * 0.35, d * 0.03, th, 0.01, d * 0.14), "hh_gold"))
        elif v == 2:
            parts.append(visual(g.flat_decal(w * 0.6, d * 0.35, th, 0.01, 0.0, r=0.01), "hh_face"))
            parts.append(visual(g.flat_decal(w * 0.45, d * 0.05, th + 0.0004, 0.01, d * 0.05), "hh_ink"))
        else:
            parts.append(visual(g.flat_decal(w * 0.62, d * 0.62, th, 0.02, 0.0), "hh_photo"))
            parts.append(visual(g.flat_decal(w * 0.5, d * 0.06, th, 0.02, -d * 0.4), "hh_face"))
    return small_asset("Book", v, parts, [0.6, 0.25, 1.4, 1.2][v], "closed book lying flat")


def _print_layout(w: float, d: float, z: float, cols: int, style: str) -> list[Part]:
    """Masthead, headline, photo and columns of text lines printed on a w x d page at height z.

    The head of the page is at -y, so it reads the right way up from the front (+y)."""
    parts = [visual(g.flat_decal(w * 0.86, d * 0.08, z, 0, -d * 0.4), "hh_ink")]
    if style == "tabloid":  # a big photo under a screaming headline
        parts.append(visual(g.flat_decal(w * 0.86, d * 0.07, z, 0, -d * 0.29), "hh_ink"))
        parts.append(visual(g.flat_decal(w * 0.86, d * 0.36, z, 0, -d * 0.04), "hh_photo"))
        top = d * 0.17
    else:
        parts.append(visual(g.flat_decal(w * 0.7, d * 0.035, z, -w * 0.06, -d * 0.3), "hh_ink"))
        top = -d * 0.26
    bottom = d * 0.44
    cw = w * 0.86 / cols
    for c in range(cols):
        cx = -w * 0.43 + cw * (c + 0.5)
        y0 = top
        if style == "broad" and c < 2:
            ph = d * 0.28
            if c == 0:
                parts.append(visual(g.flat_decal(cw * 2 - 0.008, ph, z, cx + cw / 2, top + ph / 2), "hh_photo"))
            y0 = top + ph + 0.012
        n = int((bottom - y0) / 0.022)
        for k in range(n):
            ln = cw - 0.008 - (0.02 * cw if (k + c) % 4 == 3 else 0.0)
            parts.append(visual(g.flat_decal(ln, 0.006, z, cx, y0 + 0.011 + 0.022 * k), "hh_print"))
    return parts


@register("Newspaper", variants=3, category="small")
def newspaper(v: int, rng: np.random.Generator) -> AssetSpec:
    """A folded newspaper lying flat: broadsheet folded in half, flat tabloid, broadsheet folded in quarters."""
    w, d, th = [(0.3, pick(rng, 0.28, 0.3), 0.008), (pick(rng, 0.27, 0.29), 0.36, 0.006),
                (0.15, pick(rng, 0.28, 0.3), 0.014)][v]
    parts = [solid(g.box_at((-w / 2, -d / 2, 0), (w / 2, d / 2, th)), "hh_newsprint")]
    if v == 0:  # folded in half: the fold runs along the bottom of the front page
        parts.append(solid(g.cylinder(th / 2, w, (0, d / 2, th / 2), axis="x", sections=10), "hh_newsprint"))
    elif v == 1:  # loose sheets: the inner pages stick out a little
        inner = g.box_at((-w / 2 + 0.004, -d / 2 - 0.004, 0.001), (w / 2 + 0.003, d / 2 - 0.004, th - 0.002))
        parts.append(solid(inner, "hh_newsprint"))
    else:  # folded twice: fold along the right edge and a thin seam line
        parts.append(solid(g.cylinder(th / 2, d, (w / 2, 0, th / 2), axis="y", sections=10), "hh_newsprint"))
    parts += _print_layout(w * 0.96, d * 0.96, th, [4, 4, 2][v], ["broad", "tabloid", "quarter"][v])
    return small_asset("Newspaper", v, parts, [0.3, 0.25, 0.3][v], "folded newspaper")


@register("CD", variants=3, category="small")
def cd(v: int, rng: np.random.Generator) -> AssetSpec:
    """A compact disc in its case lying flat: jewel case, slim case with the disc on top, double case."""
    w, d = 0.142, 0.125
    th = [0.0104, 0.005, 0.024][v]
    parts: list[Part] = []
    tray_h = th * 0.6
    parts.append(solid(g.box_at((-w / 2, -d / 2, 0), (w / 2, d / 2, tray_h)), "hh_ink" if v != 1 else "hh_art"))
    parts.append(solid(g.box_at((-w / 2 + 0.006, -d / 2, tray_h), (w / 2, d / 2, th)), "glass"))
    parts.append(solid(g.box_at((-w / 2, -d / 2, tray_h), (-w / 2 + 0.006, d / 2, th)), "hh_ink"))
    if v != 1:  # printed booklet seen through the lid
        parts.append(visual(g.flat_decal(w - 0.02, d - 0.012, th, 0.004, 0), "hh_art"))
        parts.append(visual(g.flat_decal(w * 0.55, 0.012, th + 0.0004, 0.01, d * 0.32), "hh_face"))
        parts.append(visual(g.flat_disc(0.03, th + 0.0004, 0.02, -0.01, n=20), "hh_face"))
        parts.append(visual(g.box((0.0008, d * 0.7, th * 0.5), (-w / 2 - 0.0004, 0, th / 2)), "hh_face"))
    else:  # the disc lies on its case, label up, half off the edge
        z = th
        cx = pick(rng, 0.03, 0.04)
        parts.append(solid(g.cylinder(0.06, 0.0012, (cx, 0.004, z + 0.0006), sections=32), "hh_disc"))
        label = g.revolve([(0.0205, 0), (0.0585, 0), (0.0585, 0.0003), (0.0205, 0.0003), (0.0205, 0)], sections=32)
        label.apply_translation((cx, 0.004, z + 0.0012))
        parts.append(visual(label, "hh_art"))
        parts.append(visual(g.flat_disc(0.0075, z + 0.0012, cx, 0.004, n=12), "hh_ink"))
        parts.append(visual(g.flat_decal(0.05, 0.008, z + 0.0015, cx + 0.01, 0.004 + 0.035), "hh_face"))
    return small_asset("CD", v, parts, [0.1, 0.06, 0.18][v], "compact disc in its case")


@register("CreditCard", variants=3, category="small")
def credit_card(v: int, rng: np.random.Generator) -> AssetSpec:
    """A plastic card lying flat: bank card with chip, portrait ID badge, key-tag loyalty card."""
    th = 0.004
    if v == 0:
        w, d = 0.0856, 0.054
        parts = [solid(g.rounded_slab(w, d, th, 0.0032), "hh_card"),
                 visual(g.flat_decal(0.012, 0.009, th, -0.027, 0.004, r=0.0015), "hh_gold"),
                 visual(g.flat_disc(0.0065, th, 0.027, -0.016, n=14), "hh_red"),
                 visual(g.flat_disc(0.0065, th + 0.0002, 0.035, -0.016, n=14), "hh_gold")]
        for k in range(4):
            parts.append(visual(g.flat_decal(0.014, 0.003, th, -0.03 + k * 0.018, -0.008), "hh_face"))
        parts.append(visual(g.flat_decal(0.03, 0.0025, th, -0.024, -0.018), "hh_face"))
    elif v == 1:
        w, d = 0.054, 0.0856
        parts = [solid(g.rounded_slab(w, d, th, 0.0032), "hh_face"),
                 visual(g.flat_decal(w, 0.014, th, 0, d / 2 - 0.007), "hh_card"),
                 visual(g.flat_decal(0.022, 0.028, th, -0.01, 0.006), "hh_photo"),
                 visual(g.flat_decal(0.012, 0.003, th + 0.0004, 0, d / 2 - 0.007, r=0.0014), "hh_ink")]
        for k in range(3):
            parts.append(visual(g.flat_decal(0.04 - 0.008 * k, 0.003, th, 0.0, -0.016 - 0.007 * k), "hh_ink"))
        parts.append(visual(g.flat_decal(0.012, 0.02, th, 0.017, 0.008), "hh_ink"))
    else:
        w, d = 0.066, 0.035
        parts = [solid(g.rounded_slab(w, d, th, 0.006), "hh_card"),
                 visual(g.flat_disc(0.0035, th, -w / 2 + 0.007, 0, n=12), "hh_dark"),
                 visual(g.flat_decal(0.04, 0.018, th, 0.006, -0.002), "hh_face")]
        for k in range(14):
            bw = 0.0012 if k % 3 else 0.0022
            parts.append(visual(g.flat_decal(bw, 0.012, th + 0.0004, -0.011 + k * 0.0026, -0.002), "hh_ink"))
    return small_asset("CreditCard", v, parts, 0.01, "plastic card")


# ------------------------------------------------------------------------------------------------ boots

def _boot(length: float, width: float, sole_h: float, shaft_h: float, style: str) -> list[Part]:
    """One boot, toe towards +y: sole, toe box, shaft with a dark opening and style details."""
    slot = "hh_boot"
    parts = [solid(g.rounded_slab(width, length, sole_h, width * 0.45), "hh_sole")]
    foot_h = 0.062
    vamp = g.clip_below(g.ellipsoid((width / 2 * 0.95, length / 2 * 0.96, foot_h), (0, 0.0, sole_h), 2), sole_h)
    parts.append(solid(vamp, slot))
    rx, ry = width / 2 * 0.93, length * 0.22
    sy = -length / 2 + ry + 0.01
    hs = shaft_h - sole_h
    top_scale = 1.12 if style == "rain" else 1.0
    shaft = g.frustum(1.0, top_scale, hs, (0, 0, 0), sections=20)
    shaft.apply_scale((rx, ry, 1.0))
    shaft.apply_translation((0, sy, sole_h))
    parts.append(solid(shaft, slot))
    opening = g.cylinder(1.0, 0.001, (0, 0, 0), sections=20)
    opening.apply_scale((rx * top_scale * 0.82, ry * top_scale * 0.8, 1.0))
    opening.apply_translation((0, sy, shaft_h))
    parts.append(visual(opening, "hh_dark"))
    if style == "work":
        front = sy + ry
        for k in range(5):
            z = sole_h + 0.05 + k * (hs - 0.07) / 4
            parts.append(visual(g.rod((-rx * 0.45, front - 0.004, z), (rx * 0.45, front - 0.004, z + 0.012), 0.0018,
                                      sections=5), "hh_lace"))
        parts.append(visual(g.box((rx * 0.7, 0.008, 0.025), (0, front - 0.01, shaft_h + 0.006)), slot))
    elif style == "rain":
        band = g.cylinder(1.0, 0.025, (0, 0, 0), sections=20)
        band.apply_scale((rx * top_scale * 1.03, ry * top_scale * 1.03, 1.0))
        band.apply_translation((0, sy, shaft_h - 0.0125))
        parts.append(visual(band, "hh_sole"))
    else:  # chelsea: elastic side panels and a pull tab
        for s in (-1, 1):
            panel = g.box((0.003, ry * 0.7, hs * 0.65), (s * rx, sy, shaft_h - hs * 0.35))
            parts.append(visual(panel, "hh_dark"))
        parts.append(visual(g.box((0.014, 0.004, 0.035), (0, sy - ry + 0.002, shaft_h + 0.005)), "hh_dark"))
    return parts


@register("Boots", variants=3, category="small")
def boots(v: int, rng: np.random.Generator) -> AssetSpec:
    """Boots standing on their soles: a lace-up work boot, a tall rain boot, a pair of ankle boots."""
    if v == 0:
        parts = _boot(pick(rng, 0.28, 0.3), pick(rng, 0.1, 0.11), 0.028, pick(rng, 0.16, 0.18), "work")
    elif v == 1:
        parts = _boot(pick(rng, 0.28, 0.3), pick(rng, 0.1, 0.11), 0.022, pick(rng, 0.34, 0.38), "rain")
    else:
        length, width = pick(rng, 0.26, 0.28), pick(rng, 0.09, 0.1)
        parts = []
        for s, yaw in ((-1, 0.0), (1, np.radians(-8))):
            one = _boot(length, width, 0.02, pick(rng, 0.14, 0.16), "chelsea")
            for p in one:
                g.rotate_z(p.mesh, yaw)
                p.mesh.apply_translation((s * (width / 2 + 0.012), 0.01 * s, 0))
            parts += one
    return small_asset("Boots", v, parts, [0.8, 0.9, 1.3][v], ["work boot", "rain boot", "pair of ankle boots"][v])


# ------------------------------------------------------------------------------------------------ candles

def _wick(x: float, y: float, z: float, ln: float = 0.012) -> Part:
    return visual(g.cylinder(0.0012, ln, (x, y, z + ln / 2 - 0.002), sections=6), "hh_wick")


@register("Candle", variants=4, category="small")
def candle(v: int, rng: np.random.Generator) -> AssetSpec:
    """Candles: a pillar, a taper in a brass candlestick, a jar candle, a three-wick candle on a saucer."""
    parts: list[Part] = []
    if v == 0:
        r, h = pick(rng, 0.032, 0.04), pick(rng, 0.09, 0.13)
        body = g.revolve([(0, 0), (r, 0), (r, h - 0.002), (r * 0.92, h), (r * 0.6, h - 0.0025), (0, h - 0.004)],
                         sections=20)
        parts += [solid(body, "hh_wax"), _wick(0, 0, h - 0.004)]
        desc = "pillar candle"
    elif v == 1:
        parts.append(solid(g.revolve([(0, 0), (0.045, 0), (0.045, 0.006), (0.035, 0.012), (0.012, 0.018), (0, 0.018)],
                                     sections=20), "brass"))
        stem = [(0, 0.015), (0.009, 0.015), (0.013, 0.03), (0.007, 0.045), (0.007, 0.07), (0.013, 0.08),
                (0.008, 0.09), (0, 0.09)]
        parts.append(solid(g.revolve(stem, sections=12), "brass"))
        parts.append(solid(g.container([(0.012, 0), (0.03, 0.012)], wall=0.003, bottom=0.004, center=(0, 0, 0.088),
                                       sections=20), "brass"))
        ln = pick(rng, 0.18, 0.22)
        taper = g.revolve([(0, 0), (0.0105, 0), (0.0095, ln - 0.012), (0.004, ln), (0, ln)], sections=12)
        taper.apply_translation((0, 0, 0.092))
        parts += [solid(taper, "hh_wax"), _wick(0, 0, 0.092 + ln)]
        desc = "taper candle in a brass candlestick"
    elif v == 2:
        r, h = pick(rng, 0.038, 0.045), pick(rng, 0.085, 0.1)
        jar = g.container([(r * 0.95, 0), (r, 0.01), (r, h)], wall=0.004, bottom=0.006, sections=20)
        parts.append(solid(jar, "glass"))
        parts.append(visual(g.cylinder(r - 0.0042, h * 0.72, (0, 0, 0.006 + h * 0.36), sections=20), "hh_wax"))
        parts.append(visual(g.cylinder(r + 0.0006, h * 0.35, (0, 0, h * 0.45), sections=20), "hh_art"))
        parts.append(_wick(0, 0, 0.006 + h * 0.72))
        desc = "candle in a glass jar"
    else:
        r, h = pick(rng, 0.045, 0.05), pick(rng, 0.07, 0.08)
        dish = [(0, 0), (0.055, 0), (0.075, 0.014), (0.071, 0.015), (0.05, 0.004), (0, 0.004)]
        parts.append(solid(g.revolve(dish, sections=20), "ceramic"))
        body = g.revolve([(0, 0), (r, 0), (r, h), (r * 0.85, h - 0.004), (0, h - 0.006)], sections=20)
        body.apply_translation((0, 0, 0.004))
        parts.append(solid(body, "hh_wax"))
        for k in range(3):
            a = 2 * PI * k / 3 + PI / 2
            parts.append(_wick(0.02 * np.cos(a), 0.02 * np.sin(a), 0.004 + h - 0.005))
        desc = "three-wick candle on a saucer"
    return small_asset("Candle", v, parts, [0.4, 0.5, 0.45, 0.6][v], desc)


# ---------------------------------------------------------------------------------------- desk & pocket

def _key(length: float, head: str, rng: np.random.Generator, slot: str) -> list[Part]:
    """A flat key along +x with its ring hole at the origin."""
    kt = 0.0035
    if head == "round":
        parts = [solid(g.cylinder(0.012, kt, (0.01, 0, kt / 2), sections=14), slot)]
    elif head == "cap":
        parts = [solid(g.rounded_slab(0.024, 0.022, kt + 0.001, 0.006, 0, 0.01), "plastic")]
    else:
        parts = [solid(g.rounded_slab(0.022, 0.02, kt, 0.004, 0, 0.01), slot)]
    parts.append(solid(g.box_at((0.02, -0.004, 0), (0.021 + length, 0.0045, kt)), slot))
    x = 0.028
    for _ in range(4):
        dw = pick(rng, 0.004, 0.007)
        parts.append(visual(g.box_at((x, 0.0045, 0.0002), (x + dw * 0.8, 0.0045 + pick(rng, 0.001, 0.0025),
                                                           kt - 0.0002)),
                            slot))
        x += dw
    parts.append(visual(g.flat_disc(0.0022, parts[0].mesh.bounds[1][2], 0.002, 0, n=8), "hh_dark"))
    return parts


def _place_key(parts: list[Part], ring_r: float, angle: float) -> list[Part]:
    for p in parts:
        g.rotate_z(p.mesh, angle)
        p.mesh.apply_translation(((ring_r - 0.002) * np.cos(angle), (ring_r - 0.002) * np.sin(angle), 0))
    return parts


@register("KeyChain", variants=3, category="small")
def key_chain(v: int, rng: np.random.Generator) -> AssetSpec:
    """A split ring with keys lying flat: two keys, three keys with a tag, a car key fob with a key."""
    ring_r = pick(rng, 0.012, 0.015)
    minor = 0.00175
    parts = [solid(g.torus_ring(ring_r, minor, (0, 0, minor), n=24, m=6), "metal")]
    if v == 0:
        parts += _place_key(_key(0.04, "round", rng, "brass"), ring_r, np.radians(-38))
        parts += _place_key(_key(0.036, "square", rng, "metal"), ring_r, np.radians(38))
    elif v == 1:
        for ang, head, ln in ((-70, "cap", 0.038), (0, "square", 0.045), (70, "round", 0.034)):
            parts += _place_key(_key(ln, head, rng, "metal"), ring_r, np.radians(ang))
        tag = g.rounded_slab(0.045, 0.028, 0.0035, 0.006, 0, -ring_r - 0.02, 0)
        parts.append(solid(tag, "hh_card"))
        parts.append(visual(g.flat_decal(0.026, 0.014, 0.0035, -ring_r - 0.024, 0, r=0.002), "hh_face"))
    else:
        parts += _place_key(_key(0.042, "square", rng, "metal"), ring_r, 0.0)
        fx = -ring_r - 0.033
        parts.append(solid(g.rounded_slab(0.06, 0.032, 0.012, 0.012, 0, fx, 0), "hh_remote"))
        parts.append(solid(g.box_at((-ring_r - 0.008, -0.004, 0.002), (-ring_r + 0.002, 0.004, 0.009)), "hh_remote"))
        for k in range(3):
            parts.append(visual(g.flat_disc(0.0045, 0.012, fx - 0.014 + k * 0.012, 0, t=0.0008, n=10), "hh_button"))
    return small_asset("KeyChain", v, parts, [0.04, 0.07, 0.09][v], "key ring with keys")


@register("Pen", variants=3, category="small")
def pen(v: int, rng: np.random.Generator) -> AssetSpec:
    """A pen lying along x (tip at +x) on a flat facet: capped ballpoint, click pen, fountain pen."""
    n = 8
    parts: list[Part] = []
    if v == 0:
        r, ln = 0.0042, pick(rng, 0.14, 0.15)
        zc = g.prism_axis_height(r, n)
        x0 = -ln / 2
        parts.append(solid(g.prism_x(r, ln - 0.05, x0, zc, n), "hh_pen_barrel"))
        parts.append(visual(g.prism_x(r * 0.8, 0.004, x0 - 0.003, zc, n), "hh_pen"))
        rc = r * 1.12
        zc_cap = g.prism_axis_height(rc, n)
        cap = [(0, 0), (rc, 0), (rc, 0.046), (rc * 0.75, 0.05), (0, 0.05)]
        parts.append(solid(g.lathe_x(cap, ln / 2 - 0.05, zc_cap, n), "hh_pen"))
        parts.append(visual(g.box_at((ln / 2 - 0.048, -0.0013, zc_cap + rc * 0.85), (ln / 2 - 0.012, 0.0013,
                                                                                     zc_cap + rc + 0.0016)), "hh_pen"))
        parts.append(visual(g.prism_x(r * 0.35, ln - 0.06, x0 + 0.004, zc, n), "hh_pen"))
    elif v == 1:
        r, ln = 0.0048, pick(rng, 0.135, 0.145)
        zc = g.prism_axis_height(r, n)
        x0 = -ln / 2
        body_len = ln - 0.03
        parts.append(solid(g.prism_x(r, body_len, x0 + 0.008, zc, n), "hh_pen"))
        parts.append(solid(g.lathe_x([(0, 0), (r, 0), (r * 0.45, 0.02), (0.0007, 0.022), (0, 0.022)],
                                     x0 + 0.008 + body_len, zc, n), "metal"))
        parts.append(visual(g.prism_x(r * 1.06, 0.03, x0 + 0.008 + body_len - 0.035, g.prism_axis_height(r * 1.06, n),
                                      n), "rubber"))
        parts.append(visual(g.prism_x(r * 0.55, 0.01, x0, zc, n), "metal"))
        parts.append(visual(g.box_at((x0 + 0.012, -0.0014, zc + r * 0.85), (x0 + 0.048, 0.0014, zc + r + 0.0018)),
                            "metal"))
    else:
        r, ln = 0.0065, pick(rng, 0.14, 0.145)
        zc = g.prism_axis_height(r, n)
        x0 = -ln / 2
        parts.append(solid(g.lathe_x([(0, 0), (r * 0.7, 0), (r, 0.015), (r, ln * 0.45), (0, ln * 0.45)], x0, zc, n),
                           "hh_pen"))
        parts.append(solid(g.lathe_x([(0, 0), (r * 1.05, 0), (r * 1.05, ln * 0.42), (r * 0.8, ln * 0.5), (0, ln * 0.5)],
                                     x0 + ln * 0.45, g.prism_axis_height(r * 1.05, n), n), "hh_pen"))
        for xb in (x0 + ln * 0.45 + 0.004, x0 + ln * 0.45 + ln * 0.4):
            parts.append(visual(g.prism_x(r * 1.1, 0.004, xb, g.prism_axis_height(r * 1.1, n), n), "hh_gold"))
        zt = g.prism_axis_height(r * 1.05, n) + r * 1.05
        parts.append(visual(g.box_at((x0 + ln * 0.5, -0.0017, zt - 0.0015), (x0 + ln * 0.86, 0.0017, zt + 0.0018)),
                            "hh_gold"))
    return small_asset("Pen", v, parts, [0.012, 0.015, 0.03][v], "pen lying flat")


@register("Pencil", variants=4, category="small")
def pencil(v: int, rng: np.random.Generator) -> AssetSpec:
    """A hexagonal pencil lying along x on a flat face (point at +x): new, stub, coloured, flat carpenter's."""
    parts: list[Part] = []
    if v == 3:  # carpenter's pencil: flat rectangular section, chisel point
        ln, wy, hz = pick(rng, 0.17, 0.18), 0.012, 0.007
        body = g.box_at((-ln / 2, -wy / 2, 0), (ln / 2 - 0.022, wy / 2, hz))
        tip = trimesh.convex.convex_hull(np.array([
            [ln / 2 - 0.022, s1 * wy / 2, z] for s1 in (-1, 1) for z in (0, hz)] +
            [[ln / 2, s1 * wy * 0.35, z] for s1 in (-1, 1) for z in (hz * 0.35, hz * 0.55)]))
        parts += [solid(body, "hh_red"), solid(tip, "hh_pencil_wood")]
        parts.append(visual(g.box_at((ln / 2 - 0.0045, -wy * 0.3, hz * 0.4), (ln / 2 + 0.0003, wy * 0.3, hz * 0.5)),
                            "hh_graphite"))
        parts.append(visual(g.flat_decal(0.05, 0.004, hz, -0.02, 0), "hh_ink"))
        return small_asset("Pencil", v, parts, 0.012, "flat carpenter's pencil")
    n = 6
    r = 0.0037
    zc = g.prism_axis_height(r, n)
    ln = [pick(rng, 0.185, 0.19), pick(rng, 0.085, 0.1), pick(rng, 0.17, 0.176)][v]
    x0 = -ln / 2
    eraser = v != 2
    tip_len = 0.02
    x_body = x0 + (0.015 if eraser else 0.0)
    body_len = ln - tip_len - (x_body - x0)
    parts.append(solid(g.prism_x(r, body_len, x_body, zc, n), "hh_pencil"))
    cone = [(0, 0), (r, 0), (0.0013, tip_len - 0.004), (0, tip_len - 0.004)]
    parts.append(solid(g.lathe_x(cone, x_body + body_len, zc, n), "hh_pencil_wood"))
    graphite = "hh_graphite" if v != 2 else "hh_pencil"
    parts.append(visual(g.lathe_x([(0, 0), (0.0013, 0), (0.0002, 0.0045), (0, 0.0045)],
                                  x_body + body_len + tip_len - 0.0045, zc, n), graphite))
    if eraser:
        rf = r * 0.87
        parts.append(solid(g.lathe_x([(0, 0), (rf, 0), (rf, 0.009), (0, 0.009)], x0 + 0.006, zc, 12), "metal"))
        parts.append(solid(g.lathe_x([(0, 0), (rf * 0.8, 0), (rf * 0.93, 0.002), (rf * 0.93, 0.007), (0, 0.007)],
                                     x0 - 0.0005, zc, 12), "hh_eraser"))
    else:
        parts.append(visual(g.prism_x(r * 1.005, 0.006, x0 - 0.0002, zc, n), "hh_ink"))
    parts.append(visual(g.box_at((x0 + 0.03, -0.0012, 2 * zc - 0.0002), (x0 + 0.06, 0.0012, 2 * zc + 0.0001)),
                        "hh_gold"))
    return small_asset("Pencil", v, parts, 0.01, "hexagonal pencil")


# ------------------------------------------------------------------------------------------- ornaments

@register("Statue", variants=4, category="small")
def statue(v: int, rng: np.random.Generator) -> AssetSpec:
    """A small sculpture on a base: abstract ring-and-flame form, classical bust, sitting cat, stone cairn."""
    parts: list[Part] = []
    if v == 0:
        bw = pick(rng, 0.085, 0.1)
        parts.append(solid(g.box_at((-bw / 2, -bw / 2, 0), (bw / 2, bw / 2, 0.03)), "dark_wood"))
        flame = g.ellipsoid((0.024, 0.02, 0.1), (0, 0, 0), 2)
        g.rotate_y(flame, np.radians(10))
        flame.apply_translation((0.006, 0, 0.12))
        parts.append(solid(flame, "hh_bronze"))
        parts.append(solid(g.torus_ring(0.045, 0.008, (0, 0, 0.13), plane="xz", n=28, m=8), "hh_bronze"))
        tip = (0.006 + 0.1 * np.sin(np.radians(10)), 0.0, 0.12 + 0.1 * np.cos(np.radians(10)) + 0.012)
        parts.append(solid(g.sphere(0.017, tip, subdivisions=2), "hh_bronze"))
        desc = "abstract bronze sculpture on a wooden base"
    elif v == 1:
        parts.append(solid(g.revolve([(0, 0), (0.055, 0), (0.055, 0.015), (0.045, 0.02), (0.04, 0.05), (0.05, 0.055),
                                      (0.05, 0.065), (0, 0.065)], sections=20), "stone"))
        chest = g.clip_below(g.ellipsoid((0.075, 0.042, 0.06), (0, 0, 0.065), 2), 0.065)
        parts.append(solid(chest, "stone"))
        parts.append(solid(g.cylinder(0.02, 0.04, (0, 0.004, 0.135), sections=12), "stone"))
        parts.append(solid(g.ellipsoid((0.034, 0.04, 0.046), (0, 0.008, 0.182), 2), "stone"))
        parts.append(visual(g.ellipsoid((0.007, 0.012, 0.014), (0, 0.046, 0.178), 1), "stone"))
        for s in (-1, 1):
            parts.append(visual(g.ellipsoid((0.006, 0.012, 0.014), (s * 0.033, 0.004, 0.182), 1), "stone"))
        parts.append(visual(g.clip_below(g.ellipsoid((0.037, 0.043, 0.04), (0, 0.0, 0.19), 2), 0.19), "stone"))
        desc = "classical marble bust on a pedestal"
    elif v == 2:
        s = pick(rng, 0.9, 1.1)
        parts.append(solid(g.rounded_slab(0.1 * s, 0.14 * s, 0.015, 0.04 * s), "dark_wood"))
        z0 = 0.015
        body = g.ellipsoid((0.04 * s, 0.05 * s, 0.065 * s), (0, -0.012 * s, z0 + 0.05 * s), 2)
        parts.append(solid(g.clip_below(body, z0), "hh_bronze"))
        parts.append(solid(g.ellipsoid((0.028 * s, 0.024 * s, 0.05 * s), (0, 0.02 * s, z0 + 0.075 * s), 2),
                           "hh_bronze"))
        hz = z0 + 0.135 * s
        parts.append(solid(g.ellipsoid((0.032 * s, 0.029 * s, 0.028 * s), (0, 0.024 * s, hz), 2), "hh_bronze"))
        for sx in (-1, 1):
            ear = g.frustum(0.012 * s, 0.001, 0.024 * s, (0, 0, 0), sections=6)
            g.rotate_y(ear, sx * 0.35)
            ear.apply_translation((sx * 0.018 * s, 0.02 * s, hz + 0.017 * s))
            parts.append(visual(ear, "hh_bronze"))
            parts.append(solid(g.cylinder(0.009 * s, 0.07 * s, (sx * 0.014 * s, 0.04 * s, z0 + 0.035 * s), sections=8),
                               "hh_bronze"))
            parts.append(visual(g.sphere(0.004 * s, (sx * 0.011 * s, 0.05 * s, hz + 0.006 * s), 1), "hh_ink"))
        tail = g.torus_arc(0.045 * s, 0.007 * s, (0, -0.01 * s, z0 + 0.007 * s), plane="xy", start=-PI * 0.9,
                           end=PI * 0.1, sections=12, minor_sections=6)
        parts.append(visual(tail, "hh_bronze"))
        desc = "bronze figurine of a sitting cat"
    else:
        parts = []
        z = 0.0
        stones = [(0.07, 0.055, 0.026), (0.056, 0.046, 0.024), (0.042, 0.034, 0.02), (0.03, 0.024, 0.017),
                  (0.02, 0.016, 0.013)]
        for k, (a, b, c) in enumerate(stones):
            st = g.ellipsoid((a, b, c), (0, 0, 0), 2)
            g.rotate_z(st, pick(rng, 0.0, PI))
            st.apply_translation((pick(rng, -0.006, 0.006), pick(rng, -0.006, 0.006), z + c * 0.85))
            if k == 0:
                st = g.clip_below(st, 0.004)
            parts.append(solid(st, "stone"))
            z += c * 1.65
        desc = "stacked stone cairn sculpture"
    return small_asset("Statue", v, parts, [1.5, 3.0, 1.2, 2.5][v], desc)


@register("TeddyBear", variants=4, category="small")
def teddy_bear(v: int, rng: np.random.Generator) -> AssetSpec:
    """A sitting teddy bear facing +y: body, head with snout and ears, arms, legs stretched forward."""
    s = [1.0, 0.85, 1.1, 1.45][v] * pick(rng, 0.95, 1.05)
    big_head = 1.2 if v == 1 else 1.0
    fur, light = "hh_fur", "hh_fur_light"
    flat = 0.012 * s
    parts: list[Part] = []
    parts.append(solid(g.clip_below(g.ellipsoid((0.085 * s, 0.075 * s, 0.1 * s), (0, 0, 0.1 * s), 2), flat), fur))
    parts.append(visual(g.smooth_ellipsoid((0.05 * s, 0.02 * s, 0.06 * s), (0, 0.058 * s, 0.1 * s)), light))
    for sx in (-1, 1):
        leg = g.clip_below(g.smooth_ellipsoid((0.036 * s, 0.068 * s, 0.036 * s),
                                              (sx * 0.047 * s, 0.065 * s, 0.04 * s)), flat)
        parts.append(solid(leg, fur))
        parts.append(visual(g.ellipsoid((0.027 * s, 0.006 * s, 0.026 * s), (sx * 0.047 * s, 0.13 * s, 0.043 * s), 1),
                            light))
        arm = g.smooth_ellipsoid((0.028 * s, 0.028 * s, 0.065 * s))
        arm.apply_transform(trimesh.transformations.euler_matrix(-0.5, sx * 0.35, 0, axes="sxyz"))
        arm.apply_translation((sx * 0.082 * s, 0.03 * s, 0.125 * s))
        parts.append(solid(arm, fur))
    hr = 0.068 * s * big_head
    hz = 0.19 * s + hr * 0.8
    parts.append(solid(g.sphere(hr, (0, 0.008 * s, hz), subdivisions=2), fur))
    parts.append(visual(g.smooth_ellipsoid((0.46 * hr, 0.4 * hr, 0.34 * hr), (0, 0.008 * s + 0.88 * hr,
                                                                              hz - 0.22 * hr)), light))
    parts.append(visual(g.ellipsoid((0.17 * hr, 0.11 * hr, 0.11 * hr), (0, 0.008 * s + 1.27 * hr, hz - 0.12 * hr), 1),
                        "hh_ink"))
    for sx in (-1, 1):
        parts.append(visual(g.sphere(0.11 * hr, (sx * 0.37 * hr, 0.008 * s + 0.86 * hr, hz + 0.22 * hr), 0), "hh_ink"))
        ear_c = np.array([sx * 0.7 * hr, 0.0, hz + 0.72 * hr])
        parts.append(solid(g.ellipsoid((0.36 * hr, 0.17 * hr, 0.36 * hr), ear_c, 1), fur))
        parts.append(visual(g.ellipsoid((0.22 * hr, 0.06 * hr, 0.22 * hr), ear_c + [0, 0.13 * hr, -0.02 * hr], 1),
                            light))
    if v == 2:  # a ribbon bow under the chin
        bz = 0.19 * s
        for sx in (-1, 1):
            loop = g.ellipsoid((0.024 * s, 0.008 * s, 0.015 * s), (0, 0, 0), 1)
            g.rotate_y(loop, sx * 0.3)
            loop.apply_translation((sx * 0.022 * s, 0.062 * s, bz))
            parts.append(visual(loop, "hh_ribbon"))
        parts.append(visual(g.sphere(0.009 * s, (0, 0.066 * s, bz), 1), "hh_ribbon"))
    return small_asset("TeddyBear", v, parts, [0.3, 0.25, 0.35, 0.6][v], "sitting teddy bear")


@register("Vase", variants=4, category="small")
def vase(v: int, rng: np.random.Generator) -> AssetSpec:
    """A ceramic vase with a real cavity (coacd collision): amphora, cylinder, round bulb, trumpet."""
    k = pick(rng, 0.92, 1.08)
    prof = [
        [(0.04, 0), (0.07, 0.05), (0.08, 0.11), (0.06, 0.18), (0.032, 0.22), (0.03, 0.25), (0.042, 0.27)],
        [(0.05, 0), (0.052, 0.01), (0.052, 0.24), (0.056, 0.25)],
        [(0.045, 0), (0.075, 0.03), (0.085, 0.07), (0.07, 0.12), (0.03, 0.15), (0.025, 0.17), (0.032, 0.18)],
        [(0.05, 0), (0.05, 0.012), (0.03, 0.03), (0.034, 0.12), (0.055, 0.22), (0.08, 0.27)],
    ][v]
    prof = [(r * k, z * k) for r, z in prof]
    body = g.container(prof, wall=0.006, bottom=0.012, sections=20)
    parts = [Part(body, "ceramic", convex=False)]
    if v in (0, 2):
        zb = prof[2][1]
        parts.append(visual(g.torus_ring(prof[2][0] + 0.0005, 0.002, (0, 0, zb), n=20, m=4), "hh_gold"))
    elif v == 1:
        parts.append(visual(g.cylinder(prof[1][0] + 0.0008, 0.03, (0, 0, 0.16 * k), sections=20), "hh_art"))
    return small_asset("Vase", v, parts, [0.9, 0.8, 0.7, 0.8][v], "ceramic vase")


# ------------------------------------------------------------------------------------------------ garden

def _spout(p0: np.ndarray, p1: np.ndarray, r: float, rose: tuple[float, float, float, int], slot: str) -> list[Part]:
    """A watering can's spout from p0 to p1 (radius r) with a rose (frustum r_bottom, r_top, length, sections)."""
    d = p1 - p0
    r0, r1, length, sections = rose
    head = g.point_along(g.frustum(r0, r1, length, sections=sections), d, p1 - d / np.linalg.norm(d) * 0.01)
    return [solid(g.rod(p0, p1, r, sections=10), slot), solid(head, slot)]


@register("WateringCan", variants=3, category="small")
def watering_can(v: int, rng: np.random.Generator) -> AssetSpec:
    """A watering can (spout towards +y): classic metal can with a rose, plastic can, small indoor can."""
    parts: list[Part] = []
    if v == 0:
        r, h = pick(rng, 0.09, 0.1), pick(rng, 0.19, 0.21)
        parts.append(solid(g.revolve([(0, 0), (r, 0), (r, h), (r * 0.85, h + 0.012), (0, h + 0.012)], sections=24),
                           "hh_can"))
        parts.append(solid(g.cylinder(0.035, 0.018, (0, -0.035, h + 0.018), sections=16), "hh_can"))
        parts.append(visual(g.flat_disc(0.029, h + 0.027, 0, -0.035, n=16), "hh_dark"))
        p0, p1 = np.array([0, r * 0.75, 0.035]), np.array([0, r + 0.24, h + 0.07])
        parts += _spout(p0, p1, 0.011, (0.012, 0.03, 0.035, 14), "hh_can")
        handle = g.torus_arc(0.082, 0.009, (0, -0.012, h + 0.006), plane="yz", start=0.0, end=PI, sections=14,
                             minor_sections=8)
        parts.append(Part(handle, "hh_can", convex=False))
        desc = "metal watering can with a rose on its long spout"
    elif v == 1:
        a, b, c = pick(rng, 0.065, 0.075), pick(rng, 0.105, 0.115), 0.115
        body = g.clip_below(g.superquadric((a, b, c), 0.55, 0.6, (0, 0, c), nu=10, nv=20), 0.01)
        parts.append(solid(body, "plastic"))
        top = float(body.bounds[1][2])
        p0, p1 = np.array([0, b * 0.8, 0.04]), np.array([0, b + 0.2, top + 0.05])
        parts += _spout(p0, p1, 0.012, (0.013, 0.024, 0.03, 12), "plastic")
        handle = g.torus_arc(0.085, 0.011, (0, -0.02, top - 0.045), plane="yz", start=0.35, end=PI - 0.1, sections=14,
                             minor_sections=8)
        parts.append(Part(handle, "plastic", convex=False))
        parts.append(solid(g.cylinder(0.03, 0.015, (0, 0.035, top - 0.003), sections=14), "plastic"))
        desc = "plastic watering can with an arched top handle"
    else:
        r = pick(rng, 0.07, 0.08)
        body = g.clip_below(g.sphere(r, (0, 0, r), subdivisions=2), 0.25 * r)
        parts.append(solid(body, "hh_can"))
        parts.append(solid(g.cylinder(0.022, 0.015, (0, 0, 2 * r + 0.004), sections=14), "brass"))
        p0, p1 = np.array([0, r * 0.75, r * 0.6]), np.array([0, r + 0.19, 2 * r + 0.02])
        parts.append(solid(g.frustum(0.011, 0.005, float(np.linalg.norm(p1 - p0)), sections=10), "brass"))
        g.point_along(parts[-1].mesh, p1 - p0, p0)
        handle = g.torus_arc(0.045, 0.008, (0, -r * 0.88, r * 1.05), plane="yz", start=PI / 2, end=3 * PI / 2,
                             sections=12, minor_sections=8)
        parts.append(Part(handle, "brass", convex=False))
        desc = "small indoor watering can with a long thin spout"
    return small_asset("WateringCan", v, parts, [0.7, 0.5, 0.35][v], desc)
