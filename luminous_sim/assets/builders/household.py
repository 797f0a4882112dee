"""Household small objects: books, electronics, sports gear, textiles, toiletries, ornaments.

Everything here is built in its natural resting pose (flat things lie flat along x or y, round things
carry a small flat spot) so that it settles upright when dropped. Sizes are real-world metres.
"""

from __future__ import annotations

import itertools

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, small_asset, solid, visual
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Joint, Link, Part

add_palettes(
    hh_clock=hex_colours("c0392b", "2f3235", "3f88c5", "e9e2d6", "5aa469"),
    hh_face=hex_colours("fbfbf8", "f5f1e6", "fafafa"),
    hh_ink=hex_colours("1b1b1b", "262626"),
    hh_led=hex_colours("ff3b30", "3ddc84", "5ad1ff"),
    hh_basketball=hex_colours("d9642b", "c8561f", "e07a3a", "cf6a32"),
    hh_alu=hex_colours("9aa0a6", "3a3d41", "c0392b", "1d3557"),
    hh_grip=hex_colours("222222", "f0f0f0", "3f88c5"),
    hh_boot=hex_colours("7b4a2a", "2d2420", "1f3b2c", "a0703c", "d94f4f"),
    hh_sole=hex_colours("2b2b2b", "4a3526", "1e1e1e"),
    hh_lace=hex_colours("c8a97e", "1e1e1e"),
    hh_disc=hex_colours("d8dde3", "e5e5e5", "c9ced4"),
    hh_art=hex_colours("e76f51", "2a9d8f", "264653", "e9c46a", "6d597a"),
    hh_wax=hex_colours("f4efe1", "e8d9b5", "c94c4c", "f2c14e", "9fb59a"),
    hh_wick=hex_colours("2a2a2a"),
    hh_phone=hex_colours("1e1e1e", "f0f0f0", "c9b8a0", "3f5e8a", "8c2f39"),
    hh_button=hex_colours("5a5a5a", "7d7d7d", "9a9a9a"),
    hh_red=hex_colours("d62828", "c1121f"),
    hh_cloth=hex_colours("4f86c6", "f2c14e", "e07a5f", "81b29a", "d9d9d9"),
    hh_stripe=hex_colours("c1121f", "264653", "f4f4f4"),
    hh_card=hex_colours("1d4e89", "2a9d8f", "c1121f", "222222", "e9c46a"),
    hh_gold=hex_colours("d4af37", "c9a227"),
    hh_photo=hex_colours("8a8f94", "6f7b86", "a3a8ad"),
    hh_towel=hex_colours("f5f5f0", "9cc3d5", "e7c6b8", "6a8caf", "b8d8b0", "f0e0b0", "8e9aa6"),
    hh_towel_band=hex_colours("c8c8c0", "6f96ac", "c9a393", "4f6d8f", "93b78a", "d2bf8c", "6d7884"),
    hh_laptop=hex_colours("b8bcc2", "2d2d2d", "d0d3d6", "3a3d41"),
    hh_key=hex_colours("1e1e1e", "2d2d2d"),
    hh_lit_screen=hex_colours("4f9de0", "5fb0f0", "3d8bd0"),
    hh_window=hex_colours("f4f6f8", "e8edf2"),
    hh_newsprint=hex_colours("e9e5da", "efece3", "e0dccf"),
    hh_print=hex_colours("9a978f", "8c8980"),
    hh_pen=hex_colours("1d4ed8", "111111", "c1121f", "1f7a3a"),
    hh_pen_barrel=hex_colours("e6e9ec", "f0f0f0", "111111"),
    hh_pencil=hex_colours("f2c14e", "3f88c5", "c94c4c", "5aa469"),
    hh_pencil_wood=hex_colours("e8c89a", "dcb886"),
    hh_graphite=hex_colours("3a3a3a", "2f2f2f"),
    hh_eraser=hex_colours("f4a6a6", "f19a9a"),
    hh_piping=hex_colours("c8b99c", "6b7a8f", "9e4a3c", "3f5e4a"),
    hh_plunger=hex_colours("b3261e", "1e1e1e", "c0392b"),
    hh_remote=hex_colours("1e1e1e", "2d2d2d", "e6e6e6", "3a3a3a"),
    hh_soap=hex_colours("f3e9dc", "f7d6e0", "d5ecd4", "fff5c2", "cfe3f2"),
    hh_bottle=hex_colours("7fb8e6", "f2f2f2", "5aa469", "f2c14e", "e7e1f5"),
    hh_bronze=hex_colours("8c6a3f", "a97d4a", "6e5230", "4a4a4a"),
    hh_fur=hex_colours("8b5a2b", "c8a06e", "e8d8c0", "5a3a22", "d9b38c"),
    hh_fur_light=hex_colours("d9b38c", "efe0c8", "fbf3e8", "a0744c", "f0dcc0"),
    hh_ribbon=hex_colours("c0392b", "3f88c5", "e76f98"),
    hh_strings=hex_colours("f0f0f0", "e8e25a", "f5f0dc"),
    hh_racket=hex_colours("1d3557", "c1121f", "2d2d2d", "a0703c"),
    hh_tissuebox=hex_colours("9fb6a2", "bcd4e6", "e8d9b5", "d9a6a0"),
    hh_tissue=hex_colours("fafafa", "f6f6f2"),
    hh_cardboard=hex_colours("c8a97e", "b8976a", "d4b892"),
    hh_dark=hex_colours("141414"),
    hh_can=hex_colours("5aa469", "3f88c5", "b8bcc2", "f2c14e", "d94f4f"),
    hh_strap=hex_colours("5b3a29", "1f1f1f", "8b5a3c", "2f3b52"),
    hh_case=hex_colours("e76f51", "2a9d8f", "1d3557", "f4a6a6"),
)

