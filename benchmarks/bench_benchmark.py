"""The frozen S+/U+ benchmark's figures (issue 26): build time and size of the canonical build, the oracle's
replay success per task type over every built trial, a random agent per type, and the agreement of the
episode keys of `dataset build`, `eval --data` and `env.reset`.

    python benchmarks/bench_benchmark.py --split U+ --workers 2                # the whole of U+
    python benchmarks/bench_benchmark.py --split S+ --count 140 --workers 2    # S+'s first 140 entries

For the split's first COUNT entries (default all) it builds the canonical split without frames under
--out (resumable: a second run reuses it and reprints the figures), timing the build and measuring its size
on disk; then times a build of the first --frames-sample entries with frames and video (what a dataset user
downloads), to give the size and time per trajectory with frames; evaluates the oracle (replaying each
trial's recorded actions through the agent interface) and a random agent over every built trial
(`evaluate_data`); and checks that the manifest's, the evaluation's and a fresh env's `episode_key` agree for
the first --agree entries (70 by default). Prints the CPU model and load.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from machine import machine

from luminous_sim.benchmark import benchmark_entry, benchmark_size, frozen_header
from luminous_sim.data import BuildOptions, Manifest, build_split, make_backend
from luminous_sim.env import LuminousEnv
from luminous_sim.eval import EVAL_ENV, evaluate_data, markdown_table


def size_mb(root: Path) -> float:
    return sum(p.stat().st_size for p in root.rglob("*") if p.is_file()) / 1e6


def timed_build(out: Path, split: str, count: int, workers: int, frames: bool) -> tuple[float, int]:
    """Seconds for the part of the build this run did, and how many trials it built now."""
    with make_backend("local", workers, None) as backend:
        start = time.perf_counter()
        report = build_split(out, split, count, backend, BuildOptions(frames=frames, video=frames), progress=True)
        seconds = time.perf_counter() - start
    print(report.summary())
    return seconds, report.ran


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--split", default="U+", choices=["S+", "U+", "U+test"])
    parser.add_argument("--count", type=int, default=None, help="the split's first COUNT entries (default all)")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--frames-sample", type=int, default=14, help="entries built with frames too (default 14)")
    parser.add_argument("--agree", type=int, default=70, help="entries whose keys are compared (default 70)")
    parser.add_argument("--out", type=Path, default=Path("out/bench_benchmark"))
    parser.add_argument("--fresh", action="store_true", help="start over")
    args = parser.parse_args()
    split = args.split
    count = args.count or benchmark_size(split)
    tag = split.replace("+", "plus")
    if args.fresh and args.out.exists():
        shutil.rmtree(args.out)
    print(f"machine: {machine()}")
    header = frozen_header(split)
    print(f"frozen {split} v{header['version']}: {header['entries']} entries; per type: "
          + ", ".join(f"{t} {s['built']} (distinct tasks {s['distinct_tasks']}, draws {s['draws']}, rejected "
                      f"{s['rejected']}, repeats {s['repeats']})" for t, s in header["stats"].items()))

    build = args.out / f"{tag}-build"
    seconds, ran = timed_build(build, split, count, args.workers, frames=False)
    trials = sum(1 for _ in (build / split).rglob("traj_data.json"))
    timing = (f"this run built {ran} in {seconds:.0f} s ({seconds / ran:.2f} s per trajectory on {args.workers} "
              "workers)") if ran else "all kept from an earlier run"
    print(f"build without frames: {trials}/{count} trials, {size_mb(build):.1f} MB; {timing}")
    if args.frames_sample:
        framed = args.out / f"{tag}-frames-sample"
        seconds, ran = timed_build(framed, split, args.frames_sample, args.workers, frames=True)
        mb = size_mb(framed)
        print(f"build with frames and video, first {args.frames_sample}: {mb:.1f} MB ({mb / args.frames_sample:.2f} "
              f"MB per trajectory); this run built {ran} in {seconds:.0f} s"
              + (f" ({seconds / ran:.1f} s per trajectory)" if ran else ""))

    reports = []
    for policy in ("oracle", "random"):
        start = time.perf_counter()
        report = evaluate_data(policy, build, split=split, episodes=count, workers=args.workers,
                               out_dir=args.out / f"{tag}-eval-{policy}")
        print(f"{policy}: {len(report.outcomes)} episodes in {time.perf_counter() - start:.0f} s "
              f"(kept ones read back); unavailable {report.unavailable()}")
        reports.append(report)
    print(markdown_table(reports), end="")
    failures = [o for o in reports[0].outcomes if o.drawn and not o.success]
    for o in failures[:10]:
        print(f"  oracle replay failed: {o.split} {o.index} {o.task_type} ({o.end}) {o.trial}")

    agree = min(args.agree, count)
    records = {r["order"]: r for r in Manifest(build / "manifest.jsonl") if r["split"] == split}
    evaluated = {o.index: o.episode_key for o in reports[0].outcomes}
    env = LuminousEnv(**{**EVAL_ENV, "verify_expert": False, "high_descs": False})
    same = 0
    times = []
    try:
        for i in range(agree):
            start = time.perf_counter()
            key = env.reset(options={"split": split, "index": i})[1]["episode_key"]
            times.append(time.perf_counter() - start)
            frozen = benchmark_entry(split, i).episode_key
            same += key == frozen == records[i].get("episode_key") == evaluated.get(i)
    finally:
        env.close()
    print(f"agreement: {same}/{agree} of the first {agree} entries have one key in the frozen manifest, the "
          f"build's manifest, the evaluation of the built trials and env.reset (reset median "
          f"{statistics.median(times):.2f} s)")
    print(f"machine at the end: {machine()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
