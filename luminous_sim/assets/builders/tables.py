"""Tables, desks, TV stands and shelves (furniture).

Every piece is built from convex slabs, legs and carcass panels; drawers come from `common.drawer`
(prismatic, with a volume region), doors from `common.hinged_door`. Every top, shelf level and open
compartment declares a surface region whose clearance is the free height up to the next board.
"""

from __future__ import annotations

from itertools import pairwise

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import (
    carcass,
    drawer,
    hinged_door,
    pick,
    shift_footprint,
    surface,
)
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Joint, Link, Part, Region

TOP_CLEARANCE = 0.6
"""Free height declared above table tops and the tops of low units."""


# ----------------------------------------------------------------------------------------------- helpers

def _slab(lo, hi, slot: str, bevel: float = 0.004) -> Part:
    """A board or table top with slightly bevelled edges."""
    return Part(g.soft_box_at(lo, hi, bevel), slot, convex=True)


def _leg(style: str, x: float, y: float, h: float, size: float, slot: str, z0: float = 0.0) -> Part:
    """A vertical leg of width `size` standing at (x, y) from z0 to z0 + h.

    Styles: square, taper (square, narrowing to the foot), round, turned.
    """
    if style == "square":
        mesh = g.box((size, size, h), (x, y, z0 + h / 2))
    elif style == "taper":
        a, b = size / 2, size * 0.3
        mesh = g.hull([(x + sx * a, y + sy * a, z0 + h) for sx in (-1, 1) for sy in (-1, 1)] +
                      [(x + sx * b, y + sy * b, z0) for sx in (-1, 1) for sy in (-1, 1)])
    elif style == "round":
        mesh = g.cylinder(size / 2, h, (x, y, z0 + h / 2), sections=12)
    else:
        mesh = g.turned_leg(x, y, h, size / 2, z0)
    return Part(mesh, slot, convex=True)


def _legs(style: str, w: float, d: float, h: float, inset: float, size: float, slot: str,
          z0: float = 0.0) -> list[Part]:
    """Four legs at the corners of a w x d footprint, their centres `inset` from the edges."""
    return [_leg(style, sx * (w / 2 - inset), sy * (d / 2 - inset), h, size, slot, z0)
            for sx in (-1, 1) for sy in (-1, 1)]


def _apron(w: float, d: float, z_top: float, height: float, inset: float, slot: str, t: float = 0.02,
           sides: str = "fblr") -> list[Part]:
    """Boards under a top joining the legs: their outer faces `inset` from the top's edges."""
    xo, yo = w / 2 - inset, d / 2 - inset
    z0 = z_top - height
    boxes = {
        "f": ((-xo, yo - t, z0), (xo, yo, z_top)),
        "b": ((-xo, -yo, z0), (xo, -yo + t, z_top)),
        "l": ((-xo, -yo, z0), (-xo + t, yo, z_top)),
        "r": ((xo - t, -yo, z0), (xo, yo, z_top)),
    }
    return [Part(g.box_at(*boxes[s]), slot, convex=True) for s in sides]


def _drawer_stack(
    first: int, x0: float, x1: float, y_front: float, z_lo: float, z_hi: float, depth: float, slot: str,
    weights: tuple[float, ...] = (1.0,), mass: float = 1.5, front_slot: str | None = None,
) -> tuple[list[Part], list[Link], list[Joint], list[Region]]:
    """Drawers stacked in the opening x0..x1, z_lo..z_hi of a carcass whose front face is at y_front.

    The fronts sit flush with the face; thin rails behind the gaps hide the interior. Drawers are named
    drawer_<first>, drawer_<first+1>, ... from the bottom up; `weights` sets their relative heights.
    """
    gap = 0.004
    edges = z_lo + (z_hi - z_lo) * np.concatenate([[0.0], np.cumsum(weights)]) / sum(weights)
    parts: list[Part] = []
    links: list[Link] = []
    joints: list[Joint] = []
    regions: list[Region] = []
    for i in range(len(weights)):
        za, zb = float(edges[i]), float(edges[i + 1])
        link, joint, region = drawer(f"drawer_{first + i}", "base", x1 - x0 - 2 * gap, depth, zb - za - 2 * gap,
                                     (x0 + x1) / 2, y_front - 0.02, za + gap, slot, front_slot=front_slot, mass=mass)
        links.append(link)
        joints.append(joint)
        regions.append(region)
        if i > 0:
            rail = g.box_at((x0, y_front - depth - 0.02, za - 0.006), (x1, y_front - 0.02, za + 0.002))
            parts.append(Part(rail, slot, collide=False))
    return parts, links, joints, regions


def _round_top(r: float, t: float, z_top: float, slot: str, sx: float = 1.0, sy: float = 1.0) -> Part:
    """A round (or, scaled, oval) top of radius r, thickness t, its upper face at z_top, with a bevelled edge."""
    prof = [(0, 0), (r - 0.006, 0), (r, 0.006), (r, t - 0.004), (r - 0.004, t), (0, t)]
    mesh = g.revolve(prof, (0, 0, z_top - t), sections=32)
    mesh.apply_scale((sx, sy, 1.0))
    return Part(mesh, slot, convex=True)


def _spec(type_name: str, v: int, parts: list[Part], mass: float, regions: list[Region], desc: str,
          links: list[Link] = (), joints: list[Joint] = ()) -> AssetSpec:
    """An AssetSpec whose base link gets what is left of `mass` after the moving links' masses."""
    moving = sum(link.mass for link in links)
    return AssetSpec(type_name, v, "furniture", [Link("base", parts, mass - moving)] + list(links), list(joints),
                     regions=regions, description=desc)


