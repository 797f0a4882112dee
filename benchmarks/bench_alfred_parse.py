"""ALFRED task parser coverage: parsed, realised (CSSG in each trajectory's own floor plan's shell) and, with
--solve, solved (the parsed CDF's own task run by the oracle in the realised scene, as `luminous run --cdf`
does, no frames) per task type; the first causes of the scenes not realised and of the tasks not solved by
frequency, the same for the per-floor-plan merge, and timings.

    python benchmarks/bench_alfred_parse.py                     # ../shared/alfred/valid_seen, seed 0
    python benchmarks/bench_alfred_parse.py --alfred DIR --seeds 0 1 2
    python benchmarks/bench_alfred_parse.py --seeds 0 --solve --workers 2
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.data import CoverageReport, make_backend, map_jobs, parse_directory

DEFAULT = Path(__file__).resolve().parents[2] / "shared" / "alfred" / "valid_seen"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--alfred", type=Path, default=DEFAULT, help="folder of traj_data.json files (an ALFRED split)")
    ap.add_argument("--seeds", type=int, nargs="+", default=[0], help="CSSG seeds (one realisation run each)")
    ap.add_argument("--solve", action="store_true",
                    help="also run each realised CDF's own task with the oracle and count the solved")
    ap.add_argument("--workers", type=int, default=1, help="processes for --solve (default 1)")
    args = ap.parse_args()
    if args.workers < 1:
        sys.exit(f"--workers {args.workers}: expected a whole number >= 1")
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
        if args.solve:
            t0 = time.process_time()
            w0 = time.perf_counter()
            solved = solve_all(report, seed, args.workers)
            cpu = time.process_time() - t0 + _children_cpu()
            print(f"\nseed {seed}: solved {len(solved)} realised CDFs' own tasks in {time.perf_counter() - w0:.1f} s "
                  f"wall, {cpu:.1f} CPU s ({cpu / max(1, len(solved)):.2f} CPU s each) on {args.workers} workers; "
                  f"load average {os.getloadavg()[0]:.1f}")
            solved_table(report, solved)
    if len(rates) > 1:
        print(f"\nrealised over seeds: median {100 * statistics.median(rates):.1f}% "
              f"({100 * min(rates):.1f}..{100 * max(rates):.1f})")


SolveJob = tuple[str, Any, str, int]
"""(trajectory file, its parsed CDF, its floor plan, the seed)."""


def solve_one(job: SolveJob) -> tuple[bool, str]:
    """Run a parsed CDF's own task in its floor plan's shell, as `luminous run --cdf --room PLAN` does (no
    frames, no files): (solved, the first cause when not; "" when solved)."""
    from luminous_sim.cdf_episode import run_document
    from luminous_sim.errors import LuminousError
    from luminous_sim.rooms import load_room

    rel, cdf, floor_plan, seed = job
    try:
        ran = run_document(cdf, rel, seed, room=load_room(floor_plan), record_frames=False, follow_script=False)
    except LuminousError as exc:  # bad task, start, initial state, or no layout: the first line, file named
        return False, f"{type(exc).__name__}: {str(exc).removeprefix(rel + ': ').splitlines()[0]}"
    r = ran.result
    if r.success:
        return True, ""
    code = f"[{r.failure_code}] " if r.failure_code else ""
    return False, code + (r.failure or f"goal unmet ({r.goal_conditions[0]}/{r.goal_conditions[1]} conditions)")


def solve_all(report: CoverageReport, seed: int, workers: int) -> dict[str, tuple[bool, str]]:
    """`solve_one` for every realised file of `report`, on `workers` processes: file -> (solved, cause)."""
    jobs: list[SolveJob] = [(f.path, f.parse.cdf, f.parse.floor_plan, seed) for f in report.files
                            if f.parse is not None and f.realised is not None and f.realised.ok]
    backend = make_backend("local", workers)
    try:
        return {job[0]: out for job, out in map_jobs(solve_one, jobs, backend)}
    finally:
        backend.close()


def _children_cpu() -> float:
    import resource

    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def cause_kind(cause: str) -> str:
    """A cause without object names and numbers, so that causes add up across trajectories."""
    kind = re.sub(r"\b[a-z][a-z0-9]*(_[a-z0-9]+)*_\d+\b", "OBJ", cause)
    kind = re.sub(r"[-+]?\d+(\.\d+)?", "N", kind)
    return kind[:140]


def solved_table(report: CoverageReport, solved: dict[str, tuple[bool, str]]) -> None:
    """Print total, parsed, realised and solved per task type (every file counts; a file not parsed or not
    realised is not solved), then the first causes of the realised but unsolved by frequency."""
    rows = report.by_task_type()
    for row in rows.values():
        row["solved"] = 0
    for f in report.files:
        rows[f.task_type]["solved"] += bool(solved.get(f.path, (False, ""))[0])
    n = len(report.files)
    print(f"{'task type':36s} {'total':>5s} {'parsed':>6s} {'realised':>8s} {'solved':>6s}")
    for t, row in rows.items():
        print(f"{t:36s} {row['total']:5d} {row['parsed']:6d} {row['realised']:8d} {row['solved']:6d}")
    total_solved = sum(row["solved"] for row in rows.values())
    print(f"{'all':36s} {n:5d} {report.parsed:6d} {report.realised:8d} {total_solved:6d} "
          f"({100 * total_solved / max(1, n):.1f}% of all files; {total_solved}/{len(solved)} of the realised)")
    unsolved = Counter(cause_kind(cause) for ok, cause in solved.values() if not ok)
    print(f"not solved: {n - total_solved} ({n - report.parsed} not parsed, {report.parsed - report.realised} "
          f"not realised, {len(solved) - total_solved} realised but unsolved); first causes of the unsolved:")
    for cause, k in unsolved.most_common():
        print(f"  {k:3d}  {cause}")
    for path, (ok, cause) in sorted(solved.items()):
        if not ok:
            print(f"    {path}: {cause}")


if __name__ == "__main__":
    main()
