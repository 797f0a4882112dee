"""Where a dataset build episode's CPU time goes, per stage.

Runs split episodes (S+ 0..6 by default: one per task type) exactly as `data.build` runs them, each in a
fresh temporary folder, with the functions of each stage wrapped by a timer. Time is CPU time
(`time.process_time`), exclusive: a render inside a reach check counts as "render", not as "simulate".
Figures are per episode (the total over the episodes divided by their number), median over repeats.
With `--cprofile FILE` the run is also profiled (cProfile) and the stats are written to FILE.

    python benchmarks/profile_episode.py [--split S+] [--count 7] [--repeats 1] [--cprofile FILE]
"""

from __future__ import annotations

import argparse
import functools
import importlib
import os
import statistics
import sys
import tempfile
import time
from collections import defaultdict
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

STAGES: list[tuple[str, str, str]] = [
    # (stage, module, attribute: "function" or "Class.method")
    ("scene generation (CSSG)", "luminous_sim.cssg", "generate"),
    ("world build + settle", "luminous_sim.world.world", "World.__init__"),
    ("task sampling + feasibility", "luminous_sim.planning.task_fit", "draw_task"),
    ("oracle: symbolic planning", "luminous_sim.planning.symbolic.solver", "solve"),
    ("oracle: interaction poses", "luminous_sim.world.poses", "find_interaction_pose"),
    ("oracle: navigation graph + paths", "luminous_sim.planning.navigation", "NavGraph.__init__"),
    ("oracle: navigation graph + paths", "luminous_sim.planning.navigation", "goto_actions"),
    ("simulate actions (World.step)", "luminous_sim.world.world", "World.step"),
    ("render (TinyRenderer)", "luminous_sim.world.camera", "render"),
    ("visibility, masks from frames", "luminous_sim.world.frame_facts", "FrameFacts.visible"),
    ("visibility, masks from frames", "luminous_sim.world.frame_facts", "FrameFacts.masks"),
    ("instructions", "luminous_sim.language", "Describer.describe"),
    ("export: traj_data, PDDL, sidecar", "luminous_sim.data.alfred_export", "export_alfred"),
    ("export: JPEG encoding", "luminous_sim.data.alfred_export", "_jpeg"),
    ("export: video encoding", "luminous_sim.episode", "write_video"),
    ("build: fsync + move into place", "luminous_sim.data.build", "_fsync_tree"),
]


class StageTimer:
    """Exclusive CPU seconds per stage: time inside a stage's function, minus nested stages' time."""

    def __init__(self) -> None:
        self.seconds: dict[str, float] = defaultdict(float)
        self.calls: dict[str, int] = defaultdict(int)
        self._stack: list[str] = []
        self._since = time.process_time()

    def _switch(self) -> None:
        now = time.process_time()
        self.seconds[self._stack[-1] if self._stack else "other"] += now - self._since
        self._since = now

    def wrap(self, stage: str, fn: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(fn)
        def timed(*args: Any, **kwargs: Any) -> Any:
            self._switch()
            self._stack.append(stage)
            self.calls[stage] += 1
            try:
                return fn(*args, **kwargs)
            finally:
                self._switch()
                self._stack.pop()
        return timed

    def flush(self) -> None:
        self._switch()


@contextmanager
def instrumented(timer: StageTimer) -> Iterator[None]:
    """Wrap every stage's function where it is defined and wherever a module imported it by name."""
    undo: list[tuple[Any, str, Any]] = []
    for stage, module, attr in STAGES:
        mod = importlib.import_module(module)
        if "." in attr:
            cls_name, meth = attr.split(".")
            cls = getattr(mod, cls_name)
            original = cls.__dict__[meth]
            undo.append((cls, meth, original))
            setattr(cls, meth, timer.wrap(stage, original))
            continue
        original = getattr(mod, attr)
        wrapped = timer.wrap(stage, original)
        for other in list(sys.modules.values()):
            if getattr(other, "__name__", "").startswith("luminous_sim") and getattr(other, attr, None) is original:
                undo.append((other, attr, original))
                setattr(other, attr, wrapped)
    try:
        yield
    finally:
        for owner, attr, original in reversed(undo):
            setattr(owner, attr, original)


def _import_all() -> None:
    """Import the modules whose names the stages patch, so that by-name imports see the wrappers."""
    for name in ("luminous_sim.data.build", "luminous_sim.episode", "luminous_sim.planning.oracle",
                 "luminous_sim.planning.task_fit", "luminous_sim.world.view", "luminous_sim.world.poses",
                 "luminous_sim.language", "luminous_sim.data.alfred_export", "luminous_sim.world.world"):
        importlib.import_module(name)


def run_once(split: str, count: int, profile: Any = None) -> tuple[dict[str, float], float, int, dict[str, int]]:
    """(exclusive CPU seconds per stage, total CPU seconds, trials built, calls per stage) of one pass over
    the episodes."""
    from luminous_sim.benchmark import layout_scene
    from luminous_sim.data.build import BuildOptions, _run_job, split_jobs

    _import_all()
    layout_scene.cache_clear()
    timer = StageTimer()
    built = 0
    options = BuildOptions(frames=True, video=True)
    with tempfile.TemporaryDirectory(prefix="profile_episode_") as tmp, instrumented(timer):
        start = time.process_time()
        timer._since = start
        if profile is not None:
            profile.enable()
        for job in split_jobs(split, count):
            record = _run_job(job, Path(tmp), options)
            built += record["status"] == "built"
        if profile is not None:
            profile.disable()
        timer.flush()
        total = time.process_time() - start
    return dict(timer.seconds), total, built, dict(timer.calls)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--split", default="S+")
    parser.add_argument("--count", type=int, default=7)
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--cprofile", type=Path, default=None, help="also write cProfile stats here")
    args = parser.parse_args()
    load = "/".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"{args.split} episodes 0..{args.count - 1}, 300x300 frames + JPEGs + video, {args.repeats} repeat(s); "
          f"CPU time per episode (exclusive per stage); load average at the start {load}")
    runs = []
    for r in range(args.repeats):
        profile = None
        if args.cprofile is not None and r == 0:
            import cProfile

            profile = cProfile.Profile(time.process_time)  # CPU time: other work on the machine does not count
        runs.append(run_once(args.split, args.count, profile))
        if profile is not None:
            profile.dump_stats(str(args.cprofile))
    stages = sorted({s for per, *_ in runs for s in per}, key=lambda s: -statistics.median(
        per.get(s, 0.0) for per, *_ in runs))
    n = args.count
    print(f"{'stage':<36} {'s/episode':>10} {'share':>6} {'calls/episode':>14}")
    totals = [t for _, t, *_ in runs]
    for s in stages:
        v = [per.get(s, 0.0) / n for per, *_ in runs]
        calls = runs[0][3].get(s, 0) / n
        print(f"{s:<36} {statistics.median(v):10.3f} {statistics.median(v) * n / statistics.median(totals):6.1%} "
              f"{calls:14.1f}")
    per_ep = [t / n for t in totals]
    print(f"{'total':<36} {statistics.median(per_ep):10.3f}  (min..max {min(per_ep):.3f}..{max(per_ep):.3f}); "
          f"built {runs[0][2]}/{n}; {60 / statistics.median(per_ep):.1f} episodes per CPU-minute")
    print(f"load average at the end {'/'.join(f'{x:.1f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