# ----------------------------------------------------------------------------------------- dining table

@register("DiningTable", variants=5, category="furniture")
def dining_table(v: int, rng: np.random.Generator) -> AssetSpec:
    """A dining table: a top at ~0.75 m on legs, a pedestal or trestles.

    Variants: rectangular with tapered legs and an apron, round pedestal, farmhouse trestle, glass top on
    a metal frame, oval on turned legs.
    """
    h = pick(rng, 0.74, 0.77)
    parts: list[Part] = []
    if v == 0:
        w, d, tt = pick(rng, 1.5, 1.8), pick(rng, 0.85, 0.95), 0.035
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "wood", 0.006))
        parts += _legs("taper", w, d, h - tt, 0.08, 0.075, "wood")
        parts += _apron(w, d, h - tt, 0.1, 0.06, "wood")
        rw, rd, desc = w, d, "rectangular dining table with tapered legs and an apron"
    elif v == 1:
        r, tt = pick(rng, 0.5, 0.6), 0.035
        parts.append(_round_top(r, tt, h, "dark_wood"))
        zt = h - tt
        col = [(0, 0.05), (0.09, 0.05), (0.065, 0.14), (0.05, 0.32), (0.07, 0.46), (0.05, zt - 0.1), (0.1, zt - 0.02),
               (0.1, zt), (0, zt)]
        parts.append(Part(g.revolve(col, sections=16), "dark_wood", convex=True))
        reach = r * 0.78
        for k in range(4):
            a = np.pi / 4 + k * np.pi / 2
            foot = g.hull([(0, sy * 0.04, z) for sy in (-1, 1) for z in (0, 0.11)] +
                          [(reach, sy * 0.03, z) for sy in (-1, 1) for z in (0, 0.04)])
            parts.append(Part(g.transformed(foot, yaw=a), "dark_wood", convex=True))
        rw = rd = r * np.sqrt(2)
        desc = "round pedestal dining table on four splayed feet"
    elif v == 2:
        w, d, tt = pick(rng, 1.8, 2.0), pick(rng, 0.85, 0.95), 0.045
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "wood", 0.008))
        xe = w / 2 - 0.3
        for sx in (-1, 1):
            x = sx * xe
            parts.append(Part(g.box_at((x - 0.035, -0.08, 0.07), (x + 0.035, 0.08, h - tt - 0.05)), "wood",
                              convex=True))
            foot = [(x + sx2 * 0.045, y, z) for sx2 in (-1, 1)
                    for y, z in ((-(d / 2 - 0.06), 0), (d / 2 - 0.06, 0), (-(d / 2 - 0.12), 0.08),
                                 (d / 2 - 0.12, 0.08))]
            parts.append(Part(g.hull(foot), "wood", convex=True))
            cleat = [(x + sx2 * 0.04, y, z) for sx2 in (-1, 1)
                     for y, z in ((-(d / 2 - 0.08), h - tt), (d / 2 - 0.08, h - tt), (-(d / 2 - 0.15), h - tt - 0.06),
                                  (d / 2 - 0.15, h - tt - 0.06))]
            parts.append(Part(g.hull(cleat), "wood", convex=True))
        parts.append(Part(g.box_at((-xe, -0.025, 0.3), (xe, 0.025, 0.38)), "wood", convex=True))
        rw, rd, desc = w, d, "farmhouse trestle dining table"
    elif v == 3:
        w, d, tt = pick(rng, 1.4, 1.6), pick(rng, 0.8, 0.9), 0.012
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "glass", 0.003))
        parts += _legs("square", w, d, h - tt, 0.06, 0.04, "dark_metal")
        parts += _apron(w, d, h - tt, 0.05, 0.04, "dark_metal", t=0.025)
        rw, rd, desc = w, d, "glass-top dining table on a black metal frame"
    else:
        a, b, tt = pick(rng, 0.8, 0.9), pick(rng, 0.48, 0.53), 0.035
        parts.append(_round_top(1.0, tt, h, "wood", sx=a, sy=b))
        lx, ly = a * 0.62, b * 0.6
        parts += [_leg("turned", sx * lx, sy * ly, h - tt, 0.07, "wood") for sx in (-1, 1) for sy in (-1, 1)]
        parts += _apron(2 * lx + 0.06, 2 * ly + 0.06, h - tt, 0.09, 0.0, "wood")
        rw, rd = a * np.sqrt(2), b * np.sqrt(2)
        desc = "oval dining table on turned legs"
    return _spec("DiningTable", v, parts, 25.0, [surface("top", rw, rd, h, TOP_CLEARANCE)], desc)


# ----------------------------------------------------------------------------------------- coffee table