PI = float(np.pi)


# ----------------------------------------------------------------------------------------------- helpers

# ---------------------------------------------------------------------------------------------- clocks

_SEGMENTS = {
    "0": "abcdef", "1": "bc", "2": "abged", "3": "abgcd", "4": "fgbc", "5": "afgcd", "6": "afgedc", "7": "abc",
    "8": "abcdefg", "9": "abcdfg",
}


def _digits(text: str, cx: float, y: float, cz: float, hd: float, slot: str) -> list[Part]:
    """Seven-segment digits on a front face at y (read from the front, where +x is on the viewer's left)."""
    wd, s, t = 0.55 * hd, 0.14 * hd, 0.001
    pitch = wd + 0.45 * hd
    parts = []
    for i, ch in enumerate(text):
        x = cx - (i - (len(text) - 1) / 2) * pitch
        if ch == ":":
            for dz in (-0.22 * hd, 0.22 * hd):
                parts.append(visual(g.box((s, t, s), (x, y + t / 2, cz + dz)), slot))
            continue
        segs = {
            "a": ((wd, t, s), (x, cz + hd / 2)), "d": ((wd, t, s), (x, cz - hd / 2)), "g": ((wd, t, s), (x, cz)),
            "b": ((s, t, hd / 2), (x - wd / 2, cz + hd / 4)), "c": ((s, t, hd / 2), (x - wd / 2, cz - hd / 4)),
            "f": ((s, t, hd / 2), (x + wd / 2, cz + hd / 4)), "e": ((s, t, hd / 2), (x + wd / 2, cz - hd / 4)),
        }
        for k in _SEGMENTS[ch]:
            size, (sx, sz) = segs[k]
            parts.append(visual(g.box(size, (sx, y + t / 2, sz)), slot))
    return parts


def _clock_face(r: float, cx: float, y: float, cz: float, hour: float, minute: float, ticks: int = 12,
                face_slot: str = "hh_face") -> list[Part]:
    """A round dial on a front face at y: disc, hour ticks, hour/minute/second hands and a centre pin."""
    t = 0.002
    parts = [visual(g.cylinder(r, t, (cx, y + t / 2, cz), axis="y", sections=24), face_slot)]
    yf = y + t
    for k in range(ticks):
        a = 2 * PI * k / ticks
        ln = 0.17 * r if k % 3 == 0 else 0.09 * r
        rr = r * 0.88 - ln / 2
        tick = g.box((0.05 * r, 0.001, ln), (0, 0, 0))
        g.rotate_y(tick, -a)
        tick.apply_translation((cx - rr * np.sin(a), yf + 0.0005, cz + rr * np.cos(a)))
        parts.append(visual(tick, "hh_ink"))
    for ang, ln, wd, dy, slot in ((2 * PI * (hour % 12 + minute / 60) / 12, 0.5 * r, 0.07 * r, 0.0012, "hh_ink"),
                                  (2 * PI * minute / 60, 0.78 * r, 0.045 * r, 0.0022, "hh_ink"),
                                  (2 * PI * 0.55, 0.82 * r, 0.015 * r, 0.0032, "hh_red")):
        hand = g.box_at((-wd / 2, -0.0005, -0.15 * ln), (wd / 2, 0.0005, ln))
        g.rotate_y(hand, -ang)
        hand.apply_translation((cx, yf + dy, cz))
        parts.append(visual(hand, slot))
    parts.append(visual(g.cylinder(0.05 * r, 0.005, (cx, yf + 0.0025, cz), axis="y", sections=8), "metal"))
    return parts


