"""Kitchen appliances and fixtures: fridge, microwave, counters, sink, faucet, stove, toaster, coffee machine."""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import (
    DOOR_OPEN,
    bar_handle,
    carcass,
    corner_legs,
    hinged_door,
    pick,
    surface,
)
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import Anchor, AssetSpec, Joint, Link, Part, Region

COUNTER_H = 0.9
"""Worktop height of kitchen counters and sink units."""

BASIN_W, BASIN_D, BASIN_H = 0.5, 0.4, 0.2
"""Outer size of every SinkBasin variant (x, y) and its height from bottom to rim.

All SinkBasin variants share this footprint and height, so a Sink's opening (BASIN_W x BASIN_D plus a
small clearance) and its SinkBasin anchor (rim flush with the worktop) fit whichever variant is chosen.
"""

BASIN_GAP = 0.002
"""Clearance between a basin and the edges of the worktop opening it sits in."""


# ----------------------------------------------------------------------------------------------------------
# small helpers


def _box(lo: Sequence[float], hi: Sequence[float], slot: str, collide: bool = True, state: str | None = None) -> Part:
    """An axis-aligned box part spanning `lo`..`hi` (always convex)."""
    return Part(g.box_at(lo, hi), slot, collide=collide, convex=True, state=state)


def _cyl(radius: float, height: float, center: Sequence[float], slot: str, axis: str = "z", sections: int = 16,
         collide: bool = True, state: str | None = None) -> Part:
    return Part(g.cylinder(radius, height, center, axis=axis, sections=sections), slot, collide=collide, convex=True,
                state=state)


def _ring(radius: float, minor: float, center: Sequence[float], slot: str, plane: str = "xy", sections: int = 20,
          state: str | None = None) -> Part:
    """A full (visual-only) torus ring: indicator rings, coils, burner flames, outlines."""
    mesh = g.torus_arc(radius, minor, center, plane=plane, start=0.0, end=2 * np.pi, sections=sections,
                       minor_sections=5)
    return Part(mesh, slot, collide=False, state=state)


def _slab_with_opening(x0: float, x1: float, y0: float, y1: float, z0: float, z1: float,
                       ox0: float, ox1: float, oy0: float, oy1: float, slot: str) -> list[Part]:
    """A worktop slab x0..x1, y0..y1 with a rectangular opening ox0..ox1, oy0..oy1, as four convex boxes."""
    parts = []
    if oy0 > y0:
        parts.append(_box((x0, y0, z0), (x1, oy0, z1), slot))
    if y1 > oy1:
        parts.append(_box((x0, oy1, z0), (x1, y1, z1), slot))
    if ox0 > x0:
        parts.append(_box((x0, oy0, z0), (ox0, oy1, z1), slot))
    if x1 > ox1:
        parts.append(_box((ox1, oy0, z0), (x1, oy1, z1), slot))
    return parts


def _moved(parts: list[Part], yaw: float = 0.0, offset: Sequence[float] = (0.0, 0.0, 0.0),
           pitch: float = 0.0, roll: float = 0.0) -> list[Part]:
    """The parts rotated (roll, pitch, yaw) and moved by `offset`."""
    return [Part(g.transformed(p.mesh, yaw=yaw, offset=offset, pitch=pitch, roll=roll), p.slot, collide=p.collide,
                 convex=p.convex, state=p.state) for p in parts]


def _mirror_x(parts: list[Part]) -> list[Part]:
    """The parts mirrored left to right (x -> -x)."""
    out = []
    for p in parts:
        mesh = p.mesh.copy()
        mesh.apply_transform(np.diag([-1.0, 1.0, 1.0, 1.0]))
        out.append(Part(mesh, p.slot, collide=p.collide, convex=p.convex, state=p.state))
    return out


def _front_panels(fronts: list[tuple[float, float, float, float, str]], y: float, style: str, slot: str,
                  collide: bool = False) -> list[Part]:
    """Door, drawer and plain fronts (x0, x1, z0, z1, kind) standing on a face at `y`, 18 mm thick with a
    3 mm gap, and their pulls ("bar", "knob" or "none": a dark finger groove). Kinds: "door+x" / "door-x"
    (a door whose pull is near its +x / -x edge), "drawer", "panel" (no pull)."""
    parts = []
    gap = 0.0015
    t = 0.018
    for x0, x1, z0, z1, kind in fronts:
        parts.append(_box((x0 + gap, y, z0 + gap), (x1 - gap, y + t, z1 - gap), slot, collide=collide))
        cx = (x0 + x1) / 2
        if kind == "panel":  # a false front or a blind panel: no pull
            continue
        if kind == "drawer":
            hx, hz, vertical = cx, z1 - min(0.05, (z1 - z0) / 2), False
        else:
            hx = x1 - 0.045 if kind == "door+x" else x0 + 0.045
            hz, vertical = z1 - 0.12, True
        if style == "bar":
            ln = min(0.16, 0.5 * (x1 - x0)) if not vertical else 0.14
            grip = g.cylinder(0.006, ln, (hx, y + t + 0.022, hz), axis="z" if vertical else "x", sections=8)
            posts = [g.box((0.01, 0.022, 0.01), (hx + (0 if vertical else s * (ln / 2 - 0.012)), y + t + 0.011,
                                                 hz + (s * (ln / 2 - 0.012) if vertical else 0))) for s in (-1, 1)]
            parts.append(Part(grip, "metal", collide=False))
            parts += [Part(p, "metal", collide=False) for p in posts]
        elif style == "knob":
            parts.append(_cyl(0.012, 0.022, (hx, y + t + 0.011, hz), "metal", axis="y", sections=10, collide=False))
        else:  # handle-less: a dark finger groove along the top edge of the front
            parts.append(_box((x0 + 0.02, y + t, z1 - 0.012), (x1 - 0.02, y + t + 0.002, z1 - 0.004), "dark_plastic",
                              collide=False))
    return parts


def _bay_fronts(x0: float, x1: float, z0: float, z1: float, layout: str) -> list[tuple[float, float, float, float,
                                                                                       str]]:
    """The fronts of one cabinet bay x0..x1, z0..z1: "door" (a drawer above one door), "doors" (a drawer
    strip above two doors), "stack" (three drawers), "sink" (a false front above two doors)."""
    top = z1 - 0.16
    if layout == "stack":
        h = z1 - z0
        zs = [z0, z0 + 0.38 * h, z0 + 0.7 * h, z1]
        return [(x0, x1, a, b, "drawer") for a, b in itertools.pairwise(zs)]
    if layout == "door":
        return [(x0, x1, top, z1, "drawer"), (x0, x1, z0, top, "door-x")]
    mid = (x0 + x1) / 2
    if layout == "sink":
        return [(x0, x1, top, z1, "panel"), (x0, mid, z0, top, "door+x"), (mid, x1, z0, top, "door-x")]
    return [(x0, mid, top, z1, "drawer"), (mid, x1, top, z1, "drawer"), (x0, mid, z0, top, "door+x"),
            (mid, x1, z0, top, "door-x")]


def _cabinet_run(length: float, d: float, layouts: list[str], style: str, body_slot: str, front_slot: str,
                 top_slot: str, slab_t: float, blind: float = 0.0, open_top: bool = False,
                 opening: tuple[float, float, float, float] | None = None, top_z: float = COUNTER_H,
                 toe: float = 0.1) -> list[Part]:
    """A base-cabinet run along x (centred, back at y=-d/2, worktop front at y=+d/2): a body on a recessed
    plinth, a worktop slab (with an optional opening ox0, ox1, oy0, oy1), fronts in bays of the given
    layouts over x in [-length/2, length/2 - blind] and a plain blind panel over the rest.

    A solid body is one convex box; `open_top` makes it an open carcass (a sink cabinet the basin hangs in)
    whose colliding fronts close it.
    """
    x0, x1 = -length / 2, length / 2
    over = 0.02
    yb = d / 2 - over - 0.018  # the body's front face; fronts stand on it
    zb = top_z - slab_t
    parts: list[Part] = []
    if open_top:
        t = 0.018
        parts.append(_box((x0, -d / 2, toe), (x1, yb, toe + t), body_slot))
        parts.append(_box((x0, -d / 2, toe + t), (x0 + t, yb, zb), body_slot))
        parts.append(_box((x1 - t, -d / 2, toe + t), (x1, yb, zb), body_slot))
        parts.append(_box((x0 + t, -d / 2, toe + t), (x1 - t, -d / 2 + t, zb), body_slot))
    else:
        parts.append(_box((x0, -d / 2, toe), (x1, yb, zb), body_slot))
    parts.append(_box((x0, -d / 2, 0.0), (x1, yb - 0.06, toe), "dark_plastic"))
    if opening is None:
        parts.append(_box((x0, -d / 2, zb), (x1, d / 2, top_z), top_slot))
    else:
        parts += _slab_with_opening(x0, x1, -d / 2, d / 2, zb, top_z, *opening, top_slot)
    # a dark shadow panel behind the fronts makes their gaps read as door and drawer outlines
    parts.append(_box((x0 + 0.004, yb - 0.001, toe), (x1 - 0.004, yb + 0.001, zb - 0.002), "dark_plastic",
                      collide=False))
    fx1 = x1 - blind
    edges = np.linspace(x0, fx1, len(layouts) + 1)
    fronts = []
    for (a, b), layout in zip(itertools.pairwise(edges), layouts):
        fronts += _bay_fronts(float(a), float(b), toe, zb, layout)
    if blind > 0:
        fronts.append((fx1, x1, toe, zb, "panel"))
    return parts + _front_panels(fronts, yb, style, front_slot, collide=open_top)


