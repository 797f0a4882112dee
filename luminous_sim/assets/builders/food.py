"""Food: fruit, vegetables, bread and eggs, with their slices (small, pickupable).

Sliceable parents return a SliceSpec whose poses rebuild the parent out of its pieces: horizontal
slices are stacked where the parent was (a tomato, a round lettuce), pieces cut across a long thing lie
flat in short stacks along its length (a loaf, a potato, a romaine head), wedges stand in a ring (an
apple). Each XSliced builder makes one piece of the matching parent variant; both read their sizes
from a function seeded with `variant_rng(parent, v)`.
"""

from __future__ import annotations

import numpy as np
import trimesh
from shapely.geometry import Polygon

from luminous_sim.assets import geometry as g
from luminous_sim.assets.builders.common import pick, robust_mass
from luminous_sim.assets.materials import add_palettes, hex_colours
from luminous_sim.assets.registry import register, variant_rng
from luminous_sim.assets.spec import AssetSpec, Link, Part, SliceSpec

add_palettes(
    food_bread_score=hex_colours("e3c08a", "d9b27a"),
    food_lettuce_heart=hex_colours("d8e9a8", "cfe39a", "e2efb8"),
    food_seed=hex_colours("f2d16b", "ead27e"),
    food_potato_eye=hex_colours("6b4a2b", "5a3e24"),
)

APPLE_SLICES = 6


def _apple_radius(v: int) -> float:
    return pick(variant_rng("Apple", v), 0.036, 0.045)


@register("Apple", variants=3, category="small")
def apple(v: int, rng: np.random.Generator) -> AssetSpec:
    """A round apple, slightly flattened, with a dimple, a stem and (variant 2) a leaf."""
    r = _apple_radius(v)
    squash = [0.9, 0.95, 0.86][v]
    body = g.ellipsoid((r, r, r * squash), (0, 0, r * squash), subdivisions=3)
    stem = g.cylinder(0.003, 0.018, (0, 0, 2 * r * squash + 0.004), sections=6)
    parts = [Part(body, "apple"), Part(stem, "stem", collide=False)]
    if v == 2:
        leaf = g.ellipsoid((0.012, 0.005, 0.0015), (0.01, 0, 2 * r * squash + 0.01))
        parts.append(Part(leaf, "plant", collide=False))
    ring = 0.62 * r
    poses = [(ring * np.cos(a), ring * np.sin(a), 0.0, float(a)) for a in np.linspace(0, 2 * np.pi, APPLE_SLICES,
                                                                                     endpoint=False)]
    return AssetSpec(
        "Apple", v, "small", [Link("base", parts, 0.18)],
        slices=SliceSpec("AppleSliced", APPLE_SLICES, [tuple(round(float(x), 4) for x in p) for p in poses]),
        description="apple",
    )


@register("AppleSliced", variants=3, category="small")
def apple_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """One wedge of the matching Apple variant, lying skin-down-outwards; origin at its bottom centre."""
    r = _apple_radius(v)
    squash = [0.9, 0.95, 0.86][v]
    half = np.pi / APPLE_SLICES
    # a wedge: a fan of the apple's outline between -half and +half, extruded radially (pointing +x)
    n = 6
    angles = np.linspace(-half, half, n)
    outline = [(0.0, 0.0)] + [(r * np.cos(a), r * np.sin(a)) for a in angles]
    wedge = g.extrude(outline, 2 * r * squash * 0.9)
    wedge.apply_translation((-0.62 * r, 0, 0))
    return AssetSpec("AppleSliced", v, "small", [Link("base", [Part(wedge, "apple_flesh", convex=True)],
                                                      0.18 / APPLE_SLICES)], description="apple wedge")


# --------------------------------------------------------------------------------------------------
# shared helpers


def _stack_poses(n: int, stacks: int, pitch: float, t: float,
                 yaw: float = 0.0) -> list[tuple[float, float, float, float]]:
    """n flat pieces in `stacks` stacks side by side along x, `pitch` apart, each piece t thick."""
    stacks = max(1, min(n, stacks))
    poses = []
    for i in range(n):
        s, level = i % stacks, i // stacks
        x = (s - (stacks - 1) / 2) * pitch
        poses.append((x, 0.0, level * (t + 0.0005), yaw))
    return [tuple(round(float(c), 4) for c in p) for p in poses]


