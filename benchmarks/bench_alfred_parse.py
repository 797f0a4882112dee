"""ALFRED task parser coverage: parsed and realised (CSSG in each trajectory's own floor plan's shell) per task
type, the causes of the scenes not realised by frequency, the same for the per-floor-plan merge, and timings.

    python benchmarks/bench_alfred_parse.py                     # ../shared/alfred/valid_seen, seed 0
    python benchmarks/bench_alfred_parse.py --alfred DIR --seeds 0 1 2
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.data import parse_directory

DEFAULT = Path(__file__).resolve().parents[2] / "shared" / "alfred" / "valid_seen"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--alfred", type=Path, default=DEFAULT, help="folder of traj_data.json files (an ALFRED split)")
    ap.add_argument("--seeds", type=int, nargs="+", default=[0], help="CSSG seeds (one realisation run each)")
    args = ap.parse_args()
    if not args.alfred.is_dir():
        sys.exit(f"{args.alfred}: not found; pass --alfred DIR")
    print(f"{args.alfred}; load average at start {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    t0 = time.perf_counter()
    parse_only = parse_directory(args.alfred, realise_scenes=False)
    parse_s = time.perf_counter() - t0
    print(f"parsed {parse_only.parsed}/{len(parse_only.files)} in {parse_s:.1f} s "
          f"({1000 * parse_s / max(1, len(parse_only.files)):.0f} ms per file)")
    rates = []
    for seed in args.seeds:
        t0 = time.perf_counter()
        report = parse_directory(args.alfred, merge=True, seed=seed)
        seconds = time.perf_counter() - t0
        rates.append(report.realised / len(report.files))
        print(f"\nseed {seed}: parse + realise + merge + realise merged in {seconds:.1f} s")
        print(f"{'task type':36s} {'total':>5s} {'parsed':>6s} {'realised':>8s}")
        for t, row in report.by_task_type().items():
            print(f"{t:36s} {row['total']:5d} {row['parsed']:6d} {row['realised']:8d}")
        print(f"{'all':36s} {len(report.files):5d} {report.parsed:6d} {report.realised:8d} "
              f"({100 * report.realised / len(report.files):.1f}%)")
        print("not realised, first cause (trajectories):")
        for cause, k in report.causes().most_common():
            print(f"  {k:3d}  {cause}")
        grouped: dict[str, int] = {}
        for cause, k in report.causes().items():
            m = re.fullmatch(r"\w+ (on|in) (\w+)", cause)
            key = f"anything {m.group(1)} {m.group(2)}" if m else cause
            grouped[key] = grouped.get(key, 0) + k
        print("  grouped by receptacle: " + "; ".join(f"{c} {k}" for c, k in sorted(grouped.items(),
                                                                                    key=lambda kv: -kv[1])))
        ok = sum(1 for r in report.merged_realised.values() if r.ok)
        conflicts = sum(len(m.conflicts) for m in report.merged.values())
        print(f"merged: {len(report.merged)} floor plans, {conflicts} conflicts resolved, realised {ok}")
        merged_causes: dict[str, int] = {}
        for r in report.merged_realised.values():
            if not r.ok:
                merged_causes[r.cause] = merged_causes.get(r.cause, 0) + 1
        for cause, k in sorted(merged_causes.items(), key=lambda kv: -kv[1]):
            print(f"  {k:3d}  {cause}")
    if len(rates) > 1:
        print(f"\nrealised over seeds: median {100 * statistics.median(rates):.1f}% "
              f"({100 * min(rates):.1f}..{100 * max(rates):.1f})")


if __name__ == "__main__":
    main()