# ----------------------------------------------------------------------------------------------------------
# Fridge


DOOR_SHELF_DEPTH = 0.09
"""Metres a fridge's door shelves reach behind its closed door."""


@register("Fridge", variants=4, category="appliance")
def fridge(v: int, rng: np.random.Generator) -> AssetSpec:
    """A fridge: an insulated body with glass shelves and a hinged door carrying door shelves.

    Variants: single door left/right hinge, tall or short, white/steel/black.
    """
    w = pick(rng, 0.6, 0.75)
    d = pick(rng, 0.62, 0.72)
    h = [1.75, 1.8, 1.55, 1.85][v]
    t = 0.05
    slot = "appliance"
    parts = carcass(w, d - 0.04, h, t, slot)
    for p in parts:
        p.mesh.apply_translation((0, -0.02, 0))
    y_front = d / 2 - 0.04
    shelf_zs = [round(z, 3) for z in np.linspace(t + 0.35, h - t - 0.3, 3)]
    inner_w, inner_d = w - 2 * t, d - 0.04 - t
    for z in shelf_zs:
        parts.append(Part(g.box((inner_w, inner_d - 0.02, 0.01), (0, -0.02 + t / 2 - 0.01, z)), "glass"))
    parts.append(Part(g.box((w, 0.03, 0.03), (0, y_front, h - 0.03)), "dark_plastic"))
    hinge = "left" if v % 2 == 0 else "right"
    sign = 1 if hinge == "left" else -1
    door_shelves = []
    for z in (0.45, 0.85, 1.25):
        x0, x1 = sorted((sign * 0.06, sign * (w - 0.06)))
        door_shelves.append(Part(g.box_at((x0, -DOOR_SHELF_DEPTH, z), (x1, 0.0, z + 0.012)), "glass"))
        door_shelves.append(Part(g.box_at((x0, -DOOR_SHELF_DEPTH, z), (x1, -DOOR_SHELF_DEPTH + 0.01, z + 0.06)),
                                 "glass"))
    door, joint = hinged_door("door", "base", -w / 2, w / 2, y_front, 0.02, h - 0.04, hinge, slot,
                              thickness=0.05, extra=door_shelves, mass=8.0)
    regions = []
    levels = [t] + shelf_zs
    tops = shelf_zs + [h - t]
    back = -0.02 + t / 2 - (inner_d - 0.04) / 2
    front = y_front - DOOR_SHELF_DEPTH - 0.01  # the closed door's shelves reach this far in
    for i, (z0, z1) in enumerate(zip(levels, tops)):
        z0 = z0 + (0.005 if i else 0.0)  # on top of the 1 cm glass shelf
        regions.append(Region(f"shelf_{i}", "volume", (0.0, (back + front) / 2, (z0 + z1) / 2),
                              (inner_w - 0.02, front - back, z1 - z0 - 0.01), requires_open=joint.name))
    return AssetSpec(
        "Fridge", v, "appliance", [Link("base", parts, 60.0), door], joints=[joint], regions=regions,
        description="fridge with shelves and a hinged door with door shelves",
    )


# ----------------------------------------------------------------------------------------------------------
# Microwave


@register("Microwave", variants=4, category="appliance")
def microwave(v: int, rng: np.random.Generator) -> AssetSpec:
    """A countertop microwave: a box body with a cavity and a turntable, a control panel on the right and a
    door with a dark window hinged on the left, both as seen from the front (the hinge is at +x, the panel
    at -x), opening outwards. On: the window and cavity light up and the display is lit.

    Built with the panel at +x and mirrored at the end, so "right" below means +x before mirroring.

    Variants: 0 classic with a keypad and a bar handle, 1 compact with two dials and a grip recess,
    2 large convection model with a touch pad and a full-height handle, 3 retro with a rounded top and feet.
    """
    w = [pick(rng, 0.48, 0.52), pick(rng, 0.44, 0.47), pick(rng, 0.56, 0.6), pick(rng, 0.46, 0.5)][v]
    d = [pick(rng, 0.36, 0.4), pick(rng, 0.33, 0.36), pick(rng, 0.4, 0.44), pick(rng, 0.35, 0.38)][v]
    h = [0.29, 0.26, 0.33, 0.3][v]
    panel_w = [0.13, 0.12, 0.15, 0.12][v]
    foot = [0.01, 0.008, 0.012, 0.025][v]
    body_slot = ["appliance", "appliance", "metal", "appliance"][v]
    panel_slot = ["appliance", "dark_plastic", "dark_plastic", "appliance"][v]
    t, door_t = 0.02, 0.03
    y_front = d / 2 - door_t
    x_div = w / 2 - panel_w
    r_top = 0.06 if v == 3 else 0.0
    top_lo = h - t - r_top  # the underside of the top shell
    parts: list[Part] = []
    # shell: bottom, top, left side, back; the control block closes the cavity on the right
    parts.append(_box((-w / 2, -d / 2, foot), (x_div, y_front, foot + t), body_slot))
    parts.append(_box((-w / 2, -d / 2, foot + t), (-w / 2 + t, y_front, top_lo), body_slot))
    parts.append(_box((-w / 2 + t, -d / 2, foot + t), (x_div, -d / 2 + t, top_lo), body_slot))
    if v == 3:
        top = g.rounded_box(w, d, r_top + t, r_top, "y", z0=h - r_top - t, sections=20)
        parts.append(Part(top, body_slot, convex=True))
        parts.append(_box((x_div, -d / 2, foot), (w / 2, d / 2, top_lo), panel_slot))
    else:
        parts.append(_box((-w / 2, -d / 2, h - t), (x_div, y_front, h), body_slot))
        parts.append(_box((x_div, -d / 2, foot), (w / 2, d / 2, h), panel_slot))
    # the cavity: liner, turntable, light
    cx0, cx1, cy0, cy1, cz0, cz1 = -w / 2 + t, x_div, -d / 2 + t, y_front, foot + t, top_lo
    lt = 0.002
    for lo, hi in (((cx0, cy0, cz0), (cx1, cy1, cz0 + lt)), ((cx0, cy0, cz1 - lt), (cx1, cy1, cz1)),
                   ((cx0, cy0, cz0), (cx0 + lt, cy1, cz1)), ((cx1 - lt, cy0, cz0), (cx1, cy1, cz1)),
                   ((cx0, cy0, cz0), (cx1, cy0 + lt, cz1))):
        parts.append(_box(lo, hi, "metal", collide=False))
    plate_r = min(cx1 - cx0, cy1 - cy0) / 2 - 0.02
    pcx, pcy = (cx0 + cx1) / 2, (cy0 + cy1) / 2
    parts.append(_cyl(0.03, 0.012, (pcx, pcy, cz0 + 0.006), "dark_plastic", sections=10))
    parts.append(_cyl(plate_r, 0.006, (pcx, pcy, cz0 + 0.015), "glass", sections=24))
    plate_top = cz0 + 0.018
    parts.append(_box((cx0 + 0.003, cy0 + 0.003, cz1 - 0.004), (cx1 - 0.003, cy1 - 0.02, cz1 - 0.003), "glow",
                      state="on"))
    parts.append(_box((cx0 + 0.02, cy0 + 0.003, cz0 + 0.03), (cx1 - 0.02, cy0 + 0.004, cz1 - 0.02), "glow",
                      state="on"))
    # feet
    for sx in (-1, 1):
        for sy in (-1, 1):
            parts.append(_cyl(0.014 if v == 3 else 0.012, foot, (sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), foot / 2),
                              "metal" if v == 3 else "rubber", sections=10))
    # control panel face at y = d/2
    pf = d / 2
    px0, px1 = x_div + 0.015, w / 2 - 0.015
    pmid = (px0 + px1) / 2
    disp_z = top_lo - 0.045 if v == 3 else h - 0.055
    parts.append(_box((px0, pf, disp_z), (px1, pf + 0.002, disp_z + 0.028), "led_off", collide=False, state="off"))
    parts.append(_box((px0, pf, disp_z), (px1, pf + 0.003, disp_z + 0.028), "led_on", collide=False, state="on"))
    if v in (0, 2):  # keypad
        rows = 4 if v == 0 else 5
        bw = (px1 - px0 - 0.02) / 3
        for r in range(rows):
            for c in range(3):
                bx0 = px0 + c * (bw + 0.01)
                bz1 = disp_z - 0.02 - r * 0.03
                parts.append(_box((bx0, pf, bz1 - 0.02), (bx0 + bw, pf + (0.005 if v == 0 else 0.0015), bz1),
                                  "dark_plastic" if panel_slot != "dark_plastic" else "metal", collide=False))
        start_z = disp_z - 0.02 - rows * 0.03 - 0.01
        parts.append(_box((px0, pf, start_z - 0.03), (px1, pf + 0.006, start_z), "plastic", collide=False))
    else:  # dials
        for zf in (0.62, 0.3):
            dz = foot + zf * (top_lo - foot)
            parts.append(_cyl(0.024, 0.008, (pmid, pf + 0.004, dz), "metal", axis="y", sections=16, collide=False))
            parts.append(_cyl(0.019, 0.022, (pmid, pf + 0.011, dz), "dark_plastic" if v == 3 else "metal", axis="y",
                              sections=16, collide=False))
            parts.append(_box((pmid - 0.003, pf + 0.02, dz + 0.004), (pmid + 0.003, pf + 0.025, dz + 0.018),
                              "appliance", collide=False))
    # door (link frame: hinge at the left front edge of the body)
    dz0, dz1 = foot + 0.004, top_lo - 0.004 if v == 3 else h - 0.004
    door_w = x_div + w / 2 - 0.003
    door_slot = ["appliance", "appliance", "metal", "appliance"][v]
    dparts = [_box((0, 0, dz0), (door_w, door_t, dz1), door_slot)]
    m, mr = 0.035, [0.07, 0.05, 0.06, 0.07][v]
    win = ((m, door_t, dz0 + m), (door_w - mr, door_t + 0.002, dz1 - m))
    dparts.append(_box(*win, "screen", collide=False))
    dparts.append(_box((m + 0.004, door_t, dz0 + m + 0.004), (door_w - mr - 0.004, door_t + 0.003, dz1 - m - 0.004),
                       "glow", state="on"))
    if v == 0:
        dparts += bar_handle(0.6 * (dz1 - dz0), (door_w - 0.03, door_t, (dz0 + dz1) / 2), True, "metal")
    elif v == 1:  # a grip recess along the free edge
        dparts.append(_box((door_w - 0.03, door_t, dz0 + 0.02), (door_w - 0.008, door_t + 0.004, dz1 - 0.02),
                           "dark_plastic" if door_slot != "dark_plastic" else "metal", collide=False))
    elif v == 2:
        dparts += bar_handle(dz1 - dz0 - 0.05, (door_w - 0.03, door_t, (dz0 + dz1) / 2), True, "metal")
    else:
        dparts.append(_box((door_w - 0.045, door_t, (dz0 + dz1) / 2 - 0.05), (door_w - 0.02, door_t + 0.025,
                                                                             (dz0 + dz1) / 2 + 0.05), "metal"))
    door = Link("door", _mirror_x(dparts), 2.0)
    joint = Joint("door_hinge", "revolute", "base", "door", (w / 2, y_front, 0.0), (0.0, 0.0, -1.0), 0.0, DOOR_OPEN,
                  "door")
    rz0, rz1 = plate_top + 0.002, cz1 - 0.01
    region = Region("inside", "volume", (-pcx, pcy, (rz0 + rz1) / 2), (cx1 - cx0 - 0.03, cy1 - cy0 - 0.03, rz1 - rz0),
                    requires_open=joint.name)
    return AssetSpec("Microwave", v, "appliance", [Link("base", _mirror_x(parts), 13.0), door], joints=[joint],
                     regions=[region], description="microwave oven with a hinged door, turntable and control panel")


