"""Composite pieces shared by the builders: legs, carcasses, hinged doors, drawers, handles.

All in the asset frame convention of `geometry` (z up, +y front, origin at the bottom centre).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from luminous_sim.assets import geometry as g
from luminous_sim.assets.spec import Joint, Link, Part, Region

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
