"""Decorations: lamps, the television, paintings and posters, house plants.

Tall light things put most of their mass low: the heavy part is the base link and the rest hangs on a
light link joined by a fixed joint (lamp shades, foliage). Wall-hung pictures have their flat back at -y
and a flat bottom deep enough to stand upright on a floor.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import fixed, pick, recenter
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part

add_palettes(
    lampshade=hex_colours("f3ead3", "e8dcc4", "d9cbb0", "fbf6ec", "c9b79c"),
    canvas=hex_colours("f4f1de", "efe9dc", "f8f4ea"),
    art_sky=hex_colours("8ec5e8", "f2b880", "b7d3e9", "5e81ac"),
    art_land=hex_colours("6a994e", "a7c957", "c2a878", "386641"),
    art_sun=hex_colours("f9c74f", "f94144", "f8961e"),
    art_red=hex_colours("d62828", "e63946", "bc4749"),
    art_blue=hex_colours("1d3557", "277da1", "3a86ff"),
    art_yellow=hex_colours("fcbf49", "ffd166", "f9c74f"),
    art_dark=hex_colours("1b1b1e", "2b2d42", "353535"),
    tv_sky=hex_colours("4fc3f7", "81d4fa", "29b6f6"),
    tv_sky_high=hex_colours("1e88e5", "1976d2", "42a5f5"),
    tv_land=hex_colours("66bb6a", "9ccc65", "43a047"),
    tv_sun=hex_colours("ffee58", "ffca28", "fff176"),
    tv_accent=hex_colours("ef5350", "ff7043", "ab47bc"),
    foliage_light=hex_colours("7cb342", "8bc34a", "9ccc65"),
    art_tree=hex_colours("2d6a4f", "40916c", "1b4332"),
    lamp_glow=hex_colours("ffd966", "ffcf4d", "ffe07a"),
    succulent=hex_colours("8fb9a8", "7fa99b", "a3c4bc"),
    bark=hex_colours("7a5c3e", "6b4f35", "8b6b4a"),
    pebble=hex_colours("bdb6aa", "9a948a", "e0dcd3"),
)

Pt = Sequence[float]


# --------------------------------------------------------------------------------------------------
# shape helpers (also used by bathroom.py)


def _moved(
    parts: list[Part], yaw: float = 0.0, offset: Pt = (0.0, 0.0, 0.0), roll: float = 0.0, pitch: float = 0.0
) -> list[Part]:
    for p in parts:
        p.mesh = g.transformed(p.mesh, yaw=yaw, offset=offset, roll=roll, pitch=pitch)
    return parts


# --------------------------------------------------------------------------------------------------
# lamps


def _lamp_head(
    profile: Sequence[tuple[float, float]],
    bulb_z: float,
    bulb_r: float,
    slot: str = "lampshade",
    wall: float = 0.004,
    sections: int = 24,
    socket: bool = True,
    open_top: bool = True,
) -> list[Part]:
    """A shade open at the bottom (and top) around a bulb; "on": a glowing lining and a lit bulb.

    Coordinates along the lamp's own axis (z up); the lining sits just inside the shade wall.
    """
    shade = g.lathe_shell(profile, wall, sections)
    lining = g.lathe_shell([(r - wall - 0.002, z) for r, z in profile], 0.002, sections)
    parts = [
        Part(shade, slot, convex=True),
        Part(g.sphere(bulb_r, (0, 0, bulb_z), subdivisions=1), "porcelain", state="off"),
        Part(g.sphere(bulb_r * 1.08, (0, 0, bulb_z), subdivisions=1), "glow", state="on"),
        Part(lining, "lamp_glow", state="on"),
    ]
    # light filling the openings, just inside the rims: seen from above through the top, from below
    (rb, zb), (rt, zt) = profile[0], profile[-1]
    parts.append(
        Part(g.cylinder(rb - wall - 0.004, 0.002, (0, 0, zb + 0.006), sections=sections), "lamp_glow", state="on")
    )
    if open_top:
        parts.append(
            Part(g.cylinder(rt - wall - 0.004, 0.002, (0, 0, zt - 0.006), sections=sections), "lamp_glow", state="on")
        )
    if socket:
        parts.append(
            Part(g.cylinder(0.016, 0.035, (0, 0, bulb_z - bulb_r - 0.015), sections=10), "brass", collide=False)
        )
    return parts


def _spider(r_top: float, z_top: float, bulb_z: float) -> list[Part]:
    """The wire arms holding a shade's top ring over the bulb (visual only)."""
    parts = []
    for k in range(3):
        a = 2 * np.pi * k / 3
        parts.append(
            Part(
                g.rod((0, 0, bulb_z + 0.02), (r_top * np.cos(a), r_top * np.sin(a), z_top - 0.004), 0.0025, sections=6),
                "metal",
                collide=False,
            )
        )
    parts.append(Part(g.sphere(0.012, (0, 0, z_top + 0.01), subdivisions=1), "brass", collide=False))
    return parts


