"""Seating and beds: chairs, armchairs, sofas, ottomans, footstools, beds (furniture).

Upholstered pieces (armchairs, sofas) share one parametric body (`_Upholstery`): legs or a skirt, a seat
deck between the arms, a back frame, arms in several styles, seat cushions and tilted back cushions.
Everything collides as convex boxes, cylinders or hulls; an L-shaped sectional is two convex seat
decks side by side.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import corner_legs, pick, shift_footprint, surface
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Link, Part, Region

add_palettes(
    bed_duvet=hex_colours("f4f1ea", "dfe6ee", "2f3e5c", "c9d3c0", "e8d8c4", "8a8f99", "b86f52"),
    bed_sheet=hex_colours("fbfaf7", "eef1f4", "f3ece0"),
)


# ----------------------------------------------------------------------------------------------- helpers

def _leg_parts(style: str, pts, h: float, slot: str) -> list[Part]:
    """Short legs of upholstered furniture at the footprint points `pts` (style block/taper/metal/bun/turned)."""
    parts = []
    for x, y in pts:
        if style == "block":
            mesh = g.box((0.05, 0.05, h), (x, y, h / 2))
        elif style == "taper":
            mesh = g.frustum(0.013, 0.022, h, (x, y, 0), sections=10)
        elif style == "metal":
            mesh = g.cylinder(0.011, h, (x, y, h / 2), sections=10)
        elif style == "bun":
            mesh = g.revolve([(0, 0), (0.026, 0), (0.038, h * 0.45), (0.03, h), (0, h)], (x, y, 0), sections=12)
        else:
            mesh = g.turned_leg(x, y, h, 0.026)
        parts.append(Part(mesh, slot, convex=True))  # a turned leg collides as its hull
    return parts


def _pillow(size, center, lean: float, slot: str = "cushion") -> Part:
    """A pillow of extents `size` (x, y thickness, z), leaning back by `lean` radians about x.

    A squared-off sphere: square in x-z with rounded corners, thickest in the middle (convex).
    """
    mesh = trimesh.creation.icosphere(subdivisions=2)
    v = mesh.vertices.copy()
    for ax in (0, 2):
        v[:, ax] = np.sign(v[:, ax]) * np.abs(v[:, ax]) ** 0.45
    mesh = trimesh.Trimesh(v * (np.asarray(size, dtype=float) / 2), mesh.faces)
    return Part(g.transformed(mesh, roll=lean, offset=center), slot, convex=True)


# ------------------------------------------------------------------------------------------------ chair

BAR_STOOL = "bar_stool"
"""Tag of the Chair variants that are counter-height stools (ALFRED types the stools at AI2-THOR's kitchen
counters as Chair; CSSG draws these only for a chair at a counter, the others everywhere else)."""


@register("Chair", variants=8, category="furniture")
def chair(v: int, rng: np.random.Generator) -> AssetSpec:
    """A dining/desk chair: four legs, a seat and a back; or (variants 5-7) a counter-height bar stool.

    Variants: slatted back, solid panel back, ladder back with stretchers, metal tube chair, upholstered
    parsons chair with tapered legs; backless round stool on splayed legs with footrest rungs, square
    wooden stool with stretchers and a low back, swivel stool on a pedestal with a round base.
    """
    if v >= 5:
        return _bar_stool(v, rng)
    w, d = pick(rng, 0.42, 0.5), pick(rng, 0.42, 0.5)
    seat_h = pick(rng, 0.44, 0.48)
    back_h = pick(rng, 0.4, 0.5)
    t = 0.035
    slot = ["wood", "dark_wood", "painted", "metal", "dark_wood"][v]
    back_y = -d / 2 + 0.03
    if v == 4:  # parsons: tapered legs, thick padded seat, tall padded back
        parts = []
        for sx in (-1, 1):
            for sy in (-1, 1):
                foot = (sx * (w / 2 - 0.035), sy * (d / 2 - 0.035), 0)
                parts.append(Part(g.frustum(0.014, 0.02, seat_h - 0.08, foot),
                                  slot, convex=True))
        parts.append(Part(g.soft_box_at((-w / 2, -d / 2, seat_h - 0.09), (w / 2, d / 2, seat_h), 0.02), "fabric",
                          convex=True))
        parts.append(Part(g.soft_box_at((-w / 2, -d / 2, seat_h - 0.01), (w / 2, -d / 2 + 0.07, seat_h + back_h + 0.1),
                                        0.02), "fabric", convex=True))
        return AssetSpec(
            "Chair", v, "furniture", [Link("base", parts, 5.0)],
            regions=[surface("seat", w, d - 0.07, seat_h, 0.4, cy=0.035)],
            description="upholstered parsons dining chair on tapered wooden legs",
        )
    parts = corner_legs(w, d, seat_h - t, 0.03, 0.018, slot, square=v in (0, 1))
    parts.append(Part(g.box((w, d, t), (0, 0, seat_h - t / 2)), "cushion" if v == 2 else slot))
    for sx in (-1, 1):  # back posts continue the rear legs
        x = sx * (w / 2 - 0.03)
        if v == 3:
            post = g.cylinder(0.018, back_h, (x, back_y, seat_h + back_h / 2), sections=10)
        else:
            post = g.box((0.036, 0.036, back_h), (x, back_y, seat_h + back_h / 2))
        parts.append(Part(post, slot))
    if v == 0:  # vertical slats under a top rail
        for x in np.linspace(-w / 2 + 0.1, w / 2 - 0.1, 4):
            parts.append(Part(g.box((0.03, 0.018, back_h * 0.7), (x, back_y, seat_h + back_h * 0.45)), slot))
        parts.append(Part(g.box((w - 0.04, 0.025, 0.06), (0, back_y, seat_h + back_h - 0.03)), slot))
    elif v == 2:  # ladder back, turned stretchers between the legs
        for z in np.linspace(seat_h + 0.12, seat_h + back_h - 0.04, 3):
            parts.append(Part(g.box((w - 0.06, 0.02, 0.05), (0, back_y, z)), slot))
        for sx in (-1, 1):
            parts.append(Part(g.cylinder(0.01, d - 0.06, (sx * (w / 2 - 0.03), 0, 0.16), axis="y", sections=8), slot))
        parts.append(Part(g.cylinder(0.01, w - 0.06, (0, 0, 0.22), axis="x", sections=8), slot))
    elif v == 3:  # bent-tube look: rounded top rail and a curved-looking panel
        parts.append(Part(g.cylinder(0.018, w - 0.06, (0, back_y, seat_h + back_h), axis="x", sections=10), slot))
        parts.append(Part(g.box((w - 0.07, 0.02, back_h * 0.45), (0, back_y, seat_h + back_h * 0.68)), "dark_plastic"))
    else:  # solid panel
        parts.append(Part(g.box((w - 0.05, 0.025, back_h * 0.75), (0, back_y, seat_h + back_h * 0.55)), slot))
    return AssetSpec(
        "Chair", v, "furniture", [Link("base", parts, 5.0)],
        regions=[surface("seat", w, d - 0.05, seat_h, 0.4, cy=0.025)],
        description="chair with four legs, a seat and a back",
    )


def _bar_stool(v: int, rng: np.random.Generator) -> AssetSpec:
    """A stool for a kitchen counter (about 0.9 m): seat at 0.62-0.68 m, a footrest about 0.25 m up."""
    seat_h = pick(rng, 0.62, 0.68)
    foot_h = pick(rng, 0.22, 0.27)
    parts: list[Part] = []
    if v == 5:  # round seat on four splayed legs, rungs between them as a footrest
        r = pick(rng, 0.16, 0.19)
        spread = r + pick(rng, 0.04, 0.07)
        at_rung = spread + (0.6 * r - spread) * foot_h / (seat_h - 0.04)  # the legs' distance out at the rungs
        rungs = []
        for k in range(4):
            a = np.pi / 4 + k * np.pi / 2
            top = (0.6 * r * np.cos(a), 0.6 * r * np.sin(a), seat_h - 0.04)
            foot = (spread * np.cos(a), spread * np.sin(a), 0.0)
            parts.append(Part(g.splayed_leg(top, foot, 0.016, 0.013), "metal", convex=True))
            rungs.append((at_rung * np.cos(a), at_rung * np.sin(a), foot_h))
        for k in range(4):
            parts.append(Part(g.rod(rungs[k], rungs[(k + 1) % 4], 0.009), "metal", convex=True))
        parts.append(Part(g.cylinder(r, 0.04, (0, 0, seat_h - 0.02), sections=24), "wood", convex=True))
        region = surface("seat", 1.4 * r, 1.4 * r, seat_h, 0.4, margin=0.0)
        desc, mass = "backless round bar stool on splayed metal legs with rungs as a footrest", 4.0
    elif v == 6:  # square wooden stool, stretchers all round, a low back
        w = pick(rng, 0.36, 0.42)
        t = 0.035
        parts += corner_legs(w, w, seat_h - t, 0.025, 0.017, "wood", square=True)
        for sy in (-1, 1):  # footrest at the front and back, side stretchers a little higher
            parts.append(Part(g.box((w - 0.05, 0.022, 0.03), (0, sy * (w / 2 - 0.025), foot_h)), "wood", convex=True))
        for sx in (-1, 1):
            parts.append(Part(g.box((0.022, w - 0.05, 0.03), (sx * (w / 2 - 0.025), 0, foot_h + 0.1)), "wood",
                              convex=True))
        parts.append(Part(g.box((w, w, t), (0, 0, seat_h - t / 2)), "wood", convex=True))
        back_y, back_h = -w / 2 + 0.02, pick(rng, 0.2, 0.26)
        for sx in (-1, 1):
            parts.append(Part(g.box((0.034, 0.034, back_h), (sx * (w / 2 - 0.025), back_y, seat_h + back_h / 2)),
                              "wood", convex=True))
        parts.append(Part(g.box((w - 0.02, 0.025, 0.07), (0, back_y, seat_h + back_h - 0.035)), "wood", convex=True))
        region = surface("seat", w, w - 0.04, seat_h, 0.4, cy=0.02)
        desc, mass = "square wooden bar stool with stretchers and a low back", 5.0
    else:  # swivel stool: round base, a column, a footrest ring and a padded seat
        r = pick(rng, 0.17, 0.2)
        base = pick(rng, 0.2, 0.23)
        parts.append(Part(g.frustum(base, base * 0.8, 0.03, sections=24), "metal", convex=True))
        parts.append(Part(g.cylinder(0.03, seat_h - 0.1, (0, 0, 0.03 + (seat_h - 0.1) / 2), sections=14), "metal",
                          convex=True))
        parts.append(Part(g.torus_ring(pick(rng, 0.15, 0.18), 0.01, (0, 0, foot_h)), "metal", collide=False))
        for a in (0.0, np.pi / 2):  # the footrest's spokes
            dx, dy = np.cos(a), np.sin(a)
            parts.append(Part(g.rod((-0.16 * dx, -0.16 * dy, foot_h), (0.16 * dx, 0.16 * dy, foot_h), 0.008),
                              "metal", collide=False))
        prof = [(0, 0), (r * 0.55, 0), (r, 0.02), (r, 0.06), (r * 0.9, 0.075), (0, 0.08)]
        parts.append(Part(g.revolve(prof, (0, 0, seat_h - 0.08), sections=24), "leather", convex=True))
        region = surface("seat", 1.4 * r, 1.4 * r, seat_h, 0.4, margin=0.0)
        desc, mass = "swivel bar stool with a padded seat on a pedestal with a round base", 7.0
    return AssetSpec("Chair", v, "furniture", [Link("base", parts, mass)], regions=[region], description=desc,
                     tags=[BAR_STOOL])


# ------------------------------------------------------------------------------------ upholstered body

@dataclass
class _Upholstery:
    """Parameters of an upholstered armchair or sofa (metres)."""

    w: float
    d: float
    seat_h: float  # top of the seat cushions
    arm_h: float
    back_h: float  # top of the back frame
    arm_w: float
    back_t: float  # back frame thickness
    leg_h: float  # 0: skirted down to the floor
    seats: int  # seat cushions across
    backs: int  # back cushions across (0: tight back)
    arm: str = "box"  # box, roll, slope, open (wooden armrests)
    legs: str = "taper"  # block, taper, metal, bun, turned
    cover: str = "fabric"
    leg_slot: str = "wood"
    cushion_slot: str | None = None
    cush_t: float = 0.13
    back_cush: float = 0.16
    back_cush_top: float = -0.03  # back cushion top relative to the back frame top
    chaise: float = 0.0  # L-shape: the right-hand seat runs this much further forward
    wings: bool = False
    pillows: int = 0


def _upholstered(s: _Upholstery) -> tuple[list[Part], list[Region]]:
    """Parts and seat regions of an armchair/sofa, centred on its footprint."""
    parts: list[Part] = []
    cover, cush = s.cover, s.cushion_slot or s.cover
    y0, y1 = -s.d / 2, s.d / 2
    yc = y1 + s.chaise  # front of the right-hand (chaise) seat
    z0 = s.leg_h
    deck = s.seat_h - s.cush_t
    aw = s.arm_w
    inner = s.w - 2 * aw
    seat_w = inner / s.seats
    open_arms = s.arm == "open"
    body = s.leg_slot if open_arms else cover
    # legs (or a skirt)
    if s.leg_h > 0:
        i = 0.05
        pts = [(-s.w / 2 + i, y0 + i), (s.w / 2 - i, y0 + i), (-s.w / 2 + i, y1 - i), (s.w / 2 - i, yc - i)]
        if s.chaise:
            pts.append((s.w / 2 - aw - seat_w + i, yc - i))
        if s.w > 1.7:
            pts += [(0.0, y0 + i), (0.0 if not s.chaise else -seat_w / 2, y1 - i)]
        parts += _leg_parts(s.legs, pts, s.leg_h, s.leg_slot)
    else:
        kick = 0.11  # skirt panels, slightly proud of the body
        parts.append(Part(g.box_at((-s.w / 2 - 0.006, y1 - 0.01, 0.005), (s.w / 2 + 0.006, y1 + 0.006, kick)), cover,
                          collide=False))
        for sx in (-1, 1):
            x_out = sx * (s.w / 2 + 0.006)
            parts.append(Part(g.box_at((min(x_out, sx * s.w / 2), y0, 0.005), (max(x_out, sx * s.w / 2), yc, kick)),
                              cover, collide=False))
    # seat deck between the arms (and the chaise extension)
    parts.append(Part(g.soft_box_at((-s.w / 2 + aw, y0 + s.back_t - 0.01, z0), (s.w / 2 - aw, y1, deck), 0.015), body,
                      convex=True))
    if s.chaise:
        parts.append(Part(g.soft_box_at((s.w / 2 - aw - seat_w, y1 - 0.02, z0), (s.w / 2 - aw, yc, deck), 0.015), body,
                          convex=True))
    # back frame
    if open_arms:
        for sx in (-1, 1):
            x = sx * (s.w / 2 - aw / 2)
            parts.append(Part(g.box_at((x - 0.025, y0, z0), (x + 0.025, y0 + s.back_t, s.back_h)), body, convex=True))
        parts.append(Part(g.box_at((-s.w / 2, y0, s.back_h - 0.07), (s.w / 2, y0 + s.back_t, s.back_h)), body,
                          convex=True))
        parts.append(Part(g.box_at((-s.w / 2 + aw, y0 + 0.01, deck), (s.w / 2 - aw, y0 + s.back_t, s.back_h - 0.07)),
                          cover, convex=True))
    else:
        parts.append(Part(g.soft_box_at((-s.w / 2, y0, z0), (s.w / 2, y0 + s.back_t, s.back_h), 0.03), cover,
                          convex=True))
    # arms
    for sx in (-1, 1):
        ya = yc if (sx > 0 and s.chaise) else y1
        xo, xi = sx * s.w / 2, sx * (s.w / 2 - aw)
        xlo, xhi = min(xo, xi), max(xo, xi)
        yb = y0 + s.back_t - 0.01
        if open_arms:  # wooden armrest on a front post, side rail at deck level
            xm = (xlo + xhi) / 2
            parts.append(Part(g.box_at((xm - 0.025, ya - 0.07, z0), (xm + 0.025, ya - 0.02, s.arm_h - 0.03)), body,
                              convex=True))
            parts.append(Part(g.soft_box_at((xlo, yb, s.arm_h - 0.035), (xhi, ya, s.arm_h), 0.008), body, convex=True))
            parts.append(Part(g.box_at((xm - 0.02, yb, z0), (xm + 0.02, ya - 0.07, deck)), body, convex=True))
        elif s.arm == "roll":
            r = aw * 0.58
            xm = (xlo + xhi) / 2 + sx * aw * 0.06
            parts.append(Part(g.soft_box_at((xlo, yb, z0), (xhi, ya, s.arm_h - r), 0.02), cover, convex=True))
            parts.append(Part(g.cylinder(r, ya - yb, (xm, (ya + yb) / 2, s.arm_h - r), axis="y", sections=16), cover,
                              convex=True))
        elif s.arm == "slope":  # top slopes down towards the front
            drop = 0.07
            pts = [(x, y, z) for x in (xlo, xhi) for y, z in ((yb, z0), (ya, z0), (yb, s.arm_h), (ya, s.arm_h - drop))]
            pts += [(x, ya - 0.04, s.arm_h - drop + 0.01) for x in (xlo + 0.02, xhi - 0.02)]
            parts.append(Part(g.hull(pts), cover, convex=True))
        else:
            parts.append(Part(g.soft_box_at((xlo, yb, z0), (xhi, ya, s.arm_h), 0.025), cover, convex=True))
    # wings of a wingback chair: panels above the arms, wide at the top
    if s.wings:
        for sx in (-1, 1):
            xo, xi = sx * s.w / 2, sx * (s.w / 2 - 0.08)
            yb = y0 + s.back_t - 0.01
            pts = []
            for x in (xo, xi):
                pts += [(x, yb, s.arm_h - 0.02), (x, yb + 0.3, s.arm_h - 0.02), (x, yb + 0.3, s.arm_h + 0.22),
                        (x, yb + 0.22, s.back_h - 0.06), (x, yb, s.back_h)]
            parts.append(Part(g.hull(pts), cover, convex=True))
    # back cushions, leaning back a little
    seat_back = y0 + s.back_t
    if s.backs:
        lean = np.radians(10)
        bw = inner / s.backs
        bh = s.back_h + s.back_cush_top - deck
        for k in range(s.backs):
            cx = -inner / 2 + bw * (k + 0.5)
            mesh = g.transformed(g.soft_box((bw - 0.008, s.back_cush, bh), r=0.035), roll=lean)
            lo, hi = mesh.bounds
            mesh.apply_translation((cx, y0 + s.back_t - 0.01 - lo[1], deck - lo[2]))
            parts.append(Part(mesh, cush, convex=True))
            seat_back = y0 + s.back_t - 0.01 + (hi[1] - lo[1]) - 0.02
    # seat cushions
    for k in range(s.seats):
        xa = -inner / 2 + seat_w * k + 0.004
        xb = xa + seat_w - 0.008
        ya = yc if (k == s.seats - 1 and s.chaise) else y1
        parts.append(Part(g.soft_box_at((xa, seat_back, deck), (xb, ya + 0.01, s.seat_h), 0.035), cush, convex=True))
    # a flat board just under the cushion tops, so that things put on the seat do not sink into the seams
    parts.append(Part(g.box_at((-inner / 2 + 0.01, seat_back + 0.02, deck), (inner / 2 - 0.01, y1 - 0.03,
                                                                           s.seat_h - 0.004)), cush, convex=True))
    # throw pillows at the ends
    for k in range(s.pillows):
        sx = -1 if k % 2 == 0 else 1
        size = 0.42 if inner > 1.0 else 0.36
        x = sx * (inner / 2 - size / 2 - 0.03)
        parts.append(_pillow((size, 0.13, size), (x, seat_back + 0.09, s.seat_h + size / 2 - 0.03), np.radians(14)))
    if s.pillows:  # the seat region starts in front of the throw pillows
        seat_back += 0.17
    regions = [surface("seat", inner, y1 - seat_back, s.seat_h, 0.35, cy=(y1 + seat_back) / 2)]
    if s.chaise:
        regions[0] = surface("seat", inner - seat_w, y1 - seat_back, s.seat_h, 0.35, cx=-seat_w / 2,
                             cy=(y1 + seat_back) / 2)
        regions.append(surface("chaise", seat_w, yc - seat_back, s.seat_h, 0.35, cx=s.w / 2 - aw - seat_w / 2,
                               cy=(yc + seat_back) / 2))
    if s.chaise:
        shift_footprint(parts, regions, 0.0, -s.chaise / 2)
    return parts, regions


# --------------------------------------------------------------------------------------------- armchair

@register("ArmChair", variants=5, category="furniture")
def armchair(v: int, rng: np.random.Generator) -> AssetSpec:
    """An upholstered armchair: arms, a back, a seat cushion and legs or a skirt.

    Variants: skirted leather club chair with rolled arms, mid-century chair on tapered legs with slim
    arms, wingback on turned legs, wooden-frame chair with open armrests, wide modern box chair.
    """
    seat_h = pick(rng, 0.43, 0.47)
    if v == 0:
        s = _Upholstery(pick(rng, 0.86, 0.95), pick(rng, 0.86, 0.92), seat_h, pick(rng, 0.6, 0.64),
                        pick(rng, 0.76, 0.8),
                        0.17, 0.17, 0.0, 1, 1, arm="roll", cover="leather")
        desc = "leather club armchair with rolled arms and a skirted base"
    elif v == 1:
        s = _Upholstery(pick(rng, 0.72, 0.8), pick(rng, 0.78, 0.84), seat_h, pick(rng, 0.6, 0.64), pick(rng, 0.8, 0.86),
                        0.075, 0.12, 0.17, 1, 1, legs="taper", cush_t=0.11)
        desc = "mid-century armchair with slim arms on tapered wooden legs"
    elif v == 2:
        s = _Upholstery(pick(rng, 0.78, 0.84), pick(rng, 0.82, 0.88), seat_h, pick(rng, 0.6, 0.64),
                        pick(rng, 1.05, 1.12), 0.12, 0.14, 0.12, 1, 1, arm="roll", legs="turned", leg_slot="dark_wood",
                        wings=True, back_cush=0.12)
        desc = "wingback armchair on turned legs"
    elif v == 3:
        s = _Upholstery(pick(rng, 0.7, 0.76), pick(rng, 0.76, 0.82), seat_h, pick(rng, 0.6, 0.64), pick(rng, 0.8, 0.86),
                        0.07, 0.06, 0.26, 1, 1, arm="open", legs="block", cushion_slot="cushion", cush_t=0.1,
                        back_cush=0.12, back_cush_top=-0.1)
        desc = "wooden-frame armchair with open armrests and loose cushions"
    else:
        s = _Upholstery(pick(rng, 0.92, 1.0), pick(rng, 0.88, 0.94), seat_h, pick(rng, 0.58, 0.62),
                        pick(rng, 0.72, 0.76),
                        0.2, 0.16, 0.07, 1, 1, legs="metal", leg_slot="dark_metal", back_cush_top=0.04)
        desc = "wide modern box armchair on low metal feet"
    parts, regions = _upholstered(s)
    return AssetSpec("ArmChair", v, "furniture", [Link("base", parts, 20.0)], regions=regions, description=desc)


# ------------------------------------------------------------------------------------------------- sofa

@register("Sofa", variants=6, category="furniture")
def sofa(v: int, rng: np.random.Generator) -> AssetSpec:
    """A sofa: arms, a back with back cushions, seat cushions.

    Variants: 2-seat loveseat on tapered legs, classic 3-seater with rolled arms, low modern leather
    sofa with a bench cushion, L-shaped sectional with a chaise, skirted 2-seat tight-back sofa, 3-seat
    pillow-back sofa with sloped arms.
    """
    seat_h = pick(rng, 0.42, 0.46)
    mass = 40.0
    if v == 0:
        s = _Upholstery(pick(rng, 1.5, 1.65), pick(rng, 0.86, 0.92), seat_h, pick(rng, 0.6, 0.64),
                        pick(rng, 0.82, 0.88),
                        0.16, 0.16, 0.14, 2, 2, legs="taper", pillows=2)
        desc = "two-seat loveseat with box arms on tapered legs"
    elif v == 1:
        s = _Upholstery(pick(rng, 2.0, 2.2), pick(rng, 0.9, 0.96), seat_h, pick(rng, 0.62, 0.66), pick(rng, 0.86, 0.92),
                        0.2, 0.17, 0.1, 3, 3, arm="roll", legs="bun", leg_slot="dark_wood", pillows=2)
        desc, mass = "classic three-seat sofa with rolled arms", 50.0
    elif v == 2:
        s = _Upholstery(pick(rng, 2.1, 2.3), pick(rng, 0.92, 0.98), seat_h - 0.02, pick(rng, 0.54, 0.58),
                        pick(rng, 0.74, 0.78), 0.09, 0.15, 0.13, 1, 2, legs="metal", leg_slot="metal", cover="leather",
                        cush_t=0.12)
        desc, mass = "low modern leather sofa with a bench seat cushion on metal legs", 50.0
    elif v == 3:
        s = _Upholstery(pick(rng, 2.4, 2.6), pick(rng, 0.92, 0.98), seat_h, pick(rng, 0.6, 0.64), pick(rng, 0.84, 0.9),
                        0.15, 0.17, 0.1, 3, 3, legs="block", leg_slot="dark_wood", chaise=pick(rng, 0.6, 0.7),
                        pillows=2)
        desc, mass = "L-shaped sectional sofa with a chaise on the right", 60.0
    elif v == 4:
        s = _Upholstery(pick(rng, 1.7, 1.8), pick(rng, 0.86, 0.92), seat_h, pick(rng, 0.7, 0.74), pick(rng, 0.74, 0.78),
                        0.2, 0.22, 0.0, 2, 0, arm="roll", cover="leather")
        desc, mass = "skirted two-seat tight-back sofa with high rolled arms", 42.0
    else:
        s = _Upholstery(pick(rng, 2.0, 2.2), pick(rng, 0.94, 1.0), seat_h, pick(rng, 0.6, 0.64), pick(rng, 0.78, 0.82),
                        0.18, 0.16, 0.0, 3, 3, arm="slope", back_cush=0.2, back_cush_top=0.1, pillows=2)
        desc, mass = "three-seat pillow-back sofa with sloped arms on a skirted base", 55.0
    parts, regions = _upholstered(s)
    return AssetSpec("Sofa", v, "furniture", [Link("base", parts, mass)], regions=regions, description=desc)


# ---------------------------------------------------------------------------------------------- ottoman

@register("Ottoman", variants=5, category="furniture")
def ottoman(v: int, rng: np.random.Generator) -> AssetSpec:
    """An ottoman: an upholstered block or a round pouf with a padded top.

    Variants: rectangular ottoman on tapered legs, round pouf, skirted cube, long tufted bench on turned
    legs, large round drum on a recessed plinth.
    """
    parts: list[Part] = []
    h = pick(rng, 0.4, 0.46)
    if v == 0:
        w, d = pick(rng, 0.75, 0.85), pick(rng, 0.5, 0.58)
        legs = 0.1
        parts += _leg_parts("taper", [(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05)) for sx in (-1, 1) for sy in (-1, 1)],
                            legs, "wood")
        parts.append(Part(g.soft_box_at((-w / 2, -d / 2, legs), (w / 2, d / 2, h - 0.08), 0.015), "fabric",
                          convex=True))
        parts.append(Part(g.soft_box_at((-w / 2, -d / 2, h - 0.09), (w / 2, d / 2, h), 0.04), "fabric", convex=True))
        rw, rd, desc = w, d, "rectangular upholstered ottoman on tapered legs"
    elif v == 1:
        r = pick(rng, 0.24, 0.29)
        prof = [(0, 0), (r * 0.86, 0), (r * 0.98, h * 0.15), (r, h * 0.5), (r * 0.97, h * 0.8), (r * 0.85, h * 0.96),
                (r * 0.5, h), (0, h)]
        parts.append(Part(g.revolve(prof, sections=20), "leather" if rng.random() < 0.5 else "fabric", convex=True))
        parts.append(Part(g.cylinder(r * 1.006, 0.012, (0, 0, h * 0.5), sections=20), "dark_plastic", collide=False))
        rw = rd = r * 1.3
        desc = "round pouf"
    elif v == 2:
        w = pick(rng, 0.45, 0.55)
        parts.append(Part(g.soft_box_at((-w / 2, -w / 2, 0), (w / 2, w / 2, h - 0.07), 0.012), "fabric", convex=True))
        parts.append(Part(g.soft_box_at((-w / 2 - 0.01, -w / 2 - 0.01, h - 0.08), (w / 2 + 0.01, w / 2 + 0.01, h),
                                        0.035),
                          "fabric", convex=True))
        parts.append(Part(g.box_at((-w / 2 - 0.005, -w / 2 - 0.005, 0.0), (w / 2 + 0.005, w / 2 + 0.005, 0.1)),
                          "fabric", collide=False))
        rw = rd = w
        desc = "skirted cube ottoman"
    elif v == 3:
        w, d = pick(rng, 1.05, 1.2), pick(rng, 0.42, 0.48)
        legs = 0.16
        for sx in (-1, 1):
            for sy in (-1, 1):
                parts.append(Part(g.turned_leg(sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), legs + 0.02, 0.025),
                                  "dark_wood",
                                  convex=True))
        parts.append(Part(g.box_at((-w / 2 + 0.01, -d / 2 + 0.01, legs), (w / 2 - 0.01, d / 2 - 0.01, legs + 0.08)),
                          "dark_wood", convex=True))
        parts.append(Part(g.soft_box_at((-w / 2, -d / 2, legs + 0.08), (w / 2, d / 2, h), 0.045), "leather",
                          convex=True))
        for x in np.linspace(-w / 2 + 0.15, w / 2 - 0.15, 5):  # tufting buttons
            for y in (-d / 6, d / 6):
                parts.append(Part(g.sphere(0.012, (x, y, h - 0.004), subdivisions=0), "leather", collide=False))
        rw, rd, desc = w, d, "long tufted bench ottoman on turned legs"
    else:
        r = pick(rng, 0.36, 0.42)
        parts.append(Part(g.cylinder(r * 0.85, 0.06, (0, 0, 0.03), sections=20), "dark_wood", convex=True))
        parts.append(Part(g.cylinder(r, h - 0.16, (0, 0, 0.06 + (h - 0.16) / 2), sections=24), "fabric", convex=True))
        top = [(0, 0), (r + 0.01, 0), (r + 0.01, 0.07), (r * 0.93, 0.1), (0, 0.1)]
        parts.append(Part(g.revolve(top, (0, 0, h - 0.1), sections=24), "cushion", convex=True))
        rw = rd = r * 1.35
        desc = "large round drum ottoman with a padded top on a plinth"
    return AssetSpec(
        "Ottoman", v, "furniture", [Link("base", parts, [9.0, 5.0, 6.0, 12.0, 14.0][v])],
        regions=[surface("top", rw, rd, h, 0.4, margin=0.05)], description=desc,
    )


# -------------------------------------------------------------------------------------------- footstool

@register("Footstool", variants=4, category="furniture")
def footstool(v: int, rng: np.random.Generator) -> AssetSpec:
    """A small stool to rest the feet or step on.

    Variants: padded footstool on turned legs, two-step wooden step stool, three-legged round milking
    stool, low square footstool with a padded top on splayed legs with stretchers.
    """
    parts: list[Part] = []
    if v == 0:
        w, d, h = pick(rng, 0.4, 0.48), pick(rng, 0.3, 0.36), pick(rng, 0.28, 0.33)
        legs = h - 0.12
        for sx in (-1, 1):
            for sy in (-1, 1):
                leg = g.turned_leg(sx * (w / 2 - 0.04), sy * (d / 2 - 0.04), legs + 0.01, 0.02)
                parts.append(Part(leg, "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2, -d / 2, legs), (w / 2, d / 2, legs + 0.04)), "wood", convex=True))
        parts.append(Part(g.soft_box_at((-w / 2 + 0.005, -d / 2 + 0.005, legs + 0.04), (w / 2 - 0.005, d / 2 - 0.005,
                                                                                        h),
                                        0.03), "fabric", convex=True))
        mass, desc = 3.0, "padded footstool on turned wooden legs"
    elif v == 1:
        w, d, h = pick(rng, 0.38, 0.44), pick(rng, 0.36, 0.42), pick(rng, 0.42, 0.46)
        t, step = 0.02, h / 2
        for sx in (-1, 1):  # side panels: full depth at the floor, stepping back to the top tread
            x0, x1 = sorted((sx * w / 2, sx * (w / 2 - t)))
            prof = [(-d / 2, 0), (d / 2, 0), (d / 2 - 0.03, step - t), (0.0, step - t), (-0.03, h - t), (-d / 2, h - t)]
            lower = [(x, y, z) for x in (x0, x1) for y, z in prof[:4]]
            upper = [(x, y, z) for x in (x0, x1) for y, z in ((-d / 2, step - t - 0.01), (0.02, step - t - 0.01),
                                                             (-0.03, h - t), (-d / 2, h - t))]
            parts.append(Part(g.hull(lower + [(x, -d / 2, step - t) for x in (x0, x1)]), "wood", convex=True))
            parts.append(Part(g.hull(upper), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2, -0.005, step - t), (w / 2, d / 2 - 0.01, step)), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2, -d / 2, h - t), (w / 2, 0.0, h)), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2 + t, -d / 2, 0.06), (w / 2 - t, -d / 2 + t, 0.14)), "wood", convex=True))
        parts.append(Part(g.box_at((-w / 2 + t, -d / 2, h - t - 0.08), (w / 2 - t, -d / 2 + t, h - t)), "wood",
                          convex=True))
        parts.append(Part(g.box_at((-w / 2 + t, d / 2 - 0.05, 0.05), (w / 2 - t, d / 2 - 0.03, 0.12)), "wood",
                          convex=True))
        mass, desc = 3.5, "two-step wooden step stool"
    elif v == 2:
        r, h = pick(rng, 0.14, 0.17), pick(rng, 0.26, 0.32)
        parts.append(Part(g.cylinder(r, 0.035, (0, 0, h - 0.0175), sections=20), "wood", convex=True))
        for k in range(3):
            a = 2 * np.pi * k / 3 + np.pi / 2
            top = (0.6 * r * np.cos(a), 0.6 * r * np.sin(a), h - 0.03)
            foot = (1.15 * r * np.cos(a), 1.15 * r * np.sin(a), 0.0)
            parts.append(Part(g.splayed_leg(top, foot, 0.017, 0.012), "wood", convex=True))
        mass, desc = 2.0, "three-legged round milking stool"
    else:
        w, h = pick(rng, 0.34, 0.4), pick(rng, 0.32, 0.37)
        parts.append(Part(g.box_at((-w / 2, -w / 2, h - 0.06), (w / 2, w / 2, h - 0.03)), "painted", convex=True))
        parts.append(Part(g.soft_box_at((-w / 2 + 0.01, -w / 2 + 0.01, h - 0.035), (w / 2 - 0.01, w / 2 - 0.01, h),
                                        0.015),
                          "cushion", convex=True))
        splay = 0.04
        feet = []
        for sx in (-1, 1):
            for sy in (-1, 1):
                top = (sx * (w / 2 - 0.04), sy * (w / 2 - 0.04), h - 0.06)
                foot = (sx * (w / 2 - 0.04 + splay), sy * (w / 2 - 0.04 + splay), 0.0)
                feet.append((top, foot))
                parts.append(Part(g.splayed_leg(top, foot, 0.016, 0.013), "painted", convex=True))
        zr = h * 0.3  # stretchers a third of the way up
        f = 1 - zr / (h - 0.06)
        ring = [(t[0] + (ft[0] - t[0]) * f, t[1] + (ft[1] - t[1]) * f) for t, ft in feet]
        ring = [ring[0], ring[1], ring[3], ring[2]]
        for k in range(4):
            a, b = ring[k], ring[(k + 1) % 4]
            parts.append(Part(g.rod((a[0], a[1], zr), (b[0], b[1], zr), 0.008, sections=8), "painted", convex=True))
        mass, desc = 2.5, "low square footstool with a padded top on splayed legs with stretchers"
    return AssetSpec("Footstool", v, "furniture", [Link("base", parts, mass)], description=desc)


# -------------------------------------------------------------------------------------------------- bed

_BED_SIZES = {"single": (0.9, 1.95), "double": (1.4, 2.0), "queen": (1.6, 2.0), "king": (1.8, 2.03)}


def _headboard(style: str, w: float, y0: float, t: float, h: float, z_top: float, slot: str) -> list[Part]:
    """A head- or footboard across x in [-w/2, w/2], y in [y0, y0 + t], from the floor to height `h`.

    `z_top` is the mattress top (where padded/panel infills start to show).
    """
    parts: list[Part] = []
    post = 0.07 if style != "metal" else 0.045
    yc = y0 + t / 2
    if style == "padded":
        parts.append(Part(g.box_at((-w / 2, y0, 0), (w / 2, y0 + t * 0.5, h - 0.02)), slot, convex=True))
        parts.append(Part(g.soft_box_at((-w / 2, y0 + t * 0.3, z_top - 0.1), (w / 2, y0 + t, h), 0.05), "fabric",
                          convex=True))
        for x in np.linspace(-w / 2 + 0.2, w / 2 - 0.2, max(3, int(w / 0.3))):
            for z in np.linspace(z_top + 0.12, h - 0.14, 3):
                parts.append(Part(g.sphere(0.014, (x, y0 + t - 0.002, z), subdivisions=0), "fabric", collide=False))
        return parts
    if style == "metal":
        for sx in (-1, 1):
            parts.append(Part(g.cylinder(0.022, h, (sx * (w / 2 - 0.022), yc, h / 2), sections=12), slot, convex=True))
            parts.append(Part(g.sphere(0.032, (sx * (w / 2 - 0.022), yc, h), subdivisions=1), "brass", convex=True))
        for z in (z_top - 0.12, h - 0.05):
            parts.append(Part(g.cylinder(0.016, w - 0.04, (0, yc, z), axis="x", sections=10), slot, convex=True))
        n = max(5, int(w / 0.14))
        for x in np.linspace(-w / 2 + 0.12, w / 2 - 0.12, n):
            parts.append(Part(g.cylinder(0.008, h - 0.05 - z_top + 0.12, (x, yc, (h - 0.05 + z_top - 0.12) / 2),
                                         sections=8), slot, convex=True))
        return parts
    for sx in (-1, 1):  # wooden posts with caps
        x = sx * (w / 2 - post / 2)
        parts.append(Part(g.box_at((x - post / 2, y0, 0), (x + post / 2, y0 + t, h)), slot, convex=True))
        cap = g.box_at((x - post / 2 - 0.008, y0 - 0.008, h), (x + post / 2 + 0.008, y0 + t + 0.008, h + 0.025))
        parts.append(Part(cap, slot, convex=True))
    xi = w / 2 - post
    parts.append(Part(g.box_at((-xi, y0 - 0.01, h - 0.07), (xi, y0 + t + 0.01, h - 0.01)), slot, convex=True))
    parts.append(Part(g.box_at((-xi, y0, z_top - 0.22), (xi, y0 + t, z_top - 0.1)), slot, convex=True))
    if style == "slats":
        n = max(4, int(w / 0.13))
        for x in np.linspace(-xi + 0.07, xi - 0.07, n):
            parts.append(Part(g.box_at((x - 0.022, yc - 0.012, z_top - 0.1), (x + 0.022, yc + 0.012, h - 0.07)), slot,
                              convex=True))
    else:  # raised panel
        parts.append(Part(g.box_at((-xi, yc - 0.012, z_top - 0.1), (xi, yc + 0.012, h - 0.07)), slot, convex=True))
        parts.append(Part(g.box_at((-xi + 0.06, y0 + t - 0.004, z_top - 0.04), (xi - 0.06, y0 + t + 0.006, h - 0.13)),
                          slot, convex=True))
    return parts


@register("Bed", variants=5, category="furniture")
def bed(v: int, rng: np.random.Generator) -> AssetSpec:
    """A bed: frame, mattress, duvet, pillows and a headboard (some with a footboard).

    Variants: single with a slatted headboard, double platform bed with a padded headboard, queen with
    panel head- and footboard, low king platform with a wide padded headboard, double metal bed with
    spindle head- and footboard. Headboard at -y (against the wall). Dirty: rumpled, stained bedding.
    """
    size, head, foot, legs = [("single", "slats", None, "block"), ("double", "padded", None, "platform"),
                              ("queen", "panel", "panel", "block"), ("king", "padded", None, "plinth"),
                              ("double", "metal", "metal", "metal")][v]
    mw, ml = _BED_SIZES[size]
    mh = pick(rng, 0.2, 0.26)
    slot = {0: "wood", 1: "fabric", 2: "dark_wood", 3: "fabric", 4: "dark_metal"}[v]
    ht = {"slats": 0.05, "padded": 0.12, "panel": 0.06, "metal": 0.045}[head]
    ft = {None: 0.05, "panel": 0.06, "metal": 0.045}[foot]
    rail = 0.05
    fw = mw + 2 * rail + 0.02  # frame width
    hw = fw + (0.3 if v == 3 else 0.0)  # headboard width
    length = ht + ml + 0.02 + ft
    y_head = -length / 2 + ht
    ym0, ym1 = y_head + 0.01, y_head + 0.01 + ml
    deck = {0: 0.3, 1: 0.32, 2: 0.36, 3: 0.22, 4: 0.34}[v]  # top of the mattress support
    top_m = deck + mh
    hb_h = {0: pick(rng, 0.85, 0.95), 1: pick(rng, 1.1, 1.2), 2: pick(rng, 1.1, 1.2), 3: pick(rng, 0.95, 1.05),
            4: pick(rng, 1.05, 1.15)}[v]
    parts: list[Part] = []
    xr = fw / 2
    # frame: side rails and foot rail around the mattress, a deck under it
    if legs == "block" or legs == "metal":
        rail_lo = deck - 0.16
        for sx in (-1, 1):
            x0, x1 = sorted((sx * xr, sx * (xr - rail)))
            parts.append(Part(g.box_at((x0, ym0 - 0.01, rail_lo), (x1, ym1 + 0.01, deck + 0.06)), slot, convex=True))
        if foot is None:
            parts.append(Part(g.box_at((-xr, ym1 + 0.01, rail_lo), (xr, ym1 + 0.01 + ft, deck + 0.06)), slot,
                              convex=True))
        parts.append(Part(g.box_at((-xr + rail, ym0, deck - 0.03), (xr - rail, ym1, deck)), slot, convex=True))
        pts = [(sx * (xr - 0.035), y) for sx in (-1, 1) for y in (ym0 + 0.04, ym1 + 0.01 + ft - 0.035)]
        if foot is not None:
            pts = [(sx * (xr - 0.035), ym0 + 0.5 * (ym1 - ym0)) for sx in (-1, 1)]
        for x, y in pts:
            if legs == "metal":
                parts.append(Part(g.cylinder(0.02, rail_lo, (x, y, rail_lo / 2), sections=10), slot, convex=True))
            else:
                parts.append(Part(g.box((0.07, 0.07, rail_lo), (x, y, rail_lo / 2)), slot, convex=True))
    else:  # upholstered platform to the floor, or a platform floating on a recessed plinth
        y_end = ym1 + 0.01 + ft
        if legs == "plinth":
            parts.append(Part(g.box_at((-xr + 0.12, ym0 + 0.12, 0), (xr - 0.12, y_end - 0.12, 0.08)), "dark_plastic",
                              convex=True))
            parts.append(Part(g.soft_box_at((-xr, ym0 - 0.01, 0.08), (xr, y_end, deck + 0.04), 0.02), slot,
                              convex=True))
        else:
            parts.append(Part(g.soft_box_at((-xr, ym0 - 0.01, 0.0), (xr, y_end, deck + 0.04), 0.025), slot,
                              convex=True))
            for sx in (-1, 1):  # small feet at the corners
                for y in (ym0 + 0.03, y_end - 0.03):
                    parts.append(Part(g.box((0.05, 0.05, 0.03), (sx * (xr - 0.04), y, 0.015)), "dark_wood",
                                      collide=False))
    parts += _headboard(head, hw, -length / 2, ht, hb_h, top_m, slot)
    if foot:
        parts += _headboard(foot, fw, ym1 + 0.01, ft, top_m + 0.12, top_m, slot)
    # bedding: mattress, duvet with the sheet turned down, pillows
    parts.append(Part(g.soft_box_at((-mw / 2, ym0, deck), (mw / 2, ym1, top_m), 0.03), "bed_sheet", convex=True))
    duvet0 = ym0 + 0.55
    duvet1 = ym1 + (0.0 if foot else 0.03)
    drop = min(0.2, mh + 0.02)
    duvet_top = top_m + 0.045
    parts.append(Part(g.soft_box_at((-mw / 2 - 0.03, duvet0, top_m - drop), (mw / 2 + 0.03, duvet1, duvet_top), 0.025),
                      "bed_duvet", convex=True))
    fold1 = duvet0 + 0.16  # the turned-down sheet stands 12 mm proud of the duvet up to here
    parts.append(Part(g.soft_box_at((-mw / 2 - 0.032, duvet0 - 0.02, top_m - drop + 0.02),
                                    (mw / 2 + 0.032, fold1, duvet_top + 0.012), 0.02), "bed_sheet", convex=True))
    n_pil = 1 if mw < 1.2 else 2
    pw = min(0.7, (mw - 0.12) / n_pil)
    for k in range(n_pil):
        x = (k - (n_pil - 1) / 2) * (mw / n_pil)
        parts.append(_pillow((pw - 0.05, 0.14, 0.4), (x, ym0 + 0.27, top_m + 0.06), np.radians(78), "bed_sheet"))
    # dirty: rumpled bedding and stains
    for x, y, sx, sy, yaw in ((-0.2, 0.2, 0.32, 0.16, 0.4), (0.15, 0.55, 0.26, 0.2, -0.3)):
        lump = g.ellipsoid((sx * mw / 1.4, sy, 0.04), subdivisions=1)
        parts.append(Part(g.transformed(lump, yaw=yaw, offset=(x * mw, duvet0 + y + 0.2, duvet_top)), "bed_sheet",
                          state="dirty"))
    for x, y, r in ((0.18, 0.35, 0.09), (-0.25, 0.85, 0.06), (0.05, 1.1, 0.07)):
        parts.append(Part(g.cylinder(r, 0.004, (x * mw, duvet0 + y, duvet_top + 0.001), sections=12), "dirt",
                          state="dirty"))
    mass = {"single": 50.0, "double": 65.0, "queen": 72.0, "king": 80.0}[size]
    # the flat duvet only: an object half on the turned-down sheet would tilt and slide as it settles
    regions = [surface("top", mw, duvet1 - fold1, duvet_top, 0.6, cy=(fold1 + duvet1) / 2, margin=0.06)]
    desc = f"{size} bed with a {head} headboard" + (f" and a {foot} footboard" if foot else "")
    return AssetSpec("Bed", v, "furniture", [Link("base", parts, mass)], regions=regions, description=desc)