@register("AlarmClock", variants=4, category="small")
def alarm_clock(v: int, rng: np.random.Generator) -> AssetSpec:
    """Alarm clocks: twin-bell on feet, square travel clock, digital LED clock, round ball clock."""
    parts: list[Part] = []
    if v == 0:  # classic twin-bell clock on two feet
        r = pick(rng, 0.05, 0.058)
        dep = pick(rng, 0.04, 0.05)
        leg = 0.014
        zc = leg + r
        parts.append(solid(g.cylinder(r, dep, (0, 0, zc), axis="y", sections=24), "hh_clock"))
        parts.append(visual(g.torus_ring(r * 0.95, 0.0035, (0, dep / 2, zc), plane="xz", n=24, m=5), "metal"))
        parts += _clock_face(r * 0.86, 0, dep / 2, zc, 10, 10)
        rb = 0.55 * r
        dome = [(0, 0), (rb, 0), (rb * 0.97, rb * 0.3), (rb * 0.8, rb * 0.65), (rb * 0.45, rb * 0.9), (0, rb * 0.95)]
        for s in (-1, 1):
            a = np.radians(40)
            d = np.array([s * np.sin(a), 0.0, np.cos(a)])
            base = np.array([0, 0, zc]) + d * (r + 0.005)
            parts.append(solid(g.point_along(g.revolve(dome, sections=16), d, base), "metal"))
            parts.append(visual(g.rod(base - d * 0.008, base + d * 0.002, 0.003, sections=6), "metal"))
            foot = g.box((0.014, dep + 0.018, leg + 0.012), (s * r * 0.6, 0, (leg + 0.012) / 2))
            parts.append(solid(foot, "metal"))
        parts.append(visual(g.rod((0, 0, zc + r - 0.004), (0, 0, zc + r + 0.03), 0.002, sections=6), "metal"))
        parts.append(visual(g.sphere(0.006, (0, 0, zc + r + 0.03), subdivisions=1), "metal"))
        parts.append(visual(g.cylinder(0.008, 0.01, (0, -dep / 2 - 0.005, zc), axis="y", sections=8), "metal"))
        desc = "twin-bell alarm clock on two feet"
    elif v == 1:  # square travel clock
        w = pick(rng, 0.085, 0.1)
        dep = pick(rng, 0.045, 0.055)
        parts.append(solid(g.rounded_slab_y(w, w, dep, 0.014, (0, 0, w / 2)), "wood"))
        parts.append(visual(g.torus_ring(w * 0.37, 0.003, (0, dep / 2, w / 2), plane="xz", n=24, m=5), "brass"))
        parts += _clock_face(w * 0.35, 0, dep / 2, w / 2, 7, 25)
        parts.append(visual(g.cylinder(0.009, 0.006, (w * 0.25, 0, w + 0.003), sections=10), "brass"))
        parts.append(visual(g.cylinder(0.006, 0.006, (-w * 0.25, 0, w + 0.003), sections=10), "brass"))
        desc = "square wooden alarm clock with a round dial"
    elif v == 2:  # digital LED clock
        w = pick(rng, 0.13, 0.16)
        h = pick(rng, 0.06, 0.075)
        dep = pick(rng, 0.06, 0.075)
        parts.append(solid(g.rounded_slab_y(w, h, dep, 0.016, (0, 0, h / 2)), "hh_clock"))
        parts.append(visual(g.rounded_slab_y(w * 0.78, h * 0.62, 0.002, 0.004, (0, dep / 2 + 0.001, h * 0.52)),
                            "screen"))
        parts += _digits("12:30", 0, dep / 2 + 0.002, h * 0.52, h * 0.36, "hh_led")
        parts.append(solid(g.box((w * 0.5, dep * 0.4, 0.008), (0, 0, h + 0.003)), "hh_button"))
        desc = "digital alarm clock with an LED display and a snooze bar"
    else:  # round ball clock with a flat dial
        r = pick(rng, 0.05, 0.06)
        rf = 0.74 * r
        yf = float(np.sqrt(r * r - rf * rf))
        ball = g.clip_below(g.sphere(r, (0, 0, r), subdivisions=2), 0.16 * r)
        ball = ball.slice_plane([0.0, yf, 0.0], [0.0, -1.0, 0.0], cap=True)
        parts.append(solid(ball, "hh_clock"))
        parts.append(visual(g.torus_ring(rf * 0.97, 0.003, (0, yf, r), plane="xz", n=24, m=5), "metal"))
        parts += _clock_face(rf * 0.92, 0, yf, r, 2, 50)
        parts.append(visual(g.cylinder(0.01, 0.008, (0, -0.004, 2 * r + 0.002), sections=10), "metal"))
        desc = "round ball alarm clock"
    return small_asset("AlarmClock", v, parts, [0.45, 0.35, 0.4, 0.35][v], desc)


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


# -------------------------------------------------------------------------------------------- electronics

@register("CellPhone", variants=4, category="small")
def cell_phone(v: int, rng: np.random.Generator) -> AssetSpec:
    """A phone lying screen up, top towards -y: full-screen, home-button, keypad bar phone, phablet in a case."""
    parts: list[Part] = []
    if v == 0:
        w, ln, t = pick(rng, 0.07, 0.076), pick(rng, 0.146, 0.16), 0.008
        parts.append(solid(g.rounded_slab(w, ln, t, 0.009, n=4), "hh_phone"))
        parts.append(visual(g.rounded_slab(w - 0.004, ln - 0.004, 0.0004, 0.008, t, n=4), "screen"))
        parts.append(visual(g.flat_disc(0.0022, t + 0.0004, 0, -ln / 2 + 0.008, n=10), "hh_ink"))
    elif v == 1:
        w, ln, t = 0.067, 0.138, 0.0074
        parts.append(solid(g.rounded_slab(w, ln, t, 0.009, n=4), "hh_phone"))
        parts.append(visual(g.flat_decal(w - 0.008, ln - 0.042, t, 0, -0.001), "screen"))
        parts.append(visual(g.flat_disc(0.0055, t, 0, ln / 2 - 0.0105, n=16), "hh_button"))
        parts.append(visual(g.flat_decal(0.01, 0.0016, t, 0, -ln / 2 + 0.011, r=0.0007), "hh_ink"))
        parts.append(visual(g.flat_disc(0.0016, t, -0.008, -ln / 2 + 0.011, n=8), "hh_ink"))
    elif v == 2:
        w, ln, t = 0.048, 0.11, 0.014
        parts.append(solid(g.rounded_slab(w, ln, t, 0.01, n=4), "hh_remote"))
        parts.append(visual(g.flat_decal(0.036, 0.03, t, 0, -0.027, r=0.002), "screen"))
        parts.append(visual(g.flat_disc(0.0065, t, 0, 0.002, n=14), "hh_button"))
        for sx in (-1, 1):
            parts.append(visual(g.flat_decal(0.01, 0.005, t, sx * 0.015, 0.002, r=0.0015), "hh_button"))
        for row in range(4):
            for col in range(3):
                key = g.flat_decal(0.011, 0.0065, t, (col - 1) * 0.0135, 0.016 + row * 0.0095, t=0.0008, r=0.002)
                parts.append(visual(key, "hh_button"))
    else:
        w, ln, t = 0.082, 0.168, 0.011
        parts.append(solid(g.rounded_slab(w, ln, t, 0.011, n=4), "hh_case"))
        parts.append(visual(g.rounded_slab(w - 0.006, ln - 0.006, 0.0006, 0.008, t - 0.0002, n=4), "screen"))
        parts.append(visual(g.flat_disc(0.0022, t + 0.0004, 0, -ln / 2 + 0.009, n=10), "hh_ink"))
        for dy in (-0.03, -0.012):
            parts.append(visual(g.box((0.0012, 0.012, 0.004), (w / 2 + 0.0005, dy, t / 2)), "hh_case"))
    if v in (0, 1):
        parts.append(visual(g.box((0.001, 0.02, 0.0025), (w / 2 + 0.0004, -0.03, t / 2)), "hh_button"))
    return small_asset("CellPhone", v, parts, [0.2, 0.15, 0.09, 0.25][v], "mobile phone lying screen up")


