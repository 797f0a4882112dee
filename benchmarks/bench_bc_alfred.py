"""Random and a behaviour-cloned agent per ALFRED task type on S+ and U+, in the layout of the paper's Table 4
(issue 26's "random and BC agents per type").

    python benchmarks/bench_bc_alfred.py                       # 350 demos, 10 entries a type a split
    python benchmarks/bench_bc_alfred.py --demos 35 --per-type 2   # the quick look

1. Oracle demonstrations of the `alfred` family (`luminous_sim.bc.FAMILIES`: the frozen split's own episodes,
   ALFRED's seven task types, 64 px, object-slot targets) on S+ entries that are not evaluated, in index order
   from --train-start (every type in the split's interleaved order, so about the split's own mix of types).
2. A `BCPolicy` trained on them (`--seed`), the same model and training as the pickup family's.
3. Random and the clone on the first --per-type entries of each type of S+ (held out: no demonstration of them)
   and of U+, each played live by `luminous_sim.eval.evaluate` in the evaluation env with ALFRED's limits (1000
   steps, 10 failed actions) at the clone's image size: SR, GC, PLW-SR, PLW-GC per type, as in Table 4.

Everything is kept under --out (default out/bench_bc_alfred): demonstrations, the checkpoint and one file per
played episode, so a second run reprints the figures without redoing the work (`--fresh` starts over). It
writes table.md and results.json there.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import time
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from machine import machine

from luminous_sim.bc import ALFRED_ENV, CHECKPOINT_VAR, collect_demos, train_bc
from luminous_sim.benchmark import benchmark_entries
from luminous_sim.eval import EvalReport, evaluate, map_local, markdown_table
from luminous_sim.fileio import write_atomic
from luminous_sim.vocab import ALFRED_TASK_TYPES

SPLITS = ("S+", "U+")
CLONE = "luminous_sim.bc:bc_agent"


def evaluated(split: str, per_type: int) -> list[int]:
    """The first `per_type` entries of each task type of `split`, in index order."""
    taken = {t: 0 for t in ALFRED_TASK_TYPES}
    out = []
    for entry in benchmark_entries(split):
        if taken[entry.task_type] < per_type:
            taken[entry.task_type] += 1
            out.append(entry.index)
    return out


def training(count: int, start: int, held_out: list[int]) -> list[int]:
    """`count` S+ entries from `start` on, none of them evaluated."""
    skip = set(held_out)
    out = []
    for entry in benchmark_entries("S+", start=start):
        if entry.index not in skip:
            out.append(entry.index)
        if len(out) == count:
            break
    return out


def _collect(job: tuple[str, list[int]]) -> dict[str, Any]:
    folder, indices = job
    return collect_demos(Path(folder), "S+", indices, family="alfred")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--demos", type=int, default=350, help="training demonstrations (default 350)")
    parser.add_argument("--train-start", type=int, default=140, help="first S+ entry demonstrated (default 140)")
    parser.add_argument("--per-type", type=int, default=10, help="evaluated entries per type and split (default 10)")
    parser.add_argument("--epochs", type=int, default=20)
    parser.add_argument("--seed", type=int, default=0, help="training seed (default 0)")
    parser.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    parser.add_argument("--out", type=Path, default=Path("out/bench_bc_alfred"))
    parser.add_argument("--fresh", action="store_true", help="discard everything kept and start over")
    args = parser.parse_args()
    if args.fresh and args.out.exists():
        shutil.rmtree(args.out)
    print(f"machine: {machine()}")
    held = {split: evaluated(split, args.per_type) for split in SPLITS}
    train = training(args.demos, args.train_start, held["S+"])
    demos = args.out / "demos"
    start = time.perf_counter()
    chunks = [(str(demos), train[k::args.workers]) for k in range(args.workers)]
    summaries = list(map_local(_collect, chunks, args.workers))
    recorded = sum(s["recorded"] for s in summaries)
    unavailable = {k: v for s in summaries for k, v in s["unavailable"].items()}
    steps = sum(s["steps"] for s in summaries)
    print(f"demonstrations: {recorded}/{len(train)} S+ entries {train[0]}..{train[-1]} ({steps} steps, "
          f"unavailable {unavailable or 'none'}) in {time.perf_counter() - start:.0f} s (kept ones are not timed)")
    checkpoint = args.out / f"bc-seed{args.seed}.pt"
    if not checkpoint.is_file():
        start = time.perf_counter()
        result = train_bc(demos, checkpoint, epochs=args.epochs, seed=args.seed, threads=args.workers)
        print(f"trained on {result.samples} steps: final loss {result.losses[-1]:.3f}, training accuracy "
              f"{result.accuracy:.3f}, {time.perf_counter() - start:.0f} s")
    os.environ[CHECKPOINT_VAR] = str(checkpoint.resolve())
    reports: list[EvalReport] = []
    for policy, label in (("random", "random"), (CLONE, "bc")):
        for split in SPLITS:
            start = time.perf_counter()
            report = evaluate(policy, split, held[split], workers=args.workers, env_kwargs=ALFRED_ENV,
                              track="privileged", out_dir=args.out / f"eval-{label}-{split.replace('+', 'plus')}")
            report = replace(report, policy=label)
            steps = sum(o.steps for o in report.outcomes)
            ends = dict(Counter(o.end for o in report.outcomes).most_common())
            print(f"{label} on {split}: {len(report.outcomes)} entries, {steps} steps, ends {ends}, "
                  f"{time.perf_counter() - start:.0f} s (kept ones are not timed)")
            reports.append(report)
    table = markdown_table(reports)
    print(table)
    write_atomic(args.out / "table.md", table + "\n")
    write_atomic(args.out / "results.json", json.dumps({
        "demos": {"entries": train, "recorded": recorded, "unavailable": unavailable},
        "evaluated": held, "reports": [r.to_dict() for r in reports]}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
