"""Room structure and wall fittings: windows, blinds, curtains and light switches.

Wall-mounted things have their flat back at -y and must still stand upright on a floor, so each has a
flat bottom that is deep enough (a sill, a bottom rail, a hem). Light hanging parts (blinds' slats,
drapes) sit on a light link joined to the base by a fixed joint.
"""

from __future__ import annotations

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import fixed, pick, recenter
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part

add_palettes(
    drape=hex_colours("c9b79c", "8d99ae", "6b705c", "a26769", "e9ecef", "3d405b"),
    rocker=hex_colours("f7f7f4", "ecebe6", "f4f4f0"),
)


@register("LightSwitch", variants=3, category="fixture")
def light_switch(v: int, rng: np.random.Generator) -> AssetSpec:
    """A wall switch: a cover plate with a rocker (single or double) or a toggle lever; "on" flips it."""
    w = [0.072, 0.072, 0.118][v]
    h = pick(rng, 0.114, 0.122)
    t = 0.012
    zc = h / 2
    parts = [Part(g.box((w, t, h), (0, 0, h / 2)), "porcelain", convex=True)]
    parts.append(Part(g.box((w - 0.008, 0.002, h - 0.008), (0, t / 2 + 0.001, h / 2)), "porcelain", collide=False))
    for sz in (-1, 1):  # screws
        parts.append(Part(g.disc_y(0.0035, (0, t / 2 + 0.002, zc + sz * 0.0415), 0.002, 8), "metal", collide=False))
    if v in (0, 2):
        xs = [0.0] if v == 0 else [-0.026, 0.026]
        for x in xs:
            parts.append(Part(g.box((0.04, 0.002, 0.072), (x, t / 2 + 0.002, zc)), "rocker", collide=False))
            for state, sign in (("on", 1.0), ("off", -1.0)):
                rocker = g.box((0.033, 0.008, 0.066))
                rocker = g.transformed(rocker, roll=sign * 0.12, offset=(x, t / 2 + 0.006, zc))
                parts.append(Part(rocker, "rocker", state=state))
        parts.append(Part(g.disc_y(0.0025, (xs[-1] + 0.012, t / 2 + 0.0085, zc - 0.027), 0.002, 8), "led_on",
                          state="on"))
    else:  # toggle lever in a bushing
        parts.append(Part(g.box((0.012, 0.003, 0.024), (0, t / 2 + 0.0025, zc)), "porcelain", collide=False))
        parts.append(Part(g.disc_y(0.005, (0, t / 2 + 0.004, zc), 0.004, 12), "metal", collide=False))
        for state, sign in (("on", 1.0), ("off", -1.0)):
            p0 = np.array([0.0, t / 2 + 0.004, zc])
            p1 = p0 + [0.0, 0.016, sign * 0.011]
            parts.append(Part(g.rod(p0, p1, 0.0032, 8), "porcelain", state=state))
            parts.append(Part(g.sphere(0.0042, p1, subdivisions=1), "porcelain", state=state))
    names = ["rocker", "toggle", "double rocker"]
    return recenter(
        AssetSpec(
            "LightSwitch",
            v,
            "fixture",
            [Link("base", parts, 0.1)],
            description=f"{names[v]} light switch on a wall plate",
        )
    )


# --------------------------------------------------------------------------------------------------
# windows, blinds, curtains