# ----------------------------------------------------------------------------------------------------------
# CounterTop


@register("CounterTop", variants=5, category="fixture")
def counter_top(v: int, rng: np.random.Generator) -> AssetSpec:
    """A kitchen counter run: base cabinets on a recessed plinth under a worktop slab, 0.9 m high.

    Variants: 0 single 0.6 m unit, 1 1.2 m run with doors, 2 1.8 m run with a drawer stack and an
    upstand, 3 2.4 m run, 4 an L-shaped corner run (two arms of convex boxes). Fronts are thin visual
    panels (no joints); separate Cabinet/Drawer assets can be set in front of or instead of them.
    """
    d = pick(rng, 0.6, 0.65)
    slab_t = [0.03, 0.04, 0.03, 0.04, 0.035][v]
    style = ["bar", "knob", "none", "bar", "knob"][v]
    body_slot = ["painted", "wood", "painted", "dark_wood", "painted"][v]
    front_slot = ["painted", "wood", "painted", "dark_wood", "wood"][v]
    regions: list[Region] = []
    if v < 4:
        w = [0.6, 1.2, 1.8, 2.4][v]
        layouts = [["door"], ["doors", "doors"], ["stack", "doors", "door"], ["door", "stack", "doors", "door"]][v]
        parts = _cabinet_run(w, d, layouts, style, body_slot, front_slot, "stone", slab_t)
        upstand = v in (2, 3)
        if upstand:
            parts.append(_box((-w / 2, -d / 2, COUNTER_H), (w / 2, -d / 2 + 0.015, COUNTER_H + 0.08), "stone"))
        back = 0.015 if upstand else 0.0
        regions.append(surface("top", w, d - back, COUNTER_H, 0.5, cy=back / 2))
        desc = f"{w:.1f} m kitchen counter with base cabinet fronts and a worktop"
    else:
        wx, wy = pick(rng, 1.8, 2.2), pick(rng, 1.3, 1.6)
        main = _cabinet_run(wx, d, ["doors", "stack"], style, body_slot, front_slot, "stone", slab_t, blind=d)
        ret_len = wy - d
        ret = _cabinet_run(ret_len, d, ["door"] * max(1, round(ret_len / 0.6)), style, body_slot, front_slot,
                           "stone", slab_t)
        parts = _moved(main, offset=(0.0, -wy / 2 + d / 2, 0.0))
        parts += _moved(ret, yaw=np.pi / 2, offset=(wx / 2 - d / 2, d / 2, 0.0))
        regions.append(surface("top", wx, d, COUNTER_H, 0.5, cy=-wy / 2 + d / 2))
        regions.append(surface("top_return", d, ret_len, COUNTER_H, 0.5, cx=wx / 2 - d / 2, cy=d / 2))
        desc = "L-shaped corner kitchen counter run with base cabinet fronts and a worktop"
    w_total = [0.6, 1.2, 1.8, 2.4, 2.8][v]
    return AssetSpec("CounterTop", v, "fixture", [Link("base", parts, round(50 + 25 * w_total, 1))],
                     regions=regions, description=desc)


# ----------------------------------------------------------------------------------------------------------
# Sink, SinkBasin, Faucet


def _basin_rails(x0: float, x1: float, by: float, top_z: float) -> list[Part]:
    """Two cross rails inside a sink cabinet that any basin's flat bottom rests on (rim flush with the worktop)."""
    z1 = top_z - BASIN_H
    return [_box((x0, y - 0.02, z1 - 0.03), (x1, y + 0.02, z1), "wood") for y in (by - 0.08, by + 0.08)]


