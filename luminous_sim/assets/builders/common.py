"""Builder plumbing shared by the builders: parts, links, composites (legs, carcasses, doors, drawers, handles)
and the finishing steps of an asset (grounding, re-centring, a mass PyBullet keeps the inertia of).

Plain mesh shapes live in `luminous_sim.assets.geometry`; this module makes `Part`s, `Link`s, `Joint`s and
`AssetSpec`s out of them. All in the asset frame convention of `geometry` (z up, +y front, origin at the
bottom centre).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.spec import AssetSpec, Joint, Link, Part, Region

DOOR_OPEN = float(np.radians(100))
"""Doors open a little past 90 degrees, as AI2-THOR's fully open doors do."""


def corner_legs(
    w: float, d: float, height: float, inset: float, radius: float, slot: str, square: bool = False,
    z0: float = 0.0,
) -> list[Part]:
    """Four vertical legs at the corners of a w x d footprint, inset from the edges."""
    parts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            x, y = sx * (w / 2 - inset), sy * (d / 2 - inset)
            if square:
                mesh = g.box((2 * radius, 2 * radius, height), (x, y, z0 + height / 2))
            else:
                mesh = g.cylinder(radius, height, (x, y, z0 + height / 2), sections=10)
            parts.append(Part(mesh, slot))
    return parts


def carcass(
    w: float, d: float, h: float, t: float, slot: str, z0: float = 0.0, open_top: bool = False
) -> list[Part]:
    """An open-fronted box (cabinet body): bottom, top, two sides and a back, panels `t` thick.

    The interior spans x in [-w/2+t, w/2-t], y in [-d/2+t, d/2], z in [z0+t, z0+h-t].
    """
    panels = [
        g.box_at((-w / 2, -d / 2, z0), (w / 2, d / 2, z0 + t)),
        g.box_at((-w / 2, -d / 2, z0 + t), (-w / 2 + t, d / 2, z0 + h - t)),
        g.box_at((w / 2 - t, -d / 2, z0 + t), (w / 2, d / 2, z0 + h - t)),
        g.box_at((-w / 2 + t, -d / 2, z0 + t), (w / 2 - t, -d / 2 + t, z0 + h - t)),
    ]
    if not open_top:
        panels.append(g.box_at((-w / 2, -d / 2, z0 + h - t), (w / 2, d / 2, z0 + h)))
    return [Part(m, slot, convex=True) for m in panels]


def bar_handle(length: float, center: Sequence[float], vertical: bool, slot: str = "metal") -> list[Part]:
    """A bar pull standing 3 cm proud of a front face at y = center[1] (two posts and a grip)."""
    cx, cy, cz = center
    r = 0.007
    if vertical:
        grip = g.cylinder(r, length, (cx, cy + 0.03, cz), axis="z", sections=8)
        posts = [g.box((0.012, 0.03, 0.012), (cx, cy + 0.015, cz + s * (length / 2 - 0.01))) for s in (-1, 1)]
    else:
        grip = g.cylinder(r, length, (cx, cy + 0.03, cz), axis="x", sections=8)
        posts = [g.box((0.012, 0.03, 0.012), (cx + s * (length / 2 - 0.01), cy + 0.015, cz)) for s in (-1, 1)]
    return [Part(grip, slot)] + [Part(p, slot) for p in posts]


def knob(center: Sequence[float], slot: str = "metal", radius: float = 0.015) -> Part:
    """A round knob on a front face at y = center[1]."""
    cx, cy, cz = center
    return Part(g.cylinder(radius, 0.025, (cx, cy + 0.0125, cz), axis="y", sections=10), slot)


def hinged_door(
    name: str, parent: str, x0: float, x1: float, y_front: float, z0: float, z1: float,
    hinge: str, slot: str, thickness: float = 0.02, handle_slot: str = "metal",
    extra: Sequence[Part] = (), mass: float = 2.0, vertical_handle: bool = True,
) -> tuple[Link, Joint]:
    """A door covering x0..x1, z0..z1 of a front face at y_front, hinged on the "left" or "right" edge.

    The door opens outwards (towards +y) about a vertical axis; `extra` parts (door shelves) are given
    in the door link frame, whose origin is the hinge at (hinge x, y_front, 0).
    """
    width = x1 - x0
    hx = x0 if hinge == "left" else x1
    sign = 1.0 if hinge == "left" else -1.0
    panel = g.box_at((min(0, sign * width), 0, z0), (max(0, sign * width), thickness, z1))
    hz = (z0 + z1) / 2 if z1 - z0 < 0.9 else z0 + 0.55 * (z1 - z0)
    handle_x = sign * (width - 0.05)
    handle_len = min(0.35, 0.5 * (z1 - z0)) if vertical_handle else min(0.25, 0.5 * width)
    parts = [Part(panel, slot, convex=True)] + bar_handle(handle_len, (handle_x, thickness, hz), vertical_handle,
                                                          handle_slot) + list(extra)
    link = Link(name, parts, mass)
    joint = Joint(f"{name}_hinge", "revolute", parent, name, (hx, y_front, 0.0), (0.0, 0.0, sign), 0.0,
                  DOOR_OPEN, "door")
    return link, joint


