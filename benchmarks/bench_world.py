"""Simulator speed and memory.

    python benchmarks/bench_world.py

Prints: navigation steps/s with a 300x300 RGB frame per step vs raw PyBullet getCameraImage FPS on the
same scene and camera (goal >= 0.9x); navigation steps/s with rendering off (goal >= 1,000); interaction
actions/s; resident memory per World (goal <= 300 MB); throughput of two worlds in two processes vs one
(goal >= 1.8x).
"""

from __future__ import annotations

import multiprocessing as mp
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.cssg import empty_cdf, generate

NAV = ["MoveAhead", "RotateRight", "MoveAhead", "LookDown", "RotateLeft", "MoveAhead", "LookUp", "RotateLeft"]


def _scene(seed: int = 0):
    return generate(empty_cdf("Kitchen"), seed=seed).scene


def _rss_mb() -> float:
    with open(f"/proc/{os.getpid()}/status") as fh:
        for line in fh:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024
    return float("nan")


def nav_rendered(world, seconds: float = 4.0) -> float:
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        world.step(NAV[n % len(NAV)])
        world.frame()
        n += 1
    return n / (time.perf_counter() - t0)


def raw_camera_fps(world, seconds: float = 4.0) -> float:
    import pybullet as p

    c, cfg = world.client, world.config
    pose = world.agent
    eye = np.array(pose.eye())
    view = c.computeViewMatrix(eye.tolist(), (eye + np.array(pose.view_direction())).tolist(), [0, 0, 1])
    proj = c.computeProjectionMatrixFOV(cfg.fov, 1.0, 0.05, 20.0)
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        c.getCameraImage(cfg.width, cfg.height, view, proj, renderer=p.ER_TINY_RENDERER,
                         flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX)
        n += 1
    return n / (time.perf_counter() - t0)


def nav_unrendered(world, seconds: float = 3.0) -> float:
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        world.step(NAV[n % len(NAV)])
        n += 1
    return n / (time.perf_counter() - t0)


def interactions_per_s(world, seconds: float = 6.0) -> float:
    from luminous_sim.world.poses import find_interaction_pose

    fridge = next(o.id for o in world.scene.objects if o.type == "Fridge")
    pose = find_interaction_pose(world, fridge)
    world.step({"action": "TeleportFull", "x": pose.x, "z": pose.y, "rotation": pose.rotation, "horizon": pose.horizon})
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        r = world.step({"action": "OpenObject" if n % 2 == 0 else "CloseObject", "objectId": fridge})
        assert r.success, r.error
        n += 1
    return n / (time.perf_counter() - t0)


def _worker(args) -> int:
    seed, seconds = args
    from luminous_sim.world.world import World

    w = World(_scene(seed))
    n, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < seconds:
        w.step(NAV[n % len(NAV)])
        w.frame()
        n += 1
    w.close()
    return n


def main() -> None:
    from luminous_sim.world.world import World

    scene = _scene()
    rss0 = _rss_mb()
    world = World(scene)
    rss1 = _rss_mb()
    fps_raw = raw_camera_fps(world)
    sps = nav_rendered(world)
    print(f"navigation with 300x300 RGB+depth+segmentation: {sps:.1f} steps/s; raw getCameraImage: "
          f"{fps_raw:.1f} FPS; ratio {sps / fps_raw:.2f}x (goal >= 0.9x)")
    print(f"navigation with rendering off: {nav_unrendered(world):,.0f} steps/s (goal >= 1,000)")
    print(f"interaction actions (open/close fridge, visibility checked): {interactions_per_s(world):.1f} actions/s")
    world.close()
    extra = [World(_scene(s)) for s in (1, 2, 3)]
    rss2 = _rss_mb()
    for w in extra:
        w.close()
    print(f"memory: first World +{rss1 - rss0:.0f} MB (process {rss1:.0f} MB incl. Python and libraries); "
          f"each further World +{(rss2 - rss1) / 3:.0f} MB (goal <= 300 MB per World)")
    seconds = 8.0
    with mp.get_context("spawn").Pool(1) as pool:
        one = sum(pool.map(_worker, [(0, seconds)]))
    with mp.get_context("spawn").Pool(2) as pool:
        two = sum(pool.map(_worker, [(0, seconds), (1, seconds)]))
    print(f"rendered navigation, 1 process: {one / seconds:.1f} steps/s; 2 processes: {two / seconds:.1f} steps/s; "
          f"speed-up {two / one:.2f}x (goal >= 1.8x; {os.cpu_count()} cores)")


if __name__ == "__main__":
    main()
