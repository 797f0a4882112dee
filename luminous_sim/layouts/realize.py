"""A layout made into a scene: match each object to the catalog, then build, repair and furnish it with CSSG
(`cssg.place_given`), which validates it as it validates a generated scene."""

from __future__ import annotations

from dataclasses import dataclass, field

from luminous_sim.assets.catalog import Catalog, default_catalog, scaled
from luminous_sim.cssg import GivenScene, Placement, place_given
from luminous_sim.errors import AssetError
from luminous_sim.layouts.convert import origin_of, shell_of_room
from luminous_sim.layouts.matching import match_category, match_size
from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject

FLOOR_SNAP = 0.05
"""metres a free-standing piece may float above or sink below the floor before the snap is reported."""


@dataclass
class Realized:
    """A layout's scene (`given.generated`: scene and validation report), how each object was matched, the
    objects left out before building, and `ok` (accepted: nothing to reject, the report passes)."""

    given: GivenScene
    matches: list[dict] = field(default_factory=list)
    unmatched: list[dict] = field(default_factory=list)
    source: str = ""
    imported_dropped: list[dict] = field(default_factory=list)
    """What the importer left out of the layout (its `provenance.notes["dropped"]`: entry path and reason)."""

    @property
    def dropped(self) -> list[dict]:
        """Every entry of the input left out: by the importer, then the objects no asset matches."""
        return self.imported_dropped + self.unmatched

    @property
    def ok(self) -> bool:
        return self.given.ok

    def problems(self) -> list[str]:
        """Why the layout is rejected (empty: accepted)."""
        report = self.given.generated.report
        out = list(self.given.problems)
        out += [f"{a} overlaps {b}" for a, b in report.overlaps]
        out += [f"{o} is out of the agent's reach" for o in report.unreachable]
        out += [f"{n} (required) could not be placed" for n in report.unplaced if n in report.required]
        if report.reachable_points == 0:
            out.append("the agent has nowhere to stand")
        return out

    def to_dict(self) -> dict:
        """The repair report: matches, what was left out, moved or added, and the validation report."""
        return {
            "source": self.source, "accepted": self.ok, "problems": self.problems(),
            "matches": self.matches, "unmatched": self.unmatched, "dropped": self.dropped,
            "repairs": [vars(r) for r in self.given.repairs],
            "scene_ids": self.given.ids,
            "layout": self.given.generated.report.to_dict(),
        }


def _is_floor(layer: str | None, object_type: str, parent: str | None) -> bool:
    from luminous_sim.vocab import FIXTURE_TYPES, FURNITURE_TYPES

    if parent is not None:
        return False
    return layer in ("furniture", "fixture") if layer else object_type in FIXTURE_TYPES | FURNITURE_TYPES


def _placement(i: int, o: LayoutObject, catalog: Catalog, where: str, matches: list[dict],
               unmatched: list[dict]) -> Placement | None:
    if o.asset is not None:  # a Luminous layout: the asset as given
        try:
            entry = scaled(catalog.get(o.asset), o.scale or 1.0)
        except AssetError:
            raise LayoutError(f"{where}: objects[{i}].asset: no asset {o.asset!r} in the catalog") from None
        if entry.type != o.category:
            raise LayoutError(f"{where}: objects[{i}].category: asset {o.asset!r} is a {entry.type}; expected "
                              f"category {entry.type}, got {o.category!r}")
        x, y, z = origin_of(entry, o.position, o.yaw)
        return Placement(o.id, entry, (x, y, z), o.yaw, o.layer, o.fixed, o.parent, o.region, o.name,
                         {str(k): v for k, v in o.states.items()}, o.color, o.color_seed, o.id)
    cat = match_category(o.category, catalog)
    if cat.type is None:
        unmatched.append({"entry": f"objects[{i}]", "id": o.id, "category": o.category, "reason": cat.reason})
        return None
    size = match_size(cat.type, o.size, catalog)
    if size is None:
        unmatched.append({"entry": f"objects[{i}]", "id": o.id, "category": o.category,
                          "reason": f"no {cat.type} asset in the catalog"})
        return None
    entry = size.entry
    x, y, z = origin_of(entry, o.position, o.yaw)
    note = {"id": o.id, "category": o.category, "type": cat.type, "method": cat.method, **size.to_dict()}
    if cat.method == "fuzzy" or cat.method == "head words":
        note["matched_label"] = cat.key
    if _is_floor(o.layer, cat.type, o.parent):
        bottom = o.position[2] - o.size[2] / 2
        if abs(bottom) > FLOOR_SNAP:
            note["floor_snap"] = round(-bottom, 3)
        z = -entry.bbox_min[2] + 0.0
    matches.append(note)
    return Placement(o.id, entry, (x, y, z), o.yaw, o.layer, o.fixed, o.parent, o.region, o.name,
                     {str(k): v for k, v in o.states.items()}, o.color, o.color_seed)


def realize(layout: Layout, seed: int | None = None, catalog: Catalog | None = None, *, repair: bool = True,
            defaults: bool | None = None, required: tuple[str, ...] = (), where: str = "layout") -> Realized:
    """The scene of a layout, validated, repaired and furnished as `cssg.place_given` does.

    Args:
        seed: for the draws of the object layer (default: the layout's provenance seed).
        defaults: add the room type's default small objects (default: only for a layout that is not a
            complete Luminous scene, i.e. whose objects do not all name an asset).
        required: object types the scene must hold (ALFRED's task objects, say).
    """
    catalog = catalog or default_catalog()
    shell = shell_of_room(layout.room, where)
    matches: list[dict] = []
    unmatched: list[dict] = []
    placements = [p for i, o in enumerate(layout.objects)
                  if (p := _placement(i, o, catalog, where, matches, unmatched)) is not None]
    if defaults is None:
        defaults = not layout.objects or any(o.asset is None for o in layout.objects)
    prov = layout.provenance
    given = place_given(shell, placements, prov.seed if seed is None else seed, catalog, repair=repair,
                        defaults=defaults, required=required, generator=prov.generator, source=prov.source,
                        notes=prov.notes)
    dropped = prov.notes.get("dropped", [])
    return Realized(given, matches, unmatched, where,
                    [d for d in dropped if isinstance(d, dict)] if isinstance(dropped, list) else [])