@register("Window", variants=3, category="structure")
def window(v: int, rng: np.random.Generator) -> AssetSpec:
    """A window unit 0.1 m deep: frame, sashes with glazing bars, glass and an interior sill at the bottom.

    Variants: double-hung sash window with glazing bars; casement pair under a transom; wide picture
    window with two side lights.
    """
    w = [pick(rng, 0.8, 1.0), pick(rng, 1.0, 1.3), pick(rng, 1.4, 1.8)][v]
    h = [pick(rng, 1.25, 1.45), pick(rng, 1.3, 1.5), pick(rng, 1.0, 1.2)][v]
    depth, fw = 0.1, 0.06
    sill_t, sill_d = 0.03, [0.2, 0.22, 0.24][v]
    slot = ["painted", "wood", "dark_metal"][v]
    z0 = sill_t
    parts = [
        Part(g.box_at((-w / 2 - 0.05, -depth / 2, 0), (w / 2 + 0.05, -depth / 2 + sill_d, sill_t)), slot, convex=True)
    ]
    frame = [
        g.box_at((-w / 2, -depth / 2, z0), (-w / 2 + fw, depth / 2, z0 + h)),
        g.box_at((w / 2 - fw, -depth / 2, z0), (w / 2, depth / 2, z0 + h)),
        g.box_at((-w / 2 + fw, -depth / 2, z0 + h - fw), (w / 2 - fw, depth / 2, z0 + h)),
        g.box_at((-w / 2 + fw, -depth / 2, z0), (w / 2 - fw, depth / 2, z0 + fw * 0.8)),
    ]
    parts += [Part(m, slot, convex=True) for m in frame]
    xi0, xi1, zi0, zi1 = -w / 2 + fw, w / 2 - fw, z0 + fw * 0.8, z0 + h - fw

    def sash(xa, xb, za, zb, y, bars_x=0, bars_z=0, sw=0.045, sd=0.04):
        """A glazed sash: stiles and rails around a pane with glazing bars."""
        out = [
            g.box_at((xa, y - sd / 2, za), (xa + sw, y + sd / 2, zb)),
            g.box_at((xb - sw, y - sd / 2, za), (xb, y + sd / 2, zb)),
            g.box_at((xa + sw, y - sd / 2, za), (xb - sw, y + sd / 2, za + sw)),
            g.box_at((xa + sw, y - sd / 2, zb - sw), (xb - sw, y + sd / 2, zb)),
        ]
        sp = [Part(m, slot, convex=True) for m in out]
        sp.append(Part(g.box_at((xa + sw, y - 0.003, za + sw), (xb - sw, y + 0.003, zb - sw)), "glass", convex=True))
        for k in range(1, bars_x + 1):
            x = xa + sw + (xb - xa - 2 * sw) * k / (bars_x + 1)
            sp.append(Part(g.box((0.016, 0.022, zb - za - 2 * sw), (x, y, (za + zb) / 2)), slot, collide=False))
        for k in range(1, bars_z + 1):
            z = za + sw + (zb - za - 2 * sw) * k / (bars_z + 1)
            sp.append(Part(g.box((xb - xa - 2 * sw, 0.022, 0.016), ((xa + xb) / 2, y, z)), slot, collide=False))
        return sp

    if v == 0:  # double hung: lower sash in front, upper sash behind, meeting rails at mid height
        zm = (zi0 + zi1) / 2
        parts += sash(xi0, xi1, zi0, zm + 0.02, 0.018, bars_x=1, bars_z=1)
        parts += sash(xi0, xi1, zm - 0.02, zi1, -0.022, bars_x=1, bars_z=1)
        parts.append(Part(g.box((0.06, 0.025, 0.012), (0, 0.02, zm + 0.026)), "brass", collide=False))
        desc = "double-hung sash window with glazing bars"
    elif v == 1:  # casement pair under a transom
        zt = zi0 + (zi1 - zi0) * 0.74
        parts.append(Part(g.box_at((xi0, -depth / 2, zt), (xi1, depth / 2, zt + 0.05)), slot, convex=True))
        parts.append(Part(g.box_at((-0.03, -depth / 2, zi0), (0.03, depth / 2, zt)), slot, convex=True))
        parts += sash(xi0, -0.03, zi0, zt, 0.01)
        parts += sash(0.03, xi1, zi0, zt, 0.01)
        parts += sash(xi0, xi1, zt + 0.05, zi1, 0.0, bars_x=1)
        for sx in (-1, 1):  # lever handles near the mullion
            hx, hz = sx * 0.075, zi0 + (zt - zi0) * 0.5
            parts.append(Part(g.box((0.02, 0.02, 0.03), (hx, 0.04, hz)), "metal", collide=False))
            parts.append(Part(g.box((0.014, 0.014, 0.1), (hx, 0.055, hz - 0.04)), "metal", collide=False))
        desc = "casement window pair under a transom light"
    else:  # picture window between two side lights
        side = (xi1 - xi0) * 0.22
        xa, xb = xi0 + side, xi1 - side
        for x in (xa, xb):
            parts.append(Part(g.box_at((x - 0.03, -depth / 2, zi0), (x + 0.03, depth / 2, zi1)), slot, convex=True))
        parts += sash(xi0, xa - 0.03, zi0, zi1, 0.0, bars_z=2, sw=0.03)
        parts += sash(xb + 0.03, xi1, zi0, zi1, 0.0, bars_z=2, sw=0.03)
        parts.append(Part(g.box_at((xa + 0.03, -0.003, zi0), (xb - 0.03, 0.003, zi1)), "glass", convex=True))
        desc = "wide picture window with two side lights"
    # interior casing (architrave) around the opening, on the room side
    ct, cw = 0.015, 0.07
    casing = [
        g.box_at((-w / 2 - cw, depth / 2, z0), (-w / 2, depth / 2 + ct, z0 + h + cw)),
        g.box_at((w / 2, depth / 2, z0), (w / 2 + cw, depth / 2 + ct, z0 + h + cw)),
        g.box_at((-w / 2, depth / 2, z0 + h), (w / 2, depth / 2 + ct, z0 + h + cw)),
    ]
    parts += [Part(m, slot, convex=True) for m in casing]
    return recenter(AssetSpec("Window", v, "structure", [Link("base", parts, 15.0)], description=desc))