@register("DeskLamp", variants=3, category="small")
def desk_lamp(v: int, rng: np.random.Generator) -> AssetSpec:
    """A desk lamp: a weighted base, a stem and a shade wider at the bottom and open at the bottom.

    Variants: straight stem with a conical shade; an arm lamp whose cone head tilts down to the front;
    a short lamp with a bell shade. Switched on, the bulb and the lining of the shade glow.
    """
    base_r = pick(rng, 0.07, 0.09)
    parts = [Part(g.cylinder(base_r, 0.025, (0, 0, 0.0125), sections=20), "dark_metal", convex=True)]
    if v == 1:  # arm lamp: stem, elbow, arm, tilted cone head
        stem_h = pick(rng, 0.24, 0.3)
        elbow = np.array([0.0, -0.02, 0.025 + stem_h])
        tip = elbow + np.array([0.0, pick(rng, 0.13, 0.17), 0.09])
        parts.append(Part(g.rod((0, -0.02, 0.02), elbow, 0.009, 8), "metal", convex=True))
        parts.append(Part(g.rod(elbow, tip, 0.008, 8), "metal", convex=True))
        parts.append(Part(g.sphere(0.014, elbow, subdivisions=1), "dark_metal", collide=False))
        hs = 0.12
        head = _lamp_head(
            [(0.075, 0.0), (0.06, 0.05), (0.03, hs)],
            0.06,
            0.026,
            slot="dark_metal",
            wall=0.003,
            sections=20,
            socket=False,
            open_top=False,
        )
        head.append(Part(g.cylinder(0.032, 0.012, (0, 0, hs - 0.006), sections=16), "dark_metal", convex=True))
        tilt = np.radians(58)
        top = np.array([0.0, -hs * np.sin(tilt), hs * np.cos(tilt)])
        head = _moved(head, roll=tilt, offset=tuple(tip - top))
        shade_parts = head
        desc = "arm desk lamp with a tilted cone head that lights up"
    else:
        stem_h = [0.28, 0.0, 0.17][v] + pick(rng, 0.0, 0.06)
        top = 0.025 + stem_h
        parts.append(Part(g.cylinder(0.01, stem_h, (0, 0, 0.025 + stem_h / 2), sections=8), "metal", convex=True))
        if v == 0:  # conical (empire) shade: wide bottom, narrow open top
            rb, rt, hs = pick(rng, 0.1, 0.12), pick(rng, 0.065, 0.075), 0.15
            profile = [(rb, 0.0), (rt, hs)]
        else:  # bell shade with a vent at the top
            rb, rt, hs = pick(rng, 0.11, 0.13), 0.055, 0.13
            profile = [(rb, 0.0), (rb * 0.93, 0.03), (rb * 0.72, 0.07), (rt * 1.25, 0.11), (rt, hs)]
        bulb_z = 0.06
        shade_parts = _lamp_head(profile, bulb_z, 0.03, wall=0.004, sections=24) + _spider(rt, hs, bulb_z)
        shade_parts = _moved(shade_parts, offset=(0, 0, top + 0.035 - bulb_z + 0.03))
        desc = "desk lamp with a conical shade that lights up" if v == 0 else "desk lamp with a bell shade"
    shade_link, joint = fixed("shade", shade_parts, 0.15)
    return recenter(
        AssetSpec("DeskLamp", v, "small", [Link("base", parts, 1.35), shade_link], joints=[joint], description=desc)
    )


@register("Lamp", variants=3, category="decor")
def table_lamp(v: int, rng: np.random.Generator) -> AssetSpec:
    """A table lamp: a ceramic body (ginger jar, square column, gourd), a brass neck and a drum shade."""
    s = pick(rng, 0.92, 1.08)
    bodies = [
        [
            (0, 0),
            (0.07, 0),
            (0.075, 0.02),
            (0.12, 0.08),
            (0.13, 0.15),
            (0.11, 0.24),
            (0.06, 0.29),
            (0.04, 0.31),
            (0.035, 0.33),
            (0, 0.33),
        ],
        [(0, 0), (0.1, 0), (0.1, 0.03), (0.075, 0.045), (0.07, 0.3), (0.08, 0.32), (0.045, 0.34), (0, 0.34)],
        [
            (0, 0),
            (0.06, 0),
            (0.1, 0.05),
            (0.11, 0.1),
            (0.09, 0.16),
            (0.06, 0.19),
            (0.075, 0.23),
            (0.07, 0.28),
            (0.04, 0.31),
            (0.03, 0.33),
            (0, 0.33),
        ],
    ]
    profile = [(r * s, z * s) for r, z in bodies[v]]
    body = g.revolve(profile, sections=4 if v == 1 else 20)
    if v == 1:
        body = g.transformed(body, yaw=np.pi / 4)
    top = profile[-1][1]
    parts = [
        Part(body, "ceramic", convex=True),
        Part(g.cylinder(0.05 * s, 0.012, (0, 0, top + 0.006), sections=16), "brass", convex=True),
        Part(g.cylinder(0.011, 0.1, (0, 0, top + 0.06), sections=8), "brass", convex=True),
    ]
    rb, rt, hs = [(0.2, 0.165, 0.24), (0.18, 0.18, 0.22), (0.17, 0.15, 0.28)][v]
    rb, rt, hs = rb * s, rt * s, hs * s
    bulb_z = 0.07
    shade = _lamp_head([(rb, 0.0), (rt, hs)], bulb_z, 0.035, wall=0.004, sections=28)
    shade.append(Part(g.cylinder(0.003, hs * 0.55, (0.0, 0.0, bulb_z + hs * 0.3), sections=6), "brass", collide=False))
    for sx in (-1, 1):  # harp
        shade.append(
            Part(g.rod((sx * 0.02, 0, bulb_z - 0.05), (sx * 0.05, 0, bulb_z + 0.03), 0.003, 6), "brass", collide=False)
        )
        shade.append(Part(g.rod((sx * 0.05, 0, bulb_z + 0.03), (0, 0, hs - 0.01), 0.003, 6), "brass", collide=False))
    shade.append(Part(g.sphere(0.015, (0, 0, hs + 0.012), subdivisions=1), "brass", collide=False))
    shade = _moved(shade, offset=(0, 0, top + 0.11 + 0.0675 - bulb_z))
    shade_link, joint = fixed("shade", shade, 0.25)
    names = ["ginger jar", "square column", "gourd"]
    return AssetSpec(
        "Lamp",
        v,
        "decor",
        [Link("base", parts, 1.75), shade_link],
        joints=[joint],
        description=f"table lamp with a {names[v]} ceramic body and a drum shade that lights up",
    )


