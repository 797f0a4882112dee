"""Gymnasium environment speed: steps/s single and vectorised, reset times, memory of one env process.

    python benchmarks/bench_env.py                            # ObjectNav v2 at 64 and 300 px, HouseNav resets
    python benchmarks/bench_env.py --repeats 5 --seconds 3    # the figures in docs/benchmarks.md (quiet machine)

Prints the CPU model and the machine load (`os.getloadavg()`) at the start and the end, then for each id (by
default `Luminous-ObjectNav-64-v2` at its 64 px and at 300 px, the same episodes and views) each figure as the
median over repeats with its spread (min..max). Every env is the one `luminous_sim.env.make_vector_env` runs in
a worker (`vector.wrapped_env`: the instruction as token ids, per-step info cut to a few keys), in one process
and in the vector envs alike, so the figures compare like with like:

- env steps/s, single process, for two action mixes from a seeded generator: `nav`, uniform over the five
  navigation actions (most succeed and each success renders a new frame; the ObjectNav ids end an episode only
  on Stop, so no episode ends while timed), and `random`, uniform over every action but Stop (mostly
  interactions at grid points, which mostly fail and render nothing new); episode limits raised; an episode
  that ends is reset inside the timed span, as the vector envs' autoreset is;
- env steps/s of `make_vector_env(..., 2, copy=False)` (gymnasium's `AsyncVectorEnv`, shared memory, the
  observations handed out as views of the shared buffers, as the single process hands out its own), of
  stable-baselines3's `SubprocVecEnv` over the same envs (`backend="subproc"`), and of `make_vector_env(...,
  2 * k, workers=2)` (`GroupedVectorEnv`: 2 worker processes stepping k envs each in turn; `--per-worker`), the
  same episode (id and seed) in every env and in the single process, counted as environment steps, and the
  ratio to the single process; then two single-env processes stepping at once (no vector env: the ceiling
  two cores give);
- reset time for a new scene (`reset(seed=s)`, a fresh seed each repeat: CSSG generates a room or a house, a
  goal is drawn and the expert's plan proved) and for a reused one (`reset(seed=s, options={"scene": scene})`
  with the scene of the previous episode: no generation, and the env's kept worlds of that scene are put
  back (`World.reset_to_start`) instead of built, where their physics was not touched). The worlds built and
  reused during the reused-scene resets are printed beside the figure; `--reset-ids` (default
  `Luminous-HouseNav-64-v2`) are measured for resets only;
- memory of one env process (a fresh spawned process: `gymnasium.make`, `reset`, 50 steps): RSS, and the
  worlds it holds (the agent's, and the expert's where its physics was untouched and so kept).
"""

from __future__ import annotations

import argparse
import multiprocessing as mp
import os
import statistics
import sys
import time
from pathlib import Path

import gymnasium
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import luminous_sim  # noqa: F401  (registers the ids)
from benchmarks.machine import cpu_model
from luminous_sim.env import make_vector_env
from luminous_sim.env.vector import wrapped_env

LIMITS = {"max_steps": 10**6, "max_failures": 10**6}
"""Episode limits while timing steps, so that truncation does not interrupt the timed span."""
STOP = 5
"""Index of Stop in the flat action space (`luminous_sim.env.actions`)."""


def spread(values: list[float], fmt: str = ".1f") -> str:
    """'median (min..max, n=K)' of the repeats."""
    return (f"{statistics.median(values):{fmt}} ({min(values):{fmt}}..{max(values):{fmt}}, "
            f"n={len(values)})")


MIXES = ("random", "nav")


def _actions(mix: str, n: int, rng: np.random.Generator, count: int) -> np.ndarray:
    """`count` uniform draws: from 0..n-1 without Stop (`random`), or from the navigation actions (`nav`)."""
    if mix == "nav":
        return rng.integers(STOP, size=count)
    draws = rng.integers(n - 1, size=count)
    return draws + (draws >= STOP)


def single_steps_per_s(env_id: str, options: dict, mix: str, seed: int, repeats: int,
                       seconds: float) -> tuple[list[float], int]:
    """Steps/s of one env per repeat, and how many episodes ended while stepping (each reset inside the timed
    span, as the vector env's autoreset is)."""
    env = wrapped_env(env_id, **options, **LIMITS)
    rng = np.random.default_rng(seed)
    env.reset(seed=seed)
    n = int(env.action_space.n)
    rates, ended = [], 0
    for _ in range(repeats):
        steps = 0
        t0 = time.perf_counter()
        while time.perf_counter() - t0 < seconds:
            for a in _actions(mix, n, rng, 16):
                _, _, terminated, truncated, _ = env.step(int(a))
                steps += 1
                if terminated or truncated:
                    ended += 1
                    env.reset()
        rates.append(steps / (time.perf_counter() - t0))
    env.close()
    return rates, ended


