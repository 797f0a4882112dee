"""Baselines that bound the v2 navigation ids: success rate, SPL and soft SPL with 95% intervals on the same
held-out episodes (the spec's `eval` seeds), and the start-distance distribution.

    python benchmarks/bench_nav_baselines.py                          # 50 episodes of each v2 id, 4 policies
    python benchmarks/bench_nav_baselines.py --env Luminous-ObjectNav-64-v2 --episodes 100 --json out.json

The first policy's resets of each episode are timed (`reset_s_median`: a new scene is generated, its world
built, the expert's plan proved; the other policies' resets of the episode reuse the scene's worlds).

Policies (each seeded; every one plays the same held-out seeds, `reset(seed=s)`, s from the id's `eval` table):

* `random`: uniform over the whole action space (navigation, Stop, the interactions on the 3x3 grid).
* `walk-stop`: a random walk over the five navigation actions that calls Stop at a random time, drawn
  uniformly from 1..max_steps at the start of the episode.
* `walk-seg`: a random walk over the navigation actions with privileged sight: ObjectNav, it calls Stop as
  soon as an instance of the target type has a pixel in the segmentation; PickUp, it picks an instance up by
  id as soon as one is visible by ALFRED's rule (the pixel threshold, within 1.5 m). A bound for exploration
  without learning, not a target.
* `walk-seg-near` (ObjectNav): the same walk, calling Stop as soon as Stop would succeed (an instance of the
  target visible by ALFRED's rule within the success distance): the bound of a random walk that always
  recognises its goal. On PickUp it is `walk-seg`.
* `oracle`: the env's expert (`env.expert_action()`; its plan ends with Stop).
* `ppo:NAME` (`--ppo NAME=DIR`, repeatable): a policy trained by `bench_ppo.py`/`examples/train_ppo.py` (DIR
  holds its `model.zip` and `config.json`), sampling from its action distribution (seeded), in the id as
  registered plus the observation options it was trained with (e.g. `goal_mask`), through the same wrappers
  (`train_ppo.make_env`: instruction tokens, its action subset, feedback): the same episodes as every other
  policy.

SR comes with a 95% Wilson interval; SPL and soft SPL with a 95% percentile bootstrap interval (2,000
resamples of the episodes, seeded). Episodes end by success, Stop (failed), the failure limit or the step
limit ("ends"). Prints the CPU model and the load at the start and the end.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import gymnasium  # noqa: E402

import luminous_sim  # noqa: E402, F401  (registers the ids)
from benchmarks.machine import cpu_model, load  # noqa: E402  (after the path)
from luminous_sim.env import LuminousEnv, eval_seeds  # noqa: E402
from luminous_sim.env.actions import NAVIGATION, STOP  # noqa: E402
from luminous_sim.env.shaping import goal_scores  # noqa: E402

ENV_IDS = ("Luminous-ObjectNav-64-v2", "Luminous-PickUp-64-v2")
POLICIES = ("random", "walk-stop", "walk-seg", "walk-seg-near", "oracle")
Policy = Callable[[LuminousEnv, Any], Any]
"""(the env, the observation as the policy's env gives it) -> action."""






def wilson(k: int, n: int, z: float = 1.959964) -> tuple[float, float]:
    """The 95% Wilson score interval of k successes in n."""
    if n == 0:
        return (0.0, 1.0)
    p = k / n
    centre = (p + z * z / (2 * n)) / (1 + z * z / n)
    half = z * np.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n)
    return (max(0.0, centre - half), min(1.0, centre + half))


def bootstrap(values: list[float], seed: int = 0, resamples: int = 2000) -> tuple[float, float]:
    """The 95% percentile bootstrap interval of the mean."""
    x = np.asarray(values, float)
    if len(x) == 0:
        return (0.0, 0.0)
    rng = np.random.default_rng(seed)
    means = x[rng.integers(0, len(x), (resamples, len(x)))].mean(axis=1)
    return (float(np.percentile(means, 2.5)), float(np.percentile(means, 97.5)))


def _target_in_segmentation(env: LuminousEnv, within_reach: bool = False) -> str | None:
    """An instance of the target type with a pixel in the current segmentation (privileged), if any; with
    `within_reach`, one visible by ALFRED's rule (pixel threshold, 1.5 m)."""
    assert env.world is not None and env.episode is not None
    object_type = getattr(env.episode.goal, "object_type", None)
    state = env.world.view().state
    shown = env.world.visible_objects() if within_reach else env.world.instance_masks()
    seen = sorted(o for o in shown if o in state.objects and state.objects[o].object_type == object_type)
    return seen[0] if seen else None