def _arc_points(a: float, b: float, z1: float, t_end: float, n: int) -> list[np.ndarray]:
    """Points of an arc lamp's pole: straight up, then an elliptical arc over towards +x."""
    pts = [np.array([0.0, 0.0, 0.05])]
    for t in np.linspace(0, t_end, n):
        pts.append(np.array([a * (1 - np.cos(t)), 0.0, z1 + b * np.sin(t)]))
    return pts


@register("FloorLamp", variants=4, category="furniture")
def floor_lamp(v: int, rng: np.random.Generator) -> AssetSpec:
    """A floor lamp: a heavy base, a tall pole or tripod and a shade open at the bottom.

    Variants: round base with an empire shade; wooden tripod with a drum shade; arc lamp with a marble
    block and an overhanging cone shade; reading lamp with a tilted cone head. The lit bulb and the
    shade's lining glow when it is on.
    """
    parts: list[Part] = []
    light: list[Part] = []
    if v in (0, 3):
        base_r = pick(rng, 0.15, 0.18)
        parts.append(Part(g.cylinder(base_r, 0.03, (0, 0, 0.015), sections=24), "dark_metal", convex=True))
        parts.append(Part(g.frustum(base_r * 0.6, 0.03, 0.03, (0, 0, 0.03), sections=16), "dark_metal", convex=True))
        pole_h = pick(rng, 1.3, 1.42)
        light.append(Part(g.cylinder(0.013, pole_h, (0, 0, 0.03 + pole_h / 2), sections=10), "metal", convex=True))
        top = 0.03 + pole_h
        if v == 0:
            rb, rt, hs = pick(rng, 0.2, 0.24), pick(rng, 0.13, 0.16), pick(rng, 0.27, 0.32)
            bulb_z = 0.1
            head = _lamp_head([(rb, 0.0), (rt, hs)], bulb_z, 0.04, wall=0.005, sections=28) + _spider(rt, hs, bulb_z)
            light += _moved(head, offset=(0, 0, top + 0.035 - bulb_z + 0.04))
            desc = "floor lamp with a round base, a pole and an empire shade"
        else:  # reading lamp: a short arm and a cone head tilted down to the front
            elbow = np.array([0.0, 0.0, top])
            tip = elbow + np.array([0.0, 0.2, 0.06])
            light.append(Part(g.rod(elbow, tip, 0.01, 8), "metal", convex=True))
            light.append(Part(g.sphere(0.018, elbow, subdivisions=1), "dark_metal", collide=False))
            hs = 0.17
            head = _lamp_head(
                [(0.1, 0.0), (0.085, 0.06), (0.04, hs)],
                0.08,
                0.032,
                slot="dark_metal",
                wall=0.003,
                sections=20,
                socket=False,
                open_top=False,
            )
            head.append(Part(g.cylinder(0.042, 0.015, (0, 0, hs - 0.008), sections=16), "dark_metal", convex=True))
            tilt = np.radians(55)
            tail = np.array([0.0, -hs * np.sin(tilt), hs * np.cos(tilt)])
            light += _moved(head, roll=tilt, offset=tuple(tip - tail))
            desc = "reading floor lamp with a tilted cone head"
    elif v == 1:  # tripod
        foot_r = pick(rng, 0.28, 0.34)
        hub_z = pick(rng, 1.1, 1.2)
        for k in range(3):
            a = np.pi / 2 + 2 * np.pi * k / 3
            foot = np.array([foot_r * np.cos(a), foot_r * np.sin(a), 0.0])
            parts.append(
                Part(g.cylinder(0.022, 0.012, tuple(foot + [0, 0, 0.006]), sections=10), "rubber", convex=True)
            )
            parts.append(Part(g.rod(foot + [0, 0, 0.012], (0.0, 0.0, hub_z), 0.014, 8), "wood", convex=True))
        parts.append(Part(g.cylinder(0.03, 0.06, (0, 0, hub_z), sections=12), "brass", convex=True))
        light.append(Part(g.cylinder(0.012, 0.16, (0, 0, hub_z + 0.11), sections=8), "brass", convex=True))
        top = hub_z + 0.19
        r, hs = pick(rng, 0.22, 0.26), pick(rng, 0.28, 0.32)
        bulb_z = 0.1
        head = _lamp_head([(r, 0.0), (r, hs)], bulb_z, 0.04, wall=0.005, sections=28) + _spider(r, hs, bulb_z)
        light += _moved(head, offset=(0, 0, top + 0.035 - bulb_z + 0.04))
        desc = "tripod floor lamp with a drum shade"
    else:  # arc lamp
        bx, by = pick(rng, 0.38, 0.42), pick(rng, 0.25, 0.28)
        parts.append(Part(g.box((bx, by, 0.07), (bx / 2 - 0.12, 0, 0.035)), "stone", convex=True))
        a, b, z1 = pick(rng, 0.45, 0.55), pick(rng, 0.65, 0.8), pick(rng, 1.05, 1.2)
        pts = _arc_points(a, b, z1, 0.85 * np.pi, 10)
        for p0, p1 in pairwise(pts):
            light.append(Part(g.rod(p0, p1, 0.013, 8), "metal", convex=True))
        for p in pts[1:-1]:
            light.append(Part(g.sphere(0.013, p, subdivisions=1), "metal", collide=False))
        end = pts[-1]
        light.append(Part(g.cylinder(0.004, 0.08, tuple(end - [0, 0, 0.04]), sections=6), "dark_metal", collide=False))
        rb, rt, hs = 0.22, 0.1, 0.2
        bulb_z = 0.08
        head = _lamp_head(
            [(rb, 0.0), (rb * 0.8, 0.08), (rt, hs)], bulb_z, 0.04, slot="metal", wall=0.004, sections=24
        ) + _spider(rt, hs, bulb_z)
        light += _moved(head, offset=tuple(end - [0, 0, hs + 0.08]))
        desc = "arc floor lamp with a marble base and an overhanging shade"
    light_link, joint = fixed("lamp", light, 0.6 if v == 2 else 1.0)
    return recenter(
        AssetSpec(
            "FloorLamp",
            v,
            "furniture",
            [Link("base", parts, 6.0 - light_link.mass), light_link],
            joints=[joint],
            description=desc + " that lights up",
        )
    )