def vector_steps_per_s(env_id: str, options: dict, mix: str, seed: int, repeats: int, seconds: float,
                       backend: str = "async", workers: int = 2, per_worker: int = 1) -> tuple[list[float], int]:
    """Environment steps/s (envs per vector step) of `make_vector_env(backend=...)` with `workers` processes of
    `per_worker` envs each, per repeat, and the autoresets."""
    extra: dict = {"copy": False} if backend == "async" else {}  # the single process hands out its arrays uncopied
    if per_worker > 1:
        extra["workers"] = workers
    n_envs = workers * per_worker
    envs = make_vector_env(env_id, n_envs, backend=backend, **extra, **options, **LIMITS)
    rng = np.random.default_rng(seed)
    if backend == "subproc":
        envs.seed(seed)
        for i in range(n_envs):  # SB3 seeds env i with seed + i: the same episode in each instead
            envs.env_method("reset", seed=seed, indices=[i])
        n = int(envs.action_space.n)
    else:
        envs.reset(seed=[seed] * n_envs)
        n = int(envs.single_action_space.n)
    rates, ended = [], 0
    for _ in range(repeats):
        steps = 0
        t0 = time.perf_counter()
        while time.perf_counter() - t0 < seconds:
            if backend == "subproc":
                _, _, done, _ = envs.step(_actions(mix, n, rng, n_envs))
            else:
                _, _, terminated, truncated, _ = envs.step(_actions(mix, n, rng, n_envs))
                done = terminated | truncated
            steps += n_envs
            ended += int(np.sum(done))
        rates.append(steps / (time.perf_counter() - t0))
    envs.close()
    return rates, ended


def _alone(job: tuple[str, dict, str, int, int, float]) -> list[float]:
    env_id, options, mix, seed, repeats, seconds = job
    return single_steps_per_s(env_id, options, mix, seed, repeats, seconds)[0]


def two_processes(env_id: str, options: dict, mix: str, seed: int, repeats: int, seconds: float) -> list[float]:
    """Steps/s of two single-env processes stepping at once, summed per repeat: what two cores give with no
    vector env between them."""
    with mp.get_context("fork").Pool(2) as pool:
        a, b = pool.map(_alone, [(env_id, options, mix, seed, repeats, seconds)] * 2)
    return [x + y for x, y in zip(a, b, strict=True)]


def reset_seconds(env_id: str, options: dict, seed: int,
                  repeats: int) -> tuple[list[float], list[float], tuple[int, int]]:
    """Seconds per reset: a new scene each repeat, and the previous episode's scene passed again; the worlds
    built and reused by the reused-scene resets."""
    env = gymnasium.make(env_id, **options)
    env.reset(seed=seed)  # imports and first-use costs stay out of the figures
    pool = env.unwrapped.worlds  # type: ignore[attr-defined]
    new, reused, builds, reuses = [], [], 0, 0
    for i in range(repeats):
        t0 = time.perf_counter()
        env.reset(seed=seed + 1 + i)
        new.append(time.perf_counter() - t0)
        scene = env.unwrapped.episode.scene  # type: ignore[attr-defined]
        counts = pool.builds, pool.reuses
        t0 = time.perf_counter()
        env.reset(seed=seed + 1000 + i, options={"scene": scene})
        reused.append(time.perf_counter() - t0)
        builds, reuses = builds + pool.builds - counts[0], reuses + pool.reuses - counts[1]
    env.close()
    return new, reused, (builds, reuses)


def _rss_mb() -> float:
    with open(f"/proc/{os.getpid()}/status") as fh:
        return next(int(line.split()[1]) / 1024 for line in fh if line.startswith("VmRSS"))


def env_process_memory(job: tuple[str, dict, int]) -> tuple[float, float, int]:
    """In a fresh process: RSS after the imports, RSS after a reset and 50 steps, and the worlds held then."""
    env_id, options, seed = job
    before = _rss_mb()
    env = gymnasium.make(env_id, **options, **LIMITS)  # 50 steps in one episode (a step after its end would raise)
    env.reset(seed=seed)
    rng = np.random.default_rng(seed)
    for a in _actions("nav", int(env.action_space.n), rng, 50):
        env.step(int(a))
    worlds = env.unwrapped.worlds.kept + (env.unwrapped.world is not None)  # type: ignore[attr-defined]
    rss = _rss_mb()
    env.close()
    return before, rss, worlds