@register("CoffeeTable", variants=5, category="furniture")
def coffee_table(v: int, rng: np.random.Generator) -> AssetSpec:
    """A low coffee table, some with a lower shelf or a drawer.

    Variants: wooden with a lower shelf, round on three splayed legs, glass top on a metal frame with a
    wooden shelf, solid block with an open slot through it, trunk-style with a drawer and a shelf.
    """
    h = pick(rng, 0.4, 0.46)
    parts: list[Part] = []
    links: list[Link] = []
    joints: list[Joint] = []
    regions: list[Region] = []
    if v == 0:
        w, d, tt = pick(rng, 1.1, 1.3), pick(rng, 0.55, 0.65), 0.035
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "wood", 0.006))
        parts += _legs("square", w, d, h - tt, 0.05, 0.05, "wood")
        parts += _apron(w, d, h - tt, 0.06, 0.04, "wood")
        zs = 0.13
        parts.append(_slab((-w / 2 + 0.035, -d / 2 + 0.035, zs - 0.02), (w / 2 - 0.035, d / 2 - 0.035, zs), "wood"))
        regions = [surface("top", w, d, h, TOP_CLEARANCE),
                   surface("shelf", w - 0.14, d - 0.14, zs, h - tt - 0.06 - zs - 0.01)]
        desc = "wooden coffee table with a lower shelf"
    elif v == 1:
        r, tt = pick(rng, 0.4, 0.45), 0.03
        parts.append(_round_top(r, tt, h, "wood"))
        for k in range(3):
            a = 2 * np.pi * k / 3 + np.pi / 2
            top = (0.55 * r * np.cos(a), 0.55 * r * np.sin(a), h - tt)
            foot = (0.8 * r * np.cos(a), 0.8 * r * np.sin(a), 0.0)
            parts.append(Part(g.splayed_leg(top, foot, 0.022, 0.014), "dark_wood", convex=True))
        regions = [surface("top", r * np.sqrt(2), r * np.sqrt(2), h, TOP_CLEARANCE)]
        desc = "round coffee table on three splayed legs"
    elif v == 2:
        w, d, tt = pick(rng, 1.0, 1.2), pick(rng, 0.55, 0.62), 0.01
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "glass", 0.003))
        parts += _legs("round", w, d, h - tt, 0.03, 0.028, "metal")
        parts += _apron(w, d, h - tt, 0.03, 0.016, "metal", t=0.02)
        zs = 0.12
        parts.append(_slab((-w / 2 + 0.045, -d / 2 + 0.045, zs - 0.022), (w / 2 - 0.045, d / 2 - 0.045, zs), "wood"))
        parts += _apron(w, d, zs - 0.022, 0.02, 0.016, "metal", t=0.02)
        regions = [surface("top", w, d, h, TOP_CLEARANCE),
                   surface("shelf", w - 0.09, d - 0.09, zs, h - tt - 0.03 - zs - 0.01)]
        desc = "glass-top coffee table on a metal frame with a wooden shelf"
    elif v == 3:
        w, d = pick(rng, 1.0, 1.2), pick(rng, 0.6, 0.7)
        te, tb = 0.05, 0.04
        parts.append(Part(g.box_at((-w / 2 + 0.05, -d / 2 + 0.05, 0), (w / 2 - 0.05, d / 2 - 0.05, 0.03)), "dark_wood",
                          convex=True))
        parts.append(_slab((-w / 2, -d / 2, 0.03), (w / 2, d / 2, 0.03 + tb), "painted"))
        for sx in (-1, 1):
            x0, x1 = sorted((sx * w / 2, sx * (w / 2 - te)))
            parts.append(_slab((x0, -d / 2, 0.03 + tb), (x1, d / 2, h - te), "painted"))
        parts.append(_slab((-w / 2, -d / 2, h - te), (w / 2, d / 2, h), "painted"))
        regions = [surface("top", w, d, h, TOP_CLEARANCE),
                   surface("slot", w - 2 * te, d, 0.03 + tb, h - te - 0.03 - tb - 0.01)]
        desc = "solid block coffee table with an open slot through it"
    else:
        w, d = pick(rng, 0.9, 1.0), pick(rng, 0.55, 0.6)
        feet, t, tt = 0.07, 0.018, 0.03
        for sx in (-1, 1):
            for sy in (-1, 1):
                parts.append(Part(g.revolve([(0, 0), (0.025, 0), (0.035, feet * 0.5), (0.03, feet), (0, feet)],
                                            (sx * (w / 2 - 0.06), sy * (d / 2 - 0.06), 0), sections=12), "dark_wood",
                                  convex=True))
        ch = h - feet - tt + t
        parts += carcass(w, d, ch, t, "wood", z0=feet, open_top=True)
        z_under = feet + ch - t  # underside of the top
        parts.append(_slab((-w / 2 - 0.015, -d / 2 - 0.015, z_under), (w / 2 + 0.015, d / 2 + 0.015, h), "wood", 0.005))
        dh = 0.13
        z_div = z_under - dh - t
        parts.append(Part(g.box_at((-w / 2 + t, -d / 2 + t, z_div), (w / 2 - t, d / 2 - 0.02, z_div + t)), "wood",
                          convex=True))
        dp, links, joints, dregs = _drawer_stack(0, -w / 2 + t, w / 2 - t, d / 2, z_div + t, z_under, d - t - 0.04,
                                                 "wood", mass=2.0)
        parts += dp
        regions = [surface("top", w + 0.03, d + 0.03, h, TOP_CLEARANCE),
                   surface("shelf", w - 2 * t, d - t, feet + t, z_div - feet - t - 0.01, cy=t / 2)] + dregs
        desc = "trunk-style coffee table with a drawer over an open shelf"
    return _spec("CoffeeTable", v, parts, 12.0, regions, desc, links, joints)


# ------------------------------------------------------------------------------------------- side table