def make_policy(name: str, env: LuminousEnv, seed: int) -> Policy:
    """A fresh policy for one episode."""
    rng = np.random.default_rng(seed)
    nav = [env.actions.index(a) for a in NAVIGATION]
    stop = env.actions.index(STOP)
    if name == "random":
        return lambda e, _: int(rng.integers(e.action_space.n))
    if name == "walk-stop":
        stop_at = int(rng.integers(1, env.config.max_steps + 1))
        steps = [0]

        def walk_stop(e: LuminousEnv, _: Any) -> Any:
            steps[0] += 1
            return stop if steps[0] >= stop_at else nav[int(rng.integers(len(nav)))]
        return walk_stop
    if name in ("walk-seg", "walk-seg-near"):
        def walk_seg(e: LuminousEnv, _: Any) -> Any:
            stops = e.episode is not None and e.episode.goal.stop_to_succeed
            if stops and name == "walk-seg-near":
                assert e.world is not None and e.episode is not None
                met = goal_scores(e.episode.goal, e.world) == e.episode.goal.weights()
                return stop if met else nav[int(rng.integers(len(nav)))]
            oid = _target_in_segmentation(e, within_reach=not stops)
            if oid is None:
                return nav[int(rng.integers(len(nav)))]
            return stop if stops else {"action": "PickupObject", "objectId": oid}
        return walk_seg
    if name == "oracle":
        return lambda e, _: e.expert_action()
    raise ValueError(f"unknown policy {name!r}; expected one of {', '.join(POLICIES)}")


def play(outer: gymnasium.Env, policy: Policy, seed: int) -> dict[str, Any]:
    """One episode from `reset(seed=seed)` of `outer` (a `LuminousEnv`, wrapped or not): its figures."""
    env = outer.unwrapped
    assert isinstance(env, LuminousEnv)
    t = time.perf_counter()
    obs, start = outer.reset(seed=seed)
    reset_s = time.perf_counter() - t
    steps, info, end = 0, start, "step limit"
    while True:
        action = policy(env, obs)
        obs, _, terminated, truncated, info = outer.step(action)
        steps += 1
        if terminated or truncated:
            if info["success"]:
                end = "success"
            elif terminated:
                end = "stop"
            elif info["failures"] >= env.config.max_failures:
                end = "failure limit"
            break
    return {"seed": seed, "success": bool(info["success"]), "spl": float(info["spl"]),
            "soft_spl": float(info["soft_spl"]), "steps": steps, "end": end,
            "path_length": float(info["path_length"]), "shortest_path_length": float(start["shortest_path_length"]),
            "start_distance": float(start["start_distance"]), "room": env.world.scene.room.name if env.world else "",
            "target": getattr(env.episode.goal, "object_type", "") if env.episode else "",
            "reset_s": reset_s, "cross_room": start.get("cross_room")}


def trained_player(env_id: str, folder: Path, seed: int) -> tuple[gymnasium.Env, Policy]:
    """The policy trained in `folder` (or saved in the `.zip` file `folder` names, e.g. a run's
    `model_warm.zip`, beside its run's `config.json`) and the env it plays in (the id with its observation
    options and wrappers)."""
    model_path = folder if folder.suffix == ".zip" else folder / "model.zip"
    folder = model_path.parent
    config = json.loads((folder / "config.json").read_text())
    if config["env_id"] != env_id:
        raise SystemExit(f"{folder}: trained on {config['env_id']}, not {env_id}")
    sys.path.insert(0, str(ROOT / "examples"))
    import train_ppo
    from stable_baselines3 import PPO

    model = PPO.load(model_path, device="cpu")
    model.set_random_seed(seed)
    outer = train_ppo.make_env(env_id, train_ppo.observation_kwargs(config["env_kwargs"]),
                               feedback=config.get("feedback", False), actions=config.get("actions"))
    return outer, lambda e, obs: int(model.predict(obs, deterministic=False)[0])


def summary(rows: list[dict[str, Any]]) -> dict[str, Any]:
    k, n = sum(r["success"] for r in rows), len(rows)
    return {"episodes": n, "successes": k, "sr": k / n if n else 0.0, "sr_ci95": wilson(k, n),
            "spl": float(np.mean([r["spl"] for r in rows])), "spl_ci95": bootstrap([r["spl"] for r in rows]),
            "soft_spl": float(np.mean([r["soft_spl"] for r in rows])),
            "soft_spl_ci95": bootstrap([r["soft_spl"] for r in rows], seed=1),
            "mean_steps": float(np.mean([r["steps"] for r in rows])),
            "ends": dict(Counter(r["end"] for r in rows))}