@register("Sink", variants=4, category="fixture")
def sink(v: int, rng: np.random.Generator) -> AssetSpec:
    """A sink unit whose worktop (four convex boxes round a rectangular opening) takes the SinkBasin, with
    the Faucet behind it (both come as anchors: basin rim flush with the worktop, faucet on the back strip).

    Variants: 0 kitchen sink cabinet, 1 wide kitchen unit with an off-centre basin, a drainer and an
    upstand, 2 bathroom vanity on legs, 3 bathroom pedestal sink.
    """
    ow, od = BASIN_W + 2 * BASIN_GAP, BASIN_D + 2 * BASIN_GAP
    faucet_gap = 0.06  # faucet axis behind the opening's back edge: its base plate stays on the back strip
    if v in (0, 1):
        top_z, d = COUNTER_H, pick(rng, 0.6, 0.64)
        w = [pick(rng, 0.8, 0.9), pick(rng, 1.2, 1.3)][v]
        bx = 0.0 if v == 0 else round(-w / 2 + 0.08 + ow / 2, 3)
        by = round(d / 2 - 0.06 - od / 2, 3)
        slab_t = 0.03 if v == 0 else 0.04
        opening = (bx - ow / 2, bx + ow / 2, by - od / 2, by + od / 2)
        layouts = ["sink"] if v == 0 else ["sink", "stack"]
        body_slot = ["painted", "wood"][v]
        parts = _cabinet_run(w, d, layouts, "bar" if v == 0 else "knob", body_slot, body_slot, "stone", slab_t,
                             open_top=True, opening=opening)
        if v == 1:  # a grooved stainless drainer on the right and an upstand along the back
            dx0, dx1 = bx + ow / 2 + 0.04, w / 2 - 0.05
            parts.append(_box((dx0, by - od / 2, top_z), (dx1, by + od / 2, top_z + 0.003), "metal", collide=False))
            for y in np.linspace(by - od / 2 + 0.05, by + od / 2 - 0.05, 7):
                parts.append(_box((dx0 + 0.03, y - 0.004, top_z + 0.003), (dx1 - 0.03, y + 0.004, top_z + 0.0035),
                                  "dark_metal", collide=False))
            parts.append(_box((-w / 2, -d / 2, top_z), (w / 2, -d / 2 + 0.015, top_z + 0.1), "stone"))
        parts += _basin_rails(-w / 2 + 0.018, w / 2 - 0.018, by, top_z)
        mass = 40.0
        desc = "kitchen sink base cabinet with a worktop cut out for the basin"
    elif v == 2:
        top_z, d, w = 0.85, 0.56, pick(rng, 0.75, 0.85)
        bx, by = 0.0, round(d / 2 - 0.045 - od / 2, 3)
        opening = (bx - ow / 2, bx + ow / 2, by - od / 2, by + od / 2)
        leg_h = 0.2
        slab_t = 0.03
        zb = top_z - slab_t
        t = 0.018
        yb = d / 2 - 0.015 - t
        parts = corner_legs(w - 0.02, d - 0.06, leg_h, 0.03, 0.018, "dark_wood", square=True)
        for p in parts:
            p.mesh.apply_translation((0, -0.02, 0))
        parts += [_box((-w / 2, -d / 2, leg_h), (w / 2, yb, leg_h + t), "wood"),
                  _box((-w / 2, -d / 2, leg_h + t), (-w / 2 + t, yb, zb), "wood"),
                  _box((w / 2 - t, -d / 2, leg_h + t), (w / 2, yb, zb), "wood"),
                  _box((-w / 2 + t, -d / 2, leg_h + t), (w / 2 - t, -d / 2 + t, zb), "wood")]
        parts.append(_box((-w / 2 + 0.004, yb - 0.001, leg_h), (w / 2 - 0.004, yb + 0.001, zb - 0.002), "dark_plastic",
                          collide=False))
        fronts = [(-w / 2, 0.0, leg_h, zb, "door+x"), (0.0, w / 2, leg_h, zb, "door-x")]
        parts += _front_panels(fronts, yb, "knob", "wood", collide=True)
        parts += _slab_with_opening(-w / 2 - 0.01, w / 2 + 0.01, -d / 2, d / 2, zb, top_z, *opening, "porcelain")
        parts += _basin_rails(-w / 2 + t, w / 2 - t, by, top_z)
        mass = 40.0
        desc = "bathroom vanity on legs with a countertop cut out for the basin"
    else:
        top_z, d, w = 0.86, 0.54, pick(rng, 0.6, 0.66)
        bx, by = 0.0, round(d / 2 - 0.03 - od / 2, 3)
        opening = (bx - ow / 2, bx + ow / 2, by - od / 2, by + od / 2)
        slab_t = 0.04
        zb = top_z - slab_t
        shell_lo = top_z - BASIN_H - 0.025  # the basin rests on the bowl housing's floor
        t = 0.02
        parts = _slab_with_opening(-w / 2, w / 2, -d / 2, d / 2, zb, top_z, *opening, "porcelain")
        hx0, hx1, hy0, hy1 = opening[0] - t, opening[1] + t, opening[2] - t, opening[3] + t
        parts += [_box((hx0, hy0, shell_lo), (hx1, hy1, shell_lo + 0.025), "porcelain"),
                  _box((hx0, hy0, shell_lo + 0.025), (hx0 + t, hy1, zb), "porcelain"),
                  _box((hx1 - t, hy0, shell_lo + 0.025), (hx1, hy1, zb), "porcelain"),
                  _box((hx0 + t, hy0, shell_lo + 0.025), (hx1 - t, hy0 + t, zb), "porcelain"),
                  _box((hx0 + t, hy1 - t, shell_lo + 0.025), (hx1 - t, hy1, zb), "porcelain")]
        col_y = (hy0 + hy1) / 2
        parts.append(_box((-0.16, col_y - 0.13, 0.0), (0.16, col_y + 0.13, 0.03), "porcelain"))
        parts.append(Part(g.frustum(0.12, 0.085, shell_lo - 0.03, (0, col_y, 0.03), sections=20), "porcelain",
                          convex=True))
        mass = 40.0
        desc = "bathroom pedestal sink: a column, a bowl housing and a top cut out for the basin"
    faucet_y = round(by - od / 2 - faucet_gap, 3)
    anchors = [Anchor("SinkBasin", (bx, by, round(top_z - BASIN_H, 4), 0.0)),
               Anchor("Faucet", (bx, faucet_y, top_z, 0.0))]
    return AssetSpec("Sink", v, "fixture", [Link("base", parts, mass)], anchors=anchors, description=desc,
                     tags=["kitchen"] if v in (0, 1) else ["bathroom"])


def _tub(x0: float, x1: float, y0: float, y1: float, t: float, bottom: float, slot: str) -> list[Part]:
    """An open rectangular tub (bottom and four walls, convex slabs) from z=0 to the basin rim."""
    return [_box((x0, y0, 0.0), (x1, y1, bottom), slot),
            _box((x0, y0, bottom), (x0 + t, y1, BASIN_H), slot),
            _box((x1 - t, y0, bottom), (x1, y1, BASIN_H), slot),
            _box((x0 + t, y0, bottom), (x1 - t, y0 + t, BASIN_H), slot),
            _box((x0 + t, y1 - t, bottom), (x1 - t, y1, BASIN_H), slot)]


def _drain(x: float, y: float, z: float, r: float = 0.04) -> list[Part]:
    return [_cyl(r, 0.003, (x, y, z + 0.0015), "metal", sections=16, collide=False),
            _cyl(r * 0.7, 0.004, (x, y, z + 0.002), "dark_metal", sections=16, collide=False)]


@register("SinkBasin", variants=3, category="fixture")
def sink_basin(v: int, rng: np.random.Generator) -> AssetSpec:
    """The basin that drops into a Sink's worktop opening: BASIN_W x BASIN_D, BASIN_H tall, rim at its top.

    Variants: 0 single rectangular stainless tub (five slabs), 1 oval ceramic bowl in a flat deck (coacd),
    2 stainless double bowl (a large and a small tub sharing a divider).
    """
    x0, x1, y0, y1 = -BASIN_W / 2, BASIN_W / 2, -BASIN_D / 2, BASIN_D / 2
    regions = []
    if v == 0:
        t, bottom = pick(rng, 0.012, 0.016), 0.012
        parts = _tub(x0, x1, y0, y1, t, bottom, "metal") + _drain(0.0, 0.0, bottom)
        regions.append(Region("inside", "volume", (0.0, 0.0, (bottom + BASIN_H) / 2),
                              (BASIN_W - 2 * t - 0.02, BASIN_D - 2 * t - 0.02, BASIN_H - bottom)))
        desc = "rectangular stainless sink basin with a drain"
    elif v == 1:
        sy = 0.8
        r_top = BASIN_W / 2 - 0.03
        r_bot = pick(rng, 0.14, 0.16)
        profile = [(r_bot, 0.0), (r_bot + 0.5 * (r_top - r_bot), 0.07), (r_top - 0.008, 0.15), (r_top, BASIN_H)]
        wall, bottom = 0.012, 0.012
        bowl = g.container(profile, wall=wall, bottom=bottom, sections=28)
        bowl.apply_scale((1.0, sy, 1.0))
        deck_t = 0.02
        hole = g.cylinder(r_top - wall / 2, deck_t + 0.02, (0, 0, BASIN_H - deck_t / 2), sections=28)
        hole.apply_scale((1.0, sy, 1.0))
        deck = g.difference(g.box_at((x0, y0, BASIN_H - deck_t), (x1, y1, BASIN_H)), hole)
        parts = [Part(bowl, "porcelain", convex=False), Part(deck, "porcelain", convex=False)]
        parts += _drain(0.0, 0.0, bottom, 0.035)
        ir = r_bot - 0.005
        # the square inscribed in the flat bottom (side sqrt(2) r): a bowl or a mug stands in it
        regions.append(Region("inside", "volume", (0.0, 0.0, (bottom + BASIN_H) / 2),
                              (1.41 * ir, 1.41 * ir * sy, BASIN_H - bottom)))
        desc = "oval ceramic sink basin set in a flat deck, with a drain"
    else:
        t, bottom = 0.012, 0.012
        xd = round(BASIN_W / 2 - pick(rng, 0.17, 0.19), 3)  # the divider: a large left and a small right bowl
        parts = _tub(x0, x1, y0, y1, t, bottom, "metal")
        parts.append(_box((xd - t / 2, y0 + t, bottom), (xd + t / 2, y1 - t, BASIN_H - 0.03), "metal"))
        lc, rc = (x0 + t + xd - t / 2) / 2, (xd + t / 2 + x1 - t) / 2
        parts += _drain(lc, 0.0, bottom) + _drain(rc, 0.0, bottom, 0.032)
        for name, c, a, b in (("inside_left", lc, x0 + t, xd - t / 2), ("inside_right", rc, xd + t / 2, x1 - t)):
            regions.append(Region(name, "volume", (c, 0.0, (bottom + BASIN_H) / 2),
                                  (b - a - 0.02, BASIN_D - 2 * t - 0.02, BASIN_H - bottom)))
        desc = "stainless double sink basin, a large and a small bowl with drains"
    return AssetSpec("SinkBasin", v, "fixture", [Link("base", parts, 8.0)], regions=regions, description=desc)


