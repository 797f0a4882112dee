"""Import a user's own mesh (OBJ, GLB/glTF, STL, PLY; e.g. from 3D-FUTURE or Objaverse) as a catalog asset."""

from __future__ import annotations

import fcntl
import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from luminous_sim.assets.catalog import CATALOG_NAME, Catalog
from luminous_sim.assets.paths import coacd_cache_dir, user_asset_root
from luminous_sim.assets.spec import AssetSpec, Link, Part, Region
from luminous_sim.assets.urdf_writer import write_asset
from luminous_sim.errors import AssetError, path_kind
from luminous_sim.fileio import write_atomic
from luminous_sim.vocab import abilities, check_type

MESH_SUFFIXES = {".obj", ".glb", ".gltf", ".stl", ".ply", ".off"}
USER_VARIANT_BASE = 100
"""Imported assets get variants 100, 101, ... so their ids never clash with built-in ones."""
DENSITY = 400.0
"""kg/m^3 used for the default mass (a mix of hollow and solid household things)."""
SIZE_FACTOR = 5.0
"""An import whose largest dimension is more than this factor off the catalog's typical one for its type is
refused (unless asked for with `any_size`): it is almost always a mesh in other units."""
UNITS = {"centimetres": 0.01, "millimetres": 0.001, "inches": 0.0254, "decimetres": 0.1}

