"""Small electronics and timepieces: alarm clocks, cell phones, laptops, remote controls, watches.

Built in their natural resting pose (phones, remotes and watches lie flat, a laptop stands on its base
with its lid on a hinge) so that they settle upright when dropped. Sizes are real-world metres.
"""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, small_asset, solid, visual
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Joint, Link, Part

add_palettes(
    hh_clock=hex_colours("c0392b", "2f3235", "3f88c5", "e9e2d6", "5aa469"),
    hh_led=hex_colours("ff3b30", "3ddc84", "5ad1ff"),
    hh_phone=hex_colours("1e1e1e", "f0f0f0", "c9b8a0", "3f5e8a", "8c2f39"),
    hh_laptop=hex_colours("b8bcc2", "2d2d2d", "d0d3d6", "3a3d41"),
    hh_key=hex_colours("1e1e1e", "2d2d2d"),
    hh_lit_screen=hex_colours("4f9de0", "5fb0f0", "3d8bd0"),
    hh_window=hex_colours("f4f6f8", "e8edf2"),
    hh_strap=hex_colours("5b3a29", "1f1f1f", "8b5a3c", "2f3b52"),
    hh_case=hex_colours("e76f51", "2a9d8f", "1d3557", "f4a6a6"),
)

PI = float(np.pi)


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
