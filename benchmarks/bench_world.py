"""Simulator speed and memory, measured so that each figure means what it says.

    python benchmarks/bench_world.py                 # about a minute and a half
    python benchmarks/bench_world.py --repeats 9 --seconds 10 --worlds 8   # longer, tighter figures

Prints the machine load at the start, then each figure as the median over repeats with its spread
(min..max):
- environment vs raw renderer on the SAME views: the World's navigation cycle is run once to record
  the camera pose of every frame it renders; the raw loop renders exactly those views with
  `getCameraImage` (same size, renderer, flags, light), the environment loop replays the cycle with
  `World.step` + `World.frame()` (goal >= 0.9x);
- navigation steps/s with rendering off (goal >= 1,000) and interaction actions/s;
- memory: N Worlds of the same scene built and held at once in a fresh process; RSS per World held
  (goal <= 150 MB per World process);
- two processes vs one, every worker on the same scene, timed from a common start (goal >= 1.9x).
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import os
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.cssg import empty_cdf, generate

NAV = ["MoveAhead", "RotateRight", "MoveAhead", "LookDown", "RotateLeft", "MoveAhead", "LookUp", "RotateLeft"]
LIGHT = [0.4, -0.6, 1.0]  # camera.render's default light direction


def _scene(seed: int):
    return generate(empty_cdf("Kitchen"), seed=seed).scene


def _rss_mb() -> float:
    with open(f"/proc/{os.getpid()}/status") as fh:
        for line in fh:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024
    return float("nan")


def spread(values: list[float], fmt: str = ".1f") -> str:
    """'median (min..max, n=K)' of the repeats."""
    return (f"{statistics.median(values):{fmt}} ({min(values):{fmt}}..{max(values):{fmt}}, "
            f"n={len(values)})")


def _rewind(world, start) -> None:
    world.agent = start
    world.invalidate_frame()


def record_views(world, steps: int) -> tuple[list[tuple[list[float], list[float]]], int]:
    """The (eye, target) of every frame the navigation cycle renders, and how many of its steps failed."""
    start, views, last, failed = world.agent, [], None, 0
    for i in range(steps):
        failed += not world.step(NAV[i % len(NAV)]).success
        frame = world.frame()
        if frame is not last:
            eye = np.array(world.agent.eye())
            views.append((eye.tolist(), (eye + np.array(world.agent.view_direction())).tolist()))
            last = frame
    _rewind(world, start)
    return views, failed


def env_steps_per_s(world, steps: int) -> float:
    """Replay the navigation cycle from the start pose: World.step + World.frame() per step."""
    start = world.agent
    t0 = time.perf_counter()
    for i in range(steps):
        world.step(NAV[i % len(NAV)])
        world.frame()
    dt = time.perf_counter() - t0
    _rewind(world, start)
    return steps / dt


def _raw_matrices(world, views):
    c, cfg = world.client, world.config
    proj = c.computeProjectionMatrixFOV(cfg.fov, cfg.width / cfg.height, 0.05, 20.0)
    return [(c.computeViewMatrix(eye, target, [0, 0, 1]), proj) for eye, target in views]


def raw_seconds(world, matrices) -> float:
    """Seconds to render every recorded view with getCameraImage as World.frame() asks for it."""
    from luminous_sim.world.client import p

    c, cfg = world.client, world.config
    renderer = getattr(c, "luminous_renderer", p.ER_TINY_RENDERER)
    t0 = time.perf_counter()
    for view, proj in matrices:
        c.getCameraImage(cfg.width, cfg.height, view, proj, renderer=renderer, shadow=0, lightDirection=LIGHT,
                         flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)
    return time.perf_counter() - t0


def _check_same_view(world, matrices) -> None:
    """The raw call draws what World.frame() draws (same segmentation for the first recorded view)."""
    from luminous_sim.world.client import p

    c, cfg = world.client, world.config
    world.step(NAV[0])
    seg = world.frame().seg
    view, proj = matrices[0]
    raw = c.getCameraImage(cfg.width, cfg.height, view, proj, renderer=getattr(c, "luminous_renderer",
                           p.ER_TINY_RENDERER), shadow=0, lightDirection=LIGHT,
                           flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)[4]
    assert np.array_equal(np.asarray(raw, dtype=np.int32).reshape(seg.shape), seg), "raw and World views differ"


def nav_unrendered(world, seconds: float) -> float:
    start, n, t0 = world.agent, 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        world.step(NAV[n % len(NAV)])
        n += 1
    rate = n / (time.perf_counter() - t0)
    _rewind(world, start)
    return rate


def interactions_per_s(world, seconds: float) -> float:
    from luminous_sim.world.poses import find_interaction_pose

    fridge = next(o.id for o in world.scene.objects if o.type == "Fridge")
    pose = find_interaction_pose(world, fridge)
    start = world.agent
    world.step({"action": "TeleportFull", "x": pose.x, "z": pose.y, "rotation": pose.rotation, "horizon": pose.horizon})
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds or n % 2:
        r = world.step({"action": "OpenObject" if n % 2 == 0 else "CloseObject", "objectId": fridge})
        assert r.success, r.error
        n += 1
    rate = n / (time.perf_counter() - t0)
    _rewind(world, start)
    return rate


def _memory(args) -> tuple[float, list[float]]:
    """In a fresh process: RSS before any World, then after each of `count` Worlds built and held."""
    seed, count = args
    from luminous_sim.world.world import World

    scene = _scene(seed)
    rss = [_rss_mb()]
    held = []
    for _ in range(count):
        held.append(World(scene))
        rss.append(_rss_mb())
    for w in held:
        w.close()
    return rss[0], rss[1:]


def _worker(seed: int, repeats: int, seconds: float, barrier, out) -> None:
    from luminous_sim.world.world import World

    with World(_scene(seed)) as w:
        start = w.agent
        for r in range(repeats):
            barrier.wait()  # every worker starts each repeat together, after all have built their World
            _rewind(w, start)
            n, t0 = 0, time.perf_counter()
            while time.perf_counter() - t0 < seconds:
                w.step(NAV[n % len(NAV)])
                w.frame()
                n += 1
            out.put((r, n / (time.perf_counter() - t0)))


def processes(count: int, seed: int, repeats: int, seconds: float) -> list[float]:
    """Summed steps/s of `count` worker processes on the same scene, one figure per repeat."""
    ctx = mp.get_context("spawn")
    barrier, out = ctx.Barrier(count), ctx.Queue()
    procs = [ctx.Process(target=_worker, args=(seed, repeats, seconds, barrier, out)) for _ in range(count)]
    for proc in procs:
        proc.start()
    totals = [0.0] * repeats
    for _ in range(count * repeats):
        r, rate = out.get()
        totals[r] += rate
    for proc in procs:
        proc.join()
    return totals


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seed", type=int, default=0, help="kitchen seed (every figure uses this one scene)")
    ap.add_argument("--repeats", type=int, default=5, help="repeats per figure (median and min..max reported)")
    ap.add_argument("--steps", type=int, default=48, help="navigation steps per environment/raw repeat")
    ap.add_argument("--seconds", type=float, default=3.0, help="seconds per repeat of the timed-loop figures")
    ap.add_argument("--worlds", type=int, default=4, help="Worlds held at once for the memory figure")
    args = ap.parse_args(argv)

    load = os.getloadavg()
    print(f"machine: {os.cpu_count()} cores; load average at start {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
          f"(1/5/15 min)")
    from luminous_sim.world.world import World

    with World(_scene(args.seed)) as world:
        c, start = world.config, world.agent
        views, failed = record_views(world, args.steps)
        matrices = _raw_matrices(world, views)
        _check_same_view(world, matrices)
        _rewind(world, start)
        env, raw, ratio = [], [], []
        for _ in range(args.repeats):  # interleaved, so that drifting load hits both alike
            e = env_steps_per_s(world, args.steps)
            r_s = raw_seconds(world, matrices)
            env.append(e)
            raw.append(len(views) / r_s)
            ratio.append(r_s / (args.steps / e))
        print(f"{c.width}x{c.height} RGB+depth+segmentation, {args.steps} navigation steps ({failed} failed, "
              f"{len(views)} distinct views rendered):")
        print(f"  environment: {spread(env)} steps/s; raw getCameraImage of the same views: {spread(raw)} FPS")
        print(f"  environment / raw, same views: {spread(ratio, '.2f')}x (goal >= 0.9x)")
        unr = [nav_unrendered(world, args.seconds / 3) for _ in range(args.repeats)]
        print(f"navigation with rendering off: {spread(unr, ',.0f')} steps/s (goal >= 1,000)")
        act = [interactions_per_s(world, args.seconds / 2) for _ in range(args.repeats)]
        print(f"interaction actions (open/close fridge, visibility checked): {spread(act)} actions/s")

    with mp.get_context("spawn").Pool(1) as pool:
        base, rss = pool.apply(_memory, ((args.seed, args.worlds),))
    per_held = (rss[-1] - rss[0]) / (len(rss) - 1) if len(rss) > 1 else float("nan")
    print(f"memory, {args.worlds} Worlds of one scene held at once in a fresh process: "
          f"{base:.0f} MB before any World (Python, libraries, scene); 1 World: {rss[0]:.0f} MB "
          f"(+{rss[0] - base:.0f} MB); {args.worlds} Worlds: {rss[-1]:.0f} MB; each further World held "
          f"+{per_held:.0f} MB (goal <= 150 MB per World process)")

    one = processes(1, args.seed, args.repeats, args.seconds)
    two = processes(2, args.seed, args.repeats, args.seconds)
    speedup = [t / o for t, o in zip(two, one, strict=True)]
    print(f"rendered navigation, same scene in every worker: 1 process {spread(one)} steps/s; "
          f"2 processes {spread(two)} steps/s; speed-up {statistics.median(two) / statistics.median(one):.2f}x "
          f"(per repeat {spread(speedup, '.2f')}; goal >= 1.9x; {os.cpu_count()} cores)")
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


if __name__ == "__main__":
    main()