def _arc_pipe(center_y: float, center_z: float, radius: float, tube: float, start: float, end: float, slot: str,
              segments: int = 6) -> list[Part]:
    """A pipe bent along an arc in the yz plane (angles from +y towards +z): a smooth visual torus part and
    thinner straight chords (colliding, hidden inside it)."""
    parts = [Part(g.torus_arc(radius, tube, (0, center_y, center_z), plane="yz", start=start, end=end,
                              sections=12, minor_sections=8), slot, collide=False)]
    angles = np.linspace(start, end, segments + 1)
    pts = [(0.0, center_y + radius * np.cos(a), center_z + radius * np.sin(a)) for a in angles]
    for p0, p1 in itertools.pairwise(pts):
        parts.append(Part(g.rod(p0, p1, tube * 0.6, sections=6), slot, convex=True))
    return parts


@register("Faucet", variants=4, category="fixture")
def faucet(v: int, rng: np.random.Generator) -> AssetSpec:
    """A tap standing on the worktop behind a basin, its spout reaching forward (+y); origin at the centre of
    its base. On: a water stream falls from the spout into the basin.

    Variants: 0 kitchen gooseneck with a side lever, 1 bathroom mixer with a short spout and a top lever,
    2 two-handle bridge faucet, 3 tall pipe faucet with an angled spout.
    """
    slot = ["metal", "metal", "brass", "dark_metal"][v]
    parts: list[Part] = []
    if v == 0:
        col_h = pick(rng, 0.2, 0.26)
        reach = pick(rng, 0.085, 0.1)  # arc radius; the outlet is 2 * reach in front of the column
        parts.append(Part(g.rounded_box(0.07, 0.09, 0.014, 0.03, "z", cy=0.01), slot, convex=True))
        parts.append(_cyl(0.026, 0.07, (0, 0, 0.014 + 0.035), slot, sections=16))
        parts.append(_cyl(0.018, col_h, (0, 0, 0.012 + col_h / 2), slot, sections=16))
        top = 0.012 + col_h
        parts += _arc_pipe(reach, top, reach, 0.012, 0.0, np.pi, slot)
        out_y = 2 * reach
        parts.append(_cyl(0.014, 0.05, (0, out_y, top - 0.025), slot, sections=12))
        out_z = top - 0.05
        hub_z = 0.012 + 0.6 * col_h
        parts.append(_cyl(0.014, 0.03, (0.03, 0, hub_z), slot, axis="x", sections=12))
        parts.append(Part(g.rod((0.042, 0, hub_z), (0.05, 0, hub_z + 0.06), 0.006, sections=8), slot, convex=True))
    elif v == 1:
        col_h = pick(rng, 0.13, 0.17)
        reach = pick(rng, 0.11, 0.13)
        parts.append(_cyl(0.028, 0.01, (0, 0, 0.005), slot, sections=20))
        parts.append(_cyl(0.022, col_h, (0, 0, 0.01 + col_h / 2), slot, sections=16))
        top = 0.01 + col_h
        sp_z = top - 0.03
        parts.append(Part(g.rod((0, 0, sp_z), (0, reach, sp_z - 0.02), 0.012, sections=12), slot, convex=True))
        parts.append(_cyl(0.01, 0.012, (0, reach, sp_z - 0.026), "dark_metal", sections=10))
        out_y, out_z = reach, sp_z - 0.032
        parts.append(_cyl(0.016, 0.02, (0, 0, top + 0.01), slot, sections=12))
        parts.append(Part(g.rod((0, 0.0, top + 0.015), (0, -0.075, top + 0.035), 0.007, sections=8), slot,
                          convex=True))
    elif v == 2:
        half = pick(rng, 0.09, 0.1)
        parts.append(_box((-half - 0.03, -0.03, 0), (half + 0.03, 0.04, 0.012), slot))
        rise = 0.09
        for sx in (-1, 1):
            parts.append(_cyl(0.016, rise, (sx * half, 0, 0.012 + rise / 2), slot, sections=12))
            hz = 0.012 + rise
            parts.append(_cyl(0.02, 0.02, (sx * half, 0, hz + 0.01), "porcelain", sections=12))
            for yaw in (np.pi / 4, -np.pi / 4):
                arm = g.transformed(g.box((0.07, 0.012, 0.012)), yaw=yaw, offset=(sx * half, 0, hz + 0.025))
                parts.append(Part(arm, "porcelain", convex=True))
        bz = 0.012 + 0.06
        parts.append(_cyl(0.013, 2 * half, (0, 0, bz), slot, axis="x", sections=12))
        col_h = 0.13
        parts.append(_cyl(0.015, col_h, (0, 0, bz + col_h / 2), slot, sections=12))
        top = bz + col_h
        parts += _arc_pipe(0.06, top, 0.06, 0.012, 0.0, np.pi, slot, segments=5)
        out_y = 0.12
        parts.append(_cyl(0.013, 0.03, (0, out_y, top - 0.015), slot, sections=12))
        out_z = top - 0.03
    else:
        col_h = pick(rng, 0.3, 0.34)
        reach = pick(rng, 0.2, 0.23)
        parts.append(Part(g.rounded_box(0.075, 0.095, 0.016, 0.03, "z", cy=0.012), slot, convex=True))
        parts.append(_cyl(0.026, 0.08, (0, 0, 0.016 + 0.04), slot, sections=16))
        parts.append(_cyl(0.016, col_h, (0, 0, 0.014 + col_h / 2), slot, sections=14))
        top = 0.014 + col_h
        parts.append(Part(g.sphere(0.02, (0, 0, top), subdivisions=1), slot, convex=True))
        tip = (0, reach, top - 0.06)
        parts.append(Part(g.rod((0, 0, top), tip, 0.011, sections=12), slot, convex=True))
        parts.append(Part(g.sphere(0.016, tip, subdivisions=1), slot, convex=True))
        parts.append(_cyl(0.014, 0.03, (0, reach, tip[2] - 0.015), slot, sections=12))
        out_y, out_z = reach, tip[2] - 0.03
        hz = 0.014 + 0.55 * col_h
        parts.append(_cyl(0.012, 0.035, (0.03, 0, hz), slot, axis="x", sections=12))
        parts.append(_box((0.045, -0.008, hz - 0.006), (0.1, 0.008, hz + 0.006), "dark_plastic"))
    # the water stream: from the outlet down into the basin below the worktop
    stream = out_z + 0.06
    parts.append(_cyl(0.0065, stream, (0, out_y, out_z - stream / 2), "water", sections=10, state="on"))
    return AssetSpec("Faucet", v, "fixture", [Link("base", parts, 2.0)],
                     description="faucet with a spout and handles; water runs when on")


# ----------------------------------------------------------------------------------------------------------
# StoveBurner, StoveKnob


def _flames(radius: float, z: float, n: int = 12, size: float = 0.018) -> list[Part]:
    """A ring of small flame cones and a glowing ring, shown only when the burner is on."""
    parts = [_ring(radius, 0.004, (0, 0, z + 0.003), "hot", sections=24, state="on")]
    for a in np.linspace(0, 2 * np.pi, n, endpoint=False):
        cone = g.frustum(0.006, 0.0015, size, (radius * np.cos(a), radius * np.sin(a), z), sections=6)
        parts.append(Part(cone, "hot", collide=False, state="on"))
    return parts