def _disc_slice(r: float, t: float, skin: str, flesh: str, sections: int = 18) -> list[Part]:
    """A round slice lying flat: a skin-coloured disc with the cut face on top."""
    disc = g.cylinder(r, t, (0, 0, t / 2), sections=sections)
    face = g.cylinder(r * 0.93, 0.0008, (0, 0, t + 0.0004), sections=sections)
    return [Part(disc, skin, convex=True), Part(face, flesh, collide=False)]


# --------------------------------------------------------------------------------------------------
# Bread


def _bread_dims(v: int) -> dict[str, float]:
    """Loaf sizes: 0 a sandwich (pan) loaf, 1 a baguette, 2 an oval country loaf (batard)."""
    rng = variant_rng("Bread", v)
    if v == 0:
        d = {"L": pick(rng, 0.22, 0.25), "W": pick(rng, 0.105, 0.115), "H": pick(rng, 0.11, 0.125), "n": 10}
    elif v == 1:
        d = {"L": pick(rng, 0.40, 0.46), "W": pick(rng, 0.062, 0.072), "H": pick(rng, 0.05, 0.058), "n": 10}
    else:
        d = {"L": pick(rng, 0.22, 0.26), "W": pick(rng, 0.14, 0.155), "H": pick(rng, 0.085, 0.095), "n": 8}
    d["t"] = round(min(0.024, 0.85 * d["L"] / d["n"]), 4)
    return d


def _bread_outline(v: int, w: float, h: float) -> list[tuple[float, float]]:
    """The loaf's cross-section (y, z), convex, counter-clockwise, bottom on z = 0."""
    if v == 0:  # straight sides, domed top, slightly rounded bottom corners
        hs = 0.6 * h
        pts = [(-w / 2 + 0.006, 0.0), (w / 2 - 0.006, 0.0), (w / 2, 0.006)]
        pts += [(w / 2 * np.cos(a), hs + (h - hs) * np.sin(a)) for a in np.linspace(0, np.pi, 11)]
        pts += [(-w / 2, 0.006)]
        return [(float(y), float(z)) for y, z in pts]
    # rounded loaves: a superellipse with a flat bottom
    p = 2.6 if v == 1 else 2.3
    flat = 0.12 if v == 1 else 0.22
    pts = []
    for a in np.linspace(0, 2 * np.pi, 20, endpoint=False):
        c, s = np.cos(a), np.sin(a)
        y = w / 2 * np.sign(c) * abs(c) ** (2 / p)
        z = h / 2 * np.sign(s) * abs(s) ** (2 / p)
        pts.append((y, z))
    zmin = -h / 2 + flat * h
    pts = [(y, max(z, zmin) - zmin) for y, z in pts]
    scale = h / max(z for _, z in pts)
    pts = [(float(y), float(z * scale)) for y, z in pts]
    out: list[tuple[float, float]] = []
    for q in pts:  # drop points pressed onto the same spot of the bottom line
        if not out or abs(q[0] - out[-1][0]) + abs(q[1] - out[-1][1]) > 1e-4:
            out.append(q)
    return out


def _bread_stations(v: int, length: float) -> list[tuple[float, float, float]]:
    half = length / 2
    if v == 0:
        return [(-half, 0.9, 0.9), (-half + 0.008, 0.97, 0.97), (-half + 0.025, 1.0, 1.0),
                (half - 0.025, 1.0, 1.0), (half - 0.008, 0.97, 0.97), (half, 0.9, 0.9)]
    xs = np.linspace(-1, 1, 11)
    power = 4 if v == 1 else 2.4
    out = []
    for x in xs:
        s = max(0.3 if v == 1 else 0.35, (1 - abs(x) ** power) ** 0.5)
        out.append((float(x * half), float(s), float(min(1.0, s * 1.05))))
    return out