@register("Laptop", variants=4, category="small")
def laptop(v: int, rng: np.random.Generator) -> AssetSpec:
    """A laptop: base with keyboard and touchpad, screen lid on a revolute hinge at the back edge.

    The lid joint is 0 when closed and opens to 110 degrees; switched on, the screen shows a lit desktop.
    """
    w, d, bh, lt, r = [
        (pick(rng, 0.3, 0.31), pick(rng, 0.208, 0.215), 0.014, 0.006, 0.008),
        (pick(rng, 0.355, 0.365), pick(rng, 0.245, 0.255), 0.022, 0.008, 0.006),
        (pick(rng, 0.295, 0.3), pick(rng, 0.195, 0.2), 0.009, 0.005, 0.011),
        (pick(rng, 0.27, 0.285), pick(rng, 0.195, 0.2), 0.026, 0.01, 0.02),
    ][v]
    shell = "hh_laptop"
    base: list[Part] = [solid(g.rounded_slab(w, d, bh, r, n=4), shell)]
    cols = 17 if v == 1 else 13
    kb_w = w * (0.9 if v == 1 else 0.84)
    pitch = kb_w / cols
    key = pitch * 0.8
    kb_back = -d / 2 + 0.018
    x0 = -kb_w / 2 + pitch / 2

    def keycap(x: float, y: float, kw: float) -> Part:
        return visual(g.box_at((x - kw / 2, y - key / 2, bh - 0.0008), (x + kw / 2, y + key / 2, bh + 0.0001)),
                      "hh_key")

    for row in range(5):
        y = kb_back + pitch * (row + 0.5)
        for col in range(cols):
            base.append(keycap(x0 + col * pitch, y, key))
    y = kb_back + pitch * 5.5
    main = 13
    for col in (0, 1, 2, 8, 9, 10, 11, 12) + tuple(range(13, cols)):
        if col != 11 or main == cols:
            base.append(keycap(x0 + col * pitch, y, key))
    base.append(keycap(x0 + 5 * pitch, y, pitch * 4.8))
    kb_front = kb_back + pitch * 6
    pad_d = min(0.07, d / 2 - kb_front - 0.015)
    pad_x = -pitch * 2 if v == 1 else 0.0
    base.append(visual(g.flat_decal(min(0.11, w * 0.34), pad_d, bh, pad_x, (kb_front + d / 2) / 2, r=0.004),
                       "hh_button"))
    base.append(visual(g.flat_decal(w * 0.6, 0.003, bh, 0, -d / 2 + 0.006), "hh_key"))
    led = g.box((0.004, 0.0012, 0.0016), (w / 2 - 0.03, d / 2 + 0.0003, bh / 2))
    base.append(visual(led, "led_off", state="off"))
    base.append(visual(led.copy(), "led_on", state="on"))

    # lid, in its own frame: hinge line along x at the origin, closed lid lying over +y
    gap = 0.0012
    lid: list[Part] = [solid(g.rounded_slab(w, d, lt, r, gap, cy=d / 2, n=4), shell)]
    sy0, sy1 = 0.02, d - 0.008
    sw = w - 0.02
    sc = (sy0 + sy1) / 2
    lid.append(visual(g.rounded_slab(sw, sy1 - sy0, 0.0005, 0.002, gap - 0.0005, cy=sc), "screen"))
    lid.append(visual(g.flat_disc(0.0016, gap - 0.0006, 0, d - 0.004, t=0.0005, n=8), "hh_ink"))
    lid.append(visual(g.flat_disc(0.013, gap + lt, 0, d / 2, n=16), "hh_face"))
    lid.append(visual(g.rounded_slab(sw - 0.001, sy1 - sy0 - 0.001, 0.0004, 0.002, gap - 0.0009, cy=sc),
                      "hh_lit_screen",
                      state="on"))
    lid.append(visual(g.rounded_slab(sw, 0.008, 0.0002, 0.0, gap - 0.0011, cy=sy0 + 0.004), "hh_ink", state="on"))
    ww, wh = sw * 0.48, (sy1 - sy0) * 0.5
    lid.append(visual(g.rounded_slab(ww, wh, 0.0002, 0.0, gap - 0.0011, cx=sw * 0.12, cy=sc + 0.01), "hh_window",
                      state="on"))
    lid.append(visual(g.rounded_slab(ww * 0.6, wh * 0.6, 0.0002, 0.0, gap - 0.0011, cx=-sw * 0.25, cy=sc - 0.02),
                      "hh_window",
                      state="on"))
    joint = Joint("lid_hinge", "revolute", "base", "lid", (0.0, -d / 2, bh), (1.0, 0.0, 0.0), 0.0,
                  float(np.radians(110)), "lid")
    return AssetSpec("Laptop", v, "small", [Link("base", base, 1.4), Link("lid", lid, 0.6)], joints=[joint],
                     description="laptop with an opening screen lid; the screen lights up when on")