@register("StoveBurner", variants=4, category="fixture")
def stove_burner(v: int, rng: np.random.Generator) -> AssetSpec:
    """One burner of a cooktop on its own flat section of cooktop: pots and pans go on the grate.

    Variants: 0 gas burner under a square grate, 1 electric coil, 2 glass-ceramic zone,
    3 wok burner under a round cast-iron grate. On: flames / a glowing coil / a glowing zone.
    """
    parts: list[Part] = []
    if v == 0:
        w = pick(rng, 0.28, 0.32)
        pt = 0.02
        parts.append(_box((-w / 2, -w / 2, 0), (w / 2, w / 2, pt), "metal"))
        parts.append(_cyl(0.05, 0.015, (0, 0, pt + 0.0075), "dark_metal", sections=20))
        parts.append(_cyl(0.038, 0.008, (0, 0, pt + 0.019), "dark_plastic", sections=20))
        g0, g1 = pt + 0.03, pt + 0.045
        e = w / 2 - 0.02
        bar = 0.012
        for s in (-1, 1):
            parts.append(_box((-e, s * e - bar / 2, g0), (e, s * e + bar / 2, g1), "dark_metal"))
            parts.append(_box((s * e - bar / 2, -e, g0), (s * e + bar / 2, e, g1), "dark_metal"))
            parts.append(_box((s * 0.042, -bar / 2, g0), (s * e, bar / 2, g1), "dark_metal"))
            parts.append(_box((-bar / 2, s * 0.042, g0), (bar / 2, s * e, g1), "dark_metal"))
            for s2 in (-1, 1):
                parts.append(_box((s * e - bar / 2, s2 * e - bar / 2, pt), (s * e + bar / 2, s2 * e + bar / 2, g0),
                                  "dark_metal"))
        parts += _flames(0.043, pt + 0.012)
        top, size = g1, 2 * e
    elif v == 1:
        w = pick(rng, 0.26, 0.3)
        pt = 0.025
        parts.append(_box((-w / 2, -w / 2, 0), (w / 2, w / 2, pt), "appliance"))
        parts.append(_cyl(0.105, 0.003, (0, 0, pt + 0.0015), "metal", sections=28, collide=False))
        zc = pt + 0.012
        for r in (0.036, 0.064, 0.092):
            parts.append(_ring(r, 0.005, (0, 0, zc), "dark_metal", sections=20))
            parts.append(_ring(r, 0.0056, (0, 0, zc), "hot", sections=20, state="on"))
        for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3):  # the coil's support arms
            arm = g.transformed(g.box_at((0.0, -0.004, pt), (0.1, 0.004, zc + 0.005)), yaw=float(a))
            parts.append(Part(arm, "dark_metal", convex=True))
        parts.append(_box((0.094, -0.012, pt), (0.125, 0.012, zc), "dark_metal"))
        top, size = zc + 0.005, 0.18
    elif v == 2:
        w = pick(rng, 0.3, 0.34)
        parts.append(_box((-w / 2, -w / 2, 0), (w / 2, w / 2, 0.03), "dark_metal"))
        parts.append(_box((-w / 2 + 0.003, -w / 2 + 0.003, 0.03), (w / 2 - 0.003, w / 2 - 0.003, 0.04), "screen"))
        parts.append(_ring(0.095, 0.0015, (0, 0, 0.04), "metal", sections=32))
        parts.append(_ring(0.07, 0.0012, (0, 0, 0.04), "metal", sections=28))
        parts.append(_cyl(0.093, 0.0012, (0, 0, 0.0406), "hot", sections=28, state="on"))
        parts.append(_box((w / 2 - 0.05, -w / 2 + 0.02, 0.04), (w / 2 - 0.02, -w / 2 + 0.028, 0.0408), "led_on",
                          state="on"))
        top, size = 0.04, w - 0.04
    else:
        w = pick(rng, 0.34, 0.37)
        pt = 0.02
        parts.append(_box((-w / 2, -w / 2, 0), (w / 2, w / 2, pt), "dark_metal"))
        parts.append(_cyl(0.058, 0.012, (0, 0, pt + 0.006), "dark_metal", sections=20))
        parts.append(_cyl(0.03, 0.016, (0, 0, pt + 0.008), "brass", sections=16))
        ring_r, g0, g1 = 0.13, pt + 0.028, pt + 0.045
        seg = 2 * ring_r * np.tan(np.pi / 10) + 0.012
        for k in range(10):
            a = float(k * np.pi / 5)
            piece = g.transformed(g.box((0.016, seg, g1 - g0), (ring_r, 0, (g0 + g1) / 2)), yaw=a)
            parts.append(Part(piece, "dark_metal", convex=True))
        for k in range(6):
            a = float(k * np.pi / 3 + np.pi / 6)
            finger = g.transformed(g.box_at((0.04, -0.007, g0), (ring_r, 0.007, g1 + 0.01)), yaw=a)
            parts.append(Part(finger, "dark_metal", convex=True))
            leg = g.transformed(g.box_at((ring_r - 0.008, -0.007, pt), (ring_r + 0.008, 0.007, g0)), yaw=a)
            parts.append(Part(leg, "dark_metal", convex=True))
        parts += _flames(0.05, pt + 0.012, n=14) + _flames(0.026, pt + 0.016, n=8, size=0.012)
        top, size = g1 + 0.01, 0.15
    region = surface("grate", size, size, top, 0.4, margin=0.0)
    return AssetSpec("StoveBurner", v, "fixture", [Link("base", parts, 3.0)], regions=[region],
                     description="stove burner on a cooktop section; hot when on")


@register("StoveKnob", variants=3, category="fixture")
def stove_knob(v: int, rng: np.random.Generator) -> AssetSpec:
    """A control knob on a small back plate that stands on a foot block; the knob faces +y (the back plate
    goes against the front of a cooktop or oven). On: the grip turns a quarter turn and the ring lights.

    Variants: 0 skirted round knob on a square plate, 1 bar knob on a round plate, 2 large dial with
    a scale of ticks.
    """
    pt = 0.01  # back plate thickness (y in [-pt, 0])
    foot_t = 0.006
    face = [0.065, 0.07, 0.085][v]
    kz = foot_t + face / 2 + 0.002
    parts: list[Part] = []
    if v == 1:
        parts.append(_cyl(face / 2, pt, (0, -pt / 2, kz), "dark_metal", axis="y", sections=24))
        parts.append(_box((-0.025, -pt, 0), (0.025, 0.0, kz), "dark_metal"))
    else:
        parts.append(_box((-face / 2, -pt, 0), (face / 2, 0, foot_t + face + 0.004), "metal" if v == 0 else
                          "dark_metal"))
    knob_r, knob_l = [0.02, 0.014, 0.027][v], [0.024, 0.018, 0.026][v]
    parts.append(_box((-0.026, -pt, 0), (0.026, knob_l + 0.01, foot_t), "dark_metal"))  # the foot block

    def along_y(mesh: trimesh.Trimesh) -> trimesh.Trimesh:
        """Turn a mesh built along +z so it points along +y, and move it onto the knob axis."""
        return g.transformed(mesh, roll=-np.pi / 2, offset=(0, 0, kz))

    if v == 0:
        skirt = g.revolve([(0, 0), (knob_r + 0.004, 0), (knob_r + 0.004, 0.004), (knob_r, 0.008), (knob_r - 0.002,
                          knob_l), (0, knob_l)], sections=20)
        parts.append(Part(along_y(skirt), "dark_plastic", convex=True))
        grip = g.box((0.008, 0.03, 0.01), (0, 0, knob_l + 0.005))
    elif v == 1:
        parts.append(Part(along_y(g.cylinder(knob_r, 0.01, (0, 0, 0.005), sections=16)), "metal", convex=True))
        grip = g.box((0.014, 0.046, knob_l - 0.01), (0, 0, 0.01 + (knob_l - 0.01) / 2))
    else:
        dial = g.revolve([(0, 0), (knob_r, 0), (knob_r, 0.012), (knob_r - 0.004, knob_l - 0.008), (0, knob_l - 0.008)],
                         sections=24)
        parts.append(Part(along_y(dial), "metal", convex=True))
        grip = g.box((0.01, 0.032, 0.01), (0, 0, knob_l - 0.008 + 0.005))
        for k in range(7):  # scale ticks round the dial
            a = float(np.radians(-135 + 45 * k))
            tick = g.box((0.003, 0.0015, 0.008), (0, 0.00075, knob_r + 0.01))
            parts.append(Part(g.transformed(tick, pitch=a, offset=(0, 0, kz)), "paper", collide=False))
    parts.append(Part(along_y(grip), "plastic" if v != 1 else "dark_plastic", collide=False, state="off"))
    parts.append(Part(along_y(g.transformed(grip, yaw=np.pi / 2)), "plastic" if v != 1 else "dark_plastic",
                      state="on"))
    ring_r = knob_r + (0.009 if v != 2 else 0.004)
    parts.append(_ring(ring_r, 0.0032, (0, 0.0005, kz), "dark_plastic", plane="xz", sections=24, state="off"))
    parts.append(_ring(ring_r, 0.0036, (0, 0.0008, kz), "hot", plane="xz", sections=24, state="on"))
    # centre the footprint (the knob sticks out in front of the plate)
    lo = np.min([p.mesh.bounds[0] for p in parts if p.state is None], axis=0)
    hi = np.max([p.mesh.bounds[1] for p in parts if p.state is None], axis=0)
    shift = (-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, 0.0)
    parts = _moved(parts, offset=shift)
    return AssetSpec("StoveKnob", v, "fixture", [Link("base", parts, 0.2)],
                     description="stove control knob on a back plate; its ring lights when on")