# --------------------------------------------------------------------------------------------------
# screens, switches


def _tv_picture(w: float, h: float, y: float, z0: float, x0: float = 0.0) -> list[Part]:
    """A bright landscape for a switched-on screen of w x h whose bottom-left corner is (x0 - w/2, z0)."""

    def rect(xa, xb, za, zb, slot, dy=0.0):
        return Part(
            g.box_at((x0 - w / 2 + xa * w, y + dy, z0 + za * h), (x0 - w / 2 + xb * w, y + dy + 0.002, z0 + zb * h)),
            slot,
            state="on",
        )

    parts = [rect(0, 1, 0.62, 1, "tv_sky_high"), rect(0, 1, 0.3, 0.62, "tv_sky"), rect(0, 1, 0, 0.3, "tv_land")]
    hill = [
        (x0 - w / 2 + w * u, z0 + h * (0.3 + 0.16 * np.sin(np.pi * (u - 0.35) / 0.5)))
        for u in np.linspace(0.35, 0.85, 8)
    ]
    parts.append(Part(g.flat_poly(hill, y + 0.001), "tv_land", state="on"))
    parts.append(Part(g.disc_y(0.09 * h, (x0 - w / 2 + 0.75 * w, y + 0.004, z0 + 0.78 * h)), "tv_sun", state="on"))
    hx, hz = x0 - w / 2 + 0.2 * w, z0 + 0.3 * h
    parts.append(
        Part(g.box_at((hx, y + 0.003, hz), (hx + 0.12 * w, y + 0.005, hz + 0.14 * h)), "tv_accent", state="on")
    )
    roof = [(hx - 0.01 * w, hz + 0.14 * h), (hx + 0.13 * w, hz + 0.14 * h), (hx + 0.06 * w, hz + 0.24 * h)]
    parts.append(Part(g.flat_poly(roof, y + 0.003), "art_dark", state="on"))
    return parts