@register("Blinds", variants=3, category="decor")
def blinds(v: int, rng: np.random.Generator) -> AssetSpec:
    """Window blinds: venetian slats, a roller blind, or vertical vanes; a weighted bottom bar stands them up."""
    w = pick(rng, 0.7, 1.2)
    h = pick(rng, 1.0, 1.4)
    top: list[Part] = []
    bottom: list[Part] = []
    slot = ["painted", "fabric", "fabric"][v]
    if v == 0:  # venetian
        top.append(Part(g.box((w, 0.05, 0.05), (0, 0, h - 0.025)), "painted", convex=True))
        bottom.append(Part(g.box((w - 0.01, 0.05, 0.025), (0, 0, 0.0125)), "painted", convex=True))
        n = int((h - 0.09) / 0.04)
        for k in range(n):
            z = 0.06 + k * (h - 0.11) / max(n - 1, 1)
            slat = g.transformed(g.box((w - 0.02, 0.045, 0.0015)), roll=-0.5, offset=(0, 0, z))
            top.append(Part(slat, slot, convex=True))
        for x in (-w / 2 + 0.1, 0.0, w / 2 - 0.1):
            for y in (-0.021, 0.021):
                top.append(Part(g.box((0.01, 0.001, h - 0.06), (x, y, h / 2 - 0.01)), slot, collide=False))
        top.append(
            Part(
                g.cylinder(0.004, h * 0.55, (w / 2 - 0.05, 0.03, h - 0.05 - h * 0.275), sections=6),
                "painted",
                collide=False,
            )
        )
        desc = "venetian blinds with tilted slats"
    elif v == 1:  # roller blind
        top.append(Part(g.box((w + 0.02, 0.07, 0.08), (0, -0.005, h - 0.04)), "painted", convex=True))
        top.append(Part(g.box((w - 0.03, 0.003, h - 0.11), (0, 0.0, 0.025 + (h - 0.11) / 2)), slot, convex=True))
        bottom.append(Part(g.box((w - 0.02, 0.05, 0.028), (0, 0, 0.014)), "painted", convex=True))
        chain_x = w / 2 - 0.02
        top.append(Part(g.box((0.004, 0.004, h * 0.6), (chain_x, 0.03, h - 0.08 - h * 0.3)), "metal", collide=False))
        top.append(Part(g.box((0.004, 0.004, h * 0.6), (chain_x, 0.04, h - 0.08 - h * 0.3)), "metal", collide=False))
        desc = "roller blind with a cassette and a bottom bar"
    else:  # vertical blinds
        top.append(Part(g.box((w, 0.06, 0.05), (0, 0, h - 0.025)), "painted", convex=True))
        n = int(w / 0.08)
        xs = np.linspace(-w / 2 + 0.045, w / 2 - 0.045, n)
        yaw = np.radians(35)
        for x in xs:
            vane = g.transformed(g.box((0.089, 0.0015, h - 0.07)), yaw=yaw, offset=(x, 0, (h - 0.07) / 2))
            top.append(Part(vane, slot, convex=True))
            weight = g.transformed(g.box((0.085, 0.004, 0.05)), yaw=yaw, offset=(x, 0, 0.025))
            bottom.append(Part(weight, slot, convex=True))
        top.append(Part(g.box((xs[-1] - xs[0], 0.003, 0.003), (0, 0.0, 0.015)), "metal", collide=False))
        desc = "vertical blinds with turned vanes"
    top_link, joint = fixed("slats" if v != 1 else "shade", top, 0.6)
    links = [Link("base", bottom, 1.4), top_link]
    return recenter(AssetSpec("Blinds", v, "decor", links, joints=[joint], description=desc))