# ----------------------------------------------------------------------------------------------------------
# CoffeeMachine, Toaster


@register("CoffeeMachine", variants=4, category="appliance")
def coffee_machine(v: int, rng: np.random.Generator) -> AssetSpec:
    """A coffee machine: a base with a drip tray (where the mug goes), a tower with a water tank and a head
    with the spout over the tray. On: the power LED and display light up.

    Variants: 0 box-shaped single-serve machine with a side tank, 1 rounded pod machine with a rear tank,
    2 wide espresso machine with a portafilter and a steam wand, 3 tall bean-to-cup machine with a hopper.
    """
    w = [pick(rng, 0.2, 0.23), pick(rng, 0.17, 0.19), pick(rng, 0.3, 0.33), pick(rng, 0.25, 0.28)][v]
    d = [pick(rng, 0.3, 0.33), pick(rng, 0.32, 0.35), pick(rng, 0.28, 0.31), pick(rng, 0.36, 0.4)][v]
    h = [0.34, 0.3, 0.33, 0.38][v]
    body_slot = ["dark_plastic", "plastic", "metal", "dark_plastic"][v]
    tower_d = [0.14, 0.15, 0.16, 0.19][v]
    head_h = [0.08, 0.09, 0.07, 0.1][v]
    plinth = 0.03
    y_back, y_tower = -d / 2, -d / 2 + tower_d
    head_lo = h - head_h
    parts: list[Part] = []
    if v == 1:  # rounded pod machine: a round-cornered tower and a loaf-topped head, tank behind
        tank_d = 0.06
        tower = g.rounded_box(w, tower_d - tank_d, h - plinth, 0.04, "z", z0=plinth, cy=y_back + tank_d +
                              (tower_d - tank_d) / 2)
        parts.append(Part(tower, body_slot, convex=True))
        head = g.rounded_box(w, d - tower_d + 0.02, head_h, 0.03, "x", z0=head_lo, cy=y_tower - 0.01 +
                             (d - tower_d + 0.02) / 2 - 0.005)
        parts.append(Part(head, body_slot, convex=True))
        tank = g.rounded_box(w - 0.03, tank_d - 0.005, h - plinth - 0.03, 0.02, "z", z0=plinth, cy=y_back + tank_d / 2)
        parts.append(Part(tank, "glass", convex=True))
        parts.append(_box((-w / 2 + 0.02, y_back + 0.005, h - 0.032), (w / 2 - 0.02, y_back + tank_d - 0.005,
                                                                       h - 0.025),
                          "dark_plastic"))
        parts.append(_cyl(0.035, 0.004, (0, y_tower + 0.05, h + 0.001), "dark_plastic", sections=20, collide=False))
        base = g.rounded_box(w, d, plinth, 0.04, "z")
        parts.append(Part(base, "dark_plastic", convex=True))
    else:
        parts.append(_box((-w / 2, y_back, 0.0), (w / 2, d / 2, plinth), "dark_plastic" if v != 1 else body_slot))
        tank_w = 0.06 if v == 0 else 0.0
        tx = w / 2 - tank_w
        parts.append(_box((-w / 2, y_back, plinth), (tx, y_tower, head_lo), body_slot))
        if v == 0:  # a glass water tank on the right of the tower with a lid
            parts.append(_box((tx, y_back + 0.01, plinth), (w / 2, y_tower - 0.01, h - 0.015), "glass"))
            parts.append(_box((tx - 0.002, y_back + 0.008, h - 0.015), (w / 2 + 0.002, y_tower - 0.008, h),
                              "dark_plastic"))
            parts.append(_box((-w / 2, y_back, head_lo), (tx, d / 2 - 0.02, h), body_slot))
        elif v == 2:  # boxy espresso head, cup warmer rails on top, tank behind a lid
            parts.append(_box((-w / 2, y_back, head_lo), (w / 2, d / 2 - 0.04, h), body_slot))
            for x in np.linspace(-w / 2 + 0.03, w / 2 - 0.03, 6):
                parts.append(_box((x - 0.003, y_back + 0.02, h), (x + 0.003, d / 2 - 0.06, h + 0.006), "metal",
                                  collide=False))
        else:  # bean-to-cup: head to the front, a bean hopper on top
            parts.append(_box((-w / 2, y_back, head_lo), (w / 2, d / 2 - 0.02, h), body_slot))
            hopper = g.frustum(0.06, 0.075, 0.06, (-w / 4, y_back + 0.1, h), sections=20)
            parts.append(Part(hopper, "glass", convex=True))
            parts.append(_cyl(0.078, 0.012, (-w / 4, y_back + 0.1, h + 0.066), "dark_plastic", sections=20))
    # drip tray with a grate
    tw = min(w - 0.03, 0.2)
    ty0, ty1 = y_tower + 0.005, d / 2 - 0.005
    tray_top = plinth + 0.015
    parts.append(_box((-tw / 2, ty0, plinth), (tw / 2, ty1, tray_top), "metal"))
    for y in np.linspace(ty0 + 0.015, ty1 - 0.015, 6):
        parts.append(_box((-tw / 2 + 0.012, y - 0.002, tray_top), (tw / 2 - 0.012, y + 0.002, tray_top + 0.001),
                          "dark_metal", collide=False))
    head_front = d / 2 - (0.02 if v != 2 else 0.04)
    if v == 1:
        head_front = d / 2 + 0.005
    spout_y = (ty0 + ty1) / 2 if v != 2 else (ty0 + head_front) / 2
    # spouts
    if v == 2:  # group head and portafilter with two spouts and a handle
        parts.append(_cyl(0.035, 0.02, (0, spout_y, head_lo - 0.01), "metal", sections=20))
        parts.append(_cyl(0.03, 0.022, (0, spout_y, head_lo - 0.031), "metal", sections=20))
        handle = g.rod((0.0, spout_y + 0.025, head_lo - 0.031), (0.03, d / 2 + 0.07, head_lo - 0.04), 0.012,
                       sections=10)
        parts.append(Part(handle, "dark_plastic", convex=True))
        for sx in (-1, 1):
            parts.append(_cyl(0.005, 0.015, (sx * 0.012, spout_y, head_lo - 0.049), "metal", sections=8,
                              collide=False))
        spout_lo = head_lo - 0.056
        wand = g.rod((w / 2 - 0.03, head_front - 0.02, head_lo), (w / 2 - 0.03, head_front + 0.01, plinth + 0.12),
                     0.005,
                     sections=8)
        parts.append(Part(wand, "metal", collide=False))
        gauge_z = head_lo + head_h / 2
        parts.append(_cyl(0.025, 0.006, (-w / 4, head_front + 0.003, gauge_z), "metal", axis="y", sections=20,
                          collide=False))
        parts.append(_cyl(0.021, 0.002, (-w / 4, head_front + 0.007, gauge_z), "paper", axis="y", sections=20,
                          collide=False))
    else:
        n_sp = 2 if v == 3 else 1
        for k in range(n_sp):
            sx = 0.0 if n_sp == 1 else (k - 0.5) * 0.03
            parts.append(_cyl(0.008 if n_sp == 2 else 0.012, 0.02, (sx, spout_y, head_lo - 0.01), "metal",
                              sections=10, collide=False))
        spout_lo = head_lo - 0.02
    # controls on the head front: power LED and display (dark when off, lit when on), buttons
    fz = head_lo + head_h * 0.5
    led_x = w / 2 - 0.025
    parts.append(_cyl(0.006, 0.003, (led_x, head_front + 0.0015, fz), "led_off", axis="y", sections=10,
                      collide=False, state="off"))
    parts.append(_cyl(0.0065, 0.004, (led_x, head_front + 0.002, fz), "led_on", axis="y", sections=10,
                      state="on"))
    if v in (0, 3):
        dw, dh = (0.06, 0.025) if v == 0 else (0.1, 0.05)
        dx = 0.0 if v == 0 else -0.01
        lo_ = (dx - dw / 2, head_front, fz - dh / 2)
        parts.append(_box(lo_, (dx + dw / 2, head_front + 0.002, fz + dh / 2), "led_off", collide=False, state="off"))
        parts.append(_box(lo_, (dx + dw / 2, head_front + 0.003, fz + dh / 2), "led_on", state="on"))
        for k in range(3 if v == 0 else 4):
            bx = -w / 2 + 0.02 + k * 0.018 if v == 0 else dx - dw / 2 + 0.012 + k * 0.025
            bz = fz if v == 0 else fz - dh / 2 - 0.012
            if v == 0 and bx > dx - dw / 2 - 0.008:
                continue
            parts.append(_cyl(0.006, 0.004, (bx, head_front + 0.002, bz), "metal", axis="y", sections=10,
                              collide=False))
    elif v == 1:
        for k in range(3):
            parts.append(_cyl(0.008, 0.003, (-0.03 + 0.03 * k, d / 2 - 0.035, h + 0.0005), "metal", sections=10,
                              collide=False))
        parts.append(_ring(0.04, 0.003, (0, y_tower + 0.05, h + 0.001), "led_on", sections=24, state="on"))
    else:
        for k in range(3):
            parts.append(_cyl(0.007, 0.005, (0.0 + 0.02 * k, head_front + 0.0025, fz + 0.015), "metal", axis="y",
                              sections=10, collide=False))
        parts.append(_box((-0.01, head_front, fz - 0.03), (0.07, head_front + 0.002, fz - 0.006), "led_off",
                          state="off"))
        parts.append(_box((-0.01, head_front, fz - 0.03), (0.07, head_front + 0.003, fz - 0.006), "led_on",
                          state="on"))
    clearance = round(spout_lo - tray_top - 0.005, 3)
    region = Region("drip_tray", "surface", (0.0, spout_y, tray_top), (tw - 0.01, min(ty1 - ty0 - 0.02, 0.12),
                                                                        clearance))
    return AssetSpec("CoffeeMachine", v, "appliance", [Link("base", parts, 5.0)], regions=[region],
                     description="coffee machine with a water tank, a spout and a drip tray for a mug")


