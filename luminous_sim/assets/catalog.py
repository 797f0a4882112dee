"""The asset catalog: every asset's type, variant, size, abilities, regions, joints and files."""

from __future__ import annotations

import json
from functools import cache
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ConfigDict

from luminous_sim.assets.paths import user_asset_root
from luminous_sim.errors import AssetError
from luminous_sim.resources import asset_library

CATALOG_NAME = "catalog.json"


class AssetEntry(BaseModel):
    """One asset as listed in a catalog (see urdf_writer.write_asset for how it is made)."""

    model_config = ConfigDict(frozen=True, extra="allow")

    id: str
    type: str
    variant: int
    category: str
    description: str = ""
    tags: list[str] = []
    urdf: str
    files: list[str]
    bbox_min: list[float]
    bbox_max: list[float]
    dims: list[float]
    mass: float
    abilities: dict[str, bool]
    links: list[str]
    link_origins: dict[str, list[float]]
    joints: list[dict[str, Any]]
    regions: list[dict[str, Any]]
    visuals: list[dict[str, Any]]
    palettes: dict[str, list[list[float]]]
    slices: dict[str, Any] | None = None
    anchors: list[dict[str, Any]] = []
    collision_hulls: int = 0
    visual_vertices: int = 0
    visual_triangles: int = 0
    lod_urdf: str = ""
    """The same asset with decimated visuals (level of detail for small frames); "" where it has none."""
    lod_visual_triangles: int = 0
    root: str = ""
    """Folder the relative paths are resolved against (filled in when loaded)."""
    scale: float = 1.0
    """Uniform scale the asset is loaded at (1 in the catalog; see `scaled`)."""

    @property
    def urdf_path(self) -> Path:
        return Path(self.root) / self.urdf

    def urdf_for(self, lod: bool) -> Path:
        """The URDF to load: the level-of-detail one if asked for and built, else the full-detail one."""
        return Path(self.root) / self.lod_urdf if lod and self.lod_urdf else self.urdf_path


def _scale_xyz(v: list[float], s: float) -> list[float]:
    return [round(x * s, 5) for x in v]


def scaled(entry: AssetEntry, s: float) -> AssetEntry:
    """The same asset loaded `s` times larger: sizes, regions, joints, anchors and slices scale along."""
    if abs(s - 1.0) < 1e-9:
        return entry
    regions = [{**r, "center": _scale_xyz(r["center"], s), "size": _scale_xyz(r["size"], s)} for r in entry.regions]
    joints = [{**j, "origin": _scale_xyz(j["origin"], s),
               **({"lower": j["lower"] * s, "upper": j["upper"] * s} if j["kind"] == "prismatic" else {})}
              for j in entry.joints]
    anchors = [{**a, "pose": _scale_xyz(a["pose"][:3], s) + [a["pose"][3]]} for a in entry.anchors]
    slices = None
    if entry.slices:
        slices = {**entry.slices, "poses": [_scale_xyz(q[:3], s) + [q[3]] for q in entry.slices["poses"]]}
    return entry.model_copy(update={
        "scale": round(entry.scale * s, 5), "bbox_min": _scale_xyz(entry.bbox_min, s),
        "bbox_max": _scale_xyz(entry.bbox_max, s), "dims": _scale_xyz(entry.dims, s),
        "mass": round(entry.mass * s ** 3, 5), "regions": regions, "joints": joints, "anchors": anchors,
        "slices": slices, "link_origins": {k: _scale_xyz(v, s) for k, v in entry.link_origins.items()},
    })


class Catalog:
    """All assets of the built-in library plus the user's imported ones."""

    def __init__(self, entries: list[AssetEntry]):
        self._by_id = {e.id: e for e in entries}
        self._by_type: dict[str, list[AssetEntry]] = {}
        for e in sorted(entries, key=lambda e: (e.type, e.variant, e.id)):
            self._by_type.setdefault(e.type, []).append(e)

    @staticmethod
    def read(root: Path) -> list[AssetEntry]:
        """The entries of one library folder (empty if it has no catalog)."""
        path = root / CATALOG_NAME
        if not path.exists():
            return []
        try:
            doc = json.loads(path.read_text())
            return [AssetEntry(**{**e, "root": str(root)}) for e in doc["assets"]]
        except (ValueError, KeyError, TypeError) as exc:
            raise AssetError(f"{path}: not a valid asset catalog ({exc})") from exc

    @classmethod
    def load(cls, root: Path | None = None, include_user: bool = True) -> Catalog:
        """The library at `root` (default: the one in use, checked against its digest) and the user's.

        Raises:
            AssetError: the default library is missing, lists no assets or has another digest.
        """
        entries = cls.read(Path(root) if root is not None else asset_library())
        if include_user:
            entries += cls.read(user_asset_root())
        return cls(entries)

    def __len__(self) -> int:
        return len(self._by_id)

    def __iter__(self):
        return iter(sorted(self._by_id.values(), key=lambda e: e.id))

    def __contains__(self, asset_id: str) -> bool:
        return asset_id in self._by_id

    def get(self, asset_id: str) -> AssetEntry:
        try:
            return self._by_id[asset_id]
        except KeyError:
            raise AssetError(f"no asset {asset_id!r} in the catalog") from None

    def for_object(self, obj) -> AssetEntry:
        """The entry of a scene object at the scale it was placed with."""
        return scaled(self.get(obj.asset), getattr(obj, "scale", 1.0))

    def of_type(self, object_type: str) -> list[AssetEntry]:
        """Every variant of a type (built-in first, then imported), possibly empty."""
        return list(self._by_type.get(object_type, []))

    def types(self) -> list[str]:
        return sorted(self._by_type)

    def to_json(self) -> list[dict[str, Any]]:
        return [e.model_dump(exclude={"root", "scale"}) for e in self]


@cache
def default_catalog() -> Catalog:
    """The catalog of the installed library plus the user library (cached per process)."""
    return Catalog.load()