def distances(rows: list[dict[str, Any]]) -> dict[str, Any]:
    ls = np.array([r["shortest_path_length"] for r in rows])
    ds = np.array([r["start_distance"] for r in rows])
    q = [0, 25, 50, 75, 100]
    return {"shortest_path_length_m": dict(zip(("min", "q25", "median", "q75", "max"),
                                              np.percentile(ls, q).round(2).tolist(), strict=True)),
            "start_distance_m": dict(zip(("min", "q25", "median", "q75", "max"),
                                         np.percentile(ds, q).round(2).tolist(), strict=True)),
            "shortest_path_length_hist_1m": dict(Counter(f"{int(v)}-{int(v) + 1}" for v in ls)),
            "rooms": dict(Counter(r["room"].split("_")[0] for r in rows)),
            "cross_room": dict(Counter(str(r["cross_room"]) for r in rows if r["cross_room"] is not None)),
            "reset_s_median": round(float(np.median([r["reset_s"] for r in rows])), 2)}


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--env", action="append", help=f"an id (repeatable; default {', '.join(ENV_IDS)})")
    p.add_argument("--episodes", type=int, default=50, help="held-out episodes per id (default 50)")
    p.add_argument("--policies", default=",".join(POLICIES))
    p.add_argument("--json", type=Path, help="write every episode and the summaries here")
    p.add_argument("--ppo", action="append", default=[], metavar="NAME=DIR",
                   help="also play the policy trained in DIR (or a model .zip of a run, e.g. DIR/model_warm.zip), "
                        "as policy ppo:NAME (repeatable)")
    args = p.parse_args(argv)
    policies = [x for x in args.policies.split(",") if x]
    trained = dict(item.partition("=")[::2] for item in args.ppo)
    if any(not name or not folder for name, folder in trained.items()):
        p.error("--ppo: expected NAME=DIR")
    print(f"CPU: {cpu_model()}, {os.cpu_count()} cores; load at start: {load()}", flush=True)
    out: dict[str, Any] = {"cpu": cpu_model(), "load_start": load(), "ids": {}}
    for env_id in args.env or ENV_IDS:
        seeds = eval_seeds(env_id)[: args.episodes]
        env = gymnasium.make(env_id).unwrapped
        assert isinstance(env, LuminousEnv)
        players = {f"ppo:{name}": trained_player(env_id, Path(folder), 0) for name, folder in trained.items()}
        rows: dict[str, list[dict[str, Any]]] = {name: [] for name in [*policies, *players]}
        t0, w0 = time.process_time(), time.perf_counter()
        for i, seed in enumerate(seeds):
            for j, name in enumerate(policies):  # all policies on one episode, then the next: its worlds are reused
                rows[name].append(play(env, make_policy(name, env, seed * 16 + j), seed))
            for name, (outer, policy) in players.items():
                rows[name].append(play(outer, policy, seed))
            if (i + 1) % 10 == 0:
                print(f"  {env_id}: {i + 1}/{len(seeds)} episodes, {time.process_time() - t0:.0f} CPU s, "
                      f"load {load()}", flush=True)
        env.close()
        for outer, _ in players.values():
            outer.close()
        result = {"seeds": [seeds[0], seeds[-1]] if seeds else [], "policies": {n: summary(r) for n, r in rows.items()},
                  "distances": distances(next(iter(rows.values()))), "episodes": rows,
                  "cpu_s": time.process_time() - t0,
                  "wall_s": time.perf_counter() - w0}
        out["ids"][env_id] = result
        print(f"\n{env_id} (seeds {seeds[0]}..{seeds[-1]}, {len(seeds)} episodes; {result['cpu_s']:.0f} CPU s, "
              f"{result['wall_s']:.0f} wall s)")
        print("| policy | SR (95% Wilson) | SPL (95% bootstrap) | soft SPL (95% bootstrap) | mean steps | ends |")
        print("|---|---|---|---|---|---|")
        for name, s in result["policies"].items():
            print(f"| {name} | {s['sr']:.2f} ({s['sr_ci95'][0]:.2f}..{s['sr_ci95'][1]:.2f}) | {s['spl']:.3f} "
                  f"({s['spl_ci95'][0]:.3f}..{s['spl_ci95'][1]:.3f}) | {s['soft_spl']:.3f} "
                  f"({s['soft_spl_ci95'][0]:.3f}..{s['soft_spl_ci95'][1]:.3f}) | {s['mean_steps']:.1f} | "
                  f"{', '.join(f'{k} {v}' for k, v in sorted(s['ends'].items()))} |")
        print("start distances:", json.dumps(result["distances"]), flush=True)
    out["load_end"] = load()
    print(f"load at end: {out['load_end']}")
    if args.json:
        args.json.write_text(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
