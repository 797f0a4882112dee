"""Build the whole asset library (or some types) deterministically into `urdf_assets/`."""

from __future__ import annotations

import fcntl
import json
import shutil
import time
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from tqdm import tqdm

from luminous_sim.assets.paths import asset_root, coacd_cache_dir
from luminous_sim.assets.registry import build_spec, builders
from luminous_sim.assets.urdf_writer import write_asset
from luminous_sim.fileio import write_atomic

CATALOG_NAME = "catalog.json"
CATALOG_VERSION = 1


@dataclass(frozen=True)
class BuildReport:
    """What a build did."""

    assets: int
    seconds: float
    decompositions_computed: int
    decompositions_in_cache: int
    catalog: Path


def _build_one(job: tuple[str, int, str, str]) -> dict[str, Any]:
    type_name, variant, out_dir, cache_dir = job
    return write_asset(build_spec(type_name, variant), Path(out_dir), Path(cache_dir))


def _cache_size(cache: Path) -> int:
    return len(list(cache.glob("*.obj"))) if cache.exists() else 0


def build_library(
    out_dir: Path | None = None, types: list[str] | None = None, jobs: int = 2, progress: bool = True
) -> BuildReport:
    """Build every registered type (or only `types`) and rewrite the catalog.

    Entries of types not rebuilt are kept; files of rebuilt types are replaced. Output is byte-identical
    for the same code whatever `jobs` is.
    """
    out = Path(out_dir or asset_root())
    cache = coacd_cache_dir(out)
    infos = builders()
    chosen = sorted(types) if types else list(infos)
    for t in chosen:
        if t not in infos:
            from luminous_sim.errors import AssetError

            raise AssetError(f"no builder for object type {t!r}")
    work = [(t, v, str(out), str(cache)) for t in chosen for v in range(infos[t].variants)]
    before = _cache_size(cache)
    start = time.perf_counter()
    for t in chosen:
        shutil.rmtree(out / t, ignore_errors=True)
    entries: list[dict[str, Any]] = []
    bar = tqdm(total=len(work), desc="assets", disable=not progress, unit="asset")
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            for entry in pool.map(_build_one, work, chunksize=1):
                entries.append(entry)
                bar.update()
    else:
        for job in work:
            entries.append(_build_one(job))
            bar.update()
    bar.close()
    catalog_path = out / CATALOG_NAME
    out.mkdir(parents=True, exist_ok=True)
    with open(out / ".catalog.lock", "w") as lock:  # partial builds in parallel merge, never clobber
        fcntl.flock(lock, fcntl.LOCK_EX)
        kept = []
        if catalog_path.exists() and types:
            kept = [e for e in json.loads(catalog_path.read_text())["assets"] if e["type"] not in set(chosen)]
        all_entries = sorted(kept + entries, key=lambda e: e["id"])
        doc = {"version": CATALOG_VERSION, "assets": all_entries}
        write_atomic(catalog_path, json.dumps(doc, indent=1, sort_keys=True) + "\n")
    computed = _cache_size(cache) - before
    return BuildReport(
        assets=len(entries),
        seconds=time.perf_counter() - start,
        decompositions_computed=computed,
        decompositions_in_cache=_cache_size(cache),
        catalog=catalog_path,
    )
