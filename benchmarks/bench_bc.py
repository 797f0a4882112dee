"""Behaviour cloning on S+ and U+ (the issue's figure "BC success on S+ and U+"), beside random and the oracle.

    python benchmarks/bench_bc.py                  # 400 demos, 3 training seeds, 200 episodes a split (~25 min)
    python benchmarks/bench_bc.py --demos 400 --eval-episodes 28 --workers 4   # the quick look

1. Oracle demonstrations of the pickup family (`luminous_sim.bc`: pick up a named object in the layouts of
   a split's entries, 64 px, object-slot targets) on S+ entries 28 .. 28+D-1 (the training entries).
2. A `BCPolicy` trained on them per seed (`--seeds`), with the wall time of each training.
3. Each policy on the first N held-out S+ entries (0 .. 27, then those after the training entries: same
   room structures and layouts as training, other entries) and on U+ entries 0 .. N-1 (ALFRED's
   valid_unseen structures, never seen in training): SR, GC, PLW-SR, PLW-GC and SR over all entries
   (`luminous_sim.eval.metrics`), for random, the clone of each
   seed, greedy (and the median and range over seeds), seed 0's clone sampling its actions, and the oracle.
   S+ is also split into the held-out episodes whose task (layout and instruction) no training demo has and
   those whose task a training demo has (another entry drew the same object type in the same layout).
4. Whether the clone's drop from S+ to U+ is more than chance: per seed, Fisher's exact test (one-sided,
   S+ SR > U+ SR); over the seeds, the drop in their mean SR with a 95% bootstrap interval (episodes
   resampled within each split, each episode keeping all seeds' results) and the bootstrap's one-sided p;
   for all held-out S+ episodes, and for those whose task no training demo has.

Everything is kept under --out (default out/bench_bc): demonstrations, checkpoints and one file per played
episode, so a second run reprints the figures without redoing the work (`--fresh` starts over). It writes
results.json and bc_success.png (SR and GC per policy and split; the clone's bar is the median over seeds,
its whisker the range).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.bc import CHECKPOINT_VAR, collect_demos, load_demos, pickup_env, play_pickup, train_bc
from luminous_sim.benchmark import benchmark_entry
from luminous_sim.eval import EpisodeOutcome, Metrics, make_agent, map_local, metrics
from luminous_sim.fileio import write_atomic

SPLITS = ("S+", "U+")
FIRST_TRAINING = 28
CLONE = "luminous_sim.bc:bc_agent"
SAMPLING = "luminous_sim.bc:bc_agent_sampling"
_RUNNERS: dict[tuple[str, str], Any] = {}


def _collect(job: tuple[str, list[int]]) -> dict[str, Any]:
    folder, indices = job
    return collect_demos(Path(folder), "S+", indices)


def _train(job: tuple[str, str, int, int]) -> dict[str, Any]:
    demo_dir, path, seed, epochs = job
    start = time.perf_counter()
    result = train_bc(Path(demo_dir), Path(path), epochs=epochs, seed=seed)
    info = {"seconds": time.perf_counter() - start, "losses": list(result.losses), "accuracy": result.accuracy,
            "samples": result.samples}
    write_atomic(Path(path).with_suffix(".json"), json.dumps(info, indent=1) + "\n")
    return info


def _play(job: tuple[str, str, str, str, int, int, str]) -> dict[str, Any]:
    """One episode (label, policy spec, checkpoint, split, index, seed, outcome file), read back when kept."""
    _label, policy, checkpoint, split, index, seed, path = job
    if Path(path).is_file():
        return json.loads(Path(path).read_text())
    key = (policy, checkpoint)
    if key not in _RUNNERS:
        os.environ[CHECKPOINT_VAR] = checkpoint
        env = pickup_env()
        _RUNNERS[key] = (env, make_agent(policy, env))
    env, agent = _RUNNERS[key]
    start = time.perf_counter()
    outcome = play_pickup(env, agent, split, index, seed).to_dict()
    outcome["seconds"] = time.perf_counter() - start
    write_atomic(Path(path), json.dumps(outcome, indent=1) + "\n")
    return outcome


def held_out(split: str, count: int, training: range) -> list[int]:
    """The first `count` entries of `split` not used for training (S+ skips the training range)."""
    if split != "S+":
        return list(range(count))
    below = list(range(min(count, training.start)))
    return below + list(range(training.stop, training.stop + count - len(below)))


def gap_test(wins: dict[str, list[list[bool]]], repeats: int = 10000, seed: int = 0) -> dict[str, Any]:
    """Is the clone's S+ SR above its U+ SR by more than chance? `wins[split][seed]` lists successes per episode.

    Per seed, Fisher's exact one-sided p; over seeds, the drop in the mean SR with a bootstrap 95% interval
    (episodes resampled within each split; an episode keeps every seed's result) and the share of
    resamples with no drop (a one-sided p).
    """
    import numpy as np
    from scipy.stats import fisher_exact

    seen, unseen = (np.array(wins[split], dtype=float) for split in SPLITS)
    per_seed = []
    for s_row, u_row in zip(seen, unseen, strict=True):
        table = [[int(s_row.sum()), int(len(s_row) - s_row.sum())], [int(u_row.sum()), int(len(u_row) - u_row.sum())]]
        per_seed.append(float(fisher_exact(table, alternative="greater")[1]))
    rng = np.random.default_rng(seed)
    s_mean, u_mean = seen.mean(axis=0), unseen.mean(axis=0)
    drops = (s_mean[rng.integers(0, len(s_mean), (repeats, len(s_mean)))].mean(axis=1)
             - u_mean[rng.integers(0, len(u_mean), (repeats, len(u_mean)))].mean(axis=1))
    return {"drop": float(s_mean.mean() - u_mean.mean()), "ci95": [float(np.quantile(drops, 0.025)),
            float(np.quantile(drops, 0.975))], "p_bootstrap": float((drops <= 0).mean()), "fisher_p": per_seed}


def _row(name: str, m: Metrics) -> str:
    cells = [f"{m.successes}/{m.episodes}"] + [_num(v) for v in (m.sr, m.gc, m.plw_sr, m.plw_gc, m.sr_all)]
    return f"| {name} | " + " | ".join(cells) + " |"


def _num(value: float | None) -> str:
    return "-" if value is None else f"{value:.3f}"


def _spread(values: list[float]) -> str:
    return f"{statistics.median(values):.3f} [{min(values):.3f}, {max(values):.3f}]"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--demos", type=int, default=400, help="training demonstrations (S+ entries from 28)")
    parser.add_argument("--eval-episodes", type=int, default=200,
                        help="held-out episodes per split (default 200: enough to tell a drop of 0.1 SR from chance)")
    parser.add_argument("--seeds", default="0,1,2", help="training seeds (default 0,1,2)")
    parser.add_argument("--epochs", type=int, default=20)
    parser.add_argument("--workers", type=int, default=2, help="local worker processes (default 2)")
    parser.add_argument("--out", type=Path, default=Path("out/bench_bc"))
    parser.add_argument("--fresh", action="store_true", help="discard everything kept and start over")
    args = parser.parse_args()
    if args.fresh and args.out.exists():
        shutil.rmtree(args.out)
    seeds = [int(s) for s in args.seeds.split(",")]
    print(f"load average at start: {os.getloadavg()}; {args.workers} workers")

    demo_dir = args.out / "demos"
    training = list(range(FIRST_TRAINING, FIRST_TRAINING + args.demos))
    evaluated = {split: held_out(split, args.eval_episodes, range(training[0], training[-1] + 1)) for split in SPLITS}
    start = time.perf_counter()
    chunks = [(str(demo_dir), training[k::args.workers]) for k in range(args.workers)]
    summaries = list(map_local(_collect, chunks, args.workers))
    unavailable = sum(len(s["unavailable"]) for s in summaries)
    demos = load_demos(demo_dir)
    demos = [d for d in demos if d.split == "S+" and d.index in set(training)]
    steps, labelled = sum(len(d.actions) for d in demos), sum(d.labelled for d in demos)
    print(f"demos: S+ entries {training[0]}..{training[-1]}: {len(demos)} recorded, {unavailable} unavailable; "
          f"{steps} steps, {labelled} labelled (the rest acted on an object in no slot); "
          f"{time.perf_counter() - start:.0f} s (with those kept from an earlier run)")
    seen_layouts = {(benchmark_entry("S+", i).floor_plan, benchmark_entry("S+", i).layout) for i in training}
    layouts = {(benchmark_entry("S+", i).floor_plan, benchmark_entry("S+", i).layout) for i in evaluated["S+"]}
    print(f"held-out S+ entries {_ranges(evaluated['S+'])}: {len(layouts & seen_layouts)} of their "
          f"{len(layouts)} layouts appear in the training demos (S+: seen layouts, other tasks); "
          "no U+ structure does")

    paths = {seed: args.out / f"bc-seed{seed}.pt" for seed in seeds}
    todo = [(str(demo_dir), str(paths[s]), s, args.epochs) for s in seeds
            if not paths[s].with_suffix(".json").is_file()]
    list(map_local(_train, todo, args.workers))
    trained = {seed: json.loads(paths[seed].with_suffix(".json").read_text()) for seed in seeds}
    for seed, info in trained.items():
        print(f"seed {seed}: {info['samples']} steps x {len(info['losses'])} epochs in {info['seconds']:.0f} s "
              f"(one torch thread, {args.workers} trainings at once), loss {info['losses'][0]:.3f} -> "
              f"{info['losses'][-1]:.3f}, training accuracy {info['accuracy']:.3f}")

    policies = [("random", "random", ""), *((f"bc seed {s}", CLONE, str(paths[s].resolve())) for s in seeds),
                (f"bc seed {seeds[0]} sampling", SAMPLING, str(paths[seeds[0]].resolve())), ("oracle", "oracle", "")]
    jobs = [(label, spec, ckpt, split, i, 0, str(args.out / "outcomes" / label.replace(" ", "-") / f"{split}-{i}.json"))
            for label, spec, ckpt in policies for split in SPLITS for i in evaluated[split]]
    start = time.perf_counter()
    played = list(map_local(_play, jobs, args.workers))
    print(f"played {len(jobs)} episodes in {time.perf_counter() - start:.0f} s")
    outcomes: dict[tuple[str, str], list[EpisodeOutcome]] = {}
    seconds: dict[str, list[float]] = {}
    for job, data in zip(jobs, played, strict=True):
        seconds.setdefault(job[0], []).append(data.pop("seconds", float("nan")))
        outcomes.setdefault((job[0], job[3]), []).append(EpisodeOutcome.from_dict(data))
    table = {key: metrics(v) for key, v in outcomes.items()}

    results: dict[str, Any] = {"demos": len(demos), "training_entries": [training[0], training[-1]],
                               "labelled_steps": labelled, "seeds": seeds, "training": trained,
                               "eval_episodes": args.eval_episodes, "eval_entries": evaluated, "metrics": {}}
    for split in SPLITS:
        print(f"\n### pickup_object on {split}: entries {_ranges(evaluated[split])}\n")
        print("| policy | successes | SR | GC | PLW-SR | PLW-GC | SR all |\n|---|---|---|---|---|---|---|")
        for label, _, _ in policies:
            print(_row(label, table[label, split]))
            results["metrics"][f"{label} {split}"] = table[label, split].to_dict()
        clone = [table[f"bc seed {s}", split] for s in seeds]
        print(f"| bc median [min, max] over {len(seeds)} seeds | | {_spread([m.sr or 0.0 for m in clone])} | "
              f"{_spread([m.gc or 0.0 for m in clone])} | {_spread([m.plw_sr or 0.0 for m in clone])} | "
              f"{_spread([m.plw_gc or 0.0 for m in clone])} | |")
    known = {(benchmark_entry(d.split, d.index).floor_plan, benchmark_entry(d.split, d.index).layout, d.instruction)
             for d in demos}
    repeated = {o.index for o in outcomes["oracle", "S+"] if (o.floor_plan, o.layout, o.instruction) in known}
    print(f"\n### S+ held-out episodes by whether a training demo has their task: {len(repeated)} of "
          f"{args.eval_episodes} do (entries {sorted(repeated)})\n")
    print("| policy | new-task successes | new-task SR | repeated-task successes | repeated-task SR |\n"
          "|---|---|---|---|---|")
    for label, _, _ in policies:
        new = metrics(o for o in outcomes[label, "S+"] if o.index not in repeated)
        old = metrics(o for o in outcomes[label, "S+"] if o.index in repeated)
        results["metrics"][f"{label} S+ new tasks"] = new.to_dict()
        results["metrics"][f"{label} S+ repeated tasks"] = old.to_dict()
        print(f"| {label} | {new.successes}/{new.episodes} | {_num(new.sr)} | {old.successes}/{old.episodes} | "
              f"{_num(old.sr)} |")
    drop = [(table[f"bc seed {s}", "S+"].sr or 0.0) - (table[f"bc seed {s}", "U+"].sr or 0.0) for s in seeds]
    print(f"\nclone SR drop S+ -> U+ per seed: {[round(d, 3) for d in drop]} (median {statistics.median(drop):.3f})")
    for name, kept in (("all held-out S+ episodes", lambda o: True),
                       ("S+ episodes whose task no training demo has", lambda o: o.index not in repeated)):
        wins = {split: [[o.success for o in outcomes[f"bc seed {s}", split]
                         if o.end != "unavailable" and (split != "S+" or kept(o))] for s in seeds] for split in SPLITS}
        gap = gap_test(wins)
        print(f"{name} ({len(wins['S+'][0])}) against U+ ({len(wins['U+'][0])}): Fisher's exact one-sided p per "
              f"seed (S+ SR > U+ SR) {[round(p, 4) for p in gap['fisher_p']]}; drop in the mean SR over seeds "
              f"{gap['drop']:.3f}, 95% bootstrap interval [{gap['ci95'][0]:.3f}, {gap['ci95'][1]:.3f}], "
              f"bootstrap p (no drop) {gap['p_bootstrap']:.4f}")
        results["gap" if name.startswith("all") else "gap_new_tasks"] = gap
    for label, _, _ in policies:
        for split in SPLITS:
            ends: dict[str, int] = {}
            for o in outcomes[label, split]:
                ends[o.end] = ends.get(o.end, 0) + 1
            print(f"{label} {split} ends: {dict(sorted(ends.items()))}")
        times = [t for t in seconds[label] if t == t]
        if times:
            print(f"{label}: s/episode (as played, under this load) median {statistics.median(times):.1f} "
                  f"range {min(times):.1f}..{max(times):.1f}")
    results["sr_drop"] = drop
    write_atomic(args.out / "results.json", json.dumps(results, indent=1) + "\n")
    print(f"wrote {args.out / 'results.json'} and {_plot(table, seeds, args.out / 'bc_success.png')}")
    print(f"load average at end: {os.getloadavg()}")
    return 0


def _ranges(indices: list[int]) -> str:
    """`0..27, 428..599` for a sorted list of integers."""
    runs: list[list[int]] = []
    for i in indices:
        if runs and i == runs[-1][1] + 1:
            runs[-1][1] = i
        else:
            runs.append([i, i])
    return ", ".join(f"{a}..{b}" if a != b else str(a) for a, b in runs)


def _plot(table: dict[tuple[str, str], Metrics], seeds: list[int], path: Path) -> Path:
    import io

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    names = ["random", "bc", "oracle"]
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8), sharey=True)
    x = np.arange(len(names))
    for ax, key, title in zip(axes, ("sr", "gc"), ("Success rate (SR)", "Goal conditions (GC)"), strict=True):
        for k, split in enumerate(SPLITS):
            heights, low, high = [], [], []
            for name in names:
                labels = [f"bc seed {s}" for s in seeds] if name == "bc" else [name]
                values = [getattr(table[label, split], key) or 0.0 for label in labels]
                mid = statistics.median(values)
                heights.append(mid)
                low.append(mid - min(values))
                high.append(max(values) - mid)
            ax.bar(x + (k - 0.5) * 0.38, heights, 0.38, yerr=[low, high], capsize=3, label=split)
        ax.set_xticks(x, ["random", f"BC (median, {len(seeds)} seeds)", "oracle"])
        ax.set_ylim(0, 1.05)
        ax.set_title(f"pickup_object: {title}")
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_ylabel("fraction")
    axes[0].legend(frameon=False)
    fig.tight_layout()
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=110)
    plt.close(fig)
    write_atomic(path, buffer.getvalue())
    return path


if __name__ == "__main__":
    sys.exit(main())
