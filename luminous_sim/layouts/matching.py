"""Matching a layout's objects to the asset catalog: a class label to an ALFRED type (a table as data, then
the catalog's own type names, then the label's last words, then a close spelling), and a box size to the
variant of that type that fits it best at a uniform scale within [MIN_SCALE, MAX_SCALE]."""

from __future__ import annotations

import difflib
import json
import math
import re
from dataclasses import dataclass
from functools import cache
from importlib import resources

from luminous_sim.assets.catalog import AssetEntry, Catalog, scaled

MIN_SCALE = 0.8
MAX_SCALE = 1.25
"""Limits of the uniform scale applied to a matched asset (beyond them its size differs from the box's)."""
CLOSE = 0.85
"""difflib ratio from which a misspelt label counts as the table's label (the fuzzy fallback)."""


@dataclass(frozen=True)
class CategoryMatch:
    """A label's ALFRED type (None: left out, `reason` says why) and how it was found: table, type name,
    head words (the label's last words), fuzzy (a close spelling of `key`), or none."""

    label: str
    type: str | None
    method: str
    key: str = ""
    reason: str = ""


@dataclass(frozen=True)
class SizeMatch:
    """The variant chosen for a box: the scaled entry, its scale, whether the scale hit a limit, and the sizes
    wanted and got (width, depth, height, metres)."""

    entry: AssetEntry
    scale: float
    clamped: bool
    wanted: tuple[float, float, float]
    got: tuple[float, float, float]

    def to_dict(self) -> dict:
        return {"asset": self.entry.id, "scale": self.scale, "scale_clamped": self.clamped,
                "wanted_size": [round(v, 3) for v in self.wanted], "got_size": [round(v, 3) for v in self.got]}


def normalise(label: str) -> str:
    """Lower case, CamelCase split, '/', '_' and '-' read as spaces, spaces collapsed."""
    text = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", label.strip())
    return " ".join(re.sub(r"[/_\-]+", " ", text.lower()).split())


@cache
def _table() -> dict:
    return json.loads(resources.files("luminous_sim.layouts").joinpath("data/categories.json").read_text())


def category_table() -> dict[str, str | None]:
    """The label table (normalised label -> ALFRED type, or None for labels left out on purpose)."""
    return dict(_table()["types"])


def match_category(label: str, catalog: Catalog) -> CategoryMatch:
    """The ALFRED type of a class label (see the module docstring for the order tried)."""
    key = normalise(label)
    table = category_table()
    types = {normalise(t): t for t in catalog.types()}
    if key in table:
        hit = table[key]
        why = _table()["left_out_because"].get(key, "no counterpart in the asset library")
        return CategoryMatch(label, hit, "table", key, "" if hit else why)
    if key in types:
        return CategoryMatch(label, types[key], "type name", key)
    words = key.split()
    for k in range(1, len(words)):
        tail = " ".join(words[k:])
        if tail in table or tail in types:
            found = _known(tail, table, types)
            return CategoryMatch(label, found, "head words", tail, "" if found else "no counterpart in the library")
    close = difflib.get_close_matches(key, sorted(set(table) | set(types)), n=1, cutoff=CLOSE)
    if close:
        found = _known(close[0], table, types)
        return CategoryMatch(label, found, "fuzzy", close[0], "" if found else "no counterpart in the library")
    return CategoryMatch(label, None, "none", reason="not in the category table and like no catalog type")


def _known(key: str, table: dict, types: dict) -> str | None:
    return table[key] if key in table else types[key]


def _fit(wanted: tuple[float, float, float], dims: list[float]) -> tuple[float, float, bool]:
    """(error, scale, clamped): the uniform scale that best fits `dims` to `wanted` in log terms, clamped."""
    logs = [math.log(max(w, 1e-3) / max(d, 1e-3)) for w, d in zip(wanted, dims)]
    ideal = math.exp(sum(logs) / 3)
    s = min(max(ideal, MIN_SCALE), MAX_SCALE)
    err = sum(abs(v - math.log(s)) for v in logs)
    return err, s, abs(s - ideal) > 1e-9


def match_size(object_type: str, wanted: tuple[float, float, float], catalog: Catalog) -> SizeMatch | None:
    """The variant of `object_type` whose uniformly scaled box fits `wanted` best; None if the type has none."""
    best = None
    for e in catalog.of_type(object_type):
        err, s, clamped = _fit(wanted, e.dims)
        if best is None or err < best[0] - 1e-12:
            best = (err, e, s, clamped)
    if best is None:
        return None
    _, e, s, clamped = best
    entry = scaled(e, round(s, 4))
    return SizeMatch(entry, entry.scale, clamped, wanted, tuple(entry.dims))  # type: ignore[arg-type]