@register("SideTable", variants=5, category="furniture")
def side_table(v: int, rng: np.random.Generator) -> AssetSpec:
    """A side table or nightstand.

    Variants: nightstand on short legs with a drawer over an open shelf, two-drawer nightstand on a
    plinth, square side table with a lower shelf, round pedestal table, mid-century nightstand on splayed
    legs with a drawer over an open cubby.
    """
    parts: list[Part] = []
    links: list[Link] = []
    joints: list[Joint] = []
    regions: list[Region] = []
    t, tt = 0.018, 0.025
    if v in (0, 1, 4):
        w, d = pick(rng, 0.45, 0.52), pick(rng, 0.38, 0.42)
        h = pick(rng, 0.55, 0.62)
        slot = ["wood", "painted", "wood"][(0, 1, 4).index(v)]
        if v == 0:
            z0 = 0.1
            parts += _legs("square", w, d, z0 + 0.01, 0.025, 0.04, slot)
        elif v == 1:
            z0 = 0.06
            plinth = g.box_at((-w / 2 + 0.03, -d / 2 + 0.03, 0), (w / 2 - 0.03, d / 2 - 0.03, z0))
            parts.append(Part(plinth, "dark_wood", convex=True))
        else:
            z0 = 0.26
            for sx in (-1, 1):
                for sy in (-1, 1):
                    top = (sx * (w / 2 - 0.06), sy * (d / 2 - 0.06), z0 + 0.005)
                    foot = (sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), 0.0)
                    parts.append(Part(g.splayed_leg(top, foot, 0.018, 0.011), "dark_wood", convex=True))
        ch = h - z0 - tt + t
        parts += carcass(w, d, ch, t, slot, z0=z0, open_top=True)
        z_under = z0 + ch - t
        parts.append(_slab((-w / 2 - 0.01, -d / 2 - 0.01, z_under), (w / 2 + 0.01, d / 2 + 0.01, h), slot, 0.005))
        regions.append(surface("top", w + 0.02, d + 0.02, h, 0.5))
        depth = d - t - 0.04
        if v == 1:
            dp, links, joints, dregs = _drawer_stack(0, -w / 2 + t, w / 2 - t, d / 2, z0 + t, z_under, depth, slot,
                                                     weights=(1.0, 1.0), mass=1.2)
            parts += dp
            desc = "two-drawer nightstand on a plinth"
        else:
            dh = 0.13 if v == 0 else 0.12
            z_div = z_under - dh - t
            parts.append(Part(g.box_at((-w / 2 + t, -d / 2 + t, z_div), (w / 2 - t, d / 2, z_div + t)), slot,
                              convex=True))
            dp, links, joints, dregs = _drawer_stack(0, -w / 2 + t, w / 2 - t, d / 2, z_div + t, z_under, depth, slot,
                                                     mass=1.2)
            parts += dp
            regions.append(surface("shelf", w - 2 * t, d - t, z0 + t, z_div - z0 - t - 0.01, cy=t / 2))
            desc = ("nightstand on short legs with a drawer over an open shelf" if v == 0 else
                    "mid-century nightstand on splayed legs with a drawer over an open cubby")
        regions += dregs
        mass = 8.0
    elif v == 2:
        w, h, tt = pick(rng, 0.45, 0.55), pick(rng, 0.55, 0.62), 0.03
        parts.append(_slab((-w / 2, -w / 2, h - tt), (w / 2, w / 2, h), "painted", 0.005))
        parts += _legs("round", w, w, h - tt, 0.04, 0.035, "painted")
        parts += _apron(w, w, h - tt, 0.06, 0.03, "painted", t=0.018)
        zs = 0.16
        parts.append(_slab((-w / 2 + 0.03, -w / 2 + 0.03, zs - 0.018), (w / 2 - 0.03, w / 2 - 0.03, zs), "painted"))
        regions = [surface("top", w, w, h, 0.5), surface("shelf", w - 0.1, w - 0.1, zs, h - tt - 0.06 - zs - 0.01)]
        desc, mass = "square side table with a lower shelf", 8.0
    else:
        r, h, tt = pick(rng, 0.22, 0.26), pick(rng, 0.55, 0.62), 0.025
        parts.append(_round_top(r, tt, h, "wood"))
        column = g.cylinder(0.022, h - tt - 0.02, (0, 0, 0.02 + (h - tt - 0.02) / 2), sections=12)
        parts.append(Part(column, "dark_metal", convex=True))
        parts.append(Part(g.revolve([(0, 0), (r * 0.75, 0), (r * 0.75, 0.012), (r * 0.7, 0.022), (0, 0.022)],
                                    sections=24), "dark_metal", convex=True))
        regions = [surface("top", r * np.sqrt(2), r * np.sqrt(2), h, 0.5, margin=0.01)]
        desc, mass = "round pedestal side table on a weighted disc base", 8.0
    return _spec("SideTable", v, parts, mass, regions, desc, links, joints)


# ------------------------------------------------------------------------------------------------- desk