@register("Television", variants=4, category="appliance")
def television(v: int, rng: np.random.Generator) -> AssetSpec:
    """A flat-screen television on a stand; switched on, the black screen shows a bright landscape.

    Variants: 32" on a pedestal, 55" on two end feet, 43" with a back housing on a bar stand, 65" curved
    screen on a pedestal.
    """
    w = [0.73, 1.23, 0.96, 1.45][v] + pick(rng, -0.02, 0.02)
    bezel = [0.018, 0.01, 0.014, 0.008][v]
    h = round(w * 0.5625 + 2 * bezel, 3)
    d = [0.05, 0.03, 0.035, 0.035][v]
    z0 = [0.08, 0.075, 0.07, 0.09][v]
    mass = [8.0, 15.0, 11.0, 14.0][v]
    parts: list[Part] = []
    sw, sh = w - 2 * bezel, h - 2 * bezel
    if v == 3:  # curved: segments along an arc bowing towards the viewer at the ends
        radius, n = 2.6, 10
        half = np.arcsin(w / 2 / radius)
        angles = np.linspace(-half, half, n + 1)
        for a0, a1 in pairwise(angles):
            am = (a0 + a1) / 2
            chord = 2 * radius * np.sin((a1 - a0) / 2) + 0.004
            cx, cy = radius * np.sin(am), radius * (1 - np.cos(am))
            seg = [
                Part(g.box((chord, d, h), (0, 0, z0 + h / 2)), "dark_plastic", convex=True),
                Part(g.box((chord, 0.002, sh), (0, d / 2 + 0.001, z0 + bezel + sh / 2)), "screen", collide=False),
            ]
            seg += _tv_band_pictures(a0, a1, half, chord, d / 2 + 0.002, z0 + bezel, sh)
            parts += _moved(seg, yaw=am, offset=(cx, cy, 0))
    else:
        parts.append(Part(g.box((w, d, h), (0, 0, z0 + h / 2)), "dark_plastic", convex=True))
        parts.append(Part(g.box((sw, 0.002, sh), (0, d / 2 + 0.001, z0 + bezel + sh / 2)), "screen", collide=False))
        parts += _tv_picture(sw, sh, d / 2 + 0.002, z0 + bezel)
        parts.append(
            Part(g.disc_y(0.003, (w / 2 - 0.03, d / 2 + 0.001, z0 + bezel / 2), 0.002, 8), "led_off", state="off")
        )
        parts.append(Part(g.disc_y(0.003, (w / 2 - 0.03, d / 2 + 0.001, z0 + bezel / 2), 0.002, 8), "led_on",
                          state="on"))
    if v in (0, 3):  # pedestal: neck and an oval foot
        fw, fd = [0.34, 0.0, 0.0, 0.5][v], [0.2, 0.0, 0.0, 0.26][v]
        foot = g.cylinder(0.5, 0.016, (0, 0, 0.008), sections=24)
        foot.apply_scale((fw, fd, 1.0))
        parts.append(Part(foot, "dark_metal", convex=True))
        parts.append(Part(g.box((0.08, 0.03, z0 + 0.1), (0, -0.01, (z0 + 0.1) / 2)), "dark_metal", convex=True))
    elif v == 1:  # two splayed feet near the ends
        for sx in (-1, 1):
            x = sx * (w / 2 - 0.12)
            for sy in (-1, 1):
                pad = np.array([x + sx * 0.03, sy * 0.12, 0.0])
                parts.append(Part(g.box((0.04, 0.03, 0.01), tuple(pad + [0, 0, 0.005])), "rubber", convex=True))
                parts.append(
                    Part(g.strut(pad + [0, 0, 0.01], (x, 0.0, z0 + 0.04), 0.024, 0.016), "dark_metal", convex=True)
                )
    else:  # back housing and a bar stand
        parts.append(
            Part(g.box((w * 0.55, 0.04, h * 0.55), (0, -d / 2 - 0.02, z0 + h * 0.45)), "dark_plastic", convex=True)
        )
        parts.append(Part(g.box((0.5, 0.22, 0.012), (0, -0.02, 0.006)), "dark_metal", convex=True))
        parts.append(
            Part(g.box((0.1, 0.03, z0 + 0.08), (0, -d / 2 - 0.015, (z0 + 0.08) / 2)), "dark_metal", convex=True)
        )
    names = ["32-inch on a pedestal", "55-inch on two feet", "43-inch on a bar stand", "65-inch curved"]
    return recenter(
        AssetSpec(
            "Television",
            v,
            "appliance",
            [Link("base", parts, mass)],
            description=f"{names[v]} flat-screen television; on: a bright picture",
        )
    )


def _tv_band_pictures(a0: float, a1: float, half: float, chord: float, y: float, z0: float, h: float) -> list[Part]:
    """The switched-on picture on one segment of a curved screen (sky bands, land, a sun on one segment)."""
    parts = [
        Part(g.box((chord, 0.002, h * 0.38), (0, y + 0.001, z0 + h * 0.81)), "tv_sky_high", state="on"),
        Part(g.box((chord, 0.002, h * 0.62), (0, y + 0.001, z0 + h * 0.31)), "tv_sky", state="on"),
    ]
    u = ((a0 + a1) / 2 + half) / (2 * half)  # 0..1 across the screen
    land = 0.3 + 0.12 * np.sin(2 * np.pi * u)
    parts.append(Part(g.box((chord, 0.002, h * land), (0, y + 0.002, z0 + h * land / 2)), "tv_land", state="on"))
    if abs(u - 0.75) < 0.06:
        parts.append(Part(g.disc_y(0.09 * h, (0, y + 0.003, z0 + 0.78 * h)), "tv_sun", state="on"))
    if abs(u - 0.25) < 0.06:
        parts.append(
            Part(g.box((chord * 0.8, 0.002, h * 0.14), (0, y + 0.003, z0 + h * (land + 0.07))), "tv_accent", state="on")
        )
    return parts


# --------------------------------------------------------------------------------------------------
# pictures


def _frame(w: float, h: float, fw: float, depth: float, slot: str, z0: float = 0.0, y0: float = 0.0) -> list[Part]:
    """A picture frame: four bars fw wide and `depth` deep around a w x h outline, back at y0."""
    bars = [
        g.box_at((-w / 2, y0, z0), (w / 2, y0 + depth, z0 + fw)),
        g.box_at((-w / 2, y0, z0 + h - fw), (w / 2, y0 + depth, z0 + h)),
        g.box_at((-w / 2, y0, z0 + fw), (-w / 2 + fw, y0 + depth, z0 + h - fw)),
        g.box_at((w / 2 - fw, y0, z0 + fw), (w / 2, y0 + depth, z0 + h - fw)),
    ]
    return [Part(m, slot, convex=True) for m in bars]