@register("Curtains", variants=3, category="decor")
def curtains(v: int, rng: np.random.Generator) -> AssetSpec:
    """A curtain rod on wall brackets with two pleated drapes: open, closed under a pelmet, or tied back.

    The weighted hems are the feet it stands on.
    """
    w = pick(rng, 1.5, 2.2)
    h = pick(rng, 2.15, 2.4)
    rod_z, rod_y = h - 0.04, 0.0
    amp = 0.07
    drapes: list[Part] = []
    feet: list[Part] = []
    hardware = [Part(g.cylinder(0.012, w, (0, rod_y, rod_z), axis="x", sections=10), "brass", convex=True)]
    for sx in (-1, 1):
        hardware.append(
            Part(g.sphere(0.025, (sx * (w / 2 + 0.02), rod_y, rod_z), subdivisions=1), "brass", convex=True)
        )
        hardware.append(Part(g.box((0.02, 0.09, 0.02), (sx * (w / 2 - 0.08), -0.045, rod_z)), "brass", convex=True))
        hardware.append(Part(g.box((0.05, 0.01, 0.07), (sx * (w / 2 - 0.08), -0.085, rod_z)), "brass", convex=True))
    z_top, z_bot = rod_z - 0.022, 0.012
    n = [10, 12, 9][v]
    panel = [pick(rng, 0.3, 0.4) * w, w / 2 - 0.05, pick(rng, 0.35, 0.42) * w][v]
    for sx in (-1, 1):
        x_out = sx * (w / 2 - 0.04)
        x_in = x_out - sx * panel
        xs_top = list(np.linspace(x_out, x_in, n + 1))
        if v == 2:  # gathered by a tieback at ~0.9 m, flaring out below
            z_tie = pick(rng, 0.85, 0.95)
            gather = 0.16
            xs_tie = list(np.linspace(x_out, x_out - sx * gather, n + 1))
            xs_bot = list(np.linspace(x_out, x_out - sx * gather * 1.9, n + 1))
            drapes += [Part(m, "drape", convex=True) for m in g.drape(xs_top, xs_tie, z_top, z_tie, 0.0, amp)]
            drapes += [Part(m, "drape", convex=True) for m in g.drape(xs_tie, xs_bot, z_tie, z_bot, 0.0, amp)]
            xt = x_out - sx * gather / 2
            drapes.append(Part(g.box((gather + 0.03, amp + 0.03, 0.05), (xt, 0.0, z_tie)), "drape", collide=False))
            foot_x = sorted((x_out, xs_bot[-1]))
        else:
            drapes += [Part(m, "drape", convex=True) for m in g.drape(xs_top, xs_top, z_top, z_bot, 0.0, amp)]
            foot_x = sorted((x_out, x_in))
        for x in xs_top[::2]:  # rings on the rod
            drapes.append(
                Part(
                    g.torus_arc(
                        0.018,
                        0.003,
                        (x, rod_y, rod_z),
                        plane="yz",
                        start=0,
                        end=2 * np.pi,
                        sections=8,
                        minor_sections=4,
                    ),
                    "brass",
                    collide=False,
                )
            )
        feet.append(
            Part(g.box_at((foot_x[0], -amp / 2 - 0.035, 0), (foot_x[1], amp / 2 + 0.035, z_bot)), "drape", convex=True)
        )
    if v == 1:  # pelmet box over the rod
        hardware.append(
            Part(g.box_at((-w / 2 - 0.06, -0.09, h - 0.24), (w / 2 + 0.06, 0.07, h + 0.02)), "drape", convex=True)
        )
    names = ["open drapes", "closed drapes under a pelmet", "drapes held by tiebacks"]
    upper, joint = fixed("drapes", drapes + hardware, 1.0)
    return recenter(
        AssetSpec(
            "Curtains",
            v,
            "decor",
            [Link("base", feet, 2.0), upper],
            joints=[joint],
            description=f"curtain rod with two pleated {names[v]}",
        )
    )
