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


def parse_colour(name: str, where: str = "attributes.colour") -> tuple[float, float, float]:
    """An RGB triple for a colour name ("white", "navy") or hex code ("#c0392b")."""
    from matplotlib import colors

    try:
        r, g, b = colors.to_rgb(name.strip().lower().replace(" ", ""))
    except ValueError:
        raise CDFError(f"{where}: unknown colour {name!r}; use a colour name (red, navy, beige...) or #rrggbb") from None
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


def sized(entry: AssetEntry, size: Any) -> AssetEntry:
    """The entry scaled as the CDF's `size` says: a factor, or {width, depth, height} in metres."""
    if size is None:
        return entry
    if isinstance(size, (int, float)):
        s = float(size)
    else:
        want = [size["width"], size["depth"], size["height"]]
        ratios = [w / max(d, 1e-6) for w, d in zip(want, entry.dims)]
        s = math.exp(sum(math.log(r) for r in ratios) / 3)
    return scaled(entry, min(max(s, SCALE_RANGE[0]), SCALE_RANGE[1]))


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
    if size is not None and not isinstance(size, (int, float)) and pool:
        best = min(size_misfit(e, size) for e in pool)
        pool = [e for e in pool if size_misfit(e, size) <= best + 0.05]
    return [sized(e, size) for e in pool]