def _picture(kind: int, x0: float, x1: float, z0: float, z1: float, y: float) -> list[Part]:
    """A simple picture over the rectangle x0..x1, z0..z1 at y (thin visual shapes facing +y)."""
    w, h = x1 - x0, z1 - z0

    def at(u, s):
        return (x0 + u * w, z0 + s * h)

    def rect(ua, ub, sa, sb, slot, dy=0.0):
        return Part(
            g.box_at((x0 + ua * w, y + dy, z0 + sa * h), (x0 + ub * w, y + dy + 0.002, z0 + sb * h)),
            slot,
            collide=False,
        )

    parts: list[Part] = []
    if kind == 0:  # landscape: sky, fields, a hill, a sun, a tree
        parts += [rect(0, 1, 0.4, 1, "art_sky"), rect(0, 1, 0, 0.4, "art_land")]
        hill = [at(u, 0.38 + 0.25 * np.sin(np.pi * u / 0.7)) for u in np.linspace(0, 0.7, 9)] + [at(0.7, 0.38)]
        parts.append(Part(g.flat_poly(hill, y + 0.001), "art_land", collide=False))
        parts.append(Part(g.disc_y(0.08 * min(w, h), (x0 + 0.8 * w, y + 0.003, z0 + 0.78 * h)), "art_sun",
                          collide=False))
        parts.append(rect(0.84, 0.855, 0.34, 0.5, "art_dark", 0.003))
        parts.append(
            Part(
                g.ellipsoid((0.05 * w, 0.002, 0.08 * h), (x0 + 0.848 * w, y + 0.004, z0 + 0.55 * h), subdivisions=1),
                "art_tree",
                collide=False,
            )
        )
    elif kind == 1:  # abstract grid of coloured blocks with black lines
        parts.append(rect(0, 0.62, 0.55, 1, "art_red"))
        parts.append(rect(0.62, 1, 0.0, 0.3, "art_blue"))
        parts.append(rect(0, 0.3, 0, 0.25, "art_yellow"))
        for u in (0.3, 0.62):
            parts.append(rect(u - 0.012, u + 0.012, 0, 1, "art_dark", 0.002))
        for ua, ub, s in ((0, 1, 0.55), (0, 0.3, 0.25), (0.62, 1, 0.3), (0.3, 0.62, 0.8)):
            parts.append(rect(ua, ub, s - 0.01, s + 0.01, "art_dark", 0.002))
    elif kind == 2:  # circles on a plain ground
        parts.append(rect(0, 1, 0, 1, "art_yellow"))
        for u, s, r, slot in (
            (0.35, 0.6, 0.28, "art_red"),
            (0.68, 0.35, 0.2, "art_blue"),
            (0.7, 0.75, 0.1, "art_dark"),
            (0.25, 0.22, 0.12, "art_sky"),
        ):
            parts.append(
                Part(
                    g.disc_y(r * min(w, h), (x0 + u * w, y + 0.003 + 0.0005 * r, z0 + s * h), 0.002, 20),
                    slot,
                    collide=False,
                )
            )
    else:  # mountains under a pale sky, a lake
        parts += [rect(0, 1, 0.3, 1, "art_sky"), rect(0, 1, 0, 0.3, "art_blue")]
        peaks = [(0.0, 0.35, 0.25, 0.78), (0.35, 0.68, 0.55, 0.88), (0.6, 1.0, 0.8, 0.7)]
        for ua, ub, um, top in peaks:
            parts.append(Part(g.flat_poly([at(ua, 0.3), at(ub, 0.3), at(um, top)], y + 0.001), "art_dark",
                              collide=False))
            cap = [
                at(um - (um - ua) * 0.22, top - (top - 0.3) * 0.22),
                at(um + (ub - um) * 0.22, top - (top - 0.3) * 0.22),
                at(um, top),
            ]
            parts.append(Part(g.flat_poly(cap, y + 0.002), "canvas", collide=False))
    return parts


@register("Painting", variants=4, category="decor")
def painting(v: int, rng: np.random.Generator) -> AssetSpec:
    """A framed painting 4-5 cm deep: a canvas with a simple picture (landscape, abstract blocks, circles,
    mountains) inside a wooden or metal frame; the deep frame stands it on its bottom edge."""
    w = [pick(rng, 0.8, 1.0), pick(rng, 0.45, 0.55), pick(rng, 0.55, 0.65), pick(rng, 1.1, 1.3)][v]
    h = [pick(rng, 0.55, 0.65), pick(rng, 0.65, 0.75), 0.0, pick(rng, 0.45, 0.5)][v] or w
    fw = [0.06, 0.035, 0.05, 0.03][v]
    depth = [0.05, 0.045, 0.05, 0.045][v]
    slot = ["wood", "dark_metal", "dark_wood", "metal"][v]
    parts = _frame(w, h, fw, depth, slot)
    # the canvas sits 1 cm behind the frame's front face
    parts.append(
        Part(
            g.box_at((-w / 2 + fw - 0.005, 0.0, fw - 0.005), (w / 2 - fw + 0.005, depth - 0.01, h - fw + 0.005)),
            "canvas",
            convex=True,
        )
    )
    if v in (0, 2):  # inner slip (a lighter liner inside the frame)
        s = 0.015
        parts += [
            Part(m.mesh, "canvas", collide=False)
            for m in _frame(w - 2 * fw + 0.01, h - 2 * fw + 0.01, s, 0.006, "canvas", fw - 0.005, depth - 0.01)
        ]
        x0, x1, z0, z1 = -w / 2 + fw + s, w / 2 - fw - s, fw + s, h - fw - s
    else:
        x0, x1, z0, z1 = -w / 2 + fw, w / 2 - fw, fw, h - fw
    parts += _picture(v, x0 + 0.005, x1 - 0.005, z0 + 0.005, z1 - 0.005, depth - 0.01)
    names = ["landscape", "abstract blocks", "circles", "mountain panorama"]
    mass = [3.5, 2.0, 2.5, 3.0][v]
    return recenter(
        AssetSpec("Painting", v, "decor", [Link("base", parts, mass)], description=f"framed painting: {names[v]}")
    )


