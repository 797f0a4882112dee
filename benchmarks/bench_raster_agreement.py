"""How closely the compiled rasteriser's frames follow PyBullet's TinyRenderer, on the same actions.

    python benchmarks/bench_raster_agreement.py                   # the figures in docs/benchmarks.md
    python benchmarks/bench_raster_agreement.py --nav-steps 50 --ids Luminous-ALFRED-PickHeat-v2 --seeds 1

Two kinds of runs, each with a TinyRenderer copy and a compiled copy stepped with the same actions:
- navigation: `World`s of generated kitchens (`--nav SEED:SIZE ...`), a fixed cycle of the navigation actions;
- oracle episodes: envs of ALFRED's task types at `--size` px (`--ids`, `--seeds`), the expert's actions.
Prints, per run and in total, the frames, the pixels whose RGB or segmentation differ, and the largest depth
difference (metres).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

NAV = ["MoveAhead", "RotateRight", "MoveAhead", "LookDown", "RotateLeft", "MoveAhead", "LookUp", "RotateLeft"]
ALFRED_IDS = [f"Luminous-ALFRED-{t}-v2" for t in
              ("PickPlace", "PickTwo", "LookInLight", "PickClean", "PickHeat", "PickCool", "PickMovable")]


def _differ(a_rgb, a_seg, b_rgb, b_seg) -> int:
    return int(((a_rgb != b_rgb).any(axis=-1) | (a_seg != b_seg)).sum())


def navigation(seed: int, size: int, steps: int) -> tuple[int, int, int, float]:
    """(frames, pixels, differing pixels, largest depth difference) over `steps` navigation steps."""
    from luminous_sim.cssg import empty_cdf, generate
    from luminous_sim.world import World, WorldConfig

    scene = generate(empty_cdf("Kitchen"), seed=seed).scene
    frames = differ = 0
    depth = 0.0
    with World(scene, WorldConfig(width=size, height=size, rasteriser="tinyrenderer")) as ref, \
            World(scene, WorldConfig(width=size, height=size, rasteriser="compiled")) as fast:
        for i in range(steps):
            ref.step(NAV[i % len(NAV)])
            fast.step(NAV[i % len(NAV)])
            a, b = ref.frame(), fast.frame()
            frames += 1
            differ += _differ(a.rgb, a.seg, b.rgb, b.seg)
            depth = max(depth, float(np.abs(a.depth - b.depth).max()))
    return frames, frames * size * size, differ, depth


def oracle_episode(env_id: str, seed: int, size: int) -> tuple[int, int, int, float]:
    """The same counts over one oracle episode of `env_id` (segmentation and depth observed)."""
    import gymnasium as gym

    import luminous_sim.env  # noqa: F401  (registers the ids)
    from luminous_sim.env import OraclePolicy

    envs = [gym.make(env_id, rasteriser=r, width=size, height=size, depth=True, segmentation=True)
            for r in ("tinyrenderer", "compiled")]
    try:
        for env in envs:
            env.reset(seed=seed)
        policy = OraclePolicy(envs[0])
        frames = differ = 0
        depth = 0.0
        done = False
        while not done:
            action = policy()
            (a, _, term, trunc, _), (b, *_) = (env.step(action) for env in envs)
            frames += 1
            differ += _differ(a["rgb"], a["segmentation"], b["rgb"], b["segmentation"])
            depth = max(depth, float(np.abs(a["depth"] - b["depth"]).max()))
            done = term or trunc
        return frames, frames * size * size, differ, depth
    finally:
        for env in envs:
            env.close()


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--nav", nargs="*", default=["0:64", "1:64", "2:128", "0:300", "3:300"],
                    help="navigation runs, each SEED:SIZE (a generated kitchen)")
    ap.add_argument("--nav-steps", type=int, default=400, help="navigation steps per run")
    ap.add_argument("--ids", nargs="*", default=ALFRED_IDS + ["Luminous-ALFRED-v2"], help="oracle episodes' ids")
    ap.add_argument("--seeds", type=int, default=3, help="episode seeds 0..N-1 of each id")
    ap.add_argument("--size", type=int, default=96, help="frame size of the oracle episodes")
    args = ap.parse_args(argv)
    total = [0, 0, 0, 0.0]
    runs = [(f"navigation, kitchen seed {s}, {z} px", navigation, (int(s), int(z), args.nav_steps))
            for s, z in (spec.split(":") for spec in args.nav)]
    runs += [(f"oracle, {i} seed {s}, {args.size} px", oracle_episode, (i, s, args.size))
             for i in args.ids for s in range(args.seeds)]
    for name, fn, fn_args in runs:
        frames, pixels, differ, depth = fn(*fn_args)  # type: ignore[operator]
        print(f"{name}: {frames} frames, {differ} of {pixels} pixels differ, depth within {depth:.1e} m", flush=True)
        total = [total[0] + frames, total[1] + pixels, total[2] + differ, max(total[3], depth)]
    print(f"total: {total[0]} frames, {total[2]} of {total[1]} pixels differ "
          f"({total[2] / max(total[1], 1) * 1e6:.1f} in a million), depth within {total[3]:.1e} m")


if __name__ == "__main__":
    main()