def drawer(
    name: str, parent: str, w: float, d: float, h: float, x: float, y_front: float, z0: float,
    slot: str, front_slot: str | None = None, t: float = 0.012, handle_slot: str = "metal",
    mass: float = 1.5, travel: float | None = None,
) -> tuple[Link, Joint, Region]:
    """A drawer: an open tray behind a front panel, sliding out along +y.

    The drawer link's origin is at (x, y_front, z0) in the parent; the tray spans y in [-d, 0].
    Returns the link, its prismatic joint and its interior volume region.
    """
    front = g.box_at((-w / 2, 0, 0), (w / 2, 0.02, h))
    ih = h * 0.8
    tray = [
        g.box_at((-w / 2 + 0.01, -d, 0.01), (w / 2 - 0.01, 0, 0.01 + t)),
        g.box_at((-w / 2 + 0.01, -d, 0.01), (-w / 2 + 0.01 + t, 0, ih)),
        g.box_at((w / 2 - 0.01 - t, -d, 0.01), (w / 2 - 0.01, 0, ih)),
        g.box_at((-w / 2 + 0.01, -d, 0.01), (w / 2 - 0.01, -d + t, ih)),
    ]
    parts = [Part(front, front_slot or slot, convex=True)] + [Part(m, slot, convex=True) for m in tray]
    parts += bar_handle(min(0.18, 0.5 * w), (0.0, 0.02, h * 0.6), False, handle_slot)
    link = Link(name, parts, mass)
    joint = Joint(f"{name}_slide", "prismatic", parent, name, (x, y_front, z0), (0.0, 1.0, 0.0), 0.0,
                  travel if travel is not None else 0.75 * d, "drawer")
    inner_w, inner_d = w - 0.02 - 2 * t, d - 2 * t
    region = Region(f"{name}_inside", "volume", (0.0, -d / 2, 0.01 + t + (ih - 0.01 - t) / 2),
                    (inner_w, inner_d, ih - 0.01 - t), link=name, requires_open=joint.name)
    return link, joint, region


def surface(name: str, w: float, d: float, z: float, clearance: float, cx: float = 0.0, cy: float = 0.0,
            link: str = "base", margin: float = 0.03, requires_open: str | None = None) -> Region:
    """A support surface region on a w x d top at height z, shrunk by `margin` from the edges."""
    return Region(name, "surface", (cx, cy, z), (max(w - 2 * margin, 0.02), max(d - 2 * margin, 0.02), clearance),
                  link=link, requires_open=requires_open)


def pick(rng: np.random.Generator, lo: float, hi: float, digits: int = 3) -> float:
    """A size drawn uniformly in [lo, hi], rounded so builds stay stable across platforms."""
    return round(float(rng.uniform(lo, hi)), digits)


# --------------------------------------------------------------------------------------------------
# parts and links


def solid(mesh: trimesh.Trimesh, slot: str) -> Part:
    """A colliding convex part (its hull is the collision shape)."""
    return Part(mesh, slot, convex=True)


def visual(mesh: trimesh.Trimesh, slot: str, state: str | None = None) -> Part:
    """A visual-only part (details, labels, state visuals)."""
    return Part(mesh, slot, collide=False, state=state)


def fixed(name: str, parts: list[Part], mass: float, parent: str = "base") -> tuple[Link, Joint]:
    """A light link rigidly joined to `parent` (its frame coincides with the parent's)."""
    return Link(name, parts, mass), Joint(f"{name}_mount", "fixed", parent, name, (0.0, 0.0, 0.0))


# --------------------------------------------------------------------------------------------------
# placing and finishing an asset


def ground_parts(parts: list[Part]) -> list[Part]:
    """Move all parts so the stateless visuals' footprint is centred at the origin with the bottom at z=0."""
    meshes = [p.mesh for p in parts if p.state is None]
    lo = np.min([m.bounds[0] for m in meshes], axis=0)
    hi = np.max([m.bounds[1] for m in meshes], axis=0)
    off = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
    for p in parts:
        p.mesh.apply_translation(off)
    return parts


def shift_footprint(parts: list[Part], regions: list[Region], dx: float, dy: float) -> None:
    """Move every part and region by (dx, dy) (re-centre a non-symmetric footprint on the origin)."""
    for p in parts:
        p.mesh.apply_translation((dx, dy, 0.0))
    for r in regions:
        r.center = (r.center[0] + dx, r.center[1] + dy, r.center[2])