@register("Bread", variants=3, category="small")
def bread(v: int, rng: np.random.Generator) -> AssetSpec:
    """A loaf lying along x: a domed sandwich loaf, a scored baguette or an oval country loaf."""
    d = _bread_dims(v)
    length, w, h, n, t = d["L"], d["W"], d["H"], int(d["n"]), d["t"]
    loaf = g.loft_x(_bread_outline(v, w, h), _bread_stations(v, length))
    parts = [Part(loaf, "bread", convex=True)]
    if v == 1:  # diagonal slashes along the top
        for k in range(5):
            x = (k - 2) * 0.17 * length
            s = max(0.3, (1 - abs(x / (length / 2)) ** 4) ** 0.5)
            cut = g.transformed(g.spheroid((0.034, 0.006, 0.004), sections=10, rings=5), yaw=0.5,
                                offset=(x, 0.0, h * min(1.0, s * 1.05) - 0.0022))
            parts.append(Part(cut, "food_bread_score", collide=False))
    elif v == 2:  # one long score along the top
        cut = g.spheroid((0.36 * length, 0.009, 0.005), (0.0, 0.004, h - 0.003), sections=12, rings=5)
        parts.append(Part(cut, "food_bread_score", collide=False))
    else:  # a split along the top crust
        cut = g.spheroid((0.4 * length, 0.006, 0.004), (0.0, 0.0, h - 0.0022), sections=10, rings=5)
        parts.append(Part(cut, "food_bread_score", collide=False))
    # lying slices: the cross-section's height lies along x (yaw 90 deg), stacked along the loaf
    stacks = max(1, min(n, round(length / (h * 1.04))))
    poses = _stack_poses(n, stacks, h * 1.04, t, yaw=float(np.pi / 2))
    return AssetSpec("Bread", v, "small", [Link("base", parts, robust_mass(parts, 0.4))],
                     slices=SliceSpec("BreadSliced", n, poses),
                     description=["sandwich loaf", "baguette", "oval country loaf"][v])


@register("BreadSliced", variants=3, category="small")
def bread_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """One slice of the matching loaf lying flat: crust all round, crumb on the cut face (top crust at +y)."""
    d = _bread_dims(v)
    w, h, t = d["W"], d["H"], d["t"]
    outline = [(y, z - h / 2) for y, z in _bread_outline(v, w, h)]
    crust = g.extrude(outline, t)
    crumb = g.extrude(g.inset_outline(outline, 0.0045 if v != 1 else 0.0035), 0.0008, t)
    parts = [Part(crust, "bread", convex=True), Part(crumb, "bread_crumb", collide=False)]
    return AssetSpec("BreadSliced", v, "small", [Link("base", parts, robust_mass(parts, 0.03))],
                     description=["slice of sandwich bread", "slice of baguette", "slice of country bread"][v])


# --------------------------------------------------------------------------------------------------
# Egg


@register("Egg", variants=3, category="small")
def egg(v: int, rng: np.random.Generator) -> AssetSpec:
    """A hen's egg lying on its side along x (blunt end at -x) on a small flat spot."""
    a = [pick(rng, 0.028, 0.030), pick(rng, 0.030, 0.032), pick(rng, 0.025, 0.027)][v]
    b = [0.735, 0.72, 0.8][v] * a
    skew = [0.13, 0.16, 0.08][v]
    ts = np.linspace(np.pi, 0.0, 13)  # from the blunt end (-a) to the pointed end (+a)
    profile = []
    for th in ts:
        x = a * np.cos(th)
        r = b * np.sin(th) * (1 - skew * x / a)
        profile.append((float(max(r, 0.0)), float(x)))
    profile[0], profile[-1] = (0.0, -a), (0.0, a)
    body = g.revolve(profile, axis="x", sections=16)
    body = g.pressed_flat(body, 0.0012)
    parts = [Part(body, "egg", convex=True)]
    return AssetSpec("Egg", v, "small", [Link("base", parts, robust_mass(parts, 0.06))],
                     description=["white egg", "large brown egg", "small round egg"][v])


# --------------------------------------------------------------------------------------------------
# Lettuce

LETTUCE_PIECES = 6


def _lettuce_dims(v: int) -> dict[str, float]:
    """0 an iceberg head, 1 a romaine head lying along x, 2 a flat, open butterhead."""
    rng = variant_rng("Lettuce", v)
    if v == 0:
        return {"rx": pick(rng, 0.068, 0.076), "ry": 0.0, "rz": pick(rng, 0.058, 0.064), "flat": 0.01}
    if v == 1:
        return {"rx": pick(rng, 0.12, 0.14), "ry": pick(rng, 0.045, 0.052), "rz": pick(rng, 0.04, 0.046)}
    return {"rx": pick(rng, 0.075, 0.082), "ry": 0.0, "rz": pick(rng, 0.045, 0.05), "flat": 0.01}


