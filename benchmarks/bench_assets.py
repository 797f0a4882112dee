"""Asset library figures: full build time (cold: no decomposition cache; cached), asset count by kind,
mean PyBullet load time per asset, and size on disk.

    python benchmarks/bench_assets.py            # cached build + counts + load time + size
    python benchmarks/bench_assets.py --cold     # also a cold build (runs coacd on every part; minutes)
"""

from __future__ import annotations

import argparse
import collections
import shutil
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.assets.build import build_library
from luminous_sim.assets.catalog import Catalog
from luminous_sim.assets.paths import asset_root


def _dir_size(root: Path) -> int:
    return sum(p.stat().st_size for p in root.rglob("*") if p.is_file())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cold", action="store_true", help="also time a build with an empty coacd cache")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    root = asset_root()
    with tempfile.TemporaryDirectory() as tmp:
        cached_dir = Path(tmp) / "cached"
        shutil.copytree(root / "_cache", cached_dir / "_cache")
        report = build_library(out_dir=cached_dir, jobs=args.jobs, progress=False)
        print(f"build (cached decompositions): {report.seconds:.1f} s for {report.assets} assets, "
              f"{report.decompositions_computed} decompositions computed")
        if args.cold:
            cold = build_library(out_dir=Path(tmp) / "cold", jobs=args.jobs, progress=True)
            print(f"build (cold, empty cache):     {cold.seconds:.1f} s for {cold.assets} assets, "
                  f"{cold.decompositions_computed} decompositions computed")
    catalog = Catalog.load(root, include_user=False)
    by_kind = collections.Counter(e.category for e in catalog)
    print(f"assets: {len(catalog)} in {len(catalog.types())} types; by kind: "
          + ", ".join(f"{k} {n}" for k, n in sorted(by_kind.items())))
    print(f"articulated: {sum(1 for e in catalog if e.joints)}, with regions: {sum(1 for e in catalog if e.regions)}, "
          f"mean collision hulls: {sum(e.collision_hulls for e in catalog) / len(catalog):.1f}, "
          f"mean visual vertices: {sum(e.visual_vertices for e in catalog) / len(catalog):.0f}")

    from luminous_sim.world.asset_loader import load_asset
    from luminous_sim.world.client import new_client

    client = new_client()
    entries = list(catalog)
    for e in entries:  # warm the file cache so the figure is PyBullet's parsing, not the disk
        load_asset(client, e)
    client.resetSimulation()
    start = time.perf_counter()
    for e in entries:
        load_asset(client, e)
    per = (time.perf_counter() - start) / len(entries)
    client.disconnect()
    print(f"mean load time per asset (PyBullet DIRECT, loadURDF): {per * 1000:.2f} ms")
    print(f"size on disk: {_dir_size(root) / 1e6:.1f} MB total, decomposition cache "
          f"{_dir_size(root / '_cache') / 1e6:.1f} MB")


if __name__ == "__main__":
    main()
