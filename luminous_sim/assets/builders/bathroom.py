"""Bathroom fixtures: toilet, bathtub and its basin, shower parts, towel holders, mirror.

Vessels (toilet bowl, tub basin) are rings of convex segments between matching outlines, so they need
no convex decomposition. Wall-mounted pieces (towel bars, paper holders, shower heads, mirrors) are built
so that they stand on a flat bottom when dropped on a floor: block brackets, a back plate reaching the
floor, a soap dish or a ledge.
"""

from __future__ import annotations

from itertools import pairwise

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import fixed, pick, recenter
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register, variant_rng
from luminous_sim.assets.spec import Anchor, AssetSpec, Joint, Link, Part, Region

add_palettes(
    curtain_vinyl=hex_colours("f8f9fa", "cfe3ef", "e7d8c9", "d8e2dc"),
    curtain_band=hex_colours("5e81ac", "9a8c98", "84a59d"),
    smudge=hex_colours("a39e93", "8f8a80", "b3aa99"),
)

SHOWER_DOOR_OPEN = float(np.radians(90))


def _bar_region(name: str, length: float, y: float, z_top: float, clearance: float = 0.25) -> Region:
    """A narrow support line along a bar (a towel or a paper roll hangs on it)."""
    return Region(name, "surface", (0.0, y, z_top), (max(length, 0.04), 0.02, clearance))


def _block_bracket(x: float, y0: float, y1: float, h: float, w: float = 0.024, slot: str = "metal") -> Part:
    """A block bracket standing on the floor from the wall (y0) out to y1: a flat foot for wall fittings."""
    return Part(g.box_at((x - w / 2, y0, 0.0), (x + w / 2, y1, h)), slot, convex=True)


# --------------------------------------------------------------------------------------------------
# toilet


@register("Toilet", variants=4, category="fixture")
def toilet(v: int, rng: np.random.Generator) -> AssetSpec:
    """A toilet: pedestal, bowl (a ring of convex pieces with water inside), seat, a lid on a hinge, a tank.

    Variants: classic two-piece; compact one-piece with a low rounded tank; elongated bowl with a tall
    narrow tank; square modern skirted bowl. Regions: the tank top and the closed lid.
    """
    rx = pick(rng, 0.18, 0.2)
    ryb = 0.12
    ryf = [0.25, 0.23, 0.28, 0.26][v] + pick(rng, -0.01, 0.01)
    tw = [pick(rng, 0.46, 0.5), pick(rng, 0.4, 0.44), pick(rng, 0.4, 0.43), pick(rng, 0.46, 0.5)][v]
    td = [0.19, 0.2, 0.16, 0.17][v]
    th = [pick(rng, 0.74, 0.78), pick(rng, 0.6, 0.64), pick(rng, 0.78, 0.82), pick(rng, 0.74, 0.78)][v]
    seat_top = pick(rng, 0.4, 0.42)
    z_rim = seat_top - 0.02
    y_tank = (0.02, 0.02 + td)
    y_hinge = y_tank[1] + 0.03
    yc = y_hinge + ryb - 0.02
    square = v == 3

    def outline(d: float, s: float = 1.0, dy: float = 0.0) -> np.ndarray:
        """The bowl's plan outline grown by d (negative: shrunk), scaled by s about its centre."""
        if square:
            loop = g.rrect_loop(rx * s + d, (ryf + ryb) / 2 * s + d, 0.07 * s + max(d, -0.06), m=4)
            return loop + [0.0, yc + (ryf - ryb) / 2 * s + dy]
        return g.oval(rx * s + d, ryf * s + d, ryb * s + d, n=20, cy=yc + dy)

    porcelain = "porcelain"
    parts: list[Part] = []
    # bowl: outer shell from the rim down to the trap, the same outline 2.5 cm inside
    z_trap, wall = 0.2, 0.025
    s_bot, dy_bot = 0.55, -0.03
    outer_bot = outline(-0.01, 0.92, -0.02) if square else outline(0, s_bot, dy_bot)
    parts += [
        Part(m, porcelain, convex=True)
        for m in g.ring_wall(outline(0), outline(-wall), z_rim, z_trap, outer_bot, outline(-wall, s_bot, dy_bot))
    ]
    parts.append(Part(g.loop_slab(outline(-0.01, s_bot, dy_bot), z_trap - 0.03, z_trap + 0.01), porcelain, convex=True))
    zw = z_trap + 0.09
    sw = s_bot + (1 - s_bot) * (zw - z_trap) / (z_rim - z_trap)
    parts.append(
        Part(g.loop_slab(outline(-wall - 0.002, sw, dy_bot * (1 - sw) / (1 - s_bot)), zw - 0.004, zw), "water",
             collide=False)
    )
    # pedestal down to the floor (skirted straight sides on the square model)
    if square:
        foot = outline(-0.01, 0.92, -0.02)
    else:
        foot = g.oval(0.12, 0.2, 0.18, n=20, cy=yc - 0.04)
    parts.append(
        Part(
            g.hull([(x, y, 0.0) for x, y in foot] + [(x, y, z_trap) for x, y in (foot if square else outer_bot)]),
            porcelain,
            convex=True,
        )
    )
    # rear deck joining the bowl to the tank
    deck = g.rrect_loop(tw / 2 - 0.06, 0.07, 0.02) + [0.0, y_tank[1] - 0.05]
    parts.append(Part(g.loop_slab(deck, z_rim - 0.12, z_rim + 0.005), porcelain, convex=True))
    # tank (its own light link: a hollow tank keeps the toilet's mass over the pedestal)
    tank: list[Part] = []
    tcy = (y_tank[0] + y_tank[1]) / 2
    if v == 1:  # one-piece: tank flows down into the deck, rounded, push button on top
        low = g.rrect_loop(tw / 2 - 0.04, td / 2 - 0.01, 0.05) + [0.0, tcy]
        high = g.rrect_loop(tw / 2, td / 2, 0.07) + [0.0, tcy]
        tank.append(
            Part(
                g.hull([(x, y, z_rim - 0.1) for x, y in low] + [(x, y, th - 0.025) for x, y in high]),
                porcelain,
                convex=True,
            )
        )
        tank.append(
            Part(
                g.loop_slab(g.rrect_loop(tw / 2 + 0.004, td / 2 + 0.004, 0.072) + [0.0, tcy], th - 0.025, th),
                    porcelain, convex=True
            )
        )
        tank.append(Part(g.cylinder(0.022, 0.008, (0.0, tcy, th + 0.004), sections=14), "metal", collide=False))
    else:
        r_t = 0.005 if square else 0.03
        z_t0 = z_rim + 0.01 if v != 2 else z_rim + 0.04
        tank.append(Part(g.loop_slab(g.rrect_loop(tw / 2, td / 2, r_t) + [0.0, tcy], z_t0, th - 0.025), porcelain,
                         convex=True))
        tank.append(
            Part(g.loop_slab(g.rrect_loop(tw / 2 + 0.008, td / 2 + 0.008, r_t) + [0.0, tcy], th - 0.025, th),
                 porcelain, convex=True)
        )
        if v == 2:  # a narrow neck between deck and tank
            tank.append(Part(g.box((tw * 0.6, td * 0.7, 0.05), (0.0, tcy, z_rim + 0.02)), porcelain, convex=True))
        if square:  # dual flush buttons on the lid
            for sx in (-1, 1):
                tank.append(Part(g.box((0.035, 0.05, 0.006), (sx * 0.02, tcy, th + 0.003)), "metal", collide=False))
        else:  # flush lever on the front left
            hx, hz = -tw / 2 + 0.06, th - 0.07
            tank.append(Part(g.disc_y(0.016, (hx, y_tank[1] + 0.004, hz), 0.008, 12), "metal", collide=False))
            tank.append(Part(g.box((0.07, 0.012, 0.012), (hx + 0.035, y_tank[1] + 0.014, hz)), "metal", collide=False))
    tank_link, tank_joint = fixed("tank", tank, 5.0)
    # seat ring on the rim, hinge blocks behind it
    seat_slot = ["porcelain", "appliance", "appliance", "wood"][v]
    parts += [Part(m, seat_slot, convex=True) for m in g.ring_wall(outline(0.006), outline(-0.06), seat_top, z_rim)]
    for sx in (-1, 1):
        parts.append(
            Part(
                g.cylinder(0.012, 0.04, (sx * 0.08, y_hinge, seat_top + 0.008), axis="x", sections=10),
                "metal",
                collide=False,
            )
        )
    # lid: from the hinge forward over the seat, in the lid frame (origin at the hinge axis)
    lid_loop = outline(0.008) - [0.0, y_hinge]
    lid_loop[:, 1] = np.maximum(lid_loop[:, 1], 0.005)
    lid_mesh = g.hull([(x, y, z) for x, y in lid_loop for z in (0.002, 0.022)])
    lid = Link("lid", [Part(lid_mesh, seat_slot, convex=True)], 1.5)
    joint = Joint("lid_hinge", "revolute", "base", "lid", (0.0, y_hinge, seat_top), (1.0, 0.0, 0.0), 0.0, 1.55, "lid")
    lid_lo, lid_hi = lid_loop.min(axis=0), lid_loop.max(axis=0)
    regions = [
        Region("tank_top", "surface", (0.0, tcy, th), (tw - 0.06, max(td - 0.05, 0.06), 0.3)),
        Region(
            "lid_top",
            "surface",
            (0.0, (lid_lo[1] + lid_hi[1]) / 2 + 0.02, 0.022),
            (2 * rx - 0.1, (lid_hi[1] - lid_lo[1]) * 0.6, 0.25),
            link="lid",
        ),
    ]
    names = ["classic two-piece", "compact one-piece", "elongated two-piece", "square skirted"]
    return recenter(
        AssetSpec(
            "Toilet",
            v,
            "fixture",
            [Link("base", parts, 23.5), tank_link, lid],
            joints=[tank_joint, joint],
            regions=regions,
            description=f"{names[v]} toilet with a seat and a hinged lid",
        )
    )


