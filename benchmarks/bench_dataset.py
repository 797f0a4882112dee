"""Dataset build throughput: trajectories per minute per core (300x300 frames, JPEGs and video, the
default build) and the speed-up from 1 to 2 workers, local processes and a local Ray cluster.

Each configuration builds episodes 0..COUNT-1 of a split into a fresh folder, REPEATS times; the figures
are the median and min..max over repeats of the whole `build` call (worker start-up included; a local
Ray cluster's own start-up is reported apart). Per core = per worker. The machine's load average before
and after each run is printed, since other work on the machine slows every figure down. For the local
backend the CPU time of the build is printed too (this process's, and its worker processes' once they
have exited), as trajectories per CPU-minute: on a loaded machine that is the figure to compare. The
files of every configuration are compared with the first's (they must be identical).

    python benchmarks/bench_dataset.py [--split S+] [--count 7] [--repeats 3] [--no-ray]
"""

from __future__ import annotations

import argparse
import hashlib
import os
import resource
import shutil
import statistics
import tempfile
import time
from pathlib import Path

from luminous_sim.data import BuildOptions, build_split, make_backend


def _tree(root: Path) -> str:
    h = hashlib.sha256()
    for p in sorted(root.rglob("*")):
        if p.is_file():
            h.update(p.relative_to(root).as_posix().encode() + hashlib.sha256(p.read_bytes()).digest())
    return h.hexdigest()


def _load() -> str:
    return "/".join(f"{x:.1f}" for x in os.getloadavg())


def _cpu() -> float:
    """CPU seconds of this process and of its child processes that have exited."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def _spread(values: list[float]) -> str:
    return f"{statistics.median(values):.2f} ({min(values):.2f}..{max(values):.2f})"


def run(split: str, count: int, repeats: int, ray: bool) -> None:
    options = BuildOptions(frames=True, video=True)
    configs = [("local", 1), ("local", 2)] + ([("ray", 1), ("ray", 2)] if ray else [])
    print(f"{split} episodes 0..{count - 1}, 300x300 frames + video, {repeats} repeats; "
          f"{os.cpu_count()} CPUs; load average (1/5/15 min) at the start {_load()}")
    seconds: dict[tuple[str, int], list[float]] = {}
    cpu: dict[tuple[str, int], tuple[float, int]] = {}
    reference: str | None = None
    with tempfile.TemporaryDirectory(prefix="bench_dataset_") as tmp:
        for name, workers in configs:
            t0 = time.perf_counter()
            cpu0, built_all = _cpu(), 0
            with make_backend(name, workers) as backend:
                started = time.perf_counter() - t0
                for r in range(repeats):
                    out = Path(tmp) / f"{name}{workers}_{r}"
                    before = _load()
                    t = time.perf_counter()
                    report = build_split(out, split, count, backend, options, progress=False)
                    took = time.perf_counter() - t
                    seconds.setdefault((name, workers), []).append(took)
                    built_all += report.built
                    digest = _tree(out)
                    reference = reference or digest
                    per_core = report.built / took * 60 / workers
                    same = "same as the first build" if digest == reference else "DIFFER from the first build"
                    print(f"  {name} x{workers} repeat {r}: {took:6.1f} s, {report.built}/{count} built, "
                          f"{per_core:5.1f} trajectories/min/core; load {before} -> {_load()}; files {same}")
                    shutil.rmtree(out)
            if name == "local":  # worker processes have exited: their CPU time is counted
                cpu[(name, workers)] = (_cpu() - cpu0, built_all)
            if name == "ray":
                print(f"  (local Ray cluster of {workers} CPUs started in {started:.1f} s, not counted above)")
            built = report.built
    print("\nconfiguration   seconds, median (min..max)   trajectories/min/core   episodes/min/core")
    for (name, workers), secs in seconds.items():
        tpm = [built / s * 60 / workers for s in secs]
        epm = [count / s * 60 / workers for s in secs]
        print(f"{name} x{workers:<10} {_spread(secs):<28} {_spread(tpm):<23} {_spread(epm)}")
    for (name, workers), (secs, n) in cpu.items():
        if n:
            print(f"{name} x{workers}: {secs:.1f} CPU s for {n} trajectories (worker start-up included): "
                  f"{secs / n:.2f} CPU s per trajectory, {n / secs * 60:.1f} trajectories per CPU-minute")
    for name in ("local", "ray"):
        if (name, 1) in seconds and (name, 2) in seconds:
            one, two = seconds[(name, 1)], seconds[(name, 2)]
            ups = [a / b for a in one for b in two]
            print(f"speed-up 1 -> 2 workers, {name}: {statistics.median(one) / statistics.median(two):.2f}x"
                  f" (ratio of medians; pairwise {min(ups):.2f}..{max(ups):.2f})")
    print(f"load average at the end {_load()}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--split", default="S+")
    parser.add_argument("--count", type=int, default=7, help="episodes per build (default 7: one per task type)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-ray", action="store_true", help="local processes only")
    args = parser.parse_args()
    ray = not args.no_ray
    if ray:
        try:
            import ray as _  # noqa: F401
        except ImportError:
            print("Ray is not installed (pip install 'luminous-sim[cluster]'): local figures only")
            ray = False
    run(args.split, args.count, args.repeats, ray)


if __name__ == "__main__":
    main()