@register("RemoteControl", variants=3, category="small")
def remote_control(v: int, rng: np.random.Generator) -> AssetSpec:
    """A remote lying flat, pointing at -y: TV remote with a keypad, slim streaming remote, AC remote."""
    parts: list[Part] = []
    if v == 0:
        w, ln, t = pick(rng, 0.048, 0.055), pick(rng, 0.19, 0.22), 0.02
        parts.append(solid(g.superquadric((w / 2, ln / 2, t / 2), 0.35, 0.25, (0, 0, t / 2), nu=8, nv=20), "hh_remote"))
        top = t - 0.0005
        parts.append(visual(g.flat_disc(0.0045, top, -w * 0.28, -ln / 2 + 0.018, t=0.002, n=10), "hh_red"))
        for row in range(4):
            for col in range(3):
                parts.append(visual(g.flat_decal(0.009, 0.0055, top, (col - 1) * 0.0135, -ln / 2 + 0.04 + row * 0.01,
                                                 t=0.0018, r=0.002), "hh_button"))
        yc = -ln / 2 + 0.1
        parts.append(visual(g.torus_ring(0.0125, 0.0025, (0, yc, top + 0.001), n=20, m=5), "hh_button"))
        parts.append(visual(g.flat_disc(0.0065, top, 0, yc, t=0.002, n=12), "hh_button"))
        for sx in (-1, 1):
            parts.append(visual(g.flat_decal(0.009, 0.026, top, sx * 0.015, yc + 0.035, t=0.0018, r=0.003),
                                "hh_button"))
        parts.append(visual(g.flat_decal(0.012, 0.006, t - 0.008, 0, -ln / 2 - 0.0005, t=0.006), "hh_dark"))
    elif v == 1:
        w, ln, t = 0.036, pick(rng, 0.13, 0.14), 0.009
        parts.append(solid(g.rounded_slab(w, ln, t, 0.012, n=4), "hh_remote"))
        parts.append(visual(g.flat_disc(0.013, t, 0, -ln / 2 + 0.022, n=20), "hh_button"))
        for k, yy in enumerate((0.012, 0.03, 0.048)):
            parts.append(visual(g.flat_disc(0.0048, t, -0.008 if k < 2 else 0.0, -ln / 2 + 0.035 + yy, t=0.0008, n=10),
                                "hh_button"))
            if k < 2:
                parts.append(visual(g.flat_disc(0.0048, t, 0.008, -ln / 2 + 0.035 + yy, t=0.0008, n=10), "hh_button"))
    else:
        w, ln, t = pick(rng, 0.055, 0.06), pick(rng, 0.14, 0.155), 0.024
        side = [(-ln / 2, 0), (ln / 2, 0), (ln / 2, t * 0.75), (ln / 2 - 0.03, t), (-ln / 2 + 0.01, t),
                (-ln / 2, t * 0.8)]
        parts.append(solid(g.extrude_yz(side, w), "hh_face"))
        parts.append(visual(g.flat_decal(w * 0.7, 0.035, t, 0, -ln / 2 + 0.03, r=0.002), "screen"))
        parts += _digits_flat(w, -ln / 2 + 0.03, t + 0.0004)
        for row in range(3):
            for col in range(2):
                parts.append(visual(g.flat_decal(0.018, 0.011, t, (col - 0.5) * 0.024, -ln / 2 + 0.062 + row * 0.017,
                                                 t=0.0015, r=0.003), "hh_button"))
        parts.append(visual(g.flat_disc(0.006, t, 0, -ln / 2 + 0.012, t=0.0008, n=10), "hh_red"))
    return small_asset("RemoteControl", v, parts, [0.15, 0.05, 0.12][v], "remote control lying flat")


def _digits_flat(w: float, cy: float, z: float) -> list[Part]:
    """The temperature read-out of an AC remote: two big segment digits lying on its screen."""
    out = []
    for ch_x, segs in ((0.006, "abged"), (-0.006, "abcdfg")):
        hd, wd, s = 0.018, 0.008, 0.002
        y = cy
        boxes = {
            "a": ((wd, s), (ch_x, y - hd / 2)), "d": ((wd, s), (ch_x, y + hd / 2)), "g": ((wd, s), (ch_x, y)),
            "b": ((s, hd / 2), (ch_x - wd / 2, y - hd / 4)), "c": ((s, hd / 2), (ch_x - wd / 2, y + hd / 4)),
            "f": ((s, hd / 2), (ch_x + wd / 2, y - hd / 4)), "e": ((s, hd / 2), (ch_x + wd / 2, y + hd / 4)),
        }
        for k in segs:
            (sx, sy), (px, py) = boxes[k]
            out.append(visual(g.flat_decal(sx, sy, z, px, py, t=0.0003), "hh_led"))
    return out


# ------------------------------------------------------------------------------------------------ textiles

def _stains(rng: np.random.Generator, n: int, w: float, d: float, z: float, cx: float = 0.0,
            cy: float = 0.0) -> list[Part]:
    """Dirty-state smudges lying on a top surface at height z (visible only when dirty)."""
    out = []
    for _ in range(n):
        rx, ry = pick(rng, 0.012, 0.03), pick(rng, 0.008, 0.02)
        x, y = cx + pick(rng, -w / 3, w / 3), cy + pick(rng, -d / 3, d / 3)
        m = g.ellipsoid((rx, ry, 0.0006), (0, 0, 0), subdivisions=1)
        g.rotate_z(m, pick(rng, 0.0, PI))
        m.apply_translation((x, y, z + 0.0002))
        out.append(visual(m, "dirt", state="dirty"))
    return out