# --------------------------------------------------------------------------------------------------
# bathtub and its basin


def _tub_dims(v: int) -> dict[str, float]:
    """Sizes shared by Bathtub variant v and BathtubBasin variant v (the basin fits the tub's opening)."""
    rng = variant_rng("Bathtub", v)
    length = [1.52, 1.62, 1.58][v] + pick(rng, -0.02, 0.02)
    depth = [pick(rng, 0.72, 0.76), pick(rng, 0.76, 0.8), pick(rng, 0.74, 0.78)][v]
    height = [pick(rng, 0.5, 0.54), pick(rng, 0.52, 0.56), pick(rng, 0.6, 0.64)][v]
    deck = [0.07, 0.08, 0.0][v]  # deck width around the opening (0: a freestanding tub's rim)
    ledge = [0.0, 0.12, 0.0][v]  # a wider deck at the +x end for the taps
    a = (length - 2 * deck - ledge) / 2 - (0.04 if v == 2 else 0.0)
    b = depth / 2 - deck - (0.04 if v == 2 else 0.0)
    r = [0.09, b * 0.95, b * 0.98][v]
    z_b = [0.05, 0.1, 0.17][v]
    return {
        "L": length,
        "D": depth,
        "H": height,
        "a": a,
        "b": b,
        "r": r,
        "z_b": z_b,
        "cx": -ledge / 2,
        "sx": [0.13, 0.15, 0.16][v],
        "sy": [0.06, 0.07, 0.08][v],
        "wall": 0.022,
        "floor": 0.03,
    }


