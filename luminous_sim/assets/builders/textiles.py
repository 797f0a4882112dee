"""Textiles: cleaning cloths, towels, hand towels, pillows.

Cloth lies flat or folded with a flat underside, so that it settles when dropped; cloths show stains when
dirty. Sizes are real-world metres.
"""

from __future__ import annotations

import numpy as np
import trimesh

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, small_asset, solid, visual
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register
from luminous_sim.assets.spec import AssetSpec, Part

add_palettes(
    hh_cloth=hex_colours("4f86c6", "f2c14e", "e07a5f", "81b29a", "d9d9d9"),
    hh_stripe=hex_colours("c1121f", "264653", "f4f4f4"),
    hh_towel=hex_colours("f5f5f0", "9cc3d5", "e7c6b8", "6a8caf", "b8d8b0", "f0e0b0", "8e9aa6"),
    hh_towel_band=hex_colours("c8c8c0", "6f96ac", "c9a393", "4f6d8f", "93b78a", "d2bf8c", "6d7884"),
    hh_piping=hex_colours("c8b99c", "6b7a8f", "9e4a3c", "3f5e4a"),
)

PI = float(np.pi)


# ------------------------------------------------------------------------------------------------ textiles

def _stains(rng: np.random.Generator, n: int, w: float, d: float, z: float, cx: float = 0.0,
            cy: float = 0.0) -> list[Part]:
    """Dirty-state smudges lying on a top surface at height z (visible only when dirty)."""
    out = []
    for _ in range(n):
        rx, ry = pick(rng, 0.012, 0.03), pick(rng, 0.008, 0.02)
        x, y = cx + pick(rng, -w / 3, w / 3), cy + pick(rng, -d / 3, d / 3)
        m = g.ellipsoid((rx, ry, 0.0006), (0, 0, 0), subdivisions=1)
        g.rotate_z(m, pick(rng, 0.0, PI))
        m.apply_translation((x, y, z + 0.0002))
        out.append(visual(m, "dirt", state="dirty"))
    return out


@register("Cloth", variants=3, category="small")
def cloth(v: int, rng: np.random.Generator) -> AssetSpec:
    """A cleaning cloth lying flat: folded microfibre square, striped dish cloth, crumpled rag; dirty stains."""
    parts: list[Part] = []
    if v == 0:
        s = pick(rng, 0.15, 0.18)
        parts.append(solid(g.rounded_slab(s, s, 0.004, 0.006), "hh_cloth"))
        parts.append(solid(g.rounded_slab(s * 0.97, s * 0.96, 0.004, 0.006, 0.004, 0.003, -0.002), "hh_cloth"))
        parts.append(solid(g.cylinder(0.004, s * 0.94, (-s / 2 + 0.003, -0.002, 0.004), axis="y", sections=10),
                           "hh_cloth"))
        parts.append(visual(g.flat_decal(0.02, 0.008, 0.008, s * 0.35, s * 0.4), "hh_face"))
        top, w, d = 0.008, s, s
    elif v == 1:
        w, d = pick(rng, 0.23, 0.26), pick(rng, 0.14, 0.16)
        parts.append(solid(g.rounded_slab(w, d, 0.007, 0.004), "hh_cloth"))
        parts.append(solid(g.cylinder(0.0035, w - 0.004, (0, -d / 2 + 0.001, 0.0035), axis="x", sections=10),
                           "hh_cloth"))
        for sx in (-1, 1):
            for dx in (0.0, 0.016):
                parts.append(visual(g.flat_decal(0.008, d - 0.002, 0.007, sx * (w * 0.36 - dx), 0), "hh_stripe"))
        top = 0.007
    else:
        w, d = pick(rng, 0.2, 0.24), pick(rng, 0.15, 0.18)
        rag = _crumple(rng, w / 2, d / 2, 0.022)
        parts.append(solid(rag, "hh_cloth"))
        top = 0.018
        w, d = w * 0.5, d * 0.5
    parts += _stains(rng, 3, w, d, top)
    return small_asset("Cloth", v, parts, [0.04, 0.05, 0.06][v], "cleaning cloth; shows stains when dirty")