@register("Desk", variants=5, category="furniture")
def desk(v: int, rng: np.random.Generator) -> AssetSpec:
    """A desk: a top at ~0.75 m, legs or drawer pedestals.

    Variants: metal-legged desk with a modesty panel, single-pedestal desk with three drawers and a panel
    end, double-pedestal executive desk, writing desk with a centre drawer on tapered legs, L-shaped
    corner desk with a two-drawer pedestal.
    """
    h = pick(rng, 0.74, 0.76)
    t, tt = 0.018, 0.03
    parts: list[Part] = []
    links: list[Link] = []
    joints: list[Joint] = []
    regions: list[Region] = []
    if v == 0:
        w, d = pick(rng, 1.1, 1.3), pick(rng, 0.55, 0.65)
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "wood", 0.005))
        parts += _legs("square", w, d, h - tt, 0.04, 0.04, "dark_metal")
        parts += _apron(w, d, h - tt, 0.06, 0.02, "dark_metal", t=0.02, sides="lr")
        parts.append(Part(g.box_at((-w / 2 + 0.06, -d / 2 + 0.05, 0.3), (w / 2 - 0.06, -d / 2 + 0.066, h - tt)),
                          "dark_metal", convex=True))
        regions = [surface("top", w, d, h, TOP_CLEARANCE)]
        desc = "desk on black metal legs with a modesty panel"
    elif v in (1, 2):
        w, d = (pick(rng, 1.2, 1.4), pick(rng, 0.6, 0.7)) if v == 1 else (pick(rng, 1.5, 1.7), pick(rng, 0.75, 0.8))
        slot = "wood" if v == 1 else "dark_wood"
        pw = 0.42
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), slot, 0.005))
        z_under = h - tt
        ch = z_under + t  # carcass sides reach the underside of the top
        sides = (1,) if v == 1 else (-1, 1)
        first = 0
        for sx in sides:
            xc = sx * (w / 2 - pw / 2 - 0.01)
            body = carcass(pw, d - 0.04, ch, t, slot, z0=0.0, open_top=True)
            for p in body:
                p.mesh.apply_translation((xc, -0.02, 0))
            parts += body
            parts.append(Part(g.box_at((xc - pw / 2 + t, d / 2 - 0.06, 0), (xc + pw / 2 - t, d / 2 - 0.04, 0.06)),
                              "dark_plastic" if v == 1 else slot, convex=True))
            weights = (1.6, 1.0, 1.0) if v == 1 else (1.6, 1.0)
            dp, dl, dj, dr = _drawer_stack(first, xc - pw / 2 + t, xc + pw / 2 - t, d / 2 - 0.04, 0.06 + t, z_under,
                                           d - 0.04 - t - 0.04, slot, weights=weights, mass=1.5)
            parts += dp
            links += dl
            joints += dj
            regions += dr
            first += len(weights)
        if v == 1:  # panel end on the left
            parts.append(_slab((-w / 2 + 0.01, -d / 2 + 0.02, 0), (-w / 2 + 0.04, d / 2 - 0.04, z_under), slot))
        x_l = -w / 2 + 0.04 if v == 1 else -w / 2 + pw + 0.01
        x_r = w / 2 - pw - 0.01
        parts.append(Part(g.box_at((x_l, -d / 2 + 0.03, 0.25), (x_r, -d / 2 + 0.03 + t, z_under)), slot, convex=True))
        regions = [surface("top", w, d, h, TOP_CLEARANCE)] + regions
        desc = ("single-pedestal desk with three drawers and a panel end" if v == 1 else
                "double-pedestal executive desk with four drawers")
    elif v == 3:
        w, d = pick(rng, 1.0, 1.2), pick(rng, 0.5, 0.58)
        parts.append(_slab((-w / 2, -d / 2, h - tt), (w / 2, d / 2, h), "dark_wood", 0.005))
        parts += _legs("taper", w, d, h - tt, 0.05, 0.05, "dark_wood")
        ah, inset = 0.12, 0.025
        parts += _apron(w, d, h - tt, ah, inset, "dark_wood", sides="blr")
        dw = min(0.55, w * 0.5)
        yf = d / 2 - inset
        for sx in (-1, 1):  # front apron either side of the drawer
            x0, x1 = sorted((sx * (w / 2 - inset), sx * dw / 2))
            parts.append(Part(g.box_at((x0, yf - 0.02, h - tt - ah), (x1, yf, h - tt)), "dark_wood", convex=True))
        for sx in (-1, 1):  # runners the drawer rides on
            x = sx * (dw / 2 + 0.01)
            runner = g.box_at((x - 0.01, -d / 2 + 0.05, h - tt - ah), (x + 0.01, yf - 0.02, h - tt))
            parts.append(Part(runner, "dark_wood", convex=True))
        dp, links, joints, dregs = _drawer_stack(0, -dw / 2, dw / 2, yf, h - tt - ah, h - tt, d - 0.14, "dark_wood",
                                                 mass=1.5)
        parts += dp
        regions = [surface("top", w, d, h, TOP_CLEARANCE)] + dregs
        desc = "writing desk on tapered legs with a centre drawer"
    else:
        w, d = pick(rng, 1.4, 1.6), pick(rng, 0.6, 0.65)
        rw, rl = pick(rng, 0.5, 0.58), pick(rng, 0.6, 0.75)  # return wing: width, length forward of the main top
        slot = "painted"
        z_under = h - tt
        parts.append(_slab((-w / 2, -d / 2, z_under), (w / 2, d / 2, h), slot, 0.005))
        parts.append(_slab((-w / 2, d / 2 - 0.002, z_under), (-w / 2 + rw, d / 2 + rl, h), slot, 0.005))
        parts.append(_slab((w / 2 - 0.04, -d / 2 + 0.02, 0), (w / 2 - 0.01, d / 2 - 0.02, z_under), slot))
        parts.append(_slab((-w / 2 + 0.02, d / 2 + rl - 0.04, 0), (-w / 2 + rw - 0.02, d / 2 + rl - 0.01, z_under),
                           slot))
        parts.append(_leg("square", -w / 2 + 0.04, -d / 2 + 0.04, z_under, 0.05, "dark_metal"))
        # a two-drawer pedestal under the main top, left of the right-hand panel; a modesty panel up to it
        pw = 0.4
        xc = w / 2 - 0.04 - pw / 2 - 0.005
        parts.append(Part(g.box_at((-w / 2 + 0.07, -d / 2 + 0.02, 0.3), (xc - pw / 2, -d / 2 + 0.036, z_under)), slot,
                          convex=True))
        body = carcass(pw, d - 0.06, z_under + t, t, slot, open_top=True)
        for p in body:
            p.mesh.apply_translation((xc, -0.01, 0))
        parts += body
        parts.append(Part(g.box_at((xc - pw / 2 + t, d / 2 - 0.06, 0), (xc + pw / 2 - t, d / 2 - 0.04, 0.05)), slot,
                          convex=True))
        dp, links, joints, dregs = _drawer_stack(0, xc - pw / 2 + t, xc + pw / 2 - t, d / 2 - 0.04, 0.05 + t, z_under,
                                                 d - 0.1 - t - 0.03, slot, weights=(1.5, 1.0), mass=1.5)
        parts += dp
        regions = [surface("top", w, d, h, TOP_CLEARANCE), surface("return", rw, rl, h, TOP_CLEARANCE,
                                                                   cx=-w / 2 + rw / 2, cy=d / 2 + rl / 2)]
        # re-centre the L footprint; the drawers move with it
        shift_footprint(parts, regions, 0.0, -rl / 2)
        for j in joints:
            j.origin = (j.origin[0], j.origin[1] - rl / 2, j.origin[2])
        regions += dregs
        desc = "L-shaped corner desk with a two-drawer pedestal"
    return _spec("Desk", v, parts, 30.0, regions, desc, links, joints)