@register("Lettuce", variants=3, category="small")
def lettuce(v: int, rng: np.random.Generator) -> AssetSpec:
    """A head of lettuce: a firm core wrapped in overlapping leaves, on a flat base."""
    d = _lettuce_dims(v)
    leaves: list[trimesh.Trimesh] = []
    hearts: list[trimesh.Trimesh] = []
    if v == 1:
        rx, ry, rz = d["rx"], d["ry"], d["rz"]
        core = g.pressed_flat(g.spheroid((rx, ry, rz), sections=16, rings=8), 0.006)
        top = 2 * rz - 0.006
        for k, (yy, zz, roll) in enumerate([(-0.7, 0.45, -0.7), (0.7, 0.45, 0.7), (-0.3, 0.85, -0.25),
                                            (0.3, 0.85, 0.25), (0.0, 0.98, 0.0)]):
            leaf = g.spheroid((rx * (0.95 - 0.05 * (k % 2)), ry * 0.62, 0.008), sections=10, rings=6)
            leaf = g.transformed(leaf, roll=roll, offset=(rx * 0.06, yy * ry, zz * top))
            leaves.append(leaf)
            rib = g.spheroid((rx * 0.75, 0.0045, 0.0035), sections=8, rings=4)
            hearts.append(g.transformed(rib, roll=roll, offset=(rx * 0.02, yy * ry * 1.02, zz * top + 0.007)))
        frill = g.spheroid((0.03, ry * 1.15, rz * 0.9), (rx * 0.86, 0.0, rz * 0.95), sections=12, rings=6)
        leaves.append(frill)
        stump = g.cylinder(ry * 0.4, 0.012, (-rx + 0.004, 0.0, rz * 0.9), axis="x", sections=10)
        hearts.append(stump)
    else:
        r, rz = d["rx"], d["rz"]
        core = g.pressed_flat(g.spheroid((r * 0.92, r * 0.92, rz), sections=16, rings=8), d["flat"])
        top = float(core.vertices[:, 2].max())
        n_out = 7 if v == 0 else 8
        splay = 0.35 if v == 0 else 0.8
        for k in range(n_out):
            a = 2 * np.pi * k / n_out + 0.2
            leaf = g.spheroid((0.011, r * 0.72, top * (0.5 if v == 0 else 0.42)), sections=10, rings=5)
            leaf = g.transformed(leaf, pitch=splay, yaw=a)
            rho = r * (0.76 if v == 0 else 0.82)
            leaf.apply_translation((rho * np.cos(a), rho * np.sin(a), top * (0.48 if v == 0 else 0.46)))
            leaves.append(leaf)
        for k in range(3):
            a = 2 * np.pi * k / 3 + 1.0
            leaf = g.spheroid((0.01, r * 0.55, top * 0.33), sections=10, rings=5)
            leaf = g.transformed(leaf, pitch=-0.9, yaw=a)
            leaf.apply_translation((0.35 * r * np.cos(a), 0.35 * r * np.sin(a), top * 0.82))
            leaves.append(leaf)
        hearts.append(g.spheroid((r * 0.3, r * 0.3, 0.012), (0.0, 0.0, top - 0.008), sections=12, rings=5))
    parts = [Part(core, "lettuce", convex=True)]
    parts += [Part(m, "lettuce", collide=False) for m in leaves]
    parts += [Part(m, "food_lettuce_heart", collide=False) for m in hearts]
    t = _lettuce_piece_t(v)
    if v == 1:  # cross-cuts lying in two stacks along the head
        poses = _stack_poses(LETTUCE_PIECES, 2, 2 * d["ry"] * 1.05, t)
    else:  # horizontal slabs stacked where the head stood
        poses = _stack_poses(LETTUCE_PIECES, 1, 0.0, t)
    return AssetSpec("Lettuce", v, "small", [Link("base", parts, robust_mass(parts, 0.5))],
                     slices=SliceSpec("LettuceSliced", LETTUCE_PIECES, poses),
                     description=["iceberg lettuce", "romaine lettuce", "butterhead lettuce"][v])


def _lettuce_piece_t(v: int) -> float:
    d = _lettuce_dims(v)
    if v == 1:
        return round(min(0.03, 1.6 * d["rx"] / LETTUCE_PIECES), 4)
    return round((2 * d["rz"] - d["flat"]) / LETTUCE_PIECES, 4)


def _band(outline: list[tuple[float, float]], width: float, t: float, z0: float) -> trimesh.Trimesh:
    """A thin ring following an outline (a leaf layer seen on a cut face), `width` wide and `t` thick."""
    ring = Polygon(outline).difference(Polygon(g.inset_outline(outline, width)))
    mesh = trimesh.creation.extrude_polygon(ring, t)
    mesh.apply_translation((0.0, 0.0, z0))
    return mesh