@register("Toaster", variants=4, category="appliance")
def toaster(v: int, rng: np.random.Generator) -> AssetSpec:
    """A toaster: a rounded body with real bread slots (the body is cut into convex pieces round them), a
    lever and a browning dial. On: the lever is down and the slots glow.

    Variants: 0 two slots, rounded corners; 1 two slots, loaf-shaped top, lever on the end;
    2 four slots (2 x 2), square; 3 retro two long slots, domed ends.
    """
    L = [pick(rng, 0.26, 0.29), pick(rng, 0.27, 0.3), pick(rng, 0.4, 0.43), pick(rng, 0.38, 0.42)][v]
    W = [pick(rng, 0.16, 0.18), pick(rng, 0.19, 0.21), pick(rng, 0.17, 0.19), pick(rng, 0.17, 0.19)][v]
    H = [0.19, 0.2, 0.19, 0.21][v]
    edges, r = [("z", 0.04), ("x", 0.05), ("z", 0.015), ("y", 0.08)][v]
    slot = ["metal", "appliance", "plastic", "metal"][v]
    body = g.rounded_box(L, W, H, r, edges, sections=20)
    sw, sd = 0.034, [0.14, 0.145, 0.14, 0.15][v]
    z_s = H - sd
    sl = [L - 0.09, L - 0.08, (L - 0.09) / 2, L - 2 * r - 0.04][v]
    sy = [-(sw / 2 + 0.012), sw / 2 + 0.012]
    sx = [0.0] if v != 2 else [-(sl / 2 + 0.012), sl / 2 + 0.012]
    slots = [(x - sl / 2, x + sl / 2, y - sw / 2, y + sw / 2) for x in sx for y in sy]
    parts: list[Part] = [Part(g.clip_to_box(body, (-L, -W, -0.01), (L, W, z_s)), slot, convex=True)]
    # the layer with the slots: bands in y, each cut into runs in x between the slots
    ys = sorted({-W / 2 - 0.01, W / 2 + 0.01} | {s[2] for s in slots} | {s[3] for s in slots})
    for ya, yb in itertools.pairwise(ys):
        mid = (ya + yb) / 2
        cuts = sorted((s[0], s[1]) for s in slots if s[2] < mid < s[3])
        xs = [-L / 2 - 0.01] + [c for cut in cuts for c in cut] + [L / 2 + 0.01]
        for xa, xb in zip(xs[0::2], xs[1::2]):
            piece = g.clip_to_box(body, (xa, ya, z_s), (xb, yb, H + 0.01))
            if len(piece.vertices) and piece.volume > 1e-7:
                parts.append(Part(piece, slot, convex=True))
    regions = []
    for i, (x0, x1, y0, y1) in enumerate(slots):
        lt = 0.001
        for ya, yb in ((y0, y0 + lt), (y1 - lt, y1)):
            parts.append(_box((x0, ya, z_s), (x1, yb, H - 0.002), "dark_metal", collide=False))
        for xa, xb in ((x0, x0 + lt), (x1 - lt, x1)):
            parts.append(_box((xa, y0, z_s), (xb, y1, H - 0.002), "dark_metal", collide=False))
        parts.append(_box((x0, y0, z_s), (x1, y1, z_s + 0.002), "dark_metal", collide=False))
        for ya, yb in ((y0 + lt, y0 + 2.5 * lt), (y1 - 2.5 * lt, y1 - lt)):
            parts.append(_box((x0 + 0.004, ya, z_s + 0.01), (x1 - 0.004, yb, H - 0.006), "hot", state="on"))
        parts.append(_box((x0 + 0.004, y0 + 0.003, z_s + 0.002), (x1 - 0.004, y1 - 0.003, z_s + 0.004), "hot",
                          state="on"))
        # a chrome bezel round the slot opening
        b = 0.005
        for lo, hi in (((x0 - b, y0 - b, H), (x1 + b, y0, H + 0.002)), ((x0 - b, y1, H), (x1 + b, y1 + b, H + 0.002)),
                       ((x0 - b, y0, H), (x0, y1, H + 0.002)), ((x1, y0, H), (x1 + b, y1, H + 0.002))):
            parts.append(_box(lo, hi, "metal" if slot != "metal" else "dark_metal", collide=False))
        regions.append(Region(f"slot_{i}", "volume", ((x0 + x1) / 2, (y0 + y1) / 2, (z_s + H) / 2),
                              (x1 - x0 - 0.01, y1 - y0 - 0.006, H - z_s)))
    # lever in a guide slot (up when off, down when on) and a browning dial
    trim = "dark_plastic" if slot != "dark_plastic" else "metal"
    lz_hi, lz_lo = z_s + sd * 0.8, 0.05
    if v == 1:  # on the +x end
        fx = L / 2
        parts.append(_box((fx, -0.005, lz_lo - 0.01), (fx + 0.002, 0.005, lz_hi + 0.01), trim, collide=False))
        for z, state in ((lz_hi, "off"), (lz_lo, "on")):
            parts.append(_box((fx, -0.02, z - 0.008), (fx + 0.022, 0.02, z + 0.008), trim, collide=False, state=state))
        parts.append(_cyl(0.014, 0.012, (fx + 0.006, 0.045, 0.05), trim, axis="x", sections=14, collide=False))
    else:
        fy = W / 2
        lx = L / 2 - (r if edges == "z" else 0.0) - 0.035
        parts.append(_box((-lx - 0.005, fy, lz_lo - 0.01), (-lx + 0.005, fy + 0.002, lz_hi + 0.01), trim,
                          collide=False))
        for z, state in ((lz_hi, "off"), (lz_lo, "on")):
            parts.append(_box((-lx - 0.022, fy, z - 0.008), (-lx + 0.022, fy + 0.022, z + 0.008), trim, collide=False,
                              state=state))
        parts.append(_cyl(0.014, 0.012, (lx, fy + 0.006, 0.06), trim, axis="y", sections=14, collide=False))
        parts.append(_box((-lx, fy, 0.008), (lx, fy + 0.003, 0.02), trim, collide=False))  # crumb tray
    return AssetSpec("Toaster", v, "appliance", [Link("base", parts, 2.0)], regions=regions,
                     description="toaster with bread slots, a lever and a browning dial; slots glow when on")
