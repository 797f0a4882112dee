"""Storage: cabinets, drawers, dressers, carts, safes, hampers, garbage cans, boxes."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import (
    carcass,
    corner_legs,
    drawer,
    hinged_door,
    knob,
    pick,
    surface,
)
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register, variant_rng
from luminous_sim.assets.spec import AssetSpec, Joint, Link, Part, Region

add_palettes(
    box_cardboard=hex_colours("b98b5e", "a67b50", "c9a27a", "d8c3a0"),
    hamper_wicker=hex_colours("b08a5a", "9c7447", "c9a878", "7a5a3a"),
)

# ----------------------------------------------------------------------------------------------------------
# shared helpers (local to this module)
# ----------------------------------------------------------------------------------------------------------


def _parts(meshes: Sequence[trimesh.Trimesh], slot: str, collide: bool = True) -> list[Part]:
    return [Part(m, slot, collide=collide, convex=True if collide else None) for m in meshes]


def _shift(parts: Sequence[Part], offset: Sequence[float]) -> None:
    for p in parts:
        p.mesh.apply_translation(np.asarray(offset, dtype=float))


def _set_pull(link: Link, style: str, w: float, h: float, y: float, slot: str, n_keep: int) -> None:
    """Replace the bar pull that `drawer()` adds (parts after the first `n_keep`) by another pull style."""
    if style == "bar":
        return
    keep = link.parts[:n_keep]
    if style == "knob":
        xs = (-w / 4, w / 4) if w > 0.55 else (0.0,)
        link.parts = keep + [knob((x, y, h * 0.55), "metal" if slot == "metal" else slot, 0.016) for x in xs]
    elif style == "cup":  # a half-round bin pull
        cup = g.box((min(0.1, w * 0.4), 0.022, 0.03), (0.0, y + 0.011, h * 0.62))
        lip = g.box((min(0.1, w * 0.4), 0.012, 0.008), (0.0, y + 0.016, h * 0.62 - 0.018))
        link.parts = keep + [Part(cup, slot, collide=False), Part(lip, slot, collide=False)]
    elif style == "ring":  # brass ring pulls on round back plates
        xs = (-w / 4, w / 4) if w > 0.55 else (0.0,)
        extra = []
        for x in xs:
            extra.append(Part(g.cylinder(0.02, 0.004, (x, y + 0.002, h * 0.6), axis="y", sections=12), slot,
                              collide=False))
            extra.append(Part(g.torus_arc(0.018, 0.003, (x, y + 0.008, h * 0.6), plane="xz", start=np.pi,
                                          end=2 * np.pi, sections=8, minor_sections=6), slot, collide=False))
        link.parts = keep + extra


def _door(name: str, x0: float, x1: float, y_front: float, z0: float, z1: float, hinge: str, slot: str,
          handle_z: float, style: str = "bar", glass: bool = False, thickness: float = 0.02,
          mass: float = 2.0, handle_slot: str = "metal") -> tuple[Link, Joint]:
    """A cabinet door (common.hinged_door) with its pull moved to `handle_z` and an optional glass panel."""
    link, joint = hinged_door(name, "base", x0, x1, y_front, z0, z1, hinge, slot, thickness=thickness,
                              handle_slot=handle_slot, mass=mass)
    sign = 1.0 if hinge == "left" else -1.0
    width = x1 - x0
    panel, handle = link.parts[0], link.parts[1:4]
    hz_old = float(handle[0].mesh.bounds.mean(axis=0)[2])
    half = 0.07 if style == "knob" else float(np.ptp(handle[0].mesh.bounds[:, 2])) / 2 + 0.04
    hz = float(np.clip(handle_z, z0 + half, z1 - half))
    if style == "knob":
        handle = [knob((sign * (width - 0.04), thickness, hz), handle_slot, 0.016)]
    else:
        _shift(handle, (0, 0, hz - hz_old))
    body = [panel]
    if glass:  # a frame of stiles and rails around a glass pane
        f = min(0.07, width * 0.18)
        xa, xb = min(0, sign * width), max(0, sign * width)
        body = [
            Part(g.box_at((xa, 0, z0), (xa + f, thickness, z1)), slot, convex=True),
            Part(g.box_at((xb - f, 0, z0), (xb, thickness, z1)), slot, convex=True),
            Part(g.box_at((xa + f, 0, z0), (xb - f, thickness, z0 + f)), slot, convex=True),
            Part(g.box_at((xa + f, 0, z1 - f), (xb - f, thickness, z1)), slot, convex=True),
            Part(g.box_at((xa + f, thickness * 0.35, z0 + f), (xb - f, thickness * 0.65, z1 - f)), "glass",
                 convex=True),
        ]
    else:  # a shaker-style raised centre panel
        m = min(0.06, width * 0.15)
        xa, xb = min(0, sign * width), max(0, sign * width)
        if z1 - z0 > 0.25 and width > 0.2:
            body.append(Part(g.box_at((xa + m, thickness, z0 + m), (xb - m, thickness + 0.006, z1 - m)), slot,
                             collide=False))
    link.parts = body + handle + link.parts[4:]
    return link, joint


def _volume(name: str, x0: float, x1: float, y0: float, y1: float, z0: float, z1: float,
            requires_open: str | None = None, link: str = "base", margin: float = 0.01) -> Region:
    """A box interior region spanning the given extents, shrunk by `margin`."""
    return Region(name, "volume", ((x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2),
                  (x1 - x0 - 2 * margin, y1 - y0 - 2 * margin, z1 - z0 - 2 * margin),
                  link=link, requires_open=requires_open)


# ----------------------------------------------------------------------------------------------------------
# Cabinet
# ----------------------------------------------------------------------------------------------------------

_CABINETS = [
    # kind, doors, style, shelves
    ("base", "left", "bar", 1),
    ("base", "double", "knob", 1),
    ("wall", "right", "bar", 1),
    ("wall", "double", "glass", 2),
    ("pantry", "double", "bar", 4),
    ("pantry", "stacked", "knob", 4),
]


@register("Cabinet", variants=6, category="furniture")
def cabinet(v: int, rng: np.random.Generator) -> AssetSpec:
    """Kitchen cabinets: base cabinets (toe kick, 1-2 doors, a shelf), wall cabinets (box-shaped, 1-2 doors,
    one with glass fronts) and tall pantry cabinets (double doors or stacked upper/lower doors)."""
    kind, doors, style, n_shelves = _CABINETS[v]
    t = 0.018
    dt = 0.02  # door thickness
    if kind == "base":
        w = pick(rng, 0.45, 0.6) if doors != "double" else pick(rng, 0.76, 0.92)
        d, h, toe = 0.6, 0.9, 0.1
    elif kind == "wall":
        w = pick(rng, 0.4, 0.6) if doors != "double" else pick(rng, 0.7, 0.9)
        d, h, toe = 0.35, pick(rng, 0.6, 0.8), 0.0
    else:
        w = pick(rng, 0.7, 0.85) if doors == "double" else pick(rng, 0.5, 0.6)
        d, h, toe = 0.6, pick(rng, 2.0, 2.1), 0.1
    slot = ["wood", "painted", "painted", "wood", "painted", "dark_wood"][v]
    cd = d - dt
    y_front = d / 2 - dt
    parts = carcass(w, cd, h - toe, t, slot, z0=toe)
    _shift(parts, (0, -dt / 2, 0))
    if toe:  # recessed plinth
        plinth = g.box_at((-w / 2 + 0.01, -d / 2, 0), (w / 2 - 0.01, y_front - 0.06, toe))
        parts.append(Part(plinth, "dark_plastic", convex=True))
    y_back = -d / 2 + t
    z_floor, z_ceil = toe + t, h - t
    # shelves split the interior evenly; a stacked pantry has a fixed divider where the doors meet
    split = round(toe + 0.62 * (h - toe), 3) if doors == "stacked" else None
    shelf_zs = [round(z, 3) for z in np.linspace(z_floor, z_ceil, n_shelves + 2)[1:-1]]
    if split is not None:
        shelf_zs = sorted(set([round(z, 3) for z in np.linspace(z_floor, split, 3)[1:-1]] + [split] +
                              [round(z, 3) for z in np.linspace(split, z_ceil, 3)[1:-1]]))
    for z in shelf_zs:
        front = y_front if z == split else y_front - 0.03
        parts.append(Part(g.box_at((-w / 2 + t, y_back, z - t / 2), (w / 2 - t, front, z + t / 2)), slot,
                          convex=True))
    # doors
    links, joints = [Link("base", parts, {"base": 26.0, "wall": 18.0, "pantry": 36.0}[kind])], []
    gap = 0.003
    dz0, dz1 = toe + gap, h - gap
    handle_z = dz1 if kind == "base" else (dz0 if kind == "wall" else toe + 0.55 * (h - toe))
    xl, xr = -w / 2 + gap, w / 2 - gap
    xi0, xi1 = -w / 2 + t, w / 2 - t
    # each door: (name, hinge, x0, x1, z0, z1, handle z, and the interior x0, x1, z0, z1 it uncovers)
    if doors in ("left", "right"):
        plan = [("door", doors, xl, xr, dz0, dz1, handle_z, xi0, xi1, z_floor, z_ceil)]
    elif doors == "double":
        plan = [("door_left", "left", xl, -gap, dz0, dz1, handle_z, xi0, 0.0, z_floor, z_ceil),
                ("door_right", "right", gap, xr, dz0, dz1, handle_z, 0.0, xi1, z_floor, z_ceil)]
    else:  # stacked: a lower and an upper door, both hinged on the left, handles near the split
        plan = [("door_lower", "left", xl, xr, dz0, split - gap, split - 0.15, xi0, xi1, z_floor, split - t / 2),
                ("door_upper", "left", xl, xr, split + gap, dz1, split + 0.15, xi0, xi1, split + t / 2, z_ceil)]
    sections = []  # (joint name, x0, x1, z0, z1): the interior each door uncovers
    for name, hinge, x0, x1, z0, z1, hz, sx0, sx1, sz0, sz1 in plan:
        lk, jt = _door(name, x0, x1, y_front, z0, z1, hinge, slot, hz, "bar" if style == "glass" else style,
                       glass=style == "glass", mass=2.5 if kind == "pantry" else 2.0)
        links.append(lk)
        joints.append(jt)
        sections.append((jt.name, sx0, sx1, sz0, sz1))
    regions = []
    levels = [z_floor] + [z + t / 2 for z in shelf_zs]
    tops = [z - t / 2 for z in shelf_zs] + [z_ceil]
    for jname, x0, x1, sz0, sz1 in sections:
        side = jname.replace("_hinge", "").replace("door", "").strip("_")
        k = 0
        for z0, z1 in zip(levels, tops):
            if z0 >= sz0 - 1e-6 and z1 <= sz1 + 1e-6:
                regions.append(_volume(f"shelf_{side + '_' if side else ''}{k}", x0, x1, y_back, y_front,
                                       z0, z1, requires_open=jname))
                k += 1
    desc = {"base": "kitchen base cabinet with a toe kick", "wall": "wall-hung kitchen cabinet",
            "pantry": "tall pantry cabinet"}[kind]
    return AssetSpec("Cabinet", v, "furniture", links, joints=joints, regions=regions,
                     description=f"{desc}, hinged doors and interior shelves")


# ----------------------------------------------------------------------------------------------------------
# Drawer (a single drawer unit) and Dresser
# ----------------------------------------------------------------------------------------------------------


def _drawer_bank(w: float, d: float, h: float, t: float, z0: float, rows: Sequence[tuple[float, int]],
                 slot: str, front_slot: str, pull: str, pull_slot: str, drawer_mass: float = 1.5
                 ) -> tuple[list[Part], list[Link], list[Joint], list[Region]]:
    """A carcass w x d x h (bottom at z0) filled with rows of inset drawers, bottom row first.

    `rows` lists (relative height, number of drawers side by side). Returns carcass parts (with rails and
    dividers), drawer links, their slide joints and their inside regions.
    """
    parts = carcass(w, d, h, t, slot, z0=z0)
    rail = 0.018
    y_front = d / 2 - 0.02
    total = sum(r for r, _ in rows)
    inner_h = h - 2 * t - rail * (len(rows) - 1)
    links, joints, regions = [], [], []
    z = z0 + t
    k = 0
    gap = 0.003
    for i, (rel, cols) in enumerate(rows):
        rh = inner_h * rel / total
        if i:  # front rail below this row
            parts.append(Part(g.box_at((-w / 2 + t, d / 2 - 0.05, z), (w / 2 - t, d / 2, z + rail)), slot,
                              convex=True))
            z += rail
        cw = (w - 2 * t - rail * (cols - 1)) / cols
        for c in range(cols):
            x_lo = -w / 2 + t + c * (cw + rail)
            if c:
                parts.append(Part(g.box_at((x_lo - rail, d / 2 - 0.05, z), (x_lo, d / 2, z + rh)), slot,
                                  convex=True))
            dw, dh = cw - 2 * gap, rh - 2 * gap
            lk, jt, rg = drawer(f"drawer_{k}", "base", dw, d - t - 0.035, dh, x_lo + cw / 2, y_front, z + gap,
                                slot, front_slot=front_slot, handle_slot=pull_slot, mass=drawer_mass)
            _set_pull(lk, pull, dw, dh, 0.02, pull_slot, 5)
            links.append(lk)
            joints.append(jt)
            regions.append(rg)
            k += 1
        z += rh
    return parts, links, joints, regions


_DRAWER_UNITS = [
    # w, h, pull, feet, top overhang
    ((0.5, 0.6), (0.2, 0.24), "bar", "plinth", False),
    ((0.4, 0.46), (0.26, 0.3), "knob", "legs", False),
    ((0.5, 0.6), (0.22, 0.27), "cup", "none", True),
    ((0.42, 0.5), (0.24, 0.3), "ring", "bun", True),
]


def _feet(style: str, w: float, d: float, fh: float, slot: str) -> list[Part]:
    """Supports under a case piece: a recessed plinth, square/tapered legs or bun feet (fh tall)."""
    if style == "plinth":
        return [Part(g.box_at((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, d / 2 - 0.04, fh)), slot,
                     convex=True)]
    if style == "legs":
        return corner_legs(w, d, fh, 0.03, 0.02, slot, square=True)
    if style == "tapered":
        parts = []
        for sx in (-1, 1):
            for sy in (-1, 1):
                parts.append(Part(g.frustum(0.012, 0.022, fh, (sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), 0),
                                            sections=10), slot, convex=True))
        return parts
    if style == "bun":
        parts = []
        r = 0.03
        for sx in (-1, 1):
            for sy in (-1, 1):
                prof = [(0, 0), (r * 0.7, 0), (r, fh * 0.45), (r * 0.8, fh), (0, fh)]
                parts.append(Part(g.revolve(prof, (sx * (w / 2 - 0.05), sy * (d / 2 - 0.05), 0), sections=12), slot,
                                  convex=True))
        return parts
    return []


@register("Drawer", variants=4, category="furniture")
def drawer_unit(v: int, rng: np.random.Generator) -> AssetSpec:
    """A single drawer unit: a small carcass with one sliding drawer (bar, knob, cup or ring pull)."""
    (w_lo, w_hi), (h_lo, h_hi), pull, feet, overhang = _DRAWER_UNITS[v]
    w, h, d = pick(rng, w_lo, w_hi), pick(rng, h_lo, h_hi), pick(rng, 0.45, 0.52)
    slot = ["wood", "painted", "dark_wood", "painted"][v]
    front_slot = ["wood", "painted", "dark_wood", "wood"][v]
    fh = {"plinth": 0.04, "legs": 0.1, "none": 0.0, "bun": 0.05}[feet]
    t = 0.016
    body_h = h - fh - (0.025 if overhang else 0.0)
    parts, links, joints, regions = _drawer_bank(w, d, body_h, t, fh, [(1.0, 1)], slot, front_slot, pull,
                                                 "brass" if pull == "ring" else "metal", drawer_mass=1.5)
    parts += _feet(feet, w, d, fh, slot)
    top_z = fh + body_h
    if overhang:
        parts.append(Part(g.box_at((-w / 2 - 0.015, -d / 2, top_z), (w / 2 + 0.015, d / 2 + 0.02, h)), front_slot,
                          convex=True))
    regions.append(surface("top", w, d, h, 0.5))
    return AssetSpec("Drawer", v, "furniture", [Link("base", parts, 6.5)] + links, joints=joints, regions=regions,
                     description="single drawer unit with one sliding drawer")


_DRESSERS = [
    # w, h, d, rows (bottom first), feet, feet height, pull, overhang top
    ((1.2, 1.45), (0.78, 0.85), [(1.0, 2), (1.0, 2), (1.0, 2)], "legs", 0.1, "knob", True),
    ((0.75, 0.9), (1.15, 1.3), [(1.2, 1), (1.1, 1), (1.0, 1), (1.0, 1), (0.9, 1)], "plinth", 0.07, "bar", False),
    ((0.9, 1.05), (0.75, 0.82), [(1.0, 1), (1.0, 1), (1.0, 1)], "tapered", 0.18, "bar", True),
    ((0.9, 1.0), (0.85, 0.95), [(1.2, 1), (1.1, 1), (0.8, 2)], "bun", 0.06, "ring", True),
    ((0.55, 0.65), (1.2, 1.35), [(1.0, 1)] * 6, "plinth", 0.06, "cup", False),
]


@register("Dresser", variants=5, category="furniture")
def dresser(v: int, rng: np.random.Generator) -> AssetSpec:
    """A chest of drawers: wide 2x3, tall 5-drawer chest, mid-century 3-drawer on tapered legs, 2+2 on bun
    feet, narrow 6-drawer lingerie chest; each drawer has an inside region, the top is a surface."""
    (w_lo, w_hi), (h_lo, h_hi), rows, feet, fh, pull, overhang = _DRESSERS[v]
    w, h, d = pick(rng, w_lo, w_hi), pick(rng, h_lo, h_hi), pick(rng, 0.45, 0.52)
    slot = ["wood", "painted", "dark_wood", "wood", "painted"][v]
    front_slot = ["wood", "painted", "wood", "wood", "painted"][v]
    top_t = 0.03 if overhang else 0.0
    body_h = h - fh - top_t
    parts, links, joints, regions = _drawer_bank(w, d, body_h, 0.02, fh, rows, slot, front_slot, pull,
                                                 "brass" if pull == "ring" else "metal")
    parts += _feet(feet, w, d, fh, slot)
    if overhang:
        parts.append(Part(g.box_at((-w / 2 - 0.02, -d / 2, h - top_t), (w / 2 + 0.02, d / 2 + 0.025, h)), front_slot,
                          convex=True))
    regions.append(surface("top", w, d, h, 0.6))
    return AssetSpec("Dresser", v, "furniture", [Link("base", parts, 42.0)] + links, joints=joints, regions=regions,
                     description=f"dresser with {len(links)} drawers and a top surface")


# ----------------------------------------------------------------------------------------------------------
# Cart
# ----------------------------------------------------------------------------------------------------------


def _caster(x: float, y: float, rw: float, mount_z: float, slot: str = "dark_plastic") -> list[Part]:
    """A swivel caster under a frame corner: wheel (axle along x), fork and stem up to `mount_z`."""
    wheel = g.cylinder(rw, 0.022, (x, y, rw), axis="x", sections=12)
    fork = g.box((0.032, 2 * rw * 0.8, rw * 0.9), (x, y, rw + rw * 0.45 + 0.004))
    top = 2 * rw + 0.004
    stem = g.cylinder(0.008, max(mount_z - top, 0.005), (x, y, (top + mount_z) / 2), sections=8)
    return [Part(wheel, "rubber", convex=True), Part(fork, "metal", collide=False),
            Part(stem, "metal", collide=False)]


_CARTS = [
    # levels, shelf style, post style, handle, top slab
    (3, "tray", "round", False, False),
    (2, "rail", "round", True, False),
    (3, "flat", "square", False, True),
    (3, "tray", "square", True, False),
]


@register("Cart", variants=4, category="furniture")
def cart(v: int, rng: np.random.Generator) -> AssetSpec:
    """A rolling cart: corner posts on casters with 2-3 shelf levels (lipped trays, railed bar-cart
    shelves, or a kitchen cart with a butcher-block top); some have a push handle."""
    levels, shelf, post, handle, slab = _CARTS[v]
    w = pick(rng, 0.55, 0.7) if v != 3 else pick(rng, 0.42, 0.5)
    d = pick(rng, 0.36, 0.45)
    h = pick(rng, 0.78, 0.9) if v != 3 else pick(rng, 0.85, 0.95)
    rw = 0.035 if v != 3 else 0.03
    frame = ["metal", "brass", "dark_metal", "plastic"][v]
    shelf_slot = {"tray": frame, "rail": "glass", "flat": "wood"}[shelf]
    mount = 2 * rw + 0.02
    inset = 0.02
    parts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            x, y = sx * (w / 2 - inset), sy * (d / 2 - inset)
            parts += _caster(x, y, rw, mount)
            if post == "round":
                parts.append(Part(g.cylinder(0.012, h - mount, (x, y, (h + mount) / 2), sections=10), frame,
                                  convex=True))
            else:
                parts.append(Part(g.box((0.025, 0.025, h - mount), (x, y, (h + mount) / 2)), frame, convex=True))
    st = 0.02
    z_bottom = mount + 0.06
    shelf_tops = [round(z, 3) for z in np.linspace(z_bottom + st, h - (0.04 if slab else 0.0), levels)]
    regions = []
    for i, zt in enumerate(shelf_tops):
        top_level = i == levels - 1
        if slab and top_level:  # butcher-block top overhanging the frame
            parts.append(Part(g.box_at((-w / 2 - 0.04, -d / 2 - 0.03, zt), (w / 2 + 0.04, d / 2 + 0.03, h)),
                              "wood", convex=True))
            regions.append(surface(f"shelf_{i}", w + 0.08, d + 0.06, h, 0.5))
            continue
        parts.append(Part(g.box_at((-w / 2, -d / 2, zt - st), (w / 2, d / 2, zt)), shelf_slot, convex=True))
        if shelf == "tray":  # lips around the tray
            parts += _parts(g.rect_rim(w, d, zt, zt + 0.035, 0.0, 0.008), frame)
        elif shelf == "rail":  # gallery rails on the long sides
            for s in (-1, 1):
                y = s * (d / 2 - inset)
                rail = g.rod((-w / 2 + inset, y, zt + 0.06), (w / 2 - inset, y, zt + 0.06), 0.006)
                parts.append(Part(rail, frame, collide=False))
        else:  # flat shelf with an apron
            parts.append(Part(g.box_at((-w / 2, d / 2 - 0.015, zt - st - 0.05), (w / 2, d / 2, zt - st)), "wood",
                              collide=False))
        clearance = (shelf_tops[i + 1] - st - zt - 0.01) if not top_level else 0.45
        if slab and i == levels - 2:
            clearance = shelf_tops[i + 1] - zt - 0.01
        regions.append(surface(f"shelf_{i}", w, d, zt, round(clearance, 3), margin=0.035))
    if handle:  # push handle above one end
        hx = w / 2 - inset
        hz = h + 0.12
        for sy in (-1, 1):
            parts.append(Part(g.rod((hx, sy * (d / 2 - inset), h - 0.01), (hx, sy * (d / 2 - inset), hz), 0.01),
                              frame, convex=True))
        parts.append(Part(g.rod((hx, -d / 2 + inset, hz), (hx, d / 2 - inset, hz), 0.013), "rubber", convex=True))
    if slab:  # towel bar on brackets at the end
        xb, zb = -w / 2 - 0.06, h - 0.1
        parts.append(Part(g.rod((xb, -d / 3, zb), (xb, d / 3, zb), 0.008), "metal", collide=False))
        for sy in (-1, 1):
            bracket = g.box_at((xb - 0.005, sy * d / 3 - 0.006, zb - 0.005), (-w / 2, sy * d / 3 + 0.006, zb + 0.005))
            parts.append(Part(bracket, "metal", collide=False))
    return AssetSpec("Cart", v, "furniture", [Link("base", parts, 10.0)], regions=regions,
                     description=f"rolling cart with {levels} shelf levels on casters")


# ----------------------------------------------------------------------------------------------------------
# Safe
# ----------------------------------------------------------------------------------------------------------

_SAFES = [
    # w, h, d, hinge, shelves, handle, plinth, keypad
    ((0.34, 0.4), (0.32, 0.38), (0.34, 0.4), "left", 0, "lever", 0.0, False),
    ((0.42, 0.48), (0.55, 0.65), (0.42, 0.48), "left", 1, "wheel", 0.0, False),
    ((0.5, 0.58), (0.3, 0.34), (0.38, 0.42), "right", 0, "lever", 0.0, True),
    ((0.48, 0.55), (0.85, 0.95), (0.45, 0.5), "right", 2, "wheel", 0.06, False),
]


@register("Safe", variants=4, category="appliance")
def safe(v: int, rng: np.random.Generator) -> AssetSpec:
    """A steel safe: thick walls, a heavy hinged door with a combination dial and a lever or spoked wheel
    handle (one with a keypad, the tall one on a plinth with two shelves); the interior is a region."""
    (w_lo, w_hi), (h_lo, h_hi), (d_lo, d_hi), hinge, n_shelves, handle, plinth, keypad = _SAFES[v]
    w, h, d = pick(rng, w_lo, w_hi), pick(rng, h_lo, h_hi), pick(rng, d_lo, d_hi)
    slot = ["dark_metal", "appliance", "dark_metal", "dark_metal"][v]
    t, dt = 0.04, 0.05
    parts = carcass(w, d - dt, h - plinth, t, slot, z0=plinth)
    _shift(parts, (0, -dt / 2, 0))
    y_front = d / 2 - dt
    if plinth:
        parts.append(Part(g.box_at((-w / 2 + 0.02, -d / 2 + 0.02, 0), (w / 2 - 0.02, y_front - 0.02, plinth)),
                          "dark_plastic", convex=True))
    z_floor, z_ceil = plinth + t, h - t
    shelf_zs = [round(z, 3) for z in np.linspace(z_floor, z_ceil, n_shelves + 2)[1:-1]]
    for z in shelf_zs:
        parts.append(Part(g.box_at((-w / 2 + t, -d / 2 + t, z - 0.005), (w / 2 - t, y_front - 0.02, z + 0.005)),
                          "metal", convex=True))
    hx = -w / 2 if hinge == "left" else w / 2
    for zc in (plinth + 0.25 * (h - plinth), plinth + 0.75 * (h - plinth)):  # hinge barrels
        parts.append(Part(g.cylinder(0.012, 0.06, (hx, y_front + 0.012, zc), sections=10), "metal", collide=False))
    gap = 0.003
    door, joint = hinged_door("door", "base", -w / 2 + gap, w / 2 - gap, y_front, plinth + gap, h - gap, hinge, slot,
                              thickness=dt, mass=10.0)
    sign = 1.0 if hinge == "left" else -1.0
    dw = w - 2 * gap
    zc = (plinth + h) / 2
    xc = sign * dw / 2
    fr = []
    m = 0.035
    x_a, x_b = sorted((sign * m, sign * (dw - m)))
    fr.append(Part(g.box_at((x_a, dt, plinth + m), (x_b, dt + 0.004, h - m)), "dark_metal" if slot == "appliance"
                   else "metal", collide=False))  # face plate
    dial_z = zc + (0.05 if h - plinth < 0.45 else 0.12)
    dial_x = xc - sign * dw * 0.12 if keypad else xc
    fr.append(Part(g.cylinder(0.038, 0.012, (dial_x, dt + 0.01, dial_z), axis="y", sections=20), "metal",
                   collide=False))
    fr.append(Part(g.cylinder(0.026, 0.022, (dial_x, dt + 0.015, dial_z), axis="y", sections=16), "dark_metal",
                   collide=False))
    fr.append(Part(g.box((0.004, 0.006, 0.012), (dial_x, dt + 0.018, dial_z + 0.044)), "brass", collide=False))
    if keypad:
        kx = xc + sign * dw * 0.15
        fr.append(Part(g.box((0.08, 0.012, 0.1), (kx, dt + 0.01, dial_z)), "dark_plastic", collide=False))
        fr.append(Part(g.box((0.06, 0.004, 0.018), (kx, dt + 0.017, dial_z + 0.03)), "led_on", collide=False))
    hub_x, hub_z = (xc + sign * dw * 0.15, zc - 0.12) if h - plinth > 0.45 else (xc + sign * dw * 0.25, zc - 0.06)
    if keypad:
        hub_x, hub_z = xc + sign * dw * 0.15, zc - 0.07
    fr.append(Part(g.cylinder(0.022, 0.03, (hub_x, dt + 0.015, hub_z), axis="y", sections=12), "metal"))
    if handle == "wheel":
        for a in (np.pi / 2, np.pi / 2 + 2 * np.pi / 3, np.pi / 2 + 4 * np.pi / 3):
            tip = (hub_x + 0.09 * np.cos(a), dt + 0.03, hub_z + 0.09 * np.sin(a))
            fr.append(Part(g.rod((hub_x, dt + 0.03, hub_z), tip, 0.007, sections=8), "metal", collide=False))
            fr.append(Part(g.sphere(0.012, tip, subdivisions=1), "metal", collide=False))
    else:
        tip_x = hub_x - sign * 0.1
        fr.append(Part(g.rod((hub_x, dt + 0.03, hub_z), (tip_x, dt + 0.03, hub_z), 0.009, sections=8), "metal",
                       collide=False))
    door.parts = [door.parts[0]] + fr
    regions = []
    levels = [z_floor] + [z + 0.005 for z in shelf_zs]
    tops = [z - 0.005 for z in shelf_zs] + [z_ceil]
    for i, (z0, z1) in enumerate(zip(levels, tops)):
        regions.append(_volume(f"inside_{i}", -w / 2 + t, w / 2 - t, -d / 2 + t, y_front, z0, z1,
                               requires_open=joint.name))
    return AssetSpec("Safe", v, "appliance", [Link("base", parts, [40.0, 55.0, 45.0, 70.0][v]), door],
                     joints=[joint], regions=regions,
                     description="steel safe with a dial and a handle on a hinged door")


# ----------------------------------------------------------------------------------------------------------
# LaundryHamper and its lid
# ----------------------------------------------------------------------------------------------------------


def _hamper_size(v: int) -> dict[str, float | str]:
    """Shared between LaundryHamper and LaundryHamperLid: variant v of the lid fits hamper variant v."""
    rng = variant_rng("LaundryHamper", v)
    shape = ["round", "square", "round", "rect"][v]
    if shape == "round":
        rt = pick(rng, 0.2, 0.24)
        return {"shape": shape, "rb": round(rt * (0.85 if v == 0 else 1.0), 3), "rt": rt,
                "h": pick(rng, 0.5, 0.6)}
    w = pick(rng, 0.38, 0.45) if shape == "square" else pick(rng, 0.5, 0.58)
    d = w if shape == "square" else pick(rng, 0.32, 0.36)
    taper = 0.04 if shape == "rect" else 0.0
    return {"shape": shape, "wt": w, "dt": d, "wb": round(w - taper, 3), "db": round(d - taper, 3),
            "h": pick(rng, 0.5, 0.6) if shape == "square" else pick(rng, 0.6, 0.66)}


@register("LaundryHamper", variants=4, category="furniture")
def laundry_hamper(v: int, rng: np.random.Generator) -> AssetSpec:
    """An open laundry basket: round tapered wicker, square wicker, round fabric on a wire frame, tall
    tapered plastic; the inside is a volume region."""
    s = _hamper_size(v)
    h = float(s["h"])
    wall, bottom = 0.012, 0.02
    slot = ["hamper_wicker", "hamper_wicker", "fabric", "plastic"][v]
    parts: list[Part] = []
    n = 18
    if s["shape"] == "round":
        rb, rt = float(s["rb"]), float(s["rt"])
        parts += _parts(g.round_wall_wedges(rb, rt, wall, 0.0, h, n), slot)
        parts.append(Part(g.cylinder(rb - wall / 2, bottom, (0, 0, bottom / 2), sections=n), slot, convex=True))
        if v == 0:  # woven bands and rope handles
            for f in (0.2, 0.45, 0.7):
                r = rb + (rt - rb) * f
                parts.append(Part(g.annulus_band(r - 0.004, r + 0.005, h * f - 0.012, h * f + 0.012, n), "dark_wood",
                                  collide=False))
            for sx in (-1, 1):
                parts.append(Part(g.torus_arc(0.045, 0.008, (sx * (rt + 0.002), 0, h - 0.07), plane="yz", start=0,
                                              end=np.pi, sections=8, minor_sections=6), "hamper_wicker",
                                  collide=False))
        else:  # wire frame: four uprights and a top hoop outside the fabric, fabric handles
            for a in (np.pi / 4, 3 * np.pi / 4, 5 * np.pi / 4, 7 * np.pi / 4):
                c, sn = np.cos(a), np.sin(a)
                parts.append(Part(g.rod(((rb + 0.006) * c, (rb + 0.006) * sn, 0.0), ((rt + 0.006) * c,
                                        (rt + 0.006) * sn, h), 0.006, sections=8), "metal", collide=False))
            parts.append(Part(g.annulus_band(rt - 0.004, rt + 0.012, h - 0.016, h, n), "metal", convex=False,
                              collide=False))
            for sx in (-1, 1):
                parts.append(Part(g.box((0.02, 0.14, 0.035), (sx * (rt + 0.008), 0, h - 0.08)), "fabric",
                                  collide=False))
        rim = rt + 0.005
        parts.append(Part(g.annulus_band(rt - wall - 0.003, rim, h - 0.025, h, n), "dark_wood" if v == 0 else slot,
                          collide=False))
        inner = (min(rb, rt) - wall) * 1.35
        regions = [Region("inside", "volume", (0.0, 0.0, bottom + (h - bottom) / 2 - 0.005),
                          (round(inner, 3), round(inner, 3), round(h - bottom - 0.03, 3)))]
    else:
        wb, db, wt, dt = (float(s[k]) for k in ("wb", "db", "wt", "dt"))
        parts += _parts(g.tapered_walls(wb, db, wt, dt, 0.0, h, wall), slot)
        parts.append(Part(g.box((wb - wall, db - wall, bottom), (0, 0, bottom / 2)), slot, convex=True))
        parts += _parts(g.rect_rim(wt, dt, h - 0.03, h, 0.008, wall + 0.004), "dark_wood" if v == 1 else "dark_plastic",
                        collide=False)
        if v == 1:  # woven look: horizontal bands and cut-out hand holds
            for f in (0.25, 0.5, 0.75):
                zb = h * f
                parts += _parts(g.rect_rim(wt, dt, zb - 0.01, zb + 0.01, 0.003, 0.003), "dark_wood", collide=False)
            for sx in (-1, 1):
                parts.append(Part(g.box((0.01, 0.11, 0.03), (sx * wt / 2, 0, h - 0.08)), "dark_wood", collide=False))
        else:  # ventilation slots on the sides, front label plate
            for sx in (-1, 1):
                for k in range(4):
                    z = h * 0.35 + k * 0.07
                    xo = (wb + (wt - wb) * z / h) / 2 + 0.001
                    parts.append(Part(g.box((0.004, dt * 0.5, 0.025), (sx * xo, 0, z)), "dark_plastic",
                                      collide=False))
            for sy in (-1, 1):
                yo = (db + (dt - db) * 0.85) / 2 + 0.001
                parts.append(Part(g.box((0.12, 0.004, 0.03), (0, sy * yo, h * 0.85)), "dark_plastic", collide=False))
        regions = [_volume("inside", -wb / 2 + wall, wb / 2 - wall, -db / 2 + wall, db / 2 - wall, bottom,
                           h - 0.01, margin=0.015)]
    return AssetSpec("LaundryHamper", v, "furniture", [Link("base", parts, 3.0)], regions=regions,
                     description="open laundry hamper basket")


@register("LaundryHamperLid", variants=4, category="small")
def laundry_hamper_lid(v: int, rng: np.random.Generator) -> AssetSpec:
    """The lid of LaundryHamper variant v: a low bevelled disc or panel with a knob or grip; lies flat."""
    s = _hamper_size(v)
    slot = ["hamper_wicker", "hamper_wicker", "fabric", "plastic"][v]
    th = 0.03
    if s["shape"] == "round":
        r = float(s["rt"]) + 0.012
        parts = [Part(g.frustum(r, r - 0.02, th, sections=20), slot, convex=True)]
        if v == 0:
            parts.append(Part(g.annulus_band(r * 0.55, r * 0.6, th - 0.002, th + 0.004, 20), "dark_wood",
                              collide=False))
            parts.append(Part(g.revolve([(0, 0), (0.012, 0), (0.01, 0.025), (0.022, 0.035), (0, 0.04)],
                                        (0, 0, th), sections=12), "dark_wood", convex=True))
        else:  # fabric drawstring cover with a loop handle
            parts.append(Part(g.cylinder(r - 0.03, 0.006, (0, 0, th + 0.003), sections=20), "fabric", collide=False))
            parts.append(Part(g.torus_arc(0.022, 0.006, (0, 0, th + 0.002), plane="xz", start=0, end=np.pi,
                                          sections=8, minor_sections=6), "fabric", collide=False))
    else:
        wt, dt = float(s["wt"]) + 0.024, float(s["dt"]) + 0.024
        parts = [Part(g.hull([(x * wt / 2, y * dt / 2, 0) for x in (-1, 1) for y in (-1, 1)] +
                             [(x * (wt / 2 - 0.02), y * (dt / 2 - 0.02), th) for x in (-1, 1) for y in (-1, 1)]),
                      slot, convex=True)]
        if v == 1:
            parts.append(Part(g.box((wt - 0.1, dt - 0.1, 0.006), (0, 0, th + 0.003)), "dark_wood", collide=False))
            parts.append(Part(g.box((0.1, 0.025, 0.025), (0, 0, th + 0.0125)), "dark_wood", convex=True))
        else:
            parts += [Part(g.box((0.012, 0.012, 0.03), (sx * 0.05, 0, th + 0.015)), "dark_plastic", collide=False)
                      for sx in (-1, 1)]
            parts.append(Part(g.box((0.12, 0.018, 0.014), (0, 0, th + 0.035)), "dark_plastic", convex=True))
    return AssetSpec("LaundryHamperLid", v, "small", [Link("base", parts, 0.5)],
                     description="lid of a laundry hamper")


# ----------------------------------------------------------------------------------------------------------
# GarbageCan
# ----------------------------------------------------------------------------------------------------------

_GARBAGE = [
    # shape, lid, slot
    ("round", "open", "metal"),
    ("square", "open", "plastic"),
    ("round", "pedal", "metal"),
    ("rect", "open", "plastic"),
    ("rect", "pedal", "appliance"),
]


@register("GarbageCan", variants=5, category="furniture")
def garbage_can(v: int, rng: np.random.Generator) -> AssetSpec:
    """A waste bin: round tapered, square office bin, round pedal bin (lid tilted open), rectangular
    recycling bin, rectangular kitchen pedal bin; the inside is a volume region."""
    shape, lid, slot = _GARBAGE[v]
    wall, bottom = 0.008, 0.015
    parts: list[Part] = []
    n = 20
    lid_mesh = None
    if shape == "round":
        rb = pick(rng, 0.11, 0.13) if v == 0 else pick(rng, 0.13, 0.15)
        rt = round(rb * 1.2, 3) if v == 0 else rb
        h = pick(rng, 0.33, 0.4) if v == 0 else pick(rng, 0.45, 0.55)
        parts += _parts(g.round_wall_wedges(rb, rt, wall, 0.0, h, n), slot)
        parts.append(Part(g.cylinder(rb - wall / 2, bottom, (0, 0, bottom / 2), sections=n), slot, convex=True))
        parts.append(Part(g.annulus_band(rt - wall - 0.002, rt + 0.006, h - 0.02, h, n),
                          "dark_plastic" if v == 0 else slot,
                          collide=False))
        if lid == "pedal":
            parts.append(Part(g.annulus_band(rb - 0.002, rb + 0.006, 0.0, 0.03, n), "dark_plastic", collide=False))
            lid_mesh = g.cylinder(rt + 0.006, 0.02, (0, rt + 0.006, 0.01), sections=n)
            depth = rt
        inner = (min(rb, rt) - wall) * 1.35
        regions = [Region("inside", "volume", (0.0, 0.0, bottom + (h - bottom) / 2 - 0.005),
                          (round(inner, 3), round(inner, 3), round(h - bottom - 0.03, 3)))]
    else:
        if shape == "square":
            wt = pick(rng, 0.26, 0.3)
            dt, h, taper = wt, pick(rng, 0.3, 0.36), 0.04
        elif lid == "open":
            wt, dt, h, taper = pick(rng, 0.34, 0.4), pick(rng, 0.26, 0.3), pick(rng, 0.55, 0.65), 0.0
        else:
            wt, dt, h, taper = pick(rng, 0.32, 0.36), pick(rng, 0.28, 0.32), pick(rng, 0.6, 0.68), 0.0
        wb, db = round(wt - taper, 3), round(dt - taper, 3)
        parts += _parts(g.tapered_walls(wb, db, wt, dt, 0.0, h, wall), slot)
        parts.append(Part(g.box((wb - wall, db - wall, bottom), (0, 0, bottom / 2)), slot, convex=True))
        parts += _parts(g.rect_rim(wt, dt, h - 0.025, h, 0.006, wall + 0.004),
                        "dark_plastic" if slot != "appliance" else "dark_metal", collide=False)
        if shape == "rect" and lid == "open":  # recycling bin: hand holds and a label
            for sx in (-1, 1):
                parts.append(Part(g.box((0.008, 0.1, 0.03), (sx * wt / 2, 0, h - 0.07)), "dark_plastic",
                                  collide=False))
            parts.append(Part(g.box((wt * 0.4, 0.004, wt * 0.3), (0, dt / 2 + 0.001, h * 0.55)), "paper",
                              collide=False))
        if lid == "pedal":
            parts += _parts(g.rect_rim(wb, db, 0.0, 0.03, 0.004, 0.004), "dark_plastic", collide=False)
            lid_mesh = g.box((wt + 0.012, dt + 0.012, 0.02), (0, dt / 2 + 0.006, 0.01))
            depth = dt / 2
        regions = [_volume("inside", -wb / 2 + wall, wb / 2 - wall, -db / 2 + wall, db / 2 - wall, bottom, h - 0.01,
                           margin=0.015)]
    if lid_mesh is not None:  # lid propped open about a hinge at the back, pedal at the front
        tilt = np.radians(75)
        hinge_y = -depth - 0.006
        parts.append(Part(g.transformed(lid_mesh, roll=tilt, offset=(0, hinge_y, h)), slot, convex=True))
        parts.append(Part(g.box((0.03, 0.03, 0.03), (0, hinge_y - 0.012, h - 0.005)), "dark_plastic", collide=False))
        parts.append(Part(g.box((0.1, 0.06, 0.018), (0, depth + 0.03, 0.02)), "dark_plastic", convex=True))
    desc = "garbage can with a pedal and an open lid" if lid == "pedal" else "open-topped garbage can"
    return AssetSpec("GarbageCan", v, "furniture", [Link("base", parts, [3.0, 3.0, 4.5, 4.0, 5.0][v])],
                     regions=regions, description=desc)


# ----------------------------------------------------------------------------------------------------------
# Box
# ----------------------------------------------------------------------------------------------------------

_BOXES = [
    # w, d, h, closure
    ((0.4, 0.5), (0.3, 0.35), (0.25, 0.3), "flaps"),
    ((0.33, 0.38), (0.21, 0.25), (0.12, 0.15), "lid"),
    ((0.28, 0.32), (0.28, 0.32), (0.27, 0.32), "flaps"),
    ((0.42, 0.48), (0.3, 0.34), (0.18, 0.22), "lid"),
]


@register("Box", variants=4, category="small")
def box(v: int, rng: np.random.Generator) -> AssetSpec:
    """A cardboard box: four hinged top flaps (long flaps meet in the middle over short dust flaps) or a
    hinged lid with a skirt (shoe box, storage box); the inside is a region reached by opening the front
    flap or the lid."""
    (w_lo, w_hi), (d_lo, d_hi), (h_lo, h_hi), closure = _BOXES[v]
    w, d, h = pick(rng, w_lo, w_hi), pick(rng, d_lo, d_hi), pick(rng, h_lo, h_hi)
    t = 0.008
    slot = "box_cardboard"
    parts = _parts(g.tapered_walls(w, d, w, d, 0.0, h, t), slot)
    parts.append(Part(g.box((w - t, d - t, t), (0, 0, t / 2)), slot, convex=True))
    links = [Link("base", parts, 0.4)]
    joints = []
    if closure == "flaps":
        ft = 0.005
        minor = round(0.3 * d, 3)  # dust flaps leave the middle free when the front flap is open
        for name, sy, axis in (("flap_front", 1, (-1.0, 0.0, 0.0)), ("flap_back", -1, (1.0, 0.0, 0.0))):
            y0, y1 = sorted((0.0, -sy * d / 2))
            mesh = g.box_at((-w / 2, y0, 0), (w / 2, y1, ft))
            fparts = [Part(mesh, slot, convex=True)]
            if v == 0:  # packing tape strip along the seam
                fparts.append(Part(g.box_at((-0.025, y0, ft), (0.025, y1, ft + 0.001)), "paper", collide=False))
            links.append(Link(name, fparts, 0.025))
            joints.append(Joint(f"{name}_hinge", "revolute", "base", name, (0.0, sy * d / 2, h + ft), axis, 0.0,
                                float(np.radians(200)), "lid"))
        for name, sx, axis in (("flap_left", -1, (0.0, -1.0, 0.0)), ("flap_right", 1, (0.0, 1.0, 0.0))):
            x0, x1 = sorted((0.0, -sx * minor))
            mesh = g.box_at((x0, -d / 2 + t, 0), (x1, d / 2 - t, ft))
            links.append(Link(name, [Part(mesh, slot, convex=True)], 0.02))
            joints.append(Joint(f"{name}_hinge", "revolute", "base", name, (sx * w / 2, 0.0, h), axis, 0.0,
                                float(np.radians(200)), "lid"))
        opener = "flap_front_hinge"
    else:
        s, lt = 0.006, 0.008
        skirt = min(0.05, h * 0.35)
        L = d + 2 * s
        lparts = [
            Part(g.box_at((-w / 2 - s, 0, 0), (w / 2 + s, L, lt)), slot, convex=True),
            Part(g.box_at((-w / 2 - s, L - s, -skirt), (w / 2 + s, L, 0)), slot, convex=True),
            Part(g.box_at((-w / 2 - s, 0, -skirt), (-w / 2, L, 0)), slot, convex=True),
            Part(g.box_at((w / 2, 0, -skirt), (w / 2 + s, L, 0)), slot, convex=True),
            Part(g.box_at((-w / 2 - s, 0, -skirt), (w / 2 + s, s, 0)), slot, convex=True),
        ]
        if v == 3:  # finger tab on the front of a storage box lid
            lparts.append(Part(g.box_at((-0.04, L, -skirt * 0.6), (0.04, L + 0.012, -skirt * 0.2)), slot,
                               collide=False))
        else:  # printed label band
            lparts.append(Part(g.box_at((-w * 0.3, L * 0.3, lt), (w * 0.3, L * 0.7, lt + 0.001)), "paper",
                               collide=False))
        links.append(Link("lid", lparts, 0.1))
        links[0].mass = 0.4
        joints.append(Joint("lid_hinge", "revolute", "base", "lid", (0.0, -d / 2 - s, h), (1.0, 0.0, 0.0), 0.0,
                            float(np.radians(110)), "lid"))
        opener = "lid_hinge"
    if closure == "flaps":
        links[0].mass = 0.41
    regions = [_volume("inside", -w / 2 + t, w / 2 - t, -d / 2 + t, d / 2 - t, t, h - 0.005, requires_open=opener)]
    return AssetSpec("Box", v, "small", links, joints=joints, regions=regions,
                     description="cardboard box with " + ("four top flaps" if closure == "flaps" else "a hinged lid"))