def recenter(spec: AssetSpec) -> AssetSpec:
    """Move the asset so the centre of its footprint (x-y bounds of all its parts) is the origin.

    Shifts the base link's parts, the joints hung on the base, base regions and anchors.
    """
    from luminous_sim.assets.urdf_writer import link_origins

    origins = link_origins(spec)
    lo = np.min([p.mesh.bounds[0] + origins[ln.name] for ln in spec.links for p in ln.parts], axis=0)
    hi = np.max([p.mesh.bounds[1] + origins[ln.name] for ln in spec.links for p in ln.parts], axis=0)
    shift = np.array([-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]])
    shift = np.round(shift, 5)
    if np.allclose(shift, 0, atol=1e-6):
        return spec
    for p in spec.links[0].parts:
        p.mesh = g.transformed(p.mesh, offset=shift)
    for j in spec.joints:
        if j.parent == "base":
            j.origin = tuple(float(x) for x in np.asarray(j.origin) + shift)
    for r in spec.regions:
        if r.link == "base":
            r.center = tuple(float(x) for x in np.asarray(r.center) + shift)
    for a in spec.anchors:
        a.pose = (a.pose[0] + float(shift[0]), a.pose[1] + float(shift[1]), a.pose[2] + float(shift[2]), a.pose[3])
    return spec


def robust_mass(parts: Sequence[Part], mass: float) -> float:
    """`mass`, nudged by up to 16 % (usually far less) so that PyBullet keeps the link's inertia.

    PyBullet zeroes the inertia of a link whose principal moments break the triangle inequality
    (izz <= ixx + iyy, ...), after which the body can no longer rotate. Flat things (cutlery, slices,
    towels) sit right on that limit (izz = ixx + iyy for a lamina), and the URDF's moments are rounded to
    1e-6, which can tip them over it. This replays the writer's computation for all-convex parts (uniform
    density over each part's hull, moments floored at 1e-6, rounded to 6 decimals) and returns the
    nearest mass whose rounded moments keep a margin of one unit.
    """
    hulls = [p.mesh.convex_hull for p in parts if p.collide]
    if not hulls or any(p.convex is not True for p in parts if p.collide):
        return mass
    vols = np.array([max(h.volume, 1e-12) for h in hulls])
    com = sum(v * h.center_mass for v, h in zip(vols, hulls)) / vols.sum()
    per_kg = np.zeros(3)
    for v, h in zip(vols, hulls):
        d = h.center_mass - com
        per_kg += np.diag(h.moment_inertia) + v * (d @ d - d * d)
    per_kg /= vols.sum()
    for k in range(81):
        step = (k + 1) // 2 * (1 if k % 2 else -1)
        m = round(mass * (1 + 0.004 * step), 5)
        diag = np.maximum(per_kg * m, 1e-6)
        for i in range(3):
            diag[i] = min(diag[i], diag[(i + 1) % 3] + diag[(i + 2) % 3])
        r = np.round(diag, 6)
        if all(r[i] <= r[(i + 1) % 3] + r[(i + 2) % 3] - 0.9e-6 for i in range(3)):
            return m
    return mass


def _rounded_inertia_ok(parts: list[Part], mass: float) -> bool:
    """Whether the diagonal inertia the URDF will carry (uniform-density hulls, rounded to 1e-6 as written)
    satisfies the triangle inequality that PyBullet checks; flat, light things sit right on its edge."""
    hulls = [p.mesh.convex_hull for p in parts if p.collide]
    vols = np.array([max(h.volume, 1e-12) for h in hulls])
    density = mass / vols.sum()
    com = sum(v * h.center_mass for v, h in zip(vols, hulls)) / vols.sum()
    inertia = np.zeros((3, 3))
    for v, h in zip(vols, hulls):
        d = h.center_mass - com
        inertia += h.moment_inertia * density + v * density * (d @ d * np.eye(3) - np.outer(d, d))
    a, b, c = (round(float(x), 6) for x in np.maximum(np.diag(inertia), 1e-6))
    return min(a + b - c, a + c - b, b + c - a) >= 5e-7


def small_asset(type_name: str, v: int, parts: list[Part], mass: float, desc: str) -> AssetSpec:
    """A single-link small object. For thin flat things the mass is nudged up (by under 60 %)
    until the written inertia is valid (otherwise PyBullet zeroes it and the object cannot rotate)."""
    ground_parts(parts)
    if all(p.convex for p in parts if p.collide):
        for k in range(60):
            m = round(mass * (1 + 0.01 * k), 4)
            if _rounded_inertia_ok(parts, m):
                mass = m
                break
    return AssetSpec(type_name, v, "small", [Link("base", parts, mass)], description=desc)