@register("Cloth", variants=3, category="small")
def cloth(v: int, rng: np.random.Generator) -> AssetSpec:
    """A cleaning cloth lying flat: folded microfibre square, striped dish cloth, crumpled rag; dirty stains."""
    parts: list[Part] = []
    if v == 0:
        s = pick(rng, 0.15, 0.18)
        parts.append(solid(g.rounded_slab(s, s, 0.004, 0.006), "hh_cloth"))
        parts.append(solid(g.rounded_slab(s * 0.97, s * 0.96, 0.004, 0.006, 0.004, 0.003, -0.002), "hh_cloth"))
        parts.append(solid(g.cylinder(0.004, s * 0.94, (-s / 2 + 0.003, -0.002, 0.004), axis="y", sections=10),
                           "hh_cloth"))
        parts.append(visual(g.flat_decal(0.02, 0.008, 0.008, s * 0.35, s * 0.4), "hh_face"))
        top, w, d = 0.008, s, s
    elif v == 1:
        w, d = pick(rng, 0.23, 0.26), pick(rng, 0.14, 0.16)
        parts.append(solid(g.rounded_slab(w, d, 0.007, 0.004), "hh_cloth"))
        parts.append(solid(g.cylinder(0.0035, w - 0.004, (0, -d / 2 + 0.001, 0.0035), axis="x", sections=10),
                           "hh_cloth"))
        for sx in (-1, 1):
            for dx in (0.0, 0.016):
                parts.append(visual(g.flat_decal(0.008, d - 0.002, 0.007, sx * (w * 0.36 - dx), 0), "hh_stripe"))
        top = 0.007
    else:
        w, d = pick(rng, 0.2, 0.24), pick(rng, 0.15, 0.18)
        rag = _crumple(rng, w / 2, d / 2, 0.022)
        parts.append(solid(rag, "hh_cloth"))
        top = 0.018
        w, d = w * 0.5, d * 0.5
    parts += _stains(rng, 3, w, d, top)
    return small_asset("Cloth", v, parts, [0.04, 0.05, 0.06][v], "cleaning cloth; shows stains when dirty")


def _crumple(rng: np.random.Generator, a: float, b: float, h: float, rings: int = 4, segs: int = 20) -> trimesh.Trimesh:
    """A crumpled cloth: a wrinkled mound over a ragged outline with a flat underside."""
    rad = np.array([pick(rng, 0.72, 1.0) for _ in range(segs)])
    rad = (rad + np.roll(rad, 1) + np.roll(rad, -1)) / 3
    verts = [(0.0, 0.0, h)]
    for i in range(1, rings + 1):
        rho = i / rings
        for j in range(segs):
            t = 2 * PI * j / segs
            bump = 1 + (pick(rng, -0.3, 0.3) if i < rings else 0.0)
            z = h * 0.3 if i == rings else h * (1 - 0.6 * rho ** 2) * bump
            verts.append((a * rho * rad[j] * np.cos(t), b * rho * rad[j] * np.sin(t), z))
    for j in range(segs):
        t = 2 * PI * j / segs
        verts.append((a * rad[j] * np.cos(t), b * rad[j] * np.sin(t), 0.0))
    verts.append((0.0, 0.0, 0.0))
    faces = [(0, 1 + j, 1 + (j + 1) % segs) for j in range(segs)]
    for i in range(rings):  # ring i -> ring i+1 (the last "ring" is the bottom rim)
        for j in range(segs):
            a0, a1 = 1 + i * segs + j, 1 + i * segs + (j + 1) % segs
            b0, b1 = a0 + segs, a1 + segs
            faces += [(a0, b0, a1), (a1, b0, b1)]
    bottom, rim = len(verts) - 1, 1 + rings * segs
    faces += [(bottom, rim + (j + 1) % segs, rim + j) for j in range(segs)]
    mesh = trimesh.Trimesh(np.asarray(verts), np.asarray(faces), process=True)
    mesh.fix_normals()
    return mesh


def _folded_towel(w: float, d: float, layers: int, lt: float, band_y: float, z0: float = 0.0,
                  cy: float = 0.0) -> list[Part]:
    """A towel folded into `layers` stacked layers with rounded fold edges and a woven border band."""
    parts = []
    inner = d - 2 * lt
    for i in range(layers):
        parts.append(solid(g.rounded_slab(w, inner, lt, min(0.012, w / 6), z0 + i * lt, cy=cy), "hh_towel"))
    for i in range(layers - 1):
        sgn = 1 if i % 2 == 0 else -1
        roll = g.cylinder(lt, w - 0.006, (0, cy + sgn * inner / 2, z0 + (i + 1) * lt), axis="x", sections=12)
        parts.append(solid(roll, "hh_towel"))
    if layers == 1:
        parts.append(solid(g.cylinder(lt / 2, w - 0.006, (0, cy + inner / 2, z0 + lt / 2), axis="x", sections=10),
                           "hh_towel"))
    ztop = z0 + layers * lt
    parts.append(visual(g.flat_decal(w + 0.001, 0.022, ztop - 0.0002, 0, cy + band_y), "hh_towel_band"))
    for s in (-1, 1):
        parts.append(visual(g.box((0.0008, 0.022, layers * lt), (s * (w / 2 + 0.0003), cy + band_y,
                                                                 z0 + layers * lt / 2)),
                            "hh_towel_band"))
    return parts


