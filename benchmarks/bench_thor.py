"""ALFRED's own evaluation loop on `luminous_sim.thor`: trials judged successful / built per task type, and
steps per second of that loop against our own World on the same trials.

    python benchmarks/bench_thor.py                      # builds S+ episodes 0..13 (no frames), then runs
    python benchmarks/bench_thor.py --count 28 --out out/bench_thor
    python benchmarks/bench_thor.py --data DIR           # a folder `luminous dataset build` wrote (S+, U+,
                                                         # or --from-alfred)
    python benchmarks/bench_thor.py --data DIR --modes eval,api --workers 2 --out OUT    # a whole split,
                                                         # resumable: rows already in OUT are kept

Needs ALFRED's code in ../shared/alfred/code (as `tests/thor` does; it says so and stops where it is absent).
For each built trial it runs, in one process under `python -m luminous_sim.thor`:

- `eval`: ALFRED's unmodified `models/eval/eval_task.py` `EvalTask.evaluate` (ThorEnv, `va_interact` with
  each interaction's recorded mask as the prediction, the dense reward, the goal checks of `env/tasks.py`),
  with the replaying stand-in model and feature extractor of `tests/thor/alfred_driver.py`; a trial counts
  as judged successful when ALFRED's code says its goal is satisfied, no action failed, and ALFRED's
  goal-condition counts equal our judge's. Its steps/s is the trial's low actions over the whole
  `evaluate` call (set-up included, as ALFRED's evaluation pays it per episode).
- `api` (with `--modes ...,api`): the replay ALFRED's data tools do: ALFRED's `restore_scene`, then each
  recorded `api_action` through `ThorEnv.step`; a trial passes when every action succeeds, the goal is
  satisfied and the goal-condition counts equal our judge's. `va`: the same with `va_interact` and the
  decompressed masks outside `EvalTask` (what `eval` does inside it).

and then, in this process, on the same trials:

- `controller`: the recorded `api_action`s through `luminous_sim.thor.Controller.step` (ai2thor's API on
  our World: metadata, segmentation colours, masks, the Event), after the same set-up as ALFRED's
  `restore_scene`; the set-up is not timed;
- `world`: the same actions through our `World.step`, each followed by the frame our Gymnasium env
  returns as its observation (`World.frame()`): the engine under our own env, without the ai2thor layer.

Prints the CPU model, core count and load average at the start and the end: figures from a loaded machine
are indications only.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from benchmarks.machine import machine  # noqa: E402  (after the path)
from tests.thor import alfred_code  # noqa: E402  (ALFRED's code folder, laid out as it runs)

DRIVER = ROOT / "tests" / "thor" / "alfred_driver.py"






def build_split(out: Path, split: str, count: int, start: int) -> Path:
    from luminous_sim.data import BuildOptions, build, split_jobs

    report = build(out, split_jobs(split, count, start), options=BuildOptions(frames=False, video=False),
                   progress=True)
    print(report.summary())
    return out


def _read_rows(out: Path) -> list[dict[str, Any]]:
    rows = []
    for path in sorted(out.glob("rows*.jsonl")):
        for line in path.read_text().splitlines():
            try:
                rows.append(json.loads(line))
            except json.JSONDecodeError:  # a line cut by an interrupted run: that trial runs again
                continue
    return rows


def alfred_rows(data: Path, mirror: Path, out: Path, trials: list[Path], modes: list[str],
                workers: int = 1) -> list[dict[str, Any]]:
    """ALFRED's code on every trial in every mode, in `workers` driver processes; rows already in `out`'s
    `rows*.jsonl` are kept (a resumed sweep runs only the rest)."""
    done = {(r["mode"], r["trial"]) for r in _read_rows(out)}
    for mode in modes:
        todo = [str(t) for t in trials if (mode, str(t)) not in done]
        chunks = [todo[k::workers] for k in range(workers) if todo[k::workers]]
        procs = [subprocess.Popen([sys.executable, "-m", "luminous_sim.thor", "--data", str(data), str(DRIVER),
                                   "--alfred", str(mirror), "--out", str(out / f"rows-{k}.jsonl"), "--mode", mode,
                                   "--trials", *chunk],
                                  cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)}, stderr=subprocess.PIPE,
                                  text=True) for k, chunk in enumerate(chunks)]
        for proc in procs:
            _, err = proc.communicate()
            if proc.returncode != 0:
                raise SystemExit(f"ALFRED's loop did not run: {err[-2000:]}")
    wanted = {str(t) for t in trials}
    latest = {(r["mode"], r["trial"]): r for r in _read_rows(out) if r["trial"] in wanted and r["mode"] in modes}
    return list(latest.values())


def _in_order(data: Path) -> list[Path]:
    """The build's trials in its manifest's episode order (path order where it has none)."""
    found = sorted(p.parent for p in data.glob("*/*/*/traj_data.json"))
    manifest = data / "manifest.jsonl"
    if not manifest.exists():
        return found
    order: dict[str, int] = {}
    for line in manifest.read_text().splitlines():
        record = json.loads(line)
        path = record.get("trial") or record.get("path")
        if isinstance(path, str):
            order.setdefault(Path(path).name, len(order))
    return sorted(found, key=lambda t: (order.get(t.name, len(order)), str(t)))


def _passed(r: dict[str, Any]) -> bool:
    return bool(r.get("satisfied") and not r.get("failures") and r.get("alfred_gc") == r.get("our_gc"))


def _set_up(c: Any, traj: dict[str, Any]) -> None:
    """ALFRED's `restore_scene` and `init_action`, through the controller."""
    scene = traj["scene"]
    c.reset(f"FloorPlan{scene['scene_num']}")
    c.step(dict(action="Initialize", gridSize=0.25, cameraY=0.75, visibility_distance=1.5, renderImage=True))
    if scene["object_toggles"]:
        c.step(dict(action="SetObjectToggles", objectToggles=scene["object_toggles"]))
    if scene["dirty_and_empty"]:
        c.step(dict(action="SetStateOfAllObjects", StateChange="CanBeDirty", forceAction=True))
        c.step(dict(action="SetStateOfAllObjects", StateChange="CanBeFilled", forceAction=False))
    c.step(dict(action="SetObjectPoses", objectPoses=scene["object_poses"]))
    c.step(dict(scene["init_action"]))


