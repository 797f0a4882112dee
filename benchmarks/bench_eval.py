"""Oracle and random SR/GC/PLW per task type on S+ and U+ (the issue's figure), with ALFRED's limits.

    python benchmarks/bench_eval.py                          # 28 episodes a split (4 per type), 2 workers
    python benchmarks/bench_eval.py --episodes 70 --workers 4

For each split (S+, U+) and policy (oracle, random) it evaluates the split's episodes 0 .. N-1
(`luminous_sim.eval.evaluate`, the same as `luminous eval`), then prints a Table 4-style table per policy
(columns S+ and U+), the entries whose episode could not be drawn (with their causes: they are failures of
the population, in the "SR all" column), and the wall time per episode (median and range, as the
workers saw it, so an indication only). Outcomes are kept under --out (default out/bench_eval), so a
second run reprints the figures without replaying; `--fresh` starts over. It also writes `metrics.png`,
the four evaluations' SR and GC per task type.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.eval import EvalReport, evaluate, markdown_table, plot

SPLITS = ("S+", "U+")
POLICIES = ("oracle", "random")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--episodes", type=int, default=28, help="episodes per split (default 28)")
    parser.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path("out/bench_eval"))
    parser.add_argument("--fresh", action="store_true", help="discard kept outcomes and replay everything")
    args = parser.parse_args()
    if args.fresh and args.out.exists():
        shutil.rmtree(args.out)
    print(f"load average at start: {os.getloadavg()}; {args.episodes} episodes per split, {args.workers} workers")
    reports: dict[tuple[str, str], EvalReport] = {}
    for policy in POLICIES:
        for split in SPLITS:
            times: list[float] = []
            last = [time.perf_counter()]

            def tick(_outcome: object, times: list[float] = times, last: list[float] = last) -> None:
                now = time.perf_counter()
                times.append(now - last[0])
                last[0] = now

            out = args.out / f"{policy}-{split}"
            kept = sum((out / "episodes" / f"{split}-{i}.json").is_file() for i in range(args.episodes))
            start = time.perf_counter()
            report = evaluate(policy, split, args.episodes, seed=args.seed, workers=args.workers, out_dir=out,
                              progress=tick)
            reports[policy, split] = report
            spread = f"{min(times):.1f}..{max(times):.1f}" if times else "-"
            print(f"{policy:>6} {split:<3} {len(report.outcomes)} episodes ({kept} read back from an earlier run) in "
                  f"{time.perf_counter() - start:.0f} s; s/episode as results arrived: median "
                  f"{statistics.median(times):.1f} (range {spread})")
    for policy in POLICIES:
        print(f"\n### {policy}: N = {args.episodes} episodes per split (entries 0..{args.episodes - 1})\n")
        print(markdown_table([reports[policy, s] for s in SPLITS]))
    for (policy, split), report in reports.items():
        for o in report.outcomes:
            if not o.drawn:
                print(f"{policy} {split} {o.index} {o.task_type} in {o.floor_plan} layout {o.layout}: "
                      f"unavailable ({o.cause}): {o.detail[:200]}")
        ends: dict[str, int] = {}
        for o in report.outcomes:
            ends[o.end] = ends.get(o.end, 0) + 1
        print(f"{policy} {split} ends: {ends}")
    print(f"wrote {plot(list(reports.values()), args.out / 'metrics.png')}")
    print(f"load average at end: {os.getloadavg()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