def _rolled_towel(length: float, r: float) -> list[Part]:
    """A towel rolled up along x, lying on a flat facet, with its spiral showing at the ends."""
    sections = 14
    zc = g.prism_axis_height(r, sections)
    parts = [solid(g.prism_x(r, length, -length / 2, zc, sections), "hh_towel")]
    for s in (-1, 1):
        for k, rr in enumerate((0.3 * r, 0.6 * r)):
            ring = g.torus_ring(rr, 0.0016 + 0.0004 * k, (s * length / 2, 0, zc), plane="yz", n=14, m=4)
            parts.append(visual(ring, "hh_towel_band"))
    parts.append(visual(g.prism_x(r * 1.01, 0.025, length * 0.25, zc, sections), "hh_towel_band"))
    return parts


@register("Towel", variants=4, category="small")
def towel(v: int, rng: np.random.Generator) -> AssetSpec:
    """A bath towel: folded in thirds, folded in quarters, rolled, or a bath towel with a hand towel on top."""
    if v == 0:
        w, d = pick(rng, 0.32, 0.36), pick(rng, 0.2, 0.24)
        parts = _folded_towel(w, d, 3, 0.018, d * 0.32)
    elif v == 1:
        s = pick(rng, 0.25, 0.28)
        parts = _folded_towel(s, s, 4, 0.014, s * 0.35)
    elif v == 2:
        parts = _rolled_towel(pick(rng, 0.32, 0.36), pick(rng, 0.06, 0.07))
    else:
        w, d = pick(rng, 0.33, 0.36), pick(rng, 0.21, 0.24)
        parts = _folded_towel(w, d, 3, 0.017, d * 0.32)
        parts += _folded_towel(w * 0.72, d * 0.6, 3, 0.008, d * 0.15, z0=3 * 0.017, cy=-d * 0.12)
    return small_asset("Towel", v, parts, [0.45, 0.4, 0.4, 0.6][v], "folded bath towel")


@register("HandTowel", variants=3, category="small")
def hand_towel(v: int, rng: np.random.Generator) -> AssetSpec:
    """A small hand towel: folded in thirds, folded in half, or rolled up."""
    if v == 0:
        w, d = pick(rng, 0.24, 0.27), pick(rng, 0.12, 0.14)
        parts = _folded_towel(w, d, 3, 0.008, d * 0.3)
    elif v == 1:
        w, d = pick(rng, 0.19, 0.21), pick(rng, 0.15, 0.17)
        parts = _folded_towel(w, d, 2, 0.011, d * 0.3)
    else:
        parts = _rolled_towel(pick(rng, 0.19, 0.22), pick(rng, 0.03, 0.035))
    return small_asset("HandTowel", v, parts, [0.15, 0.15, 0.12][v], "hand towel")


@register("Pillow", variants=4, category="small")
def pillow(v: int, rng: np.random.Generator) -> AssetSpec:
    """A puffy pillow lying flat: bed pillow, square throw pillow with piping, round cushion, lumbar pillow."""
    a, b, c, e1, e2 = [
        (pick(rng, 0.32, 0.35), pick(rng, 0.22, 0.25), 0.075, 1.25, 0.3),
        (pick(rng, 0.2, 0.23), 0.0, 0.075, 1.1, 0.35),
        (pick(rng, 0.19, 0.22), 0.0, 0.055, 0.55, 1.0),
        (pick(rng, 0.24, 0.27), pick(rng, 0.13, 0.15), 0.065, 1.2, 0.32),
    ][v]
    b = b or a
    body = g.superquadric((a, b, c), e1, e2, (0, 0, 0), nu=12, nv=28)
    verts = body.vertices.copy()
    verts[verts[:, 2] < 0, 2] *= 0.7  # it sags onto whatever it lies on
    body = trimesh.Trimesh(verts, body.faces, process=True)
    body = g.clip_below(body, -0.6 * c)
    parts = [solid(body, "cushion")]
    top = float(body.bounds[1][2])
    if v in (1, 2):
        eq = [(a * np.sign(np.cos(t)) * abs(np.cos(t)) ** e2, b * np.sign(np.sin(t)) * abs(np.sin(t)) ** e2)
              for t in np.linspace(0, 2 * PI, 40, endpoint=False)]
        parts.append(visual(g.sweep_loop(eq, g.circle_points(0.005, 5), 0.0), "hh_piping"))
        parts.append(visual(g.ellipsoid((0.012, 0.012, 0.005), (0, 0, top - 0.002), 1), "hh_piping"))
    if v == 2:
        zr = top - c * (1 - (1 - 0.5 ** (2 / e1)) ** (e1 / 2))  # the surface height at half the radius
        for k in range(6):
            t = 2 * PI * k / 6
            parts.append(visual(g.ellipsoid((0.008, 0.008, 0.004), (0.5 * a * np.cos(t), 0.5 * a * np.sin(t),
                                                                    zr - 0.001), 1),
                                "hh_piping"))
    return small_asset("Pillow", v, parts, [0.6, 0.4, 0.5, 0.3][v], "pillow lying flat")


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


# -------------------------------------------------------------------------------------------------- watch