# --------------------------------------------------------------------------------------------- TV stand

@register("TVStand", variants=5, category="furniture")
def tv_stand(v: int, rng: np.random.Generator) -> AssetSpec:
    """A low, long media unit with open compartments, shelves, drawers or doors.

    Variants: three open compartments on legs, centre drawers between open compartments on a plinth,
    metal frame with glass shelves, four-cubby low unit, cabinet doors either side of an open centre.
    """
    parts: list[Part] = []
    links: list[Link] = []
    joints: list[Joint] = []
    regions: list[Region] = []
    t = 0.02
    w, d = pick(rng, 1.3, 1.8), pick(rng, 0.38, 0.45)
    h = pick(rng, 0.45, 0.58)
    if v == 2:  # metal frame, glass shelves
        post = 0.025
        for sx in (-1, 1):
            for sy in (-1, 1):
                parts.append(Part(g.box((post, post, h), (sx * (w / 2 - post / 2), sy * (d / 2 - post / 2), h / 2)),
                                  "dark_metal", convex=True))
        levels = [0.06, round(0.06 + (h - 0.06) / 2, 3), h]
        for z in levels:
            parts.append(_slab((-w / 2 + 0.005, -d / 2 + 0.005, z - 0.01), (w / 2 - 0.005, d / 2 - 0.005, z), "glass",
                               0.002))
            parts += _apron(w, d, z - 0.01, 0.025, 0.0, "dark_metal", t=post, sides="fb")
        regions = [surface("top", w, d, h, 0.8)]
        for i, (z, z_next) in enumerate(pairwise(levels)):
            regions.append(surface(f"shelf_{i}", w - 2 * post, d - 2 * post, z, z_next - 0.035 - z - 0.01))
        return _spec("TVStand", v, parts, 25.0, regions, "TV stand: black metal frame with glass shelves")
    slot = ["wood", "painted", None, "dark_wood", "wood"][v]
    z0 = {0: 0.12, 1: 0.06, 3: 0.05, 4: 0.08}[v]
    if v == 0:
        parts += _legs("taper", w, d, z0 + 0.01, 0.05, 0.04, "dark_wood")
    elif v in (1, 3):
        parts.append(Part(g.box_at((-w / 2 + 0.04, -d / 2 + 0.04, 0), (w / 2 - 0.04, d / 2 - 0.04, z0)), "dark_plastic",
                          convex=True))
    else:
        parts += _legs("square", w, d, z0 + 0.01, 0.04, 0.04, "dark_metal")
    ch = h - z0
    parts += carcass(w, d, ch, t, slot, z0=z0)
    zb, zt = z0 + t, h - t  # interior floor and ceiling
    inner_d = d - t
    cy = t / 2
    regions.append(surface("top", w, d, h, 0.8))

    def divider(x: float) -> None:
        parts.append(Part(g.box_at((x - t / 2, -d / 2 + t, zb), (x + t / 2, d / 2, zt)), slot, convex=True))

    def cell(name: str, x0: float, x1: float, z_floor: float, z_ceil: float) -> None:
        regions.append(surface(name, x1 - x0, inner_d, z_floor, z_ceil - z_floor - 0.01, cx=(x0 + x1) / 2, cy=cy))

    xi = w / 2 - t
    if v == 0:
        divider(-w / 6)
        divider(w / 6)
        bounds = [(-xi, -w / 6 - t / 2), (-w / 6 + t / 2, w / 6 - t / 2), (w / 6 + t / 2, xi)]
        for k, (x0, x1) in enumerate(bounds):
            cell(f"compartment_{k}", x0, x1, zb, zt)
        desc = "TV stand with three open compartments on tapered legs"
    elif v == 1:
        dw = 0.5
        divider(-dw / 2 - t / 2)
        divider(dw / 2 + t / 2)
        cell("compartment_left", -xi, -dw / 2 - t, zb, zt)
        cell("compartment_right", dw / 2 + t, xi, zb, zt)
        dp, links, joints, dregs = _drawer_stack(0, -dw / 2, dw / 2, d / 2, zb, zt, d - t - 0.04, slot,
                                                 weights=(1.0, 1.0), mass=1.5)
        parts += dp
        regions += dregs
        desc = "TV stand with two centre drawers between open compartments"
    elif v == 3:
        zm = round((zb + zt) / 2, 3)
        parts.append(Part(g.box_at((-xi, -d / 2 + t, zm - t / 2), (xi, d / 2, zm + t / 2)), slot, convex=True))
        divider(0.0)
        for k, (x0, x1) in enumerate(((-xi, -t / 2), (t / 2, xi))):
            cell(f"cubby_{k}_low", x0, x1, zb, zm - t / 2)
            cell(f"cubby_{k}_high", x0, x1, zm + t / 2, zt)
        desc = "low TV unit with four open cubbies"
    else:
        ws = round(w * 0.28, 3)
        divider(-w / 2 + ws)
        divider(w / 2 - ws)
        xc0, xc1 = -w / 2 + ws + t / 2, w / 2 - ws - t / 2
        zm = round((zb + zt) / 2, 3)
        parts.append(Part(g.box_at((xc0, -d / 2 + t, zm - t / 2), (xc1, d / 2, zm + t / 2)), slot, convex=True))
        cell("centre_low", xc0, xc1, zb, zm - t / 2)
        cell("centre_high", xc0, xc1, zm + t / 2, zt)
        for side, hinge in ((-1, "left"), (1, "right")):
            x0, x1 = sorted((side * (w / 2 - 0.002), side * (w / 2 - ws + t / 2 + 0.002)))
            name = "door_left" if side < 0 else "door_right"
            link, joint = hinged_door(name, "base", x0, x1, d / 2, z0 + 0.004, h - 0.004, hinge, slot, thickness=0.018,
                                      mass=1.5, vertical_handle=True)
            links.append(link)
            joints.append(joint)
            xa, xb = sorted((side * xi, side * (w / 2 - ws + t / 2)))
            regions.append(Region(f"cabinet_{'left' if side < 0 else 'right'}", "volume",
                                  ((xa + xb) / 2, cy, (zb + zt) / 2), (xb - xa - 0.02, inner_d - 0.04, zt - zb - 0.01),
                                  requires_open=joint.name))
        desc = "TV stand with cabinet doors either side of an open centre"
    return _spec("TVStand", v, parts, 25.0, regions, desc, links, joints)