# glTF and most OBJ exports are y-up with the front towards +z; ours is z-up with the front towards +y.
_Y_UP_TO_Z_UP = np.array([[-1, 0, 0, 0], [0, 0, 1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)


@dataclass(frozen=True)
class ImportResult:
    asset_id: str
    entry: dict[str, Any]
    catalog: Path


def load_user_mesh(path: Path) -> trimesh.Trimesh:
    """Read a mesh file into one triangle mesh, with a clear AssetError for every way it can be bad."""
    path = Path(path)
    kind = path_kind(path)
    if kind != "a regular file":
        what = "no such file" if kind == "no such file or folder" else kind
        raise AssetError(f"{path}: {what}; expected a mesh file")
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise AssetError(f"{path}: not a mesh file (expected one of {', '.join(sorted(MESH_SUFFIXES))})")
    try:
        mesh = trimesh.load(path, force="mesh", process=True)
    except Exception as exc:  # trimesh raises many types for corrupt files
        raise AssetError(f"{path}: could not be read as a mesh ({type(exc).__name__}: {exc})") from exc
    if not isinstance(mesh, trimesh.Trimesh) or len(mesh.faces) == 0:
        raise AssetError(f"{path}: the file holds no triangles (empty mesh)")
    if not np.all(np.isfinite(mesh.vertices)):
        raise AssetError(f"{path}: the mesh has non-finite vertex coordinates")
    return mesh


def normalise(mesh: trimesh.Trimesh, scale: float, up: str) -> trimesh.Trimesh:
    """Rotate to z-up/front +y, scale, and move the footprint centre to the origin with the bottom at z=0."""
    out = mesh.copy()
    if up == "y":
        out.apply_transform(_Y_UP_TO_Z_UP)
    elif up != "z":
        raise AssetError(f"--up must be 'y' or 'z', not {up!r}")
    out.apply_scale(scale)
    lo, hi = out.bounds
    out.apply_translation((-(lo[0] + hi[0]) / 2, -(lo[1] + hi[1]) / 2, -lo[2]))
    return out


def typical_size(object_type: str) -> float | None:
    """The median largest dimension (m) of the built-in assets of a type (None: the library has none)."""
    sizes = [max(e.dims) for e in Catalog.load(include_user=False).of_type(object_type)]
    return float(np.median(sizes)) if sizes else None


def suggested_scale(largest: float, scale: float, typical: float) -> str:
    """`--scale X` that brings a mesh `largest` m across (at `scale`) to about `typical` m, named by unit."""
    raw = largest / scale  # the size in the file's own units
    fits = [(abs(np.log(raw * f / typical)), f, unit) for unit, f in UNITS.items()
            if 1 / SIZE_FACTOR <= raw * f / typical <= SIZE_FACTOR]
    if fits:
        _, factor, unit = min(fits)
        return f"--scale {factor:g} (a model in {unit})"
    return f"--scale {float(f'{typical / raw:.2g}'):g}"


def check_mass(mass: float | None) -> None:
    """Refuse a mass that is not a finite number above zero (NaN would freeze the object in PyBullet)."""
    if mass is not None and not (isinstance(mass, (int, float)) and np.isfinite(mass) and mass > 0):
        raise AssetError(f"--mass must be a finite number of kilograms above 0, not {mass}")


def check_size(path: Path, object_type: str, largest: float, scale: float, any_size: bool) -> None:
    """Refuse a mesh whose size is implausible for its type, suggesting the --scale that fixes it."""
    if largest > 10.0 or largest < 0.005:
        raise AssetError(f"{path}: after scaling the object is {largest:.3g} m across; pass --scale "
                         "(e.g. 0.01 for a model in centimetres)")
    typical = typical_size(object_type)
    if any_size or typical is None or 1 / SIZE_FACTOR <= largest / typical <= SIZE_FACTOR:
        return
    raise AssetError(
        f"{path}: a {object_type} {largest:.3g} m across is implausible (the library's are about {typical:.2g} m); "
        f"pass {suggested_scale(largest, scale, typical)}, or --any-size to keep this size")


def import_mesh(
    path: Path, object_type: str, scale: float = 1.0, up: str = "y", mass: float | None = None,
    root: Path | None = None, any_size: bool = False,
) -> ImportResult:
    """Normalise, decompose, write a URDF and add the asset to the user catalog (atomically).

    Raises:
        AssetError: An unreadable mesh, a scale or mass that is not a finite positive number, or (unless
            `any_size`) a size more than SIZE_FACTOR off the library's typical size for the type.
    """
    check_type(object_type, where="--type")
    if not isinstance(scale, (int, float)) or not np.isfinite(scale) or scale <= 0:
        raise AssetError(f"--scale must be a positive number, not {scale}")
    check_mass(mass)
    mesh = normalise(load_user_mesh(path), scale, up)
    dims = mesh.extents
    check_size(Path(path), object_type, float(dims.max()), float(scale), any_size)
    if not mesh.is_watertight:
        trimesh.repair.fill_holes(mesh)
    if abilities(object_type).movable_receptacle and not mesh.is_watertight:
        raise AssetError(f"{path}: a {object_type} holds things, so its mesh must be watertight (closed); "
                         "this one has holes that could not be filled")
    volume = abs(mesh.volume) if mesh.is_watertight else mesh.convex_hull.volume
    kg = float(mass) if mass is not None else max(0.05, DENSITY * volume)
    out = Path(root or user_asset_root())
    ab = abilities(object_type)
    category = "small" if ab.pickupable else "furniture"
    regions = []
    if ab.receptacle:
        regions.append(Region("top", "surface", (0.0, 0.0, float(dims[2])), (float(dims[0] * 0.7),
                                                                             float(dims[1] * 0.7), 0.4)))
    out.mkdir(parents=True, exist_ok=True)
    with open(out / ".catalog.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        catalog_path = out / CATALOG_NAME
        doc = json.loads(catalog_path.read_text()) if catalog_path.exists() else {"version": 1, "assets": []}
        taken = {e["variant"] for e in doc["assets"] if e["type"] == object_type}
        variant = next(v for v in range(USER_VARIANT_BASE, USER_VARIANT_BASE + 10_000) if v not in taken)
        spec = AssetSpec(object_type, variant, category, [Link("base", [Part(mesh, "imported")], kg)],
                         regions=regions, description=f"imported from {Path(path).name}")
        entry = write_asset(spec, out, coacd_cache_dir(out))
        entry["source"] = str(Path(path).resolve())
        doc["assets"] = sorted(doc["assets"] + [entry], key=lambda e: e["id"])
        write_atomic(catalog_path, json.dumps(doc, indent=1, sort_keys=True) + "\n")
    return ImportResult(spec.asset_id, entry, catalog_path)