@register("LettuceSliced", variants=3, category="small")
def lettuce_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """A cross-cut slab of the matching head lying flat: green rim, pale cut face with leaf layers."""
    d = _lettuce_dims(v)
    t = _lettuce_piece_t(v)
    if v == 1:
        outline = g.ellipse_points(d["ry"] * 0.95, d["rz"] * 0.95, 18)
        layers = [(0.72, 0.0, 0.0), (0.45, 0.0, 0.002)]
    else:
        rr = 0.86 * d["rx"] * 0.92
        outline = g.ellipse_points(rr, rr * 0.97, 20)
        layers = [(0.78, 0.004, 0.0), (0.56, -0.003, 0.004), (0.33, 0.002, -0.002)]
    parts = [Part(g.extrude(outline, t), "lettuce", convex=True),
             Part(g.extrude(g.inset_outline(outline, 0.003), 0.0006, t), "food_lettuce_heart", collide=False)]
    for s, ox, oy in layers:
        ring = [(x * s + ox, y * s + oy) for x, y in outline]
        parts.append(Part(_band(ring, 0.0025, 0.0008, t), "lettuce", collide=False))
    mass = robust_mass(parts, round(0.5 / LETTUCE_PIECES, 4))
    return AssetSpec("LettuceSliced", v, "small", [Link("base", parts, mass)],
                     description="cross-cut slab of lettuce" if v != 1 else "cross-cut piece of romaine")


# --------------------------------------------------------------------------------------------------
# Potato


def _potato_dims(v: int) -> dict:
    """0 a long russet, 1 a round potato, 2 a small waxy potato; lumps drawn from the same stream."""
    rng = variant_rng("Potato", v)
    rx = [pick(rng, 0.055, 0.062), pick(rng, 0.042, 0.046), pick(rng, 0.036, 0.04)][v]
    ry = [0.58, 0.85, 0.72][v] * rx
    rz = [0.5, 0.75, 0.64][v] * rx
    bumps = []
    for _ in range(6):
        dvec = rng.normal(size=3)
        dvec /= np.linalg.norm(dvec)
        bumps.append((tuple(round(float(c), 3) for c in dvec), pick(rng, -0.08, 0.1)))
    n = [6, 5, 5][v]
    return {"rx": rx, "ry": ry, "rz": rz, "bumps": bumps, "n": n,
            "r_slice": round(0.9 * (ry + rz) / 2, 4), "t": round(min(0.014, 1.7 * rx / n), 4)}


@register("Potato", variants=3, category="small")
def potato(v: int, rng: np.random.Generator) -> AssetSpec:
    """A lumpy potato lying along x, with a few dark eyes."""
    d = _potato_dims(v)
    body = g.spheroid((1.0, 1.0, 1.0), sections=16, rings=9)
    vv = np.array(body.vertices)
    dirs = vv / np.linalg.norm(vv, axis=1, keepdims=True)
    factor = np.ones(len(vv))
    for dvec, amp in d["bumps"]:
        factor += amp * np.maximum(0.0, dirs @ np.asarray(dvec)) ** 3
    vv = vv * factor[:, None] * np.array([d["rx"], d["ry"], d["rz"]])
    body = g.pressed_flat(trimesh.Trimesh(vv, body.faces, process=False), 0.004)
    parts = [Part(body, "potato", convex=True)]
    # eyes on the upper surface: small dark dimples at fixed vertices
    top = body.vertices[:, 2].max()
    cand = [i for i, p in enumerate(body.vertices) if p[2] > 0.55 * top]
    for k in range(4):
        i = cand[(k * 7 + 3) % len(cand)]
        p = body.vertices[i]
        parts.append(Part(g.spheroid((0.0035, 0.0035, 0.0035), p, sections=6, rings=3), "food_potato_eye",
                          collide=False))
    pitch = 2 * d["r_slice"] * 1.05
    poses = _stack_poses(d["n"], max(1, round(2 * d["rx"] / pitch)), pitch, d["t"])
    return AssetSpec("Potato", v, "small", [Link("base", parts, robust_mass(parts, 0.2))],
                     slices=SliceSpec("PotatoSliced", d["n"], poses),
                     description=["russet potato", "round potato", "small potato"][v])