def ours(data: Path, trials: list[Path]) -> dict[str, tuple[int, float, int]]:
    """Per engine (`controller`, `world`): (actions, seconds, failed actions) over every trial."""
    from luminous_sim.thor import Controller

    totals = {"controller": [0, 0.0, 0], "world": [0, 0.0, 0]}
    c = Controller(data=data)
    c.start(player_screen_width=300, player_screen_height=300)
    for trial in trials:
        traj = json.loads((trial / "traj_data.json").read_text())
        actions = [dict(a["api_action"]) for a in traj["plan"]["low_actions"]]
        _set_up(c, traj)
        t0 = time.perf_counter()
        failed = sum(not c.step(a).metadata["lastActionSuccess"] for a in actions)
        row = totals["controller"]
        row[0], row[1], row[2] = row[0] + len(actions), row[1] + time.perf_counter() - t0, row[2] + failed
        _set_up(c, traj)
        world = c.world
        t0 = time.perf_counter()
        failed = 0
        for a in actions:
            failed += not world.step(a).success
            world.frame()
        row = totals["world"]
        row[0], row[1], row[2] = row[0] + len(actions), row[1] + time.perf_counter() - t0, row[2] + failed
    c.stop()
    return {k: (int(v[0]), float(v[1]), int(v[2])) for k, v in totals.items()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", type=Path, help="a built dataset folder (default: build S+ into --out)")
    parser.add_argument("--split", default="S+")
    parser.add_argument("--count", type=int, default=14, help="episodes to build (default 14: two per type)")
    parser.add_argument("--start", type=int, default=0)
    parser.add_argument("--out", type=Path, default=Path("out/bench_thor"))
    parser.add_argument("--modes", default="eval", help="driver modes, comma-separated: eval, va, api (default eval)")
    parser.add_argument("--workers", type=int, default=1, help="driver processes (trials split between them)")
    parser.add_argument("--no-ours", action="store_true", help="skip the controller/World steps/s comparison")
    parser.add_argument("--every", type=int, default=1,
                        help="every K-th trial of the build in episode order (a sample across types; default 1)")
    args = parser.parse_args()
    modes = [m for m in args.modes.split(",") if m]
    if not modes or set(modes) - {"eval", "va", "api"} or args.workers < 1 or args.every < 1:
        parser.error("--modes: some of eval, va, api; --workers, --every: positive numbers")
    why = alfred_code.missing()
    if why:
        print(f"not run: {why}")
        return 1
    print(f"start: {machine()}")
    args.out.mkdir(parents=True, exist_ok=True)
    data = args.data or build_split(args.out / "data", args.split, args.count, args.start)
    mirror = args.out / "alfred"
    if not mirror.exists():
        alfred_code.mirror(mirror)
    trials = _in_order(data)[::args.every]
    built = Counter(t.parent.name.split("-")[0] for t in trials)
    t0 = time.perf_counter()
    rows = alfred_rows(data, mirror, args.out, trials, modes, args.workers)
    print(f"ALFRED's code ran in {time.perf_counter() - t0:.0f} s (this call; rows kept from earlier calls are "
          "not timed)")
    for mode in modes:
        mine_rows = [r for r in rows if r["mode"] == mode]
        judged = Counter(r["task_type"] for r in mine_rows if _passed(r))
        print(f"\nmode {mode}: {'task type':28s} judged successful by ALFRED's code / built")
        for t in sorted(built):
            print(f"{'':10s}{t:34s} {judged[t]:4d} / {built[t]:4d}")
        print(f"{'':10s}{'all':34s} {sum(judged.values()):4d} / {len(trials):4d} "
              f"({sum(judged.values()) / max(len(trials), 1):.3f}; rows {len(mine_rows)})")
        for r in mine_rows:
            if not _passed(r):
                print("  not judged successful:", Path(r["trial"]).parent.name, Path(r["trial"]).name,
                      r.get("crash") or {k: r.get(k) for k in ("satisfied", "alfred_gc", "our_gc", "failures")})
    timed = [r for r in rows if r["mode"] == "eval" and "crash" not in r]
    steps = sum(r.get("steps", 0) for r in timed)
    seconds = sum(r.get("seconds", 0.0) for r in timed)
    if args.no_ours or not timed:
        print(f"\nend: {machine()}")
        return 0
    mine = ours(data, trials)
    print(f"\n{'engine':52s} actions  seconds  steps/s  failed")
    print(f"{'ALFRED EvalTask.evaluate on luminous_sim.thor':52s} {steps:7d} {seconds:8.1f} {steps / seconds:8.1f}"
          f"       -")
    for name, label in (("controller", "luminous_sim.thor Controller.step (api_action)"),
                        ("world", "our World.step + frame (what our env does)")):
        n, s, f = mine[name]
        print(f"{label:52s} {n:7d} {s:8.1f} {n / s:8.1f} {f:7d}")
    print(f"\nend: {machine()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