def _crumple(rng: np.random.Generator, a: float, b: float, h: float, rings: int = 4, segs: int = 20) -> trimesh.Trimesh:
    """A crumpled cloth: a wrinkled mound over a ragged outline with a flat underside."""
    rad = np.array([pick(rng, 0.72, 1.0) for _ in range(segs)])
    rad = (rad + np.roll(rad, 1) + np.roll(rad, -1)) / 3
    verts = [(0.0, 0.0, h)]
    for i in range(1, rings + 1):
        rho = i / rings
        for j in range(segs):
            t = 2 * PI * j / segs
            bump = 1 + (pick(rng, -0.3, 0.3) if i < rings else 0.0)
            z = h * 0.3 if i == rings else h * (1 - 0.6 * rho ** 2) * bump
            verts.append((a * rho * rad[j] * np.cos(t), b * rho * rad[j] * np.sin(t), z))
    for j in range(segs):
        t = 2 * PI * j / segs
        verts.append((a * rad[j] * np.cos(t), b * rad[j] * np.sin(t), 0.0))
    verts.append((0.0, 0.0, 0.0))
    faces = [(0, 1 + j, 1 + (j + 1) % segs) for j in range(segs)]
    for i in range(rings):  # ring i -> ring i+1 (the last "ring" is the bottom rim)
        for j in range(segs):
            a0, a1 = 1 + i * segs + j, 1 + i * segs + (j + 1) % segs
            b0, b1 = a0 + segs, a1 + segs
            faces += [(a0, b0, a1), (a1, b0, b1)]
    bottom, rim = len(verts) - 1, 1 + rings * segs
    faces += [(bottom, rim + (j + 1) % segs, rim + j) for j in range(segs)]
    mesh = trimesh.Trimesh(np.asarray(verts), np.asarray(faces), process=True)
    mesh.fix_normals()
    return mesh


def _folded_towel(w: float, d: float, layers: int, lt: float, band_y: float, z0: float = 0.0,
                  cy: float = 0.0) -> list[Part]:
    """A towel folded into `layers` stacked layers with rounded fold edges and a woven border band."""
    parts = []
    inner = d - 2 * lt
    for i in range(layers):
        parts.append(solid(g.rounded_slab(w, inner, lt, min(0.012, w / 6), z0 + i * lt, cy=cy), "hh_towel"))
    for i in range(layers - 1):
        sgn = 1 if i % 2 == 0 else -1
        roll = g.cylinder(lt, w - 0.006, (0, cy + sgn * inner / 2, z0 + (i + 1) * lt), axis="x", sections=12)
        parts.append(solid(roll, "hh_towel"))
    if layers == 1:
        parts.append(solid(g.cylinder(lt / 2, w - 0.006, (0, cy + inner / 2, z0 + lt / 2), axis="x", sections=10),
                           "hh_towel"))
    ztop = z0 + layers * lt
    parts.append(visual(g.flat_decal(w + 0.001, 0.022, ztop - 0.0002, 0, cy + band_y), "hh_towel_band"))
    for s in (-1, 1):
        parts.append(visual(g.box((0.0008, 0.022, layers * lt), (s * (w / 2 + 0.0003), cy + band_y,
                                                                 z0 + layers * lt / 2)),
                            "hh_towel_band"))
    return parts


def _rolled_towel(length: float, r: float) -> list[Part]:
    """A towel rolled up along x, lying on a flat facet, with its spiral showing at the ends."""
    sections = 14
    zc = g.prism_axis_height(r, sections)
    parts = [solid(g.prism_x(r, length, -length / 2, zc, sections), "hh_towel")]
    for s in (-1, 1):
        for k, rr in enumerate((0.3 * r, 0.6 * r)):
            ring = g.torus_ring(rr, 0.0016 + 0.0004 * k, (s * length / 2, 0, zc), plane="yz", n=14, m=4)
            parts.append(visual(ring, "hh_towel_band"))
    parts.append(visual(g.prism_x(r * 1.01, 0.025, length * 0.25, zc, sections), "hh_towel_band"))
    return parts