@register("PotatoSliced", variants=3, category="small")
def potato_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """A round slice of the matching potato lying flat: brown skin rim, pale cut face."""
    d = _potato_dims(v)
    r, t = d["r_slice"], d["t"]
    outline = g.ellipse_points(r * 1.08, r * 0.93, 18)
    disc = g.extrude(outline, t)
    face = g.extrude(g.inset_outline(outline, 0.0018), 0.0008, t)
    parts = [Part(disc, "potato", convex=True), Part(face, "potato_flesh", collide=False)]
    return AssetSpec("PotatoSliced", v, "small", [Link("base", parts, robust_mass(parts, round(0.2 / d["n"], 4)))],
                     description="potato slice")


# --------------------------------------------------------------------------------------------------
# Tomato


def _tomato_dims(v: int) -> dict:
    """0 a round salad tomato, 1 a ribbed beefsteak tomato, 2 a small vine tomato."""
    rng = variant_rng("Tomato", v)
    r = [pick(rng, 0.034, 0.038), pick(rng, 0.043, 0.048), pick(rng, 0.028, 0.031)][v]
    squash = [0.86, 0.7, 0.9][v]
    n = [5, 6, 5][v]
    h = 2 * r * squash - 0.003
    return {"r": r, "squash": squash, "ribs": [0.02, 0.07, 0.015][v], "n": n, "h": round(h, 4),
            "t": round(h / n, 4), "r_slice": round(0.88 * r, 4)}


@register("Tomato", variants=3, category="small")
def tomato(v: int, rng: np.random.Generator) -> AssetSpec:
    """A round, slightly flattened tomato with shallow ribs, a green star-shaped calyx and a stem."""
    d = _tomato_dims(v)
    r, squash = d["r"], d["squash"]
    body = g.spheroid((r, r, r * squash), sections=20, rings=9)
    vv = np.array(body.vertices)
    theta = np.arctan2(vv[:, 1], vv[:, 0])
    lat = np.sqrt(np.maximum(0.0, 1 - (vv[:, 2] / (r * squash)) ** 2))
    k = 1 + d["ribs"] * np.cos(5 * theta) * lat - 0.06 * np.clip(vv[:, 2] / (r * squash) - 0.75, 0, None) * 4
    vv[:, :2] *= k[:, None]
    body = g.pressed_flat(trimesh.Trimesh(vv, body.faces, process=False), 0.003)
    top = float(body.vertices[:, 2].max())
    parts = [Part(body, "tomato", convex=True)]
    for i in range(5):
        a = 2 * np.pi * i / 5 + 0.3
        sepal = g.spheroid((0.5 * r * 0.42, 0.0045, 0.0015), sections=8, rings=4)
        sepal = g.transformed(sepal, yaw=a, pitch=-0.15,
                              offset=(0.2 * r * np.cos(a), 0.2 * r * np.sin(a), top - 0.0005))
        parts.append(Part(sepal, "plant", collide=False))
    parts.append(Part(g.cylinder(0.0025, 0.012, (0.0, 0.0, top + 0.005), sections=6), "plant", collide=False))
    poses = _stack_poses(d["n"], 1, 0.0, d["t"])
    return AssetSpec("Tomato", v, "small", [Link("base", parts, robust_mass(parts, 0.15))],
                     slices=SliceSpec("TomatoSliced", d["n"], poses),
                     description=["tomato", "beefsteak tomato", "vine tomato"][v])


@register("TomatoSliced", variants=3, category="small")
def tomato_slice(v: int, rng: np.random.Generator) -> AssetSpec:
    """A horizontal slice of the matching tomato lying flat: red rim, flesh face with seed pockets."""
    d = _tomato_dims(v)
    r, t = d["r_slice"], d["t"]
    parts = _disc_slice(r, t, "tomato", "tomato_flesh", sections=18)
    pockets = [3, 5, 4][v]
    for i in range(pockets):
        a = 2 * np.pi * i / pockets
        seed = g.spheroid((0.28 * r, 0.16 * r, 0.0008), sections=8, rings=3)
        seed = g.transformed(seed, yaw=a, offset=(0.5 * r * np.cos(a), 0.5 * r * np.sin(a), t + 0.0008))
        parts.append(Part(seed, "food_seed", collide=False))
    return AssetSpec("TomatoSliced", v, "small", [Link("base", parts, robust_mass(parts, round(0.15 / d["n"], 4)))],
                     description="tomato slice")