def _options(spec_id: str) -> tuple[str, dict]:
    """'ID', 'ID@SIZE' (square frames of SIZE px instead of the id's own) or 'ID@SIZE/RASTERISER' (and drawn by
    that rasteriser: compiled or tinyrenderer): the id and its env options."""
    env_id, _, rest = spec_id.partition("@")
    size, _, rasteriser = rest.partition("/")
    options: dict = {"width": int(size), "height": int(size)} if size else {}
    if rasteriser:
        options["rasteriser"] = rasteriser
    return env_id, options


def _size(env_id: str, options: dict) -> str:
    kwargs = {**gymnasium.spec(env_id).kwargs, **options}
    return f"{kwargs.get('width', 300)}x{kwargs.get('height', 300)}, {kwargs.get('rasteriser', 'tinyrenderer')}"


def bench(spec_id: str, args: argparse.Namespace) -> None:
    env_id, options = _options(spec_id)
    print(f"\n{env_id} ({_size(env_id, options)})", flush=True)
    for mix in args.mixes:
        rates, ended = single_steps_per_s(env_id, options, mix, args.seed, args.repeats, args.seconds)
        print(f"  steps/s, {mix:6} single process:     {spread(rates)}   episodes ended: {ended}", flush=True)
        setups = [("async", 1, "AsyncVectorEnv, 2 envs"), ("subproc", 1, "SubprocVecEnv, 2 envs")]
        setups += [("async", k, f"grouped, 2 workers x {k} envs") for k in args.per_worker]
        for backend, per_worker, name in setups:
            vrates, vended = vector_steps_per_s(env_id, options, mix, args.seed, args.repeats, args.seconds, backend,
                                                per_worker=per_worker)
            print(f"  steps/s, {mix:6} {name:28s} {spread(vrates)}   autoresets: {vended}"
                  f"   ({statistics.median(vrates) / statistics.median(rates):.2f}x single)", flush=True)
        pair = two_processes(env_id, options, mix, args.seed, args.repeats, args.seconds)
        print(f"  steps/s, {mix:6} two independent processes     {spread(pair)}"
              f"   ({statistics.median(pair) / statistics.median(rates):.2f}x single: the ceiling of 2 cores)",
              flush=True)
    resets(spec_id, args)
    with mp.get_context("spawn").Pool(1) as pool:
        before, rss, worlds = pool.apply(env_process_memory, ((env_id, options, args.seed),))
    print(f"  memory, one env process:             {rss:.0f} MB after reset and 50 steps ({before:.0f} MB after "
          f"the imports; worlds held: {worlds}, the agent's and, where its physics was untouched, the expert's)")


def resets(spec_id: str, args: argparse.Namespace) -> None:
    env_id, options = _options(spec_id)
    new, reused, (builds, reuses) = reset_seconds(env_id, options, args.seed, args.repeats)
    print(f"  reset s, new scene:                  {spread(new, '.2f')}")
    print(f"  reset s, reused scene:               {spread(reused, '.2f')}   worlds built: {builds}, "
          f"reused: {reuses}", flush=True)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ids", nargs="+", default=["Luminous-ObjectNav-64-v2", "Luminous-ObjectNav-64-v2@300"],
                    help="ids to measure, each ID, ID@SIZE (square frames of SIZE px) or ID@SIZE/RASTERISER "
                         "(compiled or tinyrenderer)")
    ap.add_argument("--reset-ids", nargs="*", default=["Luminous-HouseNav-64-v2"],
                    help="ids whose reset times alone are measured (houses)")
    ap.add_argument("--mixes", nargs="+", choices=MIXES, default=list(MIXES), help="action mixes to time")
    ap.add_argument("--seed", type=int, default=0, help="episode seed (and action-generator seed)")
    ap.add_argument("--repeats", type=int, default=3, help="repeats per figure (median and min..max reported)")
    ap.add_argument("--seconds", type=float, default=1.5, help="seconds stepping per repeat of a steps/s figure")
    ap.add_argument("--per-worker", nargs="*", type=int, default=[8, 16],
                    help="envs per worker of the grouped vector env (2 workers) to measure")
    args = ap.parse_args(argv)
    print(f"CPU: {cpu_model()}, {os.cpu_count()} cores; load average at start (1, 5, 15 min): {os.getloadavg()}")
    for spec_id in args.ids:
        bench(spec_id, args)
    for spec_id in args.reset_ids:
        print(f"\n{spec_id} (resets)", flush=True)
        resets(spec_id, args)
    print(f"\nload average at end (1, 5, 15 min): {os.getloadavg()}")


if __name__ == "__main__":
    main()
