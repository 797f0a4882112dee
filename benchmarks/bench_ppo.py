"""PPO learns a small id within a CPU budget: success of the trained policy against two random policies and the
oracle on the same held-out seeds, and the learning curve.

    python benchmarks/bench_ppo.py                                   # 60 CPU-minutes of training, then evaluation
    python benchmarks/bench_ppo.py --cpu-minutes 60 --eval-episodes 100 --png /work/pictures/ppo/curve.png
    python benchmarks/bench_ppo.py --no-train --policies ppo         # evaluate the model in --out again

Trains SB3's PPO (`MultiInputPolicy`: a CNN over the 64x64 `rgb`, the instruction's tokens and the previous
action's feedback) with the example's recipe (`examples/train_ppo.py`) on `Luminous-NavToObject-64-v1` until
the training has used `--cpu-minutes` of CPU time (the trainer and its `--n-envs` env worker processes
together, read from `/proc`: the machine may be shared, so the budget is CPU time, not wall time), or
`--max-steps`. Why that id: its goal (walk until an object of a named type is in view and within 1.5 m) is
met by navigation alone and its dense reward includes ALFRED's navigation reward (0.2 per path step gained
toward the expert's go-to location), so a learner gets a signal every step; 64 px keeps a step cheap.

Why a random walk does well there: the episode ends with success the moment an object of the type is
visible within reach (no Stop needed), the goal's type is never one in view at the start, but the expert
needs a median of about 8 steps, and 200 steps are allowed. A uniform random policy over the whole space
mostly tries interactions, which fail, and meets the failure limit (10) within a few dozen steps; a random
walk over the five navigation actions fails only on walls and look limits, and wanders into the object in
about half the episodes before its 10th failure. The trained policy has to beat that walk by avoiding
failures and by walking toward what it is asked to find.

Training (the example's defaults): the failure limit ends a training episode as a termination
(`FailureLimitEnds`), each training scene serves 4 episodes (`SceneRepeat`), rewards are normalised
(`VecNormalize`), the observation has the previous action and whether it failed (`ActionFeedback`).
Evaluation uses the id as registered on the same held-out seeds (`EVAL_SEED0`...) for every policy:
`random` (uniform over the whole action space), `random-nav` (uniform over the five navigation actions),
`oracle` (the expert; every held-out episode is one it solves, so it bounds what is possible) and `ppo`
(the trained policy, sampling). Each line gives the success rate with its 95% Wilson interval, mean return
and length, and how episodes ended. One training run (one seed): the spread shown is the evaluation's
interval, not a spread over training seeds. Prints the machine load at the start and the end.

Writes under `--out`: the example's files (`model.zip`, `curve.csv`, `progress.json`, `config.json`),
`bench.json` (policies evaluated earlier on the same seeds are kept unless evaluated again) and the curve
PNG (`--png`, default `curve.png` in `--out`: training success and return against timesteps, the evaluated
rates as dashed lines).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT), str(ROOT / "examples")]

import train_ppo  # noqa: E402  (examples/train_ppo.py)

from luminous_sim.fileio import write_atomic  # noqa: E402

ENV_ID = "Luminous-NavToObject-64-v1"
POLICIES = ("random", "random-nav", "oracle", "ppo")


def _print_summary(name: str, s: dict[str, Any], seconds: float) -> None:
    print(f"{name:>10}: success {s['success_rate']:.3f} (95% CI {s['ci95'][0]:.3f}..{s['ci95'][1]:.3f}, "
          f"{s['successes']}/{s['episodes']}), mean return {s['mean_return']:.2f}, mean length "
          f"{s['mean_length']:.1f}, ends {s.get('ends', {})}  [{seconds:.0f} s CPU]", flush=True)


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--env", default=ENV_ID, help=f"a registered id (default {ENV_ID})")
    p.add_argument("--cpu-minutes", type=float, default=60.0,
                   help="training CPU budget, all its processes together (default 60)")
    p.add_argument("--max-steps", type=int, default=2_000_000, help="stop training here if the budget lasts")
    p.add_argument("--n-envs", type=int, default=2, help="training env processes (default 2)")
    p.add_argument("--eval-episodes", type=int, default=100, help="held-out episodes per policy (default 100)")
    p.add_argument("--policies", default=",".join(POLICIES),
                   help=f"policies to evaluate (default {','.join(POLICIES)})")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--ppo", action="append", default=[], metavar="NAME=VALUE",
                   help=f"PPO option ({train_ppo.PPO_DEFAULTS})")
    p.add_argument("--out", type=Path, default=ROOT / "out" / "bench_ppo")
    p.add_argument("--png", type=Path, default=None, help="where to write the curve (default OUT/curve.png)")
    p.add_argument("--resume", action="store_true", help="go on from the model in --out (the CPU budget counts "
                                                         "the earlier runs too)")
    p.add_argument("--no-train", action="store_true", help="evaluate the model in --out as it is")
    p.add_argument("--actions", default="navigation", choices=tuple(train_ppo.ACTION_SETS),
                   help="the agent's actions: the five navigation ones (default), those and Stop (objectnav) or "
                        "the env's whole space")
    p.add_argument("--new-place-bonus", type=float, default=train_ppo.NEW_PLACE_BONUS,
                   help=f"training reward per grid position first stood on (default {train_ppo.NEW_PLACE_BONUS}; "
                        "0: none)")
    p.add_argument("--env-kwarg", action="append", default=[], metavar="NAME=VALUE",
                   help=f"training env option (repeatable; on top of {train_ppo.TRAIN_KWARGS}); the observation "
                        "options among them are used in evaluation too")
    train_ppo.add_recipe_arguments(p)
    args = p.parse_args(argv)
    policies = [x for x in args.policies.split(",") if x]
    bad = [x for x in policies if x not in POLICIES]
    if bad or args.eval_episodes < 1 or args.n_envs < 1 or args.cpu_minutes <= 0:
        p.error(f"--policies: some of {', '.join(POLICIES)} (got {bad}); --eval-episodes, --n-envs and "
                "--cpu-minutes must be positive")

    print(f"load average at start: {os.getloadavg()}  cores: {os.cpu_count()}", flush=True)
    from stable_baselines3 import PPO

    t0 = time.perf_counter()
    if args.no_train:
        model = PPO.load(args.out / "model.zip", device="cpu")
    else:
        model = train_ppo.train(args.env, args.out, args.max_steps, seed=args.seed, n_envs=args.n_envs,
                                ppo_kwargs=train_ppo._kwargs(args.ppo), cpu_budget_s=args.cpu_minutes * 60,
                                resume=args.resume, save_every=2000, actions=train_ppo.ACTION_SETS[args.actions],
                                env_kwargs={**train_ppo.TRAIN_KWARGS, **train_ppo._kwargs(args.env_kwarg)},
                                new_place_bonus=args.new_place_bonus, **train_ppo.recipe_kwargs(args))
    wall = time.perf_counter() - t0
    progress = json.loads((args.out / "progress.json").read_text())
    config = json.loads((args.out / "config.json").read_text())
    rows = train_ppo.read_curve(args.out / "curve.csv")
    cpu_min = progress["cpu_seconds"] / 60
    print(f"trained {model.num_timesteps} timesteps, {len(rows)} episodes, {cpu_min:.1f} CPU-minutes "
          f"({model.num_timesteps / max(progress['cpu_seconds'], 1e-9):.1f} steps per CPU-second; this call "
          f"{wall / 60:.1f} wall minutes)", flush=True)

    seeds = list(range(train_ppo.EVAL_SEED0, train_ppo.EVAL_SEED0 + args.eval_episodes))
    bench_path = args.out / "bench.json"
    earlier = json.loads(bench_path.read_text()) if bench_path.exists() else {}
    summary = dict(earlier.get("eval", {})) if earlier.get("eval_seeds") == [seeds[0], seeds[-1]] else {}
    makers = {"random": lambda: train_ppo.random_policy(args.seed),
              "random-nav": lambda: train_ppo.random_nav_policy(args.seed),
              "oracle": train_ppo.oracle_policy, "ppo": lambda: train_ppo.model_policy(model, args.seed)}
    for name in policies:
        t = time.process_time()
        seen = train_ppo.observation_kwargs(config["env_kwargs"]) if name == "ppo" else {}
        outcomes = train_ppo.run_episodes(makers[name](), args.env, seeds, seen,
                                          feedback=name == "ppo" and config.get("feedback", False),
                                          actions=config.get("actions") if name == "ppo" else None)
        summary[name] = train_ppo.success_summary(outcomes)
        _print_summary(name, summary[name], time.process_time() - t)
    for name in POLICIES:
        if name in summary and name not in policies:
            _print_summary(f"({name})", summary[name], 0.0)

    quarter = max(1, len(rows) // 4)
    first, last = rows[:quarter], rows[-quarter:]
    success = {name: [r["success"] for r in part] for name, part in (("first", first), ("last", last))}
    report = {"env_id": args.env, "cpu_minutes_budget": args.cpu_minutes, "cpu_minutes": round(cpu_min, 2),
              "timesteps": int(model.num_timesteps), "training_episodes": len(rows), "n_envs": config["n_envs"],
              "ppo": config["ppo"], "actions": config.get("actions"), "eval_seeds": [seeds[0], seeds[-1]],
              "eval": summary,
              "training_success_first_quarter": round(float(np.mean(success["first"])), 4) if rows else None,
              "training_success_last_quarter": round(float(np.mean(success["last"])), 4) if rows else None,
              "load_average_end": os.getloadavg()}
    write_atomic(bench_path, json.dumps(report, indent=2) + "\n")
    png = args.png or args.out / "curve.png"
    png.parent.mkdir(parents=True, exist_ok=True)
    train_ppo.plot_curve(rows, png, references={f"{k} (held-out eval)": v["success_rate"] for k, v in summary.items()},
                         title=f"PPO on {args.env}: {model.num_timesteps} steps, {cpu_min:.0f} CPU-minutes, "
                               f"{config['n_envs']} envs")
    if rows:
        print(f"training success, first quarter of episodes {report['training_success_first_quarter']:.3f}, "
              f"last quarter {report['training_success_last_quarter']:.3f}")
    print(f"load average at end: {os.getloadavg()}")
    print(f"wrote {bench_path} and {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