@register("Watch", variants=3, category="small")
def watch(v: int, rng: np.random.Generator) -> AssetSpec:
    """A wristwatch lying flat with its strap opened out along y: leather analog, smartwatch, steel diver."""
    st = 0.004
    parts: list[Part] = []
    if v == 1:
        cw, cd, ch = 0.036, 0.043, 0.011
        parts.append(solid(g.rounded_slab(cw, cd, ch, 0.009, n=4), "hh_remote"))
        parts.append(visual(g.rounded_slab(cw - 0.005, cd - 0.005, 0.0004, 0.007, ch, n=4), "screen"))
        parts.append(visual(g.torus_ring(0.01, 0.0012, (0, 0, ch + 0.0005), n=20, m=4), "hh_led"))
        parts.append(visual(g.torus_ring(0.0065, 0.0012, (0, 0, ch + 0.0005), n=16, m=4), "hh_red"))
        parts.append(visual(g.cylinder(0.003, 0.003, (cw / 2 + 0.001, 0.006, ch / 2), axis="x", sections=10),
                            "hh_button"))
        strap_w, half = 0.022, cd / 2
    else:
        r = 0.019 if v == 0 else 0.021
        ch = 0.01 if v == 0 else 0.013
        parts.append(solid(g.cylinder(r, ch, (0, 0, ch / 2), sections=24), "metal"))
        if v == 2:
            parts.append(visual(g.torus_ring(r * 0.93, 0.0025, (0, 0, ch), n=24, m=5), "hh_ink"))
        dial = "hh_face" if v == 0 else "screen"
        marks = "hh_ink" if v == 0 else "hh_face"
        rd = r * 0.84
        parts.append(visual(g.flat_disc(rd, ch - 0.0004, n=24, t=0.0006), dial))
        for k in range(12):
            a = 2 * PI * k / 12
            ln = 0.0035 if k % 3 == 0 else 0.002
            tick = g.box((0.0011, ln, 0.0004), (0, 0, 0))
            g.rotate_z(tick, a)
            tick.apply_translation(((rd - 0.003) * -np.sin(a), (rd - 0.003) * -np.cos(a), ch + 0.0004))
            parts.append(visual(tick, marks))
        for ang, ln, wd in ((2.1, 0.55, 0.0016), (-0.9, 0.8, 0.0011)):
            hand = g.box_at((-wd / 2, -0.002, 0), (wd / 2, rd * ln, 0.0004))
            g.rotate_z(hand, ang)
            hand.apply_translation((0, 0, ch + 0.0003))
            parts.append(visual(hand, marks))
        parts.append(visual(g.cylinder(0.0025, 0.004, (r + 0.0015, 0, ch / 2), axis="x", sections=10), "metal"))
        strap_w = 0.018 if v == 0 else 0.02
        half = r * 0.85
        for sx in (-1, 1):
            for sy in (-1, 1):
                pin = g.box((0.003, 0.008, 0.005), (sx * (strap_w / 2 + 0.0005), sy * (half + 0.003), 0.004))
                parts.append(visual(pin, "metal"))
    if v == 2:  # steel bracelet: a dark core (the collision) showing between the polished links
        ln, count = 0.0085, 9
        for side in (1, -1):
            core = g.box_at((-strap_w / 2 + 0.0006, half, 0), (strap_w / 2 - 0.0006, half + ln * count, st - 0.0006))
            if side < 0:
                core.apply_transform(np.diag([1.0, -1.0, 1.0, 1.0]))
            parts.append(solid(core, "dark_metal"))
            for k in range(count):
                y0 = half + k * ln
                link = g.box_at((-strap_w / 2, y0, 0.0003), (strap_w / 2, y0 + ln - 0.0009, st))
                if side < 0:
                    link.apply_transform(np.diag([1.0, -1.0, 1.0, 1.0]))
                parts.append(visual(link, "metal"))
        parts.append(visual(g.flat_decal(strap_w * 0.8, 0.02, st, 0, -half - 0.04), "dark_metal"))
    else:
        slot = "hh_strap" if v == 0 else "rubber"
        long_l, short_l = 0.095, 0.075
        parts.append(solid(g.rounded_slab(strap_w, long_l, st, 0.004, 0, 0, half + long_l / 2), slot))
        parts.append(solid(g.rounded_slab(strap_w, short_l, st, 0.002, 0, 0, -half - short_l / 2), slot))
        for k in range(5):
            parts.append(visual(g.flat_disc(0.0012, st, 0, half + 0.04 + k * 0.008, n=6), "hh_dark"))
        by = -half - short_l
        buckle = [g.box_at((-strap_w / 2 - 0.002, by - 0.002, 0), (strap_w / 2 + 0.002, by + 0.0005, st + 0.001)),
                  g.box_at((-strap_w / 2 - 0.002, by - 0.014, 0), (strap_w / 2 + 0.002, by - 0.011, st + 0.001)),
                  g.box_at((-strap_w / 2 - 0.002, by - 0.014, 0), (-strap_w / 2 + 0.0005, by, st + 0.001)),
                  g.box_at((strap_w / 2 - 0.0005, by - 0.014, 0), (strap_w / 2 + 0.002, by, st + 0.001))]
        parts += [visual(m, "metal") for m in buckle]
        parts.append(visual(g.box_at((-0.0007, by - 0.012, st), (0.0007, by, st + 0.0012)), "metal"))
        parts.append(visual(g.box_at((-strap_w / 2 - 0.0005, by + 0.006, 0.0), (strap_w / 2 + 0.0005, by + 0.011,
                                                                                st + 0.001)), slot))
    return small_asset("Watch", v, parts, [0.05, 0.04, 0.15][v], "wristwatch lying flat")


# ------------------------------------------------------------------------------------------------ garden

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
        parts.append(solid(g.rod(p0, p1, 0.011, sections=10), "hh_can"))
        d = p1 - p0
        parts.append(solid(g.point_along(g.frustum(0.012, 0.03, 0.035, sections=14), d,
                                         p1 - d / np.linalg.norm(d) * 0.01),
                           "hh_can"))
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
        parts.append(solid(g.rod(p0, p1, 0.012, sections=10), "plastic"))
        d = p1 - p0
        parts.append(solid(g.point_along(g.frustum(0.013, 0.024, 0.03, sections=12), d,
                                         p1 - d / np.linalg.norm(d) * 0.01),
                           "plastic"))
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