@register("Poster", variants=3, category="decor")
def poster(v: int, rng: np.random.Generator) -> AssetSpec:
    """A poster: printed sheet held by wooden hanger rails, in an aluminium snap frame, or in a thin black frame.

    The rails or frame give it a bottom deep enough to stand on.
    """
    w = [pick(rng, 0.45, 0.55), pick(rng, 0.5, 0.6), pick(rng, 0.75, 0.9)][v]
    h = [pick(rng, 0.65, 0.75), pick(rng, 0.7, 0.85), pick(rng, 0.5, 0.6)][v]
    kind = [1, 2, 0][v]
    parts: list[Part] = []
    if v == 0:  # wooden hanger rails at top and bottom, a hanging cord
        rd, rh = 0.035, 0.022
        parts.append(Part(g.box_at((-w / 2 - 0.01, -rd / 2, 0), (w / 2 + 0.01, rd / 2, rh)), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2 - 0.01, -rd / 2, h - rh), (w / 2 + 0.01, rd / 2, h)), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2, -0.001, rh), (w / 2, 0.001, h - rh)), "paper", convex=True))
        for sx in (-1, 1):
            parts.append(Part(g.rod((sx * (w / 2 - 0.03), 0, h), (0, 0, h + 0.06), 0.002, 5), "rubber", collide=False))
        parts += _picture(kind, -w / 2 + 0.02, w / 2 - 0.02, rh + 0.03, h - rh - 0.03, 0.001)
    else:
        fw, depth = [0.0, 0.025, 0.018][v], 0.035
        parts += _frame(w, h, fw, depth, ["metal", "metal", "dark_plastic"][v])
        yf = depth - 0.006
        parts.append(Part(g.box_at((-w / 2 + fw, yf - 0.006, fw), (w / 2 - fw, yf, h - fw)), "paper", convex=True))
        parts.append(Part(g.box_at((-w / 2 + fw, 0.0, fw), (w / 2 - fw, 0.004, h - fw)), "paper", convex=True))
        margin = 0.03 if v == 1 else 0.02
        parts += _picture(kind, -w / 2 + fw + margin, w / 2 - fw - margin, fw + margin * 2.5, h - fw - margin, yf)
        # a printed caption strip
        parts.append(
            Part(
                g.box_at((-w / 4, yf + 0.001, fw + margin * 0.7), (w / 4, yf + 0.003, fw + margin * 1.7)),
                "art_dark",
                collide=False,
            )
        )
    names = ["with wooden hanger rails", "in an aluminium snap frame", "in a thin black frame"]
    return recenter(AssetSpec("Poster", v, "decor", [Link("base", parts, 0.5)], description=f"poster {names[v]}"))


# --------------------------------------------------------------------------------------------------
# plants