def _basin_loops(d: dict[str, float], grow: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """The basin's outer outline at its rim and at its bottom, grown by `grow`."""
    a, b, r, sx, sy = d["a"], d["b"], d["r"], d["sx"], d["sy"]
    top = g.rrect_loop(a + grow, b + grow, r + grow, m=4)
    bot = g.rrect_loop(a - sx + grow, b - sy + grow, max(r - min(sx, sy), 0.03) + grow, m=4)
    return top, bot


@register("BathtubBasin", variants=3, category="fixture")
def bathtub_basin(v: int, rng: np.random.Generator) -> AssetSpec:
    """The hollow inside of a bathtub: sloping walls and a floor with a drain; sits in Bathtub variant v."""
    d = _tub_dims(v)
    hb = d["H"] - d["z_b"]
    w, tf = d["wall"], d["floor"]
    top_o, bot_o = _basin_loops(d)
    top_i, bot_i = _basin_loops(d, -w)
    parts = [Part(m, "porcelain", convex=True) for m in g.ring_wall(top_o, top_i, hb, 0.0, bot_o, bot_i)]
    parts.append(Part(g.loop_slab(bot_o, 0.0, tf), "porcelain", convex=True))
    drain_x = -(d["a"] - d["sx"] - w - 0.08)
    parts.append(Part(g.cylinder(0.035, 0.003, (drain_x, 0.0, tf + 0.0015), sections=16), "metal", collide=False))
    parts.append(Part(g.cylinder(0.022, 0.004, (drain_x, 0.0, tf + 0.002), sections=12), "dark_metal", collide=False))
    ix, iy = d["a"] - d["sx"] - w, d["b"] - d["sy"] - w
    region = Region("inside", "volume", (0.0, 0.0, tf + (hb - tf) / 2), (2 * ix * 0.95, 2 * iy * 0.95, hb - tf - 0.01))
    shapes = ["rectangular", "rounded", "oval"]
    return AssetSpec(
        "BathtubBasin",
        v,
        "fixture",
        [Link("base", parts, 10.0)],
        regions=[region],
        description=f"{shapes[v]} bathtub basin with a drain",
    )


@register("Bathtub", variants=3, category="fixture")
def bathtub(v: int, rng: np.random.Generator) -> AssetSpec:
    """A bathtub shell around its BathtubBasin: an alcove tub with an apron, a built-in tub with a tap
    ledge and a plinth, or a freestanding claw-foot tub. The basin comes as an anchored sub-object."""
    d = _tub_dims(v)
    length, depth, height, cx, z_b = d["L"], d["D"], d["H"], d["cx"], d["z_b"]
    top_o, bot_o = _basin_loops(d)
    parts: list[Part] = []
    if v in (0, 1):
        slot = "porcelain" if v == 0 else "tile"
        t = 0.035
        # deck with the opening, skirts all round, a bed the basin sits on, a lining round the opening
        outer = g.rrect_loop(length / 2, depth / 2, 0.0, m=4) - [cx, 0.0]
        parts += [Part(_moved_xy(m, cx), slot, convex=True) for m in g.ring_wall(outer, top_o, height, height - 0.04)]
        z_sk = 0.0 if v == 0 else 0.08
        skirts = [
            g.box_at((-length / 2, depth / 2 - t, z_sk), (length / 2, depth / 2, height - 0.04)),
            g.box_at((-length / 2, -depth / 2, z_sk), (length / 2, -depth / 2 + t, height - 0.04)),
            g.box_at((-length / 2, -depth / 2 + t, z_sk), (-length / 2 + t, depth / 2 - t, height - 0.04)),
            g.box_at((length / 2 - t, -depth / 2 + t, z_sk), (length / 2, depth / 2 - t, height - 0.04)),
        ]
        parts += [Part(m, slot, convex=True) for m in skirts]
        if v == 1:  # recessed plinth
            parts.append(
                Part(
                    g.box_at((-length / 2 + 0.04, -depth / 2 + 0.04, 0.0), (length / 2 - 0.04, depth / 2 - 0.06, z_sk)),
                    "dark_wood",
                    convex=True,
                )
            )
            for sx in (-1, 1):  # deck-mounted taps and spout on the ledge
                parts.append(
                    Part(
                        g.cylinder(0.02, 0.06, (length / 2 - 0.07, sx * 0.1, height + 0.03), sections=10),
                        "metal",
                        convex=True,
                    )
                )
            parts.append(
                Part(
                    g.cylinder(0.018, 0.14, (length / 2 - 0.07, 0.0, height + 0.07), sections=10), "metal", convex=True
                )
            )
            parts.append(
                Part(
                    g.cylinder(0.014, 0.13, (length / 2 - 0.125, 0.0, height + 0.13), axis="x", sections=10),
                    "metal",
                    convex=True,
                )
            )
        lining = g.ring_wall(g.rrect_loop(d["a"] + 0.012, d["b"] + 0.012, d["r"] + 0.012, m=4), top_o, height - 0.04,
                             z_b)
        parts += [Part(_moved_xy(m, cx), "porcelain", convex=True) for m in lining]
        parts.append(Part(_moved_xy(g.loop_slab(bot_o, z_sk if v == 1 else 0.0, z_b), cx), "porcelain", convex=True))
        desc = "alcove bathtub with an apron" if v == 0 else "built-in bathtub with a tiled surround and a tap ledge"
    else:  # claw-foot: a rolled shell hugging the basin, standing on four feet
        sh = 0.035
        top_s, bot_s = _basin_loops(d, sh)
        z0 = z_b - sh
        parts += [Part(m, "painted", convex=True) for m in g.ring_wall(top_s, top_o, height - 0.02, z0, bot_s, bot_o)]
        parts.append(Part(g.loop_slab(bot_s, z0, z_b), "painted", convex=True))
        lip_o, _ = _basin_loops(d, sh + 0.012)
        parts += [Part(m, "porcelain", convex=True) for m in g.ring_wall(lip_o, top_o, height, height - 0.035)]
        fx, fy = d["a"] - d["sx"] - 0.02, d["b"] - d["sy"] - 0.04
        for sx in (-1, 1):
            for sy in (-1, 1):
                c = (sx * fx, sy * fy)
                parts.append(
                    Part(g.frustum(0.045, 0.03, z0 + 0.01, (c[0], c[1], 0.0), sections=10), "brass", convex=True)
                )
                parts.append(
                    Part(
                        g.ellipsoid((0.05, 0.04, 0.03), (c[0] + sx * 0.02, c[1], 0.03), subdivisions=1),
                        "brass",
                        collide=False,
                    )
                )
        desc = "freestanding claw-foot bathtub"
    spec = AssetSpec(
        "Bathtub",
        v,
        "fixture",
        [Link("base", parts, 60.0)],
        anchors=[Anchor("BathtubBasin", (cx, 0.0, z_b, 0.0))],
        description=desc,
    )
    return recenter(spec)


def _moved_xy(mesh: trimesh.Trimesh, dx: float) -> trimesh.Trimesh:
    return g.transformed(mesh, offset=(dx, 0.0, 0.0))


# --------------------------------------------------------------------------------------------------
# shower


@register("ShowerCurtain", variants=3, category="decor")
def shower_curtain(v: int, rng: np.random.Generator) -> AssetSpec:
    """A shower curtain on a tension rod: plain, striped or drawn aside; small weighted feet stand it up."""
    w = pick(rng, 1.45, 1.7)
    h = pick(rng, 1.9, 2.0)
    rod_z = h - 0.015
    hang: list[Part] = [Part(g.cylinder(0.013, w, (0, 0, rod_z), axis="x", sections=10), "metal", convex=True)]
    for sx in (-1, 1):  # wall flanges of the tension rod
        hang.append(
            Part(
                g.cylinder(0.028, 0.012, (sx * (w / 2 + 0.006), 0, rod_z), axis="x", sections=14), "metal", convex=True
            )
        )
    z_top, z_bot = rod_z - 0.035, 0.012
    if v == 2:  # drawn aside: dense deep folds bunched at the -x end
        span, n, amp = pick(rng, 0.4, 0.5), 12, 0.1
    else:
        span, n, amp = w - 0.06, [14, 18][v], [0.07, 0.06][v]
    x0 = -w / 2 + 0.03
    xs = list(np.linspace(x0, x0 + span, n + 1))
    strips = g.drape(xs, xs, z_top, z_bot, 0.0, amp, t=0.002)
    for k, m in enumerate(strips):
        slot = "curtain_band" if v == 1 and k % 4 in (1, 2) else "curtain_vinyl"
        hang.append(Part(m, slot, convex=True))
    for x in xs[::2]:
        hang.append(
            Part(
                g.torus_arc(
                    0.02,
                    0.0025,
                    (x, 0.0, rod_z - 0.004),
                    plane="yz",
                    start=0,
                    end=2 * np.pi,
                    sections=10,
                    minor_sections=5,
                ),
                "plastic",
                collide=False,
            )
        )
    feet = []
    for x in (xs[0], (xs[0] + xs[-1]) / 2, xs[-1]):
        feet.append(Part(g.box((0.05, 0.2, z_bot), (x, 0.0, z_bot / 2)), "rubber", convex=True))
    upper, joint = fixed("curtain", hang, 1.2)
    names = ["plain", "striped", "drawn aside"]
    return recenter(
        AssetSpec(
            "ShowerCurtain",
            v,
            "decor",
            [Link("base", feet, 1.8), upper],
            joints=[joint],
            description=f"{names[v]} shower curtain on a tension rod",
        )
    )


def _glass_door(width: float, z0: float, z1: float, sign: float, framed: bool) -> list[Part]:
    """A shower door panel in its hinge frame: glass (in a thin frame when framed) and a vertical handle."""
    x0, x1 = sorted((0.0, sign * width))
    parts = [Part(g.box_at((x0 + 0.01, -0.005, z0 + 0.01), (x1 - 0.01, 0.005, z1 - 0.01)), "glass", convex=True)]
    if framed:
        f = 0.025
        bars = [
            g.box_at((x0, -0.012, z0), (x0 + f, 0.012, z1)),
            g.box_at((x1 - f, -0.012, z0), (x1, 0.012, z1)),
            g.box_at((x0 + f, -0.012, z0), (x1 - f, 0.012, z0 + f)),
            g.box_at((x0 + f, -0.012, z1 - f), (x1 - f, 0.012, z1)),
        ]
        parts += [Part(m, "metal", convex=True) for m in bars]
    hx = sign * (width - 0.08)
    zm = z0 + (z1 - z0) * 0.5
    parts.append(Part(g.cylinder(0.01, 0.35, (hx, 0.045, zm), sections=10), "metal", convex=True))
    for sz in (-1, 1):
        parts.append(
            Part(g.cylinder(0.006, 0.04, (hx, 0.025, zm + sz * 0.15), axis="y", sections=8), "metal", collide=False)
        )
    return parts


@register("ShowerDoor", variants=3, category="structure")
def shower_door(v: int, rng: np.random.Generator) -> AssetSpec:
    """A shower door: a framed hinged glass door; a fixed panel beside a door; or a frameless door hung on
    a fixed panel. A bottom threshold rail is its foot."""
    width = [pick(rng, 0.8, 0.95), pick(rng, 1.2, 1.4), pick(rng, 1.1, 1.3)][v]
    h = pick(rng, 1.9, 2.0)
    f, depth = 0.04, 0.06
    rail_h, rail_d = 0.03, 0.16
    parts = [Part(g.box_at((-width / 2, -rail_d / 2, 0.0), (width / 2, rail_d / 2, rail_h)), "metal", convex=True)]
    if v in (0, 1):
        frame = [
            g.box_at((-width / 2, -depth / 2, rail_h), (-width / 2 + f, depth / 2, h)),
            g.box_at((width / 2 - f, -depth / 2, rail_h), (width / 2, depth / 2, h)),
            g.box_at((-width / 2 + f, -depth / 2, h - f), (width / 2 - f, depth / 2, h)),
        ]
        parts += [Part(m, "metal", convex=True) for m in frame]
    z0, z1 = rail_h + 0.01, h - (f + 0.01 if v in (0, 1) else 0.02)
    if v == 0:
        hinge_x, sign, door_w = -width / 2 + f, 1.0, width - 2 * f - 0.005
    elif v == 1:
        fixed_w = round(width * 0.42, 3)
        xm = -width / 2 + f + fixed_w
        parts.append(Part(g.box_at((xm, -depth / 2, rail_h), (xm + 0.03, depth / 2, h - f)), "metal", convex=True))
        parts.append(Part(g.box_at((-width / 2 + f, -0.005, rail_h), (xm, 0.005, h - f)), "glass", convex=True))
        hinge_x, sign, door_w = width / 2 - f, -1.0, width / 2 - f - xm - 0.035
    else:  # frameless: wall channel, fixed panel, door on pivot hinges off the panel edge
        fixed_w = round(width * 0.4, 3)
        x_edge = -width / 2 + 0.02 + fixed_w
        parts.append(Part(g.box_at((-width / 2, -0.015, rail_h), (-width / 2 + 0.02, 0.015, h)), "metal", convex=True))
        parts.append(Part(g.box_at((-width / 2 + 0.02, -0.005, rail_h), (x_edge, 0.005, h)), "glass", convex=True))
        for z in (0.3, h - 0.3):
            parts.append(Part(g.box((0.06, 0.03, 0.07), (x_edge + 0.005, 0.0, z)), "metal", collide=False))
        hinge_x, sign, door_w = x_edge + 0.008, 1.0, width / 2 - x_edge - 0.01
    door = Link("door", _glass_door(door_w, z0, z1, sign, framed=v != 2), 8.0)
    joint = Joint(
        "door_hinge", "revolute", "base", "door", (hinge_x, 0.0, 0.0), (0.0, 0.0, sign), 0.0, SHOWER_DOOR_OPEN, "door"
    )
    names = ["framed hinged shower door", "shower door beside a fixed glass panel", "frameless shower door"]
    return recenter(
        AssetSpec("ShowerDoor", v, "structure", [Link("base", parts, 17.0), door], joints=[joint], description=names[v])
    )


@register("ShowerGlass", variants=3, category="structure")
def shower_glass(v: int, rng: np.random.Generator) -> AssetSpec:
    """A fixed glass shower screen with a wall profile and a foot rail: full-height, a bath screen with a
    rounded corner, or an L-shaped screen with a return panel."""
    w = [pick(rng, 0.8, 1.0), pick(rng, 0.7, 0.8), pick(rng, 0.8, 0.95)][v]
    h = [pick(rng, 1.9, 2.0), pick(rng, 1.4, 1.5), pick(rng, 1.9, 2.0)][v]
    rail_h, rail_d = 0.03, 0.12
    parts = [
        Part(g.box_at((-w / 2, -rail_d / 2, 0.0), (w / 2, rail_d / 2, rail_h)), "metal", convex=True),
        Part(g.box_at((-w / 2, -0.015, rail_h), (-w / 2 + 0.02, 0.015, h)), "metal", convex=True),
    ]
    if v == 1:  # rounded top corner on the free side
        rad = 0.25
        outline = [(-w / 2 + 0.02, rail_h), (w / 2, rail_h), (w / 2, h - rad)]
        outline += [
            (w / 2 - rad + rad * np.cos(t), h - rad + rad * np.sin(t)) for t in np.linspace(0, np.pi / 2, 7)[1:]
        ]
        outline += [(-w / 2 + 0.02, h)]
        parts.append(Part(g.flat_poly(outline, -0.004, 0.008), "glass", convex=True))
        for z in (0.4, h - 0.3):
            parts.append(Part(g.box((0.05, 0.03, 0.08), (-w / 2 + 0.04, 0.0, z)), "metal", collide=False))
    else:
        parts.append(Part(g.box_at((-w / 2 + 0.02, -0.004, rail_h), (w / 2, 0.004, h)), "glass", convex=True))
        if v == 2:  # return panel at the free end, towards the front
            rw = pick(rng, 0.3, 0.4)
            parts.append(
                Part(
                    g.box_at((w / 2 - rail_d / 2, rail_d / 2, 0.0), (w / 2 + rail_d / 2, rw, rail_h)),
                    "metal",
                    convex=True,
                )
            )
            parts.append(Part(g.box_at((w / 2 - 0.004, 0.004, rail_h), (w / 2 + 0.004, rw, h)), "glass", convex=True))
            parts.append(
                Part(g.box_at((w / 2 - 0.012, -0.012, rail_h), (w / 2 + 0.012, 0.012, h)), "metal", collide=False)
            )
        else:  # a frosted band at eye height
            parts.append(Part(g.box_at((-w / 2 + 0.02, 0.004, 1.0), (w / 2, 0.006, 1.3)), "paper", collide=False))
    names = [
        "full-height glass shower screen",
        "glass bath screen with a rounded corner",
        "L-shaped glass shower screen",
    ]
    return recenter(AssetSpec("ShowerGlass", v, "structure", [Link("base", parts, 20.0)], description=names[v]))


@register("ShowerHead", variants=3, category="fixture")
def shower_head(v: int, rng: np.random.Generator) -> AssetSpec:
    """A shower head on its wall fitting: a rain head on a straight arm, a classic angled head, or a
    hand shower on a slide rail above a soap dish. The back plate reaches down to the head's lowest
    point, so both stand on a floor."""
    parts: list[Part] = []
    if v == 0:  # rain shower: horizontal arm, drop, flat round head
        reach, hr = pick(rng, 0.28, 0.34), pick(rng, 0.09, 0.12)
        z_arm = 0.09
        parts.append(Part(g.cylinder(hr, 0.016, (0, reach, 0.008), sections=24), "metal", convex=True))
        parts.append(Part(g.cylinder(hr * 0.85, 0.002, (0, reach, 0.0005), sections=24), "dark_metal", collide=False))
        parts.append(
            Part(
                g.cylinder(0.011, z_arm - 0.016, (0, reach, 0.016 + (z_arm - 0.016) / 2), sections=10),
                "metal",
                convex=True,
            )
        )
        parts.append(Part(g.cylinder(0.011, reach, (0, reach / 2, z_arm), axis="y", sections=10), "metal", convex=True))
        parts.append(Part(g.box_at((-0.04, -0.012, 0.0), (0.04, 0.0, z_arm + 0.04)), "metal", convex=True))
        desc = "rain shower head on a straight wall arm"
    elif v == 1:  # classic: arm angled down out of the wall, cone head facing forward-down
        length = pick(rng, 0.16, 0.2)
        drop = np.radians(30)
        start = np.array([0.0, 0.0, 0.0])
        end = start + length * np.array([0.0, np.cos(drop), -np.sin(drop)])
        tilt = np.radians(50)
        head = g.revolve([(0, 0), (0.045, 0), (0.05, 0.012), (0.02, 0.06), (0.012, 0.07), (0, 0.07)], sections=20)
        # the head's axis points from its face (z=0) back to its neck (z=0.07); face turned forward-down
        head = g.transformed(head, roll=tilt)
        neck = np.array([0.0, -0.07 * np.sin(tilt), 0.07 * np.cos(tilt)])
        head.apply_translation(end - neck)
        arm = g.rod(start, end, 0.01, 10)
        low = min(head.bounds[0][2], arm.bounds[0][2])
        lift = -low
        for m in (head, arm):
            m.apply_translation((0, 0, lift))
        face = g.transformed(
            g.cylinder(0.04, 0.002, (0, 0, -0.001), sections=16), roll=tilt, offset=tuple(end - neck + [0, 0, lift])
        )
        parts += [
            Part(head, "metal", convex=True),
            Part(arm, "metal", convex=True),
            Part(face, "dark_metal", collide=False),
        ]
        parts.append(Part(g.box_at((-0.035, -0.012, 0.0), (0.035, 0.0, lift + 0.035)), "metal", convex=True))
        parts.append(Part(g.disc_y(0.03, (0, 0.002, lift), 0.006, 16), "metal", collide=False))
        desc = "classic angled shower head on a wall arm"
    else:  # slide rail kit with a soap dish at the bottom
        rail = pick(rng, 0.6, 0.7)
        dish_w, dish_d = 0.15, 0.11
        parts.append(Part(g.box_at((-dish_w / 2, 0.0, 0.0), (dish_w / 2, dish_d, 0.008)), "metal", convex=True))
        parts.append(
            Part(g.box_at((-dish_w / 2, dish_d - 0.008, 0.008), (dish_w / 2, dish_d, 0.025)), "metal", convex=True)
        )
        parts.append(Part(g.box_at((-0.03, -0.012, 0.0), (0.03, 0.035, 0.06)), "metal", convex=True))
        parts.append(Part(g.box_at((-0.02, -0.012, rail), (0.02, 0.035, rail + 0.05)), "metal", convex=True))
        parts.append(
            Part(g.cylinder(0.012, rail, (0, 0.03, 0.05 + rail / 2 - 0.02), sections=10), "metal", convex=True)
        )
        zh = rail * 0.8
        parts.append(Part(g.box((0.04, 0.03, 0.05), (0, 0.05, zh)), "dark_plastic", convex=True))
        grip0, grip1 = np.array([0.0, 0.07, zh - 0.09]), np.array([0.0, 0.09, zh + 0.09])
        parts.append(Part(g.rod(grip0, grip1, 0.014, 10), "metal", convex=True))
        # the head at the top of the handle, its face turned forward and a little down
        face_roll = np.radians(-110)
        head = g.transformed(
            g.cylinder(0.042, 0.022, sections=20), roll=face_roll, offset=tuple(grip1 + [0, 0.01, 0.02])
        )
        face = g.transformed(
            g.cylinder(0.034, 0.002, (0, 0, 0.0115), sections=16), roll=face_roll, offset=tuple(grip1 + [0, 0.01, 0.02])
        )
        parts += [Part(head, "metal", convex=True), Part(face, "dark_metal", collide=False)]
        hose = [
            grip0,
            np.array([0.03, 0.08, zh - 0.25]),
            np.array([0.05, 0.08, 0.12]),
            np.array([0.04, 0.07, 0.06]),
            np.array([0.015, 0.045, 0.045]),
            np.array([0.0, 0.035, 0.05]),
        ]  # sags down to the outlet
        for p0, p1 in pairwise(hose):
            parts.append(Part(g.rod(p0, p1, 0.007, 8), "metal", collide=False))
        desc = "hand shower on a slide rail with a soap dish"
    return recenter(AssetSpec("ShowerHead", v, "fixture", [Link("base", parts, 1.0)], description=desc))


# --------------------------------------------------------------------------------------------------
# towel and paper holders


@register("TowelHolder", variants=3, category="fixture")
def towel_holder(v: int, rng: np.random.Generator) -> AssetSpec:
    """A towel holder: a wall bar on block brackets, a floor-standing towel stand, or a towel shelf with
    a bar under it. Regions run along the bars (and the shelf) where a towel hangs."""
    parts: list[Part] = []
    regions: list[Region] = []
    if v == 0:
        length = pick(rng, 0.45, 0.65)
        bh, reach, r = 0.055, 0.08, 0.01
        for sx in (-1, 1):
            parts.append(_block_bracket(sx * length / 2, 0.0, reach, bh))
            parts.append(Part(g.disc_y(0.026, (sx * length / 2, 0.003, bh / 2), 0.006, 16), "metal", collide=False))
        parts.append(
            Part(g.cylinder(r, length, (0, reach - 0.02, bh - 0.018), axis="x", sections=12), "metal", convex=True)
        )
        regions.append(_bar_region("bar", length - 0.08, reach - 0.02, bh - 0.018 + r))
        desc = "wall towel bar"
    elif v == 1:
        width, height, depth = pick(rng, 0.6, 0.7), pick(rng, 0.85, 0.95), pick(rng, 0.3, 0.36)
        for sx in (-1, 1):
            x = sx * width / 2
            parts.append(Part(g.box((0.03, depth, 0.025), (x, 0, 0.0125)), "wood", convex=True))
            parts.append(
                Part(
                    g.box((0.03, 0.03, height - 0.025), (x, -depth * 0.15, 0.025 + (height - 0.025) / 2)),
                    "wood",
                    convex=True,
                )
            )
        for k, (y, z) in enumerate(
            ((-depth * 0.15, height - 0.03), (depth * 0.12, height * 0.62), (-depth * 0.3, height * 0.35))
        ):
            if k == 2:
                parts.append(
                    Part(g.box((0.03, depth * 0.3, 0.025), (-width / 2, -depth * 0.22, z)), "wood", collide=False)
                )
                parts.append(
                    Part(g.box((0.03, depth * 0.3, 0.025), (width / 2, -depth * 0.22, z)), "wood", collide=False)
                )
            if k == 1:
                for sx in (-1, 1):
                    parts.append(
                        Part(g.box((0.03, depth * 0.3, 0.025), (sx * width / 2, 0.0, z)), "wood", collide=False)
                    )
            parts.append(Part(g.cylinder(0.013, width - 0.03, (0, y, z), axis="x", sections=12), "wood", convex=True))
            regions.append(_bar_region(f"bar_{k}", width - 0.1, y, z + 0.013))
        desc = "floor-standing towel stand with three bars"
    else:
        width, depth, height = pick(rng, 0.5, 0.65), pick(rng, 0.22, 0.26), pick(rng, 0.2, 0.24)
        for sx in (-1, 1):
            parts.append(
                Part(
                    g.box_at((sx * width / 2 - 0.006, 0.0, 0.0), (sx * width / 2 + 0.006, depth, height)),
                    "metal",
                    convex=True,
                )
            )
        for k in range(5):
            y = 0.02 + (depth - 0.04) * k / 4
            parts.append(
                Part(g.cylinder(0.007, width, (0, y, height - 0.007), axis="x", sections=10), "metal", convex=True)
            )
        parts.append(
            Part(g.cylinder(0.009, width, (0, depth - 0.02, 0.05), axis="x", sections=10), "metal", convex=True)
        )
        regions.append(Region("shelf", "surface", (0.0, depth / 2, height), (width - 0.06, depth - 0.05, 0.3)))
        regions.append(_bar_region("bar", width - 0.08, depth - 0.02, 0.059, clearance=0.12))
        desc = "towel shelf with a bar"
    return recenter(
        AssetSpec("TowelHolder", v, "fixture", [Link("base", parts, 0.8)], regions=regions, description=desc)
    )


@register("HandTowelHolder", variants=3, category="fixture")
def hand_towel_holder(v: int, rng: np.random.Generator) -> AssetSpec:
    """A hand towel holder: a ring on a tall back plate, a short bar on block brackets, or a countertop
    T-stand. The region is where the towel hangs."""
    parts: list[Part] = []
    if v == 0:
        major, minor = pick(rng, 0.075, 0.09), 0.006
        zc = major + minor
        y_r = 0.06
        z_arm = zc + major
        parts.append(
            Part(
                g.torus_arc(
                    major, minor, (0, y_r, zc), plane="xz", start=0, end=2 * np.pi, sections=24, minor_sections=8
                ),
                "metal",
                collide=False,
            )
        )
        # collision: straight rods hidden inside the ring's tube
        pts = [(major * np.cos(t), y_r, zc + major * np.sin(t)) for t in np.linspace(-np.pi / 2, 1.5 * np.pi, 17)]
        parts += [Part(g.rod(p0, p1, 0.0035, 6), "metal", convex=True) for p0, p1 in pairwise(pts)]
        parts.append(
            Part(g.cylinder(0.008, y_r, (0, y_r / 2, z_arm + 0.008), axis="y", sections=10), "metal", convex=True)
        )
        parts.append(Part(g.box_at((-0.025, -0.012, 0.002), (0.025, 0.0, z_arm + 0.03)), "metal", convex=True))
        region = Region("ring", "surface", (0.0, y_r, 2 * minor), (major * 1.2, 0.02, major * 1.6))
        desc = "towel ring on a back plate"
    elif v == 1:
        length = pick(rng, 0.22, 0.3)
        bh, reach = 0.05, 0.07
        for sx in (-1, 1):
            parts.append(_block_bracket(sx * length / 2, 0.0, reach, bh, w=0.02))
        parts.append(
            Part(g.cylinder(0.009, length, (0, reach - 0.018, bh - 0.016), axis="x", sections=12), "metal", convex=True)
        )
        region = _bar_region("bar", length - 0.06, reach - 0.018, bh - 0.016 + 0.009, clearance=0.2)
        desc = "short hand towel bar"
    else:
        height, arm = pick(rng, 0.34, 0.4), pick(rng, 0.2, 0.24)
        parts.append(Part(g.cylinder(0.075, 0.018, (0, 0, 0.009), sections=20), "dark_metal", convex=True))
        parts.append(Part(g.cylinder(0.008, height, (0, 0, height / 2 + 0.01), sections=10), "metal", convex=True))
        parts.append(Part(g.cylinder(0.008, arm, (0, 0, height), axis="x", sections=10), "metal", convex=True))
        for sx in (-1, 1):
            parts.append(Part(g.sphere(0.012, (sx * arm / 2, 0, height), subdivisions=1), "metal", convex=True))
        region = _bar_region("bar", arm - 0.06, 0.0, height + 0.008, clearance=0.2)
        desc = "countertop hand towel stand"
    return recenter(
        AssetSpec("HandTowelHolder", v, "fixture", [Link("base", parts, 0.5)], regions=[region], description=desc)
    )


@register("ToiletPaperHanger", variants=3, category="fixture")
def toilet_paper_hanger(v: int, rng: np.random.Generator) -> AssetSpec:
    """A toilet paper holder: a spindle between side plates under a hood, a floor-standing post with an
    arm, or a spindle on block brackets under a small shelf."""
    parts: list[Part] = []
    regions: list[Region] = []
    if v == 0:
        w, d, h, rad = pick(rng, 0.15, 0.17), 0.13, 0.13, 0.075
        arc = [(d - rad + rad * np.cos(t), h - rad + rad * np.sin(t)) for t in np.linspace(0, np.pi / 2, 6)]
        side = [(0.0, 0.0), (d * 0.7, 0.0)] + arc + [(0.0, h)]
        for sx in (-1, 1):  # D-shaped side plates standing on their flat bottom edges
            parts.append(
                Part(
                    g.hull([(x, y, z) for y, z in side for x in (sx * w / 2 - 0.004, sx * w / 2 + 0.004)]),
                    "metal",
                    convex=True,
                )
            )
        for (y0, z0), (y1, z1) in pairwise(arc):  # the curved hood
            c = np.array([d - rad, h - rad])
            pts = []
            for y, z in ((y0, z0), (y1, z1)):
                inner = c + (np.array([y, z]) - c) * (rad - 0.004) / rad
                pts += [(x, yy, zz) for x in (-w / 2, w / 2) for yy, zz in ((y, z), tuple(inner))]
            parts.append(Part(g.hull(pts), "metal", convex=True))
        parts.append(Part(g.box_at((-w / 2, 0.0, h - 0.004), (w / 2, d - rad, h)), "metal", convex=True))
        parts.append(Part(g.box_at((-w / 2, 0.0, 0.02), (w / 2, 0.005, h)), "metal", convex=True))
        ys, zs = 0.07, 0.072
        parts.append(
            Part(g.cylinder(0.011, w - 0.008, (0, ys, zs), axis="x", sections=12), "dark_plastic", convex=True)
        )
        regions.append(_bar_region("spindle", w - 0.04, ys, zs + 0.011, clearance=0.06))
        desc = "hooded toilet paper holder"
    elif v == 1:
        height, arm_z = pick(rng, 0.6, 0.7), pick(rng, 0.3, 0.36)
        parts.append(Part(g.cylinder(0.1, 0.018, (0, 0, 0.009), sections=20), "dark_metal", convex=True))
        parts.append(Part(g.cylinder(0.011, height, (0, 0, height / 2 + 0.01), sections=10), "metal", convex=True))
        parts.append(Part(g.sphere(0.018, (0, 0, height + 0.015), subdivisions=1), "metal", convex=True))
        parts.append(Part(g.cylinder(0.01, 0.14, (0.075, 0, arm_z), axis="x", sections=10), "metal", convex=True))
        parts.append(Part(g.sphere(0.013, (0.145, 0, arm_z), subdivisions=1), "metal", collide=False))
        regions.append(Region("arm", "surface", (0.085, 0.0, arm_z + 0.01), (0.08, 0.02, 0.06)))
        desc = "floor-standing toilet paper holder"
    else:
        w, reach, bh = pick(rng, 0.15, 0.17), 0.12, 0.1
        for sx in (-1, 1):
            parts.append(_block_bracket(sx * w / 2, 0.0, reach, bh, w=0.016))
        parts.append(
            Part(g.box_at((-w / 2 - 0.02, 0.0, bh), (w / 2 + 0.02, reach + 0.015, bh + 0.01)), "wood", convex=True)
        )
        ys, zs = reach - 0.04, 0.065
        parts.append(Part(g.cylinder(0.01, w - 0.01, (0, ys, zs), axis="x", sections=12), "metal", convex=True))
        regions.append(_bar_region("spindle", w - 0.04, ys, zs + 0.01, clearance=0.03))
        regions.append(Region("shelf", "surface", (0.0, (reach + 0.015) / 2, bh + 0.01), (w, reach - 0.03, 0.2)))
        desc = "toilet paper holder with a shelf"
    return recenter(
        AssetSpec("ToiletPaperHanger", v, "fixture", [Link("base", parts, 0.5)], regions=regions, description=desc)
    )


# --------------------------------------------------------------------------------------------------
# mirror


def _smudges(x0: float, x1: float, z0: float, z1: float, y: float) -> list[Part]:
    """Grey smears on a mirror's face, shown when it is dirty."""
    w, h = x1 - x0, z1 - z0
    out = []
    for u, s, rx, rz in (
        (0.3, 0.6, 0.12, 0.06),
        (0.65, 0.35, 0.09, 0.1),
        (0.55, 0.75, 0.07, 0.04),
        (0.25, 0.25, 0.06, 0.05),
    ):
        m = g.cylinder(1.0, 0.0015, (0, 0, 0), axis="y", sections=14)
        m.apply_scale((rx * w, 1.0, rz * h))
        m.apply_translation((x0 + u * w, y, z0 + s * h))
        out.append(Part(m, "smudge", state="dirty"))
    return out


@register("Mirror", variants=3, category="decor")
def mirror(v: int, rng: np.random.Generator) -> AssetSpec:
    """A wall mirror with a flat back: a framed rectangle on a ledge rail, a round mirror on a small shelf,
    or a tall arched mirror with a deeper bottom rail. Dirty: smears on the glass."""
    depth = 0.03
    parts: list[Part] = []
    if v == 0:
        w, h, fw = pick(rng, 0.5, 0.7), pick(rng, 0.7, 0.9), 0.05
        ledge = 0.07
        parts.append(Part(g.box_at((-w / 2, 0.0, 0.0), (w / 2, ledge, fw)), "wood", convex=True))
        bars = [
            g.box_at((-w / 2, 0.0, h - fw), (w / 2, depth, h)),
            g.box_at((-w / 2, 0.0, fw), (-w / 2 + fw, depth, h - fw)),
            g.box_at((w / 2 - fw, 0.0, fw), (w / 2, depth, h - fw)),
        ]
        parts += [Part(m, "wood", convex=True) for m in bars]
        parts.append(
            Part(
                g.box_at((-w / 2 + fw - 0.005, 0.0, fw - 0.005), (w / 2 - fw + 0.005, depth - 0.01, h - fw + 0.005)),
                "mirror",
                convex=True,
            )
        )
        parts += _smudges(-w / 2 + fw, w / 2 - fw, fw, h - fw, depth - 0.0095)
        desc = "framed rectangular wall mirror with a ledge"
    elif v == 1:
        rad, fw = pick(rng, 0.3, 0.38), 0.04
        shelf_h, shelf_d = 0.025, 0.1
        zc = shelf_h + rad
        n = 24
        t = np.linspace(0, 2 * np.pi, n, endpoint=False)
        outer = np.stack([rad * np.cos(t), zc + rad * np.sin(t)], axis=1)
        inner = np.stack([(rad - fw) * np.cos(t), zc + (rad - fw) * np.sin(t)], axis=1)
        parts += [Part(m, "dark_metal", convex=True) for m in g.ring_wall_xz(outer, inner, 0.0, depth)]
        parts.append(
            Part(
                g.cylinder(rad - fw + 0.005, depth - 0.01, (0, (depth - 0.01) / 2, zc), axis="y", sections=n),
                "mirror",
                convex=True,
            )
        )
        sw = rad * 1.3
        parts.append(Part(g.box_at((-sw / 2, 0.0, 0.0), (sw / 2, shelf_d, shelf_h)), "wood", convex=True))
        parts += _smudges(
            -(rad - fw) * 0.7, (rad - fw) * 0.7, zc - (rad - fw) * 0.7, zc + (rad - fw) * 0.7, depth - 0.0095
        )
        desc = "round wall mirror on a small shelf"
    else:
        w, h, fw = pick(rng, 0.5, 0.6), pick(rng, 1.0, 1.2), 0.025
        rail = 0.06
        outer = g.arch_outline(w, h)
        inner = g.arch_outline(w - 2 * fw, h - rail - fw) + [0.0, rail]
        parts += [Part(m, "brass", convex=True) for m in g.ring_wall_xz(outer, inner, 0.0, depth)]
        parts.append(Part(g.box_at((-w / 2, 0.0, 0.0), (w / 2, 0.075, rail)), "brass", convex=True))
        glass = g.arch_outline(w - 2 * fw + 0.01, h - rail - fw + 0.005) + [0.0, rail - 0.005]
        parts.append(Part(g.flat_poly([tuple(p) for p in glass[:-1]], 0.0, depth - 0.01), "mirror", convex=True))
        parts += _smudges(-w / 2 + fw, w / 2 - fw, rail, h - w / 2, depth - 0.0095)
        desc = "tall arched wall mirror"
    return recenter(AssetSpec("Mirror", v, "decor", [Link("base", parts, 5.0)], description=desc))
