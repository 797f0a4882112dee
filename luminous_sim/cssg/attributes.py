"""A CDF object's attributes (colour, material, size) applied to the choice and scale of its asset."""

from __future__ import annotations

import math
from typing import Any

from luminous_sim.assets.catalog import AssetEntry, scaled
from luminous_sim.errors import CDFError

MATERIAL_SLOTS: dict[str, frozenset[str]] = {
    "wood": frozenset({"wood", "dark_wood"}), "wooden": frozenset({"wood", "dark_wood"}),
    "oak": frozenset({"wood"}), "pine": frozenset({"wood"}), "walnut": frozenset({"dark_wood"}),
    "metal": frozenset({"metal", "dark_metal", "brass", "appliance"}), "steel": frozenset({"metal", "appliance"}),
    "brass": frozenset({"brass"}), "fabric": frozenset({"fabric", "cushion", "drape"}),
    "leather": frozenset({"leather"}), "ceramic": frozenset({"ceramic", "porcelain"}),
    "porcelain": frozenset({"porcelain"}), "glass": frozenset({"glass"}),
    "plastic": frozenset({"plastic", "dark_plastic"}), "stone": frozenset({"stone"}),
    "marble": frozenset({"stone"}), "paper": frozenset({"paper"}),
}
"""Material words a CDF may use -> the asset material slots that count as that material."""
SCALE_RANGE = (0.3, 3.0)
"""Factors by which a CDF's `size` may scale an asset; a size no variant of the type meets within it is refused."""


def parse_colour(name: str, where: str = "attributes.colour") -> tuple[float, float, float]:
    """An RGB triple for a colour name ("white", "navy") or hex code ("#c0392b")."""
    from matplotlib import colors

    try:
        r, g, b = colors.to_rgb(name.strip().lower().replace(" ", ""))
    except ValueError:
        raise CDFError(
            f"{where}: unknown colour {name!r}; use a colour name (red, navy, beige...) or #rrggbb") from None
    return (round(r, 4), round(g, 4), round(b, 4))


def _slots(entry: AssetEntry) -> set[str]:
    return {v["slot"] for v in entry.visuals}


def with_material(variants: list[AssetEntry], material: str | None) -> list[AssetEntry]:
    """The variants made of `material` (all of them when none is, or no material is asked for)."""
    if not material:
        return variants
    wanted = MATERIAL_SLOTS.get(material.strip().lower(), frozenset({material.strip().lower()}))
    hits = [e for e in variants if _slots(e) & wanted]
    return hits or variants


def scale_for(entry: AssetEntry, size: Any) -> float:
    """The factor the CDF's `size` asks of this entry: the factor itself, or the geometric mean of the ratios
    of {width, depth, height} (metres) to the entry's dimensions."""
    if isinstance(size, (int, float)):
        return float(size)
    want = [size["width"], size["depth"], size["height"]]
    ratios = [w / max(d, 1e-6) for w, d in zip(want, entry.dims)]
    return math.exp(sum(math.log(r) for r in ratios) / 3)


def fits(entry: AssetEntry, size: Any) -> bool:
    """Whether `size` scales this entry by a factor within SCALE_RANGE."""
    return size is None or SCALE_RANGE[0] <= scale_for(entry, size) <= SCALE_RANGE[1]


def sized(entry: AssetEntry, size: Any) -> AssetEntry:
    """The entry scaled as the CDF's `size` says: a factor, or {width, depth, height} in metres."""
    if size is None:
        return entry
    return scaled(entry, min(max(scale_for(entry, size), SCALE_RANGE[0]), SCALE_RANGE[1]))


def _describe(size: Any) -> str:
    if isinstance(size, (int, float)):
        return f"{size:g}"
    return "{" + ", ".join(f"{k}: {size[k]:g}" for k in ("width", "depth", "height")) + "}"


def check_size(variants: list[AssetEntry], size: Any, object_type: str, where: str) -> None:
    """Refuse a `size` that no variant meets within SCALE_RANGE (it used to be clamped silently).

    Raises:
        CDFError: Naming the object, the size asked for, the factor it needs and the range allowed.
    """
    if size is None or not variants or any(fits(e, size) for e in variants):
        return
    factors = sorted(scale_for(e, size) for e in variants)
    need = f"{factors[0]:.3g}x or more" if factors[0] > SCALE_RANGE[1] else f"{factors[-1]:.3g}x or less"
    dims = " x ".join(f"{d:.2f}" for d in variants[0].dims)
    raise CDFError(
        f"{where}: attributes.size {_describe(size)} would scale every {object_type} asset by {need} "
        f"(one is {dims} m); a size may scale an asset by {SCALE_RANGE[0]:g}x to {SCALE_RANGE[1]:g}x")


def check_assets(cdf: Any, catalog: Any) -> None:
    """Every type the CDF's objects name has an asset in the catalog (before any layout is drawn).

    Raises:
        AssetError: the first object whose type (or named asset) the library lacks: what, where it was looked
            for, and what provides it.
    """
    from luminous_sim.errors import AssetError

    for i, spec in enumerate(cdf.scene.objects):
        pool = catalog.of_type(spec.type)
        if pool and (not spec.asset or any(e.id == spec.asset for e in pool)):
            continue
        roots = sorted({e.root for e in catalog}) or ["(an empty catalog)"]
        what = f"no asset {spec.asset!r} among its {spec.type} variants" if pool else f"no asset of type {spec.type}"
        raise AssetError(f"scene.objects[{i}] ({spec.name}): the asset library has {what} "
                         f"(looked in {', '.join(roots)}); the shipped library has every ALFRED type: unset "
                         "LUMINOUS_ASSETS, or add one with `luminous assets import MESH --type "
                         f"{spec.type}`")


def check_sizes(cdf: Any, catalog: Any) -> None:
    """Check every CDF object's `size` against the variants it may use (before any layout is drawn).

    Raises:
        CDFError: The first object whose size no variant meets within SCALE_RANGE.
    """
    for i, spec in enumerate(cdf.scene.objects):
        attrs = spec.attributes.model_dump(exclude_none=True) if spec.attributes else {}
        if attrs.get("size") is None:
            continue
        pool = [e for e in catalog.of_type(spec.type) if not spec.asset or e.id == spec.asset]
        pool = with_material(pool, attrs.get("material"))
        check_size(pool, attrs["size"], spec.type, f"scene.objects[{i}] ({spec.name})")


def size_misfit(entry: AssetEntry, size: Any) -> float:
    """How far a variant's proportions are from requested dimensions (0 for a scale factor)."""
    if size is None or isinstance(size, (int, float)):
        return 0.0
    want = [size["width"], size["depth"], size["height"]]
    logs = [math.log(w / max(d, 1e-6)) for w, d in zip(want, entry.dims)]
    mean = sum(logs) / 3
    return sum((x - mean) ** 2 for x in logs)


def candidates(variants: list[AssetEntry], attributes: dict[str, Any] | None) -> list[AssetEntry]:
    """The variants to draw from for an object with these attributes, already scaled."""
    attributes = attributes or {}
    pool = with_material(variants, attributes.get("material"))
    size = attributes.get("size")
    if size is not None and pool and not all(fits(e, size) for e in pool):
        # variants the size would scale out of range are left out (check_sizes refused the CDF if none fits)
        pool = [e for e in pool if fits(e, size)] or pool
    if size is not None and not isinstance(size, (int, float)) and pool:
        best = min(size_misfit(e, size) for e in pool)
        pool = [e for e in pool if size_misfit(e, size) <= best + 0.05]
    return [sized(e, size) for e in pool]