@register("HousePlant", variants=4, category="decor")
def house_plant(v: int, rng: np.random.Generator) -> AssetSpec:
    """A potted house plant: a pot with soil and foliage (bushy, tall snake plant, succulent, palm).

    The pot is the heavy base link; the foliage hangs on a light link.
    """
    leaves: list[Part] = []
    s = pick(rng, 0.9, 1.1)
    if v == 0:  # bushy: a dome of leaf clusters
        rb, rt, ph = 0.1 * s, 0.13 * s, 0.22 * s
        pot = g.container([(rb, 0), (rt * 0.97, ph * 0.85), (rt, ph)], wall=0.012, bottom=0.02, sections=20)
        soil_z = ph - 0.03
        soil = g.cylinder(rt * 0.97 - 0.012, 0.01, (0, 0, soil_z - 0.005), sections=20)
        cz = soil_z + 0.17 * s
        for k in range(7):
            a = 2 * np.pi * k / 7 + 0.3
            r = 0.13 * s
            c = (r * np.cos(a), r * np.sin(a), cz - 0.04 * s + 0.03 * np.sin(3 * a))
            leaves.append(
                Part(
                    g.ellipsoid((0.1 * s, 0.1 * s, 0.085 * s), c, subdivisions=1),
                    "plant" if k % 2 else "foliage_light",
                    convex=True,
                )
            )
        leaves.append(
            Part(
                g.ellipsoid((0.12 * s, 0.12 * s, 0.1 * s), (0, 0, cz + 0.09 * s), subdivisions=1), "plant", convex=True
            )
        )
        for k in range(3):
            a = 2 * np.pi * k / 3
            leaves.append(
                Part(g.rod((0, 0, soil_z), (0.08 * np.cos(a), 0.08 * np.sin(a), cz), 0.006, 5), "stem", collide=False)
            )
        desc = "bushy house plant in a round pot"
    elif v == 1:  # snake plant: upright sword leaves in a square pot
        a_, ph = 0.12 * s, 0.26 * s
        pot = g.revolve(
            [(0, 0), (a_ * 1.3, 0), (a_ * 1.45, ph), (a_ * 1.3, ph), (a_ * 1.2, 0.03), (0, 0.03)], sections=4
        )
        pot = g.transformed(pot, yaw=np.pi / 4)
        soil_z = ph - 0.025
        side = a_ * 1.38 / np.sqrt(2) - 0.01
        soil = g.box((2 * side, 2 * side, 0.01), (0, 0, soil_z - 0.005))
        for k in range(9):
            a = 2 * np.pi * k / 9 + 0.2
            r = 0.015 + 0.03 * (k % 3)
            length = (0.2 + 0.05 * ((k * 7) % 4)) * s
            leaf = g.ellipsoid((0.032, 0.007, length), subdivisions=1)
            tilt = 0.06 + 0.06 * (k % 3)
            leaf = g.transformed(leaf, pitch=tilt, offset=(0, 0, length * 0.92))
            leaves.append(
                Part(
                    g.transformed(leaf, yaw=a, offset=(r * np.cos(a), r * np.sin(a), soil_z - 0.02)),
                    "plant" if k % 2 else "foliage_light",
                    convex=True,
                )
            )
        desc = "tall snake plant in a square pot"
    elif v == 2:  # succulent rosettes in a low bowl
        rb, rt, ph = 0.09 * s, 0.13 * s, 0.09 * s
        pot = g.container([(rb, 0), (rt * 0.95, ph * 0.7), (rt, ph)], wall=0.01, bottom=0.015, sections=20)
        soil_z = ph - 0.015
        soil = g.cylinder(rt - 0.012, 0.01, (0, 0, soil_z - 0.005), sections=20)
        for cx, cy, sc in ((0.0, 0.0, 1.0), (0.075 * s, 0.05 * s, 0.55), (-0.07 * s, -0.045 * s, 0.6)):
            rings = ((8, 0.045, 0.35, 1.0), (6, 0.025, 0.8, 0.75), (4, 0.008, 1.2, 0.5))
            if sc < 1:
                rings = ((6, 0.04, 0.45, 1.0), (4, 0.015, 0.95, 0.7))
            for ring_i, (n, rad, tilt, size) in enumerate(rings):
                for k in range(n):
                    a = 2 * np.pi * k / n + ring_i * 0.4
                    leaf = g.ellipsoid(
                        (0.04 * size * sc, 0.02 * size * sc, 0.011 * sc), subdivisions=int(sc == 1.0 and ring_i == 0)
                    )
                    off = (
                        cx + rad * sc * np.cos(a),
                        cy + rad * sc * np.sin(a),
                        soil_z + 0.012 * sc + ring_i * 0.012 * sc,
                    )
                    leaves.append(Part(g.transformed(leaf, yaw=a, pitch=-tilt, offset=off), "succulent", convex=True))
        for k in range(5):
            a = 1.3 * k
            leaves.append(
                Part(
                    g.ellipsoid(
                        (0.012, 0.01, 0.006), (0.1 * s * np.cos(a), 0.1 * s * np.sin(a), soil_z), subdivisions=1
                    ),
                    "pebble",
                    collide=False,
                )
            )
        desc = "succulent rosettes in a low bowl"
    else:  # palm: ringed trunk and arching fronds
        rb, rt, ph = 0.12 * s, 0.16 * s, 0.3 * s
        pot = g.container([(rb, 0), (rt, ph * 0.9), (rt * 1.05, ph)], wall=0.012, bottom=0.02, sections=20)
        soil_z = ph - 0.03
        soil = g.cylinder(rt * 1.02 - 0.012, 0.01, (0, 0, soil_z - 0.005), sections=20)
        trunk_h = 0.75 * s
        for k in range(5):
            z = soil_z + k * trunk_h / 5
            leaves.append(
                Part(
                    g.frustum(0.045 - 0.004 * k, 0.03 - 0.003 * k, trunk_h / 5, (0, 0, z), sections=10),
                    "bark",
                    convex=True,
                )
            )
        crown = soil_z + trunk_h
        for k in range(8):
            a = 2 * np.pi * k / 8
            d = np.array([np.cos(a), np.sin(a), 0.0])
            p = np.array([0, 0, crown])
            for seg, (rise, length) in enumerate(((0.75, 0.24), (0.1, 0.26), (-0.55, 0.24))):
                direction = d * np.cos(rise) + np.array([0, 0, np.sin(rise)])
                q = p + direction * length * s
                mid = (p + q) / 2
                frond = g.ellipsoid((length * s / 2, 0.07 * s * (1 - 0.2 * seg), 0.008), subdivisions=1)
                leaves.append(
                    Part(
                        g.transformed(frond, yaw=a, pitch=-rise, offset=tuple(mid)),
                        "plant" if k % 2 else "foliage_light",
                        convex=True,
                    )
                )
                p = q
        desc = "palm in a tall pot"
    parts = [Part(pot, "ceramic", convex=True), Part(soil, "soil", collide=False)]
    mass = [4.0, 5.0, 2.0, 7.0][v]
    foliage, joint = fixed("foliage", leaves, [0.8, 0.8, 0.4, 1.2][v])
    return recenter(
        AssetSpec(
            "HousePlant",
            v,
            "decor",
            [Link("base", parts, mass - foliage.mass), foliage],
            joints=[joint],
            description=desc,
        )
    )
