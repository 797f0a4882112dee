"""Simulator speed and memory, measured so that each figure means what it says.

    python benchmarks/bench_world.py                 # about three minutes
    python benchmarks/bench_world.py --repeats 9 --seconds 10 --worlds 8   # longer, tighter figures
    python benchmarks/bench_world.py --sizes 64 --only-frames               # one frame size, frames only
    python benchmarks/bench_world.py --only-frames --ablation               # and each optimisation alone
    python benchmarks/bench_world.py --size-ratio 300,64                    # one step's cost, small vs large

Prints the machine load at the start, then each figure as the median over repeats with its spread
(min..max):
- per frame size (300, 128, 64 px), before and after the render optimisations, in the same run on the
  same views, interleaved: "before" is a World with `lod_max_size=0, cull=False, structure_last=False`
  (full-detail visuals, every body drawn, floor and walls painted first, as before them), "after" the
  default World (the level-of-detail visuals at <= 128 px, frustum culling of objects, portal culling of the
  outdoors, structure painted last).
  Each as steps/s of wall-clock time and of this process's CPU time (the machine is shared: CPU time
  is what one core does, and moves less with the load); with `--ablation`, each optimisation alone (the
  frustum culling of objects, that and the portal culling of the outdoors, the structure painted last, the
  level of detail) on the same views;
- environment vs raw renderer on the SAME views: the World's navigation cycle is run once to record
  the camera pose of every frame it renders; the raw loop renders exactly those views with
  `getCameraImage` (same size, renderer, flags, light) in the same World, the environment loop replays
  the cycle with `World.step` + `World.frame()` (goal >= 0.9x);
- with `--size-ratio BIG,SMALL` (only that): the default World at two frame sizes on the same views,
  interleaved: CPU and wall-clock milliseconds per navigation step (World.step + World.frame()) at each,
  and the BIG/SMALL ratio of CPU time per repeat (how much cheaper a small frame is); and the small size
  with every culled link shown again after each frame (as culling did before culled links stayed hidden);
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


def env_steps_per_s(world, steps: int, after_frame=None) -> tuple[float, float]:
    """Replay the navigation cycle from the start pose: World.step + World.frame() (and `after_frame(world)`)
    per step; steps per second of wall-clock time and of CPU time."""
    start = world.agent
    t0, c0 = time.perf_counter(), time.process_time()
    for i in range(steps):
        world.step(NAV[i % len(NAV)])
        world.frame()
        if after_frame is not None:
            after_frame(world)
    dt, dc = time.perf_counter() - t0, time.process_time() - c0
    _rewind(world, start)
    return steps / dt, steps / max(dc, 1e-9)


def _raw_matrices(world, views):
    c, cfg = world.client, world.config
    proj = c.computeProjectionMatrixFOV(cfg.fov, cfg.width / cfg.height, 0.05, 20.0)
    return [(c.computeViewMatrix(eye, target, [0, 0, 1]), proj) for eye, target in views]


def raw_seconds(world, matrices) -> tuple[float, float]:
    """Seconds (wall clock, CPU) to render every recorded view with getCameraImage as World.frame() asks."""
    from luminous_sim.world.client import p

    c, cfg = world.client, world.config
    renderer = getattr(c, "luminous_renderer", p.ER_TINY_RENDERER)
    t0, c0 = time.perf_counter(), time.process_time()
    for view, proj in matrices:
        c.getCameraImage(cfg.width, cfg.height, view, proj, renderer=renderer, shadow=0, lightDirection=LIGHT,
                         flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)
    return time.perf_counter() - t0, time.process_time() - c0


def _check_same_view(world, matrices) -> None:
    """The raw call draws what World.frame() draws (same picture for the first recorded view)."""
    from luminous_sim.world.client import p

    c, cfg = world.client, world.config
    start = world.agent
    world.step(NAV[0])
    frame = world.frame()
    view, proj = matrices[0]
    raw = c.getCameraImage(cfg.width, cfg.height, view, proj, renderer=getattr(c, "luminous_renderer",
                           p.ER_TINY_RENDERER), shadow=0, lightDirection=LIGHT,
                           flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)
    rgb = np.asarray(raw[2], dtype=np.uint8).reshape(cfg.height, cfg.width, 4)[:, :, :3]
    seg = np.asarray(raw[4], dtype=np.int32).reshape(frame.seg.shape)
    assert np.array_equal(rgb, frame.rgb) and np.array_equal(seg, frame.seg), "raw and World views differ"
    _rewind(world, start)


BEFORE = {"lod_max_size": 0, "cull": False, "structure_last": False}
"""The World as it rendered before the level of detail, culling and the structure painted last."""


def ablation(seed: int, size: int, steps: int, repeats: int) -> None:
    """CPU-time steps/s with each render optimisation alone, on the same views (which change buys what)."""
    from luminous_sim.world.config import WorldConfig
    from luminous_sim.world.world import World

    scene = _scene(seed)
    variants = {"before": BEFORE, "frustum culling of objects only": {**BEFORE, "cull": True, "cull_outdoors": False},
                "culling of objects and outdoors only": {**BEFORE, "cull": True},
                "structure last only": {**BEFORE, "structure_last": True}}
    if size <= WorldConfig().lod_max_size:
        variants["LOD only"] = {**BEFORE, "lod_max_size": WorldConfig().lod_max_size}
    variants["all (default)"] = {}
    worlds = {name: World(scene, WorldConfig(width=size, height=size, **cfg)) for name, cfg in variants.items()}
    try:
        rates: dict[str, list[float]] = {name: [] for name in worlds}
        for _ in range(repeats):
            for name, w in worlds.items():
                rates[name].append(env_steps_per_s(w, steps)[1])
        base = statistics.median(rates["before"])
        print(f"{size}x{size}, CPU-time steps/s with one change at a time:")
        for name, r in rates.items():
            print(f"  {name}: {spread(r)} ({statistics.median(r) / base:.2f}x)")
    finally:
        for w in worlds.values():
            w.close()


def frame_figures(seed: int, size: int, steps: int, repeats: int) -> None:
    """Before/after steps/s at one frame size on the same recorded views, and env vs raw (after)."""
    from luminous_sim.world.config import WorldConfig
    from luminous_sim.world.world import World

    scene = _scene(seed)
    with World(scene, WorldConfig(width=size, height=size, **BEFORE)) as before, \
            World(scene, WorldConfig(width=size, height=size)) as after:
        views, failed = record_views(after, steps)
        assert record_views(before, steps)[0] == views, "the two Worlds took different views"
        matrices = _raw_matrices(after, views)
        _check_same_view(after, matrices)
        env_b, env_a, cpu_b, cpu_a, raw, ratio = [], [], [], [], [], []
        for _ in range(repeats):  # interleaved, so that drifting load hits all alike
            wall, cpu = env_steps_per_s(before, steps)
            env_b.append(wall)
            cpu_b.append(cpu)
            wall, cpu = env_steps_per_s(after, steps)
            env_a.append(wall)
            cpu_a.append(cpu)
            r_wall, _ = raw_seconds(after, matrices)
            raw.append(len(views) / r_wall)
            ratio.append(r_wall / (steps / env_a[-1]))
        lod = "level-of-detail visuals" if after.config.use_lod else "full detail"
        print(f"{size}x{size} RGB+depth+segmentation, {steps} navigation steps ({failed} failed, {len(views)} distinct "
              f"views), after: {lod}, culling of objects and outdoors, structure last:")
        print(f"  before: {spread(env_b)} steps/s wall clock, {spread(cpu_b)} steps/s of CPU time")
        print(f"  after:  {spread(env_a)} steps/s wall clock, {spread(cpu_a)} steps/s of CPU time")
        gain = [a / b for a, b in zip(cpu_a, cpu_b, strict=True)]
        print(f"  after / before, CPU time per repeat: {spread(gain, '.2f')}x")
        print(f"  raw getCameraImage of the same views (after's World, no culling): {spread(raw)} FPS; "
              f"environment / raw: {spread(ratio, '.2f')}x (goal >= 0.9x)")


def _show_culled(world) -> None:
    world._culler.reveal()


def size_ratio(seed: int, big: int, small: int, steps: int, repeats: int) -> None:
    """Milliseconds per step of the default World at two frame sizes on the same views, interleaved; and at the
    small size with every culled link shown again after each frame (culling as it was before culled links
    stayed hidden between frames), in the same World."""
    from luminous_sim.world.config import WorldConfig
    from luminous_sim.world.world import World

    scene = _scene(seed)
    compiled, compiled_big = f"{small}x{small}, compiled rasteriser", f"{big}x{big}, compiled rasteriser"
    with World(scene, WorldConfig(width=big, height=big)) as large, \
            World(scene, WorldConfig(width=small, height=small)) as little, \
            World(scene, WorldConfig(width=small, height=small, rasteriser="compiled")) as fast, \
            World(scene, WorldConfig(width=big, height=big, rasteriser="compiled")) as fast_large:
        views, failed = record_views(large, steps)
        for world in (little, fast, fast_large):
            assert record_views(world, steps)[0] == views, "the Worlds took different views"
        for world in (large, little, fast, fast_large):
            env_steps_per_s(world, steps)  # warm them (caches, first renders, numba's compilation)
        runs = {f"{big}x{big}": (large, None), f"{small}x{small}": (little, None),
                f"{small}x{small}, culled links shown after each frame": (little, _show_culled),
                compiled: (fast, None), compiled_big: (fast_large, None)}
        ms: dict[str, tuple[list[float], list[float]]] = {name: ([], []) for name in runs}
        for _ in range(repeats):
            for name, (world, after) in runs.items():
                wall, cpu = env_steps_per_s(world, steps, after)
                ms[name][0].append(1e3 / cpu)
                ms[name][1].append(1e3 / wall)
        print(f"default World, {steps} navigation steps ({failed} failed, {len(views)} distinct views), "
              f"the same views at both sizes, ms per step:")
        for name in runs:
            print(f"  {name}: {spread(ms[name][0], '.3f')} ms of CPU time, {spread(ms[name][1], '.3f')} ms "
                  f"wall clock")
        big_ms, small_ms = ms[f"{big}x{big}"][0], ms[f"{small}x{small}"][0]
        ratio = [b / s for b, s in zip(big_ms, small_ms, strict=True)]
        print(f"  {big}/{small} CPU time per step, per repeat: {spread(ratio, '.2f')}x")
        kept = [a / s for a, s in zip(ms[f"{small}x{small}, culled links shown after each frame"][0], small_ms,
                                      strict=True)]
        print(f"  {small} px, shown after each frame / kept hidden, CPU time per repeat: {spread(kept, '.2f')}x")
        for size, name, tiny in ((small, compiled, small_ms), (big, compiled_big, big_ms)):
            faster = [f / t for f, t in zip(ms[name][0], tiny, strict=True)]
            print(f"  {size} px, compiled rasteriser / TinyRenderer, CPU time per repeat: {spread(faster, '.2f')}x")
        both = [b / f for b, f in zip(ms[compiled_big][0], ms[compiled][0], strict=True)]
        print(f"  {big}/{small} CPU time per step with the compiled rasteriser at both, per repeat: "
              f"{spread(both, '.2f')}x")


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
    seed, count, size = args
    from luminous_sim.world.config import WorldConfig
    from luminous_sim.world.world import World

    scene = _scene(seed)
    rss = [_rss_mb()]
    held = []
    for _ in range(count):
        held.append(World(scene, WorldConfig(width=size, height=size)))
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
    ap.add_argument("--sizes", default="300,128,64", help="frame sizes for the before/after frame figures")
    ap.add_argument("--only-frames", action="store_true", help="only the before/after frame figures")
    ap.add_argument("--size-ratio", default="", metavar="BIG,SMALL",
                    help="only the ms per step at two frame sizes on the same views, and their ratio")
    ap.add_argument("--ablation", action="store_true", help="also each render optimisation alone, per size")
    args = ap.parse_args(argv)

    load = os.getloadavg()
    print(f"machine: {os.cpu_count()} cores; load average at start {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} "
          f"(1/5/15 min)")
    if args.size_ratio:
        big, small = (int(x) for x in args.size_ratio.split(","))
        size_ratio(args.seed, big, small, args.steps, args.repeats)
        load = os.getloadavg()
        print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
        return
    for size in (int(x) for x in args.sizes.split(",")):
        frame_figures(args.seed, size, args.steps, args.repeats)
        if args.ablation:
            ablation(args.seed, size, args.steps, args.repeats)
    if args.only_frames:
        load = os.getloadavg()
        print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
        return
    from luminous_sim.world.world import World

    with World(_scene(args.seed)) as world:
        unr = [nav_unrendered(world, args.seconds / 3) for _ in range(args.repeats)]
        print(f"navigation with rendering off: {spread(unr, ',.0f')} steps/s (goal >= 1,000)")
        act = [interactions_per_s(world, args.seconds / 2) for _ in range(args.repeats)]
        print(f"interaction actions (open/close fridge, visibility checked): {spread(act)} actions/s")

    for size in (300, 64):
        with mp.get_context("spawn").Pool(1) as pool:
            base, rss = pool.apply(_memory, ((args.seed, args.worlds, size),))
        per_held = (rss[-1] - rss[0]) / (len(rss) - 1) if len(rss) > 1 else float("nan")
        print(f"memory, {args.worlds} Worlds ({size} px) of one scene held at once in a fresh process: "
              f"{base:.0f} MB before any World (Python, libraries, scene); 1 World: {rss[0]:.0f} MB "
              f"(+{rss[0] - base:.0f} MB); {args.worlds} Worlds: {rss[-1]:.0f} MB; each further World held "
              f"+{per_held:.0f} MB (goal <= 150 MB per World process)")

    one = processes(1, args.seed, args.repeats, args.seconds)
    two = processes(2, args.seed, args.repeats, args.seconds)
    speedup = [t / o for t, o in zip(two, one, strict=True)]
    print(f"rendered navigation (300 px), same scene in every worker: 1 process {spread(one)} steps/s; "
          f"2 processes {spread(two)} steps/s; speed-up {statistics.median(two) / statistics.median(one):.2f}x "
          f"(per repeat {spread(speedup, '.2f')}; goal >= 1.9x; {os.cpu_count()} cores)")
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")


if __name__ == "__main__":
    main()
