"""Method (b): ALFRED's own task designs re-solved in generated scenes, each in its own floor plan's room
shell (`data.solve_design`). Prints success per task type over every design (a design with no scene counts
as a failure), overall, and failures grouped by their first cause; writes a JSON of per-design results.

    python benchmarks/bench_alfred_designs.py --workers 2 --out /tmp/designs.json      # all 251 of valid_seen
    python benchmarks/bench_alfred_designs.py --limit 20 --types pick_and_place_simple
    python benchmarks/bench_alfred_designs.py --only-failed /tmp/designs.json           # re-run past failures

Every design is also appended to `<out>.jsonl` as it finishes; a rerun with the same --out skips the designs
already there, so a long run can be stopped and resumed.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections import Counter, defaultdict
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.data.alfred_designs import SCENE_TRIES

DEFAULT_SPLIT = Path(__file__).resolve().parents[1].parent / "shared" / "alfred" / "valid_seen"


def solve_one(path: str, seed: int, tries: int) -> dict:
    from luminous_sim.data import read_design, solve_design

    t0 = time.perf_counter()
    result = solve_design(read_design(path), seed, tries=tries).to_json()
    return {**result, "path": path, "seed": seed, "tries": tries, "seconds": round(time.perf_counter() - t0, 2)}


def report(rows: list[dict]) -> None:
    by_type: dict[str, list[bool]] = defaultdict(list)
    for r in rows:
        by_type[r["task_type"]].append(r["success"])
    print(f"{'task type':36s} {'solved':>7s} {'of':>4s} {'rate':>6s}")
    for t in sorted(by_type):
        ok = by_type[t]
        print(f"{t:36s} {sum(ok):7d} {len(ok):4d} {sum(ok) / len(ok):6.3f}")
    n_ok = sum(r["success"] for r in rows)
    print(f"{'overall':36s} {n_ok:7d} {len(rows):4d} {n_ok / max(len(rows), 1):6.3f}")
    causes = Counter(r["cause"] for r in rows if not r["success"])
    if causes:
        print("\nfailures by first cause:")
        for cause, n in causes.most_common():
            print(f"  {n:4d}  {cause}")
            for r in [r for r in rows if not r["success"] and r["cause"] == cause][:4]:
                print(f"          {r['design']}: {r['message'][:160]}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--split", type=Path, default=DEFAULT_SPLIT, help="an ALFRED split folder (valid_seen)")
    ap.add_argument("--limit", type=int, default=None, help="only the first N designs (after --types)")
    ap.add_argument("--types", nargs="*", default=None, help="only these task types")
    ap.add_argument("--only-failed", type=Path, default=None, help="only the designs that failed in this JSON")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--tries", type=int, default=SCENE_TRIES, help="layouts generated per design")
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--out", type=Path, default=Path("bench_alfred_designs.json"))
    args = ap.parse_args(argv)
    if not args.split.is_dir():
        print(f"no ALFRED split at {args.split} (give --split)", file=sys.stderr)
        return 2
    paths = sorted(str(p) for p in args.split.glob("*/*/traj_data.json"))
    if args.types:
        paths = [p for p in paths if Path(p).parent.parent.name.split("-")[0] in args.types]
    if args.only_failed:
        failed = {r["path"] for r in json.loads(args.only_failed.read_text())["designs"] if not r["success"]}
        paths = [p for p in paths if p in failed]
    paths = paths[: args.limit]
    log = args.out.with_suffix(".jsonl")
    done = {}
    if log.exists():
        for line in log.read_text().splitlines():
            r = json.loads(line)
            if (r["seed"], r.get("tries")) == (args.seed, args.tries):
                done[r["path"]] = r
    todo = [p for p in paths if p not in done]
    print(f"{len(paths)} designs, {len(paths) - len(todo)} already in {log}, {args.workers} worker(s)", flush=True)
    t0 = time.perf_counter()
    with log.open("a") as fh:
        def keep(r: dict) -> None:
            done[r["path"]] = r
            fh.write(json.dumps(r) + "\n")
            fh.flush()
            mark = "ok " if r["success"] else f"FAIL {r['cause']}"
            print(f"[{len(done)}/{len(paths)}] {r['design']}: {mark} ({r['seconds']} s)", flush=True)

        if args.workers > 1:
            with ProcessPoolExecutor(args.workers) as pool:
                futures = [pool.submit(solve_one, p, args.seed, args.tries) for p in todo]
                for f in as_completed(futures):
                    keep(f.result())
        else:
            for p in todo:
                keep(solve_one(p, args.seed, args.tries))
    rows = [done[p] for p in paths]
    print(f"\n{len(todo)} designs solved in {time.perf_counter() - t0:.0f} s\n")
    report(rows)
    from luminous_sim.fileio import write_atomic

    summary = {"split": str(args.split), "seed": args.seed, "tries": args.tries, "designs": rows}
    write_atomic(args.out, json.dumps(summary, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