@register("Towel", variants=4, category="small")
def towel(v: int, rng: np.random.Generator) -> AssetSpec:
    """A bath towel: folded in thirds, folded in quarters, rolled, or a bath towel with a hand towel on top."""
    if v == 0:
        w, d = pick(rng, 0.32, 0.36), pick(rng, 0.2, 0.24)
        parts = _folded_towel(w, d, 3, 0.018, d * 0.32)
    elif v == 1:
        s = pick(rng, 0.25, 0.28)
        parts = _folded_towel(s, s, 4, 0.014, s * 0.35)
    elif v == 2:
        parts = _rolled_towel(pick(rng, 0.32, 0.36), pick(rng, 0.06, 0.07))
    else:
        w, d = pick(rng, 0.33, 0.36), pick(rng, 0.21, 0.24)
        parts = _folded_towel(w, d, 3, 0.017, d * 0.32)
        parts += _folded_towel(w * 0.72, d * 0.6, 3, 0.008, d * 0.15, z0=3 * 0.017, cy=-d * 0.12)
    return small_asset("Towel", v, parts, [0.45, 0.4, 0.4, 0.6][v], "folded bath towel")


@register("HandTowel", variants=3, category="small")
def hand_towel(v: int, rng: np.random.Generator) -> AssetSpec:
    """A small hand towel: folded in thirds, folded in half, or rolled up."""
    if v == 0:
        w, d = pick(rng, 0.24, 0.27), pick(rng, 0.12, 0.14)
        parts = _folded_towel(w, d, 3, 0.008, d * 0.3)
    elif v == 1:
        w, d = pick(rng, 0.19, 0.21), pick(rng, 0.15, 0.17)
        parts = _folded_towel(w, d, 2, 0.011, d * 0.3)
    else:
        parts = _rolled_towel(pick(rng, 0.19, 0.22), pick(rng, 0.03, 0.035))
    return small_asset("HandTowel", v, parts, [0.15, 0.15, 0.12][v], "hand towel")


@register("Pillow", variants=4, category="small")
def pillow(v: int, rng: np.random.Generator) -> AssetSpec:
    """A puffy pillow lying flat: bed pillow, square throw pillow with piping, round cushion, lumbar pillow."""
    a, b, c, e1, e2 = [
        (pick(rng, 0.32, 0.35), pick(rng, 0.22, 0.25), 0.075, 1.25, 0.3),
        (pick(rng, 0.2, 0.23), 0.0, 0.075, 1.1, 0.35),
        (pick(rng, 0.19, 0.22), 0.0, 0.055, 0.55, 1.0),
        (pick(rng, 0.24, 0.27), pick(rng, 0.13, 0.15), 0.065, 1.2, 0.32),
    ][v]
    b = b or a
    body = g.superquadric((a, b, c), e1, e2, (0, 0, 0), nu=12, nv=28)
    verts = body.vertices.copy()
    verts[verts[:, 2] < 0, 2] *= 0.7  # it sags onto whatever it lies on
    body = trimesh.Trimesh(verts, body.faces, process=True)
    body = g.clip_below(body, -0.6 * c)
    parts = [solid(body, "cushion")]
    top = float(body.bounds[1][2])
    if v in (1, 2):
        eq = [(a * np.sign(np.cos(t)) * abs(np.cos(t)) ** e2, b * np.sign(np.sin(t)) * abs(np.sin(t)) ** e2)
              for t in np.linspace(0, 2 * PI, 40, endpoint=False)]
        parts.append(visual(g.sweep_loop(eq, g.circle_points(0.005, 5), 0.0), "hh_piping"))
        parts.append(visual(g.ellipsoid((0.012, 0.012, 0.005), (0, 0, top - 0.002), 1), "hh_piping"))
    if v == 2:
        zr = top - c * (1 - (1 - 0.5 ** (2 / e1)) ** (e1 / 2))  # the surface height at half the radius
        for k in range(6):
            t = 2 * PI * k / 6
            parts.append(visual(g.ellipsoid((0.008, 0.008, 0.004), (0.5 * a * np.cos(t), 0.5 * a * np.sin(t),
                                                                    zr - 0.001), 1),
                                "hh_piping"))
    return small_asset("Pillow", v, parts, [0.6, 0.4, 0.5, 0.3][v], "pillow lying flat")