# ------------------------------------------------------------------------------------------------ shelf

def _levels(z_bottom: float, z_top: float, n: int) -> list[float]:
    """n shelf-board tops evenly spaced from z_bottom to z_top (inclusive)."""
    return [round(float(z), 3) for z in np.linspace(z_bottom, z_top, n)]


@register("Shelf", variants=6, category="furniture")
def shelf(v: int, rng: np.random.Generator) -> AssetSpec:
    """A shelving unit with 3-5 levels; every level declares a surface region with its free clearance.

    Variants: tall five-level bookcase, low two-column bookcase, metal wire rack, ladder shelf with
    shelves narrowing upwards, small wall shelf unit, 3x3 cube organiser.
    """
    parts: list[Part] = []
    regions: list[Region] = []
    t = 0.02
    if v in (0, 1, 4):
        w, d, h, n, slot, mass = [
            (pick(rng, 0.8, 0.9), pick(rng, 0.3, 0.35), pick(rng, 1.8, 1.95), 4, "wood", 35.0),
            (pick(rng, 1.0, 1.2), pick(rng, 0.3, 0.35), pick(rng, 0.8, 0.9), 2, "painted", 25.0),
            (pick(rng, 0.6, 0.75), pick(rng, 0.2, 0.24), pick(rng, 0.7, 0.8), 3, "dark_wood", 20.0),
        ][(0, 1, 4).index(v)]
        z0 = 0.0 if v == 4 else 0.07
        parts += carcass(w, d, h - z0, t, slot, z0=z0)
        if z0:
            parts.append(Part(g.box_at((-w / 2 + t, d / 2 - 0.03, 0), (w / 2 - t, d / 2 - 0.01, z0)), slot,
                              convex=True))
            parts.append(Part(g.box_at((-w / 2, -d / 2, 0), (w / 2, -d / 2 + t, z0)), slot, convex=True))
            for sx in (-1, 1):
                x0, x1 = sorted((sx * w / 2, sx * (w / 2 - t)))
                parts.append(Part(g.box_at((x0, -d / 2, 0), (x1, d / 2, z0)), slot, convex=True))
        zs = _levels(z0 + t, h - t, n + 1)  # interior floor .. ceiling
        boards = zs[1:-1]
        for z in boards:
            parts.append(Part(g.box_at((-w / 2 + t, -d / 2 + t, z), (w / 2 - t, d / 2, z + t)), slot, convex=True))
        floors = [zs[0]] + [z + t for z in boards]
        ceilings = boards + [zs[-1]]
        columns = [(-w / 2 + t, w / 2 - t)]
        if v == 1:
            parts.append(Part(g.box_at((-t / 2, -d / 2 + t, z0 + t), (t / 2, d / 2, h - t)), slot, convex=True))
            columns = [(-w / 2 + t, -t / 2), (t / 2, w / 2 - t)]
        for i, (zf, zc) in enumerate(zip(floors, ceilings)):
            for k, (xa, xb) in enumerate(columns):
                name = f"level_{i}" if len(columns) == 1 else f"level_{i}_{k}"
                regions.append(surface(name, xb - xa, d - t, zf, zc - zf - 0.01, cx=(xa + xb) / 2, cy=t / 2,
                                       margin=0.02))
        regions.append(surface(f"level_{len(floors)}", w, d, h, 0.3 if v == 0 else 0.5, margin=0.02))
        desc = {0: "tall bookcase with five levels", 1: "low two-column bookcase with three levels",
                4: "small wall shelf unit with four levels"}[v]
    elif v == 2:
        w, d, h = pick(rng, 0.9, 1.2), pick(rng, 0.35, 0.45), pick(rng, 1.5, 1.8)
        mass = 20.0
        post = 0.013
        for sx in (-1, 1):
            for sy in (-1, 1):
                parts.append(Part(g.cylinder(post, h, (sx * (w / 2 - post), sy * (d / 2 - post), h / 2), sections=10),
                                  "metal", convex=True))
        zs = _levels(0.12, h - 0.02, 5)
        for z in zs:
            parts.append(Part(g.box_at((-w / 2 + 0.004, -d / 2 + 0.004, z - 0.012), (w / 2 - 0.004, d / 2 - 0.004, z)),
                              "metal", convex=True))
            for sy in (-1, 1):  # folded front and back lips
                parts.append(Part(g.box_at((-w / 2 + 0.004, sy * (d / 2 - 0.004) - 0.004, z - 0.035),
                                           (w / 2 - 0.004, sy * (d / 2 - 0.004) + 0.004, z)), "metal", convex=True))
        for i, z in enumerate(zs):
            clear = zs[i + 1] - 0.035 - z - 0.01 if i + 1 < len(zs) else 0.4
            regions.append(surface(f"level_{i}", w, d, z, clear, margin=0.025))
        desc = "metal wire shelving rack with five levels"
    elif v == 3:
        w, h = pick(rng, 0.6, 0.75), pick(rng, 1.6, 1.8)
        d0, d1 = pick(rng, 0.42, 0.48), 0.2  # depth at the floor and at the top
        mass = 20.0
        yb = -d0 / 2
        rail = 0.035
        for sx in (-1, 1):
            x0, x1 = sorted((sx * w / 2, sx * (w / 2 - rail)))
            side = [(x, y, z) for x in (x0, x1) for y, z in ((yb, 0), (yb + rail, 0), (yb, h), (yb + rail, h))]
            parts.append(Part(g.hull(side), "wood", convex=True))
            front = [(x, y, z) for x in (x0, x1)
                     for y, z in ((yb + d0 - rail, 0), (yb + d0, 0), (yb + d1 - rail, h), (yb + d1, h))]
            parts.append(Part(g.hull(front), "wood", convex=True))
        zs = _levels(0.22, h - 0.05, 4)
        for z in zs:
            depth = d0 + (d1 - d0) * z / h
            parts.append(Part(g.box_at((-w / 2 + rail, yb, z - t), (w / 2 - rail, yb + depth - rail / 2, z)), "wood",
                              convex=True))
            parts.append(Part(g.box_at((-w / 2 + rail, yb, z), (w / 2 - rail, yb + 0.012, z + 0.06)), "wood",
                              convex=True))
        parts.append(Part(g.box_at((-w / 2 + rail, yb + d0 - 0.05, 0.06), (w / 2 - rail, yb + d0 - 0.03, 0.1)), "wood",
                          convex=True))
        for i, z in enumerate(zs):
            depth = d0 + (d1 - d0) * z / h - rail / 2 - 0.012
            clear = zs[i + 1] - t - z - 0.01 if i + 1 < len(zs) else 0.3
            regions.append(surface(f"level_{i}", w - 2 * rail, depth, z, clear, cy=yb + 0.012 + depth / 2, margin=0.02))
        desc = "ladder shelf with four shelves narrowing towards the top"
    else:
        w, h, d = pick(rng, 1.05, 1.15), pick(rng, 1.05, 1.15), pick(rng, 0.36, 0.4)
        mass = 30.0
        parts += carcass(w, d, h, t, "painted")
        inner_w, inner_h = w - 2 * t, h - 2 * t
        cw, chh = (inner_w - 2 * t) / 3, (inner_h - 2 * t) / 3
        for k in (1, 2):
            x = -w / 2 + t + k * cw + (k - 0.5) * t
            parts.append(Part(g.box_at((x - t / 2, -d / 2 + t, t), (x + t / 2, d / 2, h - t)), "painted", convex=True))
            z = t + k * chh + (k - 1) * t
            parts.append(Part(g.box_at((-w / 2 + t, -d / 2 + t, z), (w / 2 - t, d / 2, z + t)), "painted", convex=True))
        for i in range(3):
            zf = t + i * (chh + t)
            for k in range(3):
                xa = -w / 2 + t + k * (cw + t)
                regions.append(surface(f"level_{i}_{k}", cw, d - t, zf, chh - 0.01, cx=xa + cw / 2, cy=t / 2,
                                       margin=0.02))
        regions.append(surface("level_3", w, d, h, 0.5, margin=0.02))
        desc = "3x3 cube organiser"
    return _spec("Shelf", v, parts, mass, regions, desc)
