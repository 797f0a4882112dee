"""The modular agent in the paper's Table 4 protocol (issue 43): SR per ALFRED task type and their average, then
GC, PLW-SR and PLW-GC, each with a 95% interval, on S (ALFRED's valid_seen designs re-solved in their own floor
plans, a `luminous dataset build --from-alfred` folder), S+ and U+ (the frozen splits), in the privileged track
(the simulator's depth and segmentation) or, with `--track rgb`, the rgb track (depth and types predicted from
RGB by the shipped perception network, `modular_rgb`; perception also scored on a sample of the agent's own
frames against the simulator's labels), over the agent's seeds (its parser's training seed and its search's),
with the ablations (task parameters given instead of parsed; the directive without the step instructions), an
error breakdown per type as FILM and HLSM report it, the difference S -> S+ per type, and the paper's rows beside
ours (figures from another simulator, quoted as the paper's).

    python benchmarks/bench_agents.py --per-type 2 --seeds 0 1 2 --parsers DIR --s-data S_BUILD --workers 2 \
        --out out/bench_agents

Each episode is played through the evaluation's own `play` (the agent reads `tracks.agent_info` only) and its
row is written to OUT/rows/ as it finishes: a stopped run resumes. `--per-type N` plays the first N entries of
each type of each split (a fixed, stated sample; never a chosen subset); 0 plays every entry.
Figures: docs/benchmarks.md, "The modular agent (bench_agents.py)".
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import sys
import time
from collections import Counter, defaultdict
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.benchmark import benchmark_entry, benchmark_size
from luminous_sim.eval import EpisodeOutcome
from luminous_sim.eval.report import TABLE4_ROWS
from luminous_sim.eval.workers import map_local
from luminous_sim.fileio import write_atomic

VARIANTS = ("parsed", "given", "no-steps")
"""parsed: the reference agent (directive and steps parsed); given: the task's type and `pddl_params` given to
it (what the parser costs); no-steps: the directive parsed alone (what the step instructions add)."""
PAPER_SR: dict[str, dict[str, tuple[float, float, float, float]]] = {
    "MOCA": {"Pick": (.295, .131, .005, .429), "Cool": (.261, .000, .070, .000), "Stack": (.052, .000, .018, .000),
             "Heat": (.158, .000, .027, .000), "Clean": (.223, .000, .024, .000),
             "Examine": (.202, .000, .132, .000), "Pick Two": (.112, .011, .011, .000),
             "Average": (.186, .022, .038, .021)},
    "ET": {"Pick": (.500, .227, .040, .381), "Cool": (.532, .035, .010, .018), "Stack": (.296, .025, .028, .000),
           "Heat": (.458, .000, .074, .000), "Clean": (.482, .129, .170, .109), "Examine": (.426, .072, .070, .034),
           "Pick Two": (.419, .034, .051, .000), "Average": (.448, .078, .066, .048)},
    "HiTUT": {"Pick": (.359, .314, .260, .259), "Cool": (.190, .035, .046, .034), "Stack": (.122, .065, .073, .038),
              "Heat": (.140, .061, .119, .000), "Clean": (.500, .229, .212, .232),
              "Examine": (.266, .173, .081, .067), "Pick Two": (.177, .096, .124, .111),
              "Average": (.252, .147, .124, .090)},
}
"""The paper's Table 4 (SR on S, S+, U, U+), measured in AI2-THOR: quoted, never compared as if like with like."""
CAUSES = ("misparsed", "not_found", "interaction", "plan_done", "limit")
"""Why a failed episode failed, the first that applies: the instruction misparsed (type or a slot); ALFRED's
step or failure limit; the current subgoal's target never seen; seen but not acted on (out of reach, or its
interaction failed); every subgoal done and the goal still unmet."""
RESAMPLES = 2000


@dataclass(frozen=True)
class Job:
    split: str
    index: int
    variant: str
    seed: int
    trial: str = ""
    parser: str = ""
    track: str = "privileged"


ENV_OVERRIDES: dict[str, Any] = {}
"""Env options over the evaluation's (for quick checks, e.g. a lower `max_steps`; none in a measured run)."""
SCORED_EVERY = 5
"""In the rgb track, every fifth of the agent's frames is scored against the simulator's labels."""


def _row_path(out: Path, job: Job) -> Path:
    track = "" if job.track == "privileged" else f"-{job.track}"
    return out / "rows" / f"{job.split}-{job.index}-{job.variant}-{job.seed}{track}.json"


_CACHE: dict[str, Any] = {}


def play_job(args: tuple[Job, str]) -> dict[str, Any]:
    """One episode of the agent (a worker's job): its outcome, diagnosis and the truth it is judged by."""
    job, out = args
    path = _row_path(Path(out), job)
    if path.exists():
        return json.loads(path.read_text())
    from luminous_sim.agents import AgentSettings, InstructionParser, ModularAgent, default_parser
    from luminous_sim.env import LuminousEnv
    from luminous_sim.eval.evaluator import EVAL_ENV, play
    from luminous_sim.eval.tracks import track_env

    key = f"env {sorted(ENV_OVERRIDES.items())}"
    if key not in _CACHE:  # the rgb track's agent is handed the frame's rgb only (below); the labels score it
        _CACHE[key] = LuminousEnv(**track_env("privileged", {**EVAL_ENV, **ENV_OVERRIDES}))
    env = _CACHE[key]
    parser = _CACHE.setdefault(job.parser, InstructionParser.load(Path(job.parser)) if job.parser else default_parser())
    truth = _truth(job)
    settings = AgentSettings(use_steps=job.variant != "no-steps", given_task=truth if job.variant == "given" else None)
    perception = None
    if job.track == "rgb":
        import torch

        from luminous_sim.agents import PerceptionScores, default_perception

        torch.set_num_threads(1)  # one worker a core

        perception = default_perception()
        scores = PerceptionScores()
    agent = ModularAgent(300, 300, parser=parser, settings=settings, perception=perception)
    acting = [0.0, 0]
    act = agent.act

    def timed(observation: dict[str, Any], info: dict[str, Any]) -> Any:
        if perception is not None:
            if acting[1] % SCORED_EVERY == 0:
                types, depth = perception.predict(observation["rgb"])
                scores.add(_room_type(job), types, observation["instance_types"], depth, observation["depth"][..., 0])
            observation = {k: v for k, v in observation.items() if k in ("rgb", "instruction")}
        t = time.process_time()
        try:
            return act(observation, info)
        finally:
            acting[0] += time.process_time() - t
            acting[1] += 1

    agent.act = timed  # type: ignore[method-assign]
    start = time.perf_counter()
    try:
        outcome = play(env, agent, job.split, job.index, job.seed, trial=job.trial)
    finally:
        env.close()
    row = {"job": asdict(job), "outcome": outcome.to_dict(), "diagnosis": agent.diagnosis() if outcome.drawn else {},
           "truth": truth, "seconds": round(time.perf_counter() - start, 2),
           "act_cpu_s": round(acting[0], 3), "acts": acting[1]}
    if perception is not None:
        row["perception"] = scores.to_counts()
    write_atomic(path, json.dumps(row, indent=1) + "\n")
    return row


def _truth(job: Job) -> dict[str, Any]:
    if job.trial:
        data = json.loads((Path(job.trial) / "traj_data.json").read_text())
        return {"task_type": data["task_type"], "pddl_params": data["pddl_params"]}
    entry = benchmark_entry(job.split, job.index)
    return {"task_type": entry.task_type, "pddl_params": dict(entry.pddl_params)}


def _room_type(job: Job) -> str:
    if job.trial:
        from luminous_sim.rooms import scene_room_type

        data = json.loads((Path(job.trial) / "traj_data.json").read_text())
        return scene_room_type(int(data["scene"]["floor_plan"].removeprefix("FloorPlan")))
    return benchmark_entry(job.split, job.index).room_type


def agent_frame_scores(results: dict[tuple[str, str], list[dict[str, Any]]]) -> dict[str, Any]:
    """Perception's scores on the rgb-track agent's own frames (the sampled ones), per split and room type."""
    from luminous_sim.agents import PerceptionScores

    out: dict[str, Any] = {}
    for (split, _), rows in sorted(results.items()):
        scores = PerceptionScores()
        for row in rows:
            scores.add_counts(row.get("perception", {}))
        if scores.rooms:
            out[split] = scores.summary()
    return out


def _sample(split: str, per_type: int) -> list[int]:
    chosen: dict[str, list[int]] = defaultdict(list)
    for i in range(benchmark_size(split)):
        t = benchmark_entry(split, i).task_type
        if per_type == 0 or len(chosen[t]) < per_type:
            chosen[t].append(i)
    return sorted(i for v in chosen.values() for i in v)


def _s_sample(data: Path, per_type: int) -> list[tuple[int, str, str]]:
    from luminous_sim.eval.trials import list_trials

    chosen: dict[str, list[tuple[int, str, str]]] = defaultdict(list)
    for ref in list_trials(data):
        if ref.unbuilt or ref.broken:
            task_type = (ref.named or ("?",))[0]
            path = ""
        else:
            task_type = json.loads((ref.path / "traj_data.json").read_text())["task_type"]
            path = str(ref.path)
        if per_type == 0 or len(chosen[task_type]) < per_type:
            chosen[task_type].append((ref.index, ref.split, path))
    return sorted(x for v in chosen.values() for x in v)


def build_s(alfred_split: Path, out: Path, workers: int) -> None:
    """`luminous dataset build --from-alfred` of an ALFRED split into `out` (what is built already is kept)."""
    from luminous_sim.cli.main import main as luminous

    code = luminous(["dataset", "build", "--from-alfred", str(alfred_split), "--out", str(out), "--no-frames",
                     "--no-video", "--no-progress", "--workers", str(workers)])
    if code:
        raise SystemExit(f"building S from {alfred_split} into {out} failed (exit {code})")


def cause(row: dict[str, Any]) -> str:
    """The first cause that applies to a failed episode (`CAUSES`)."""
    o, d, truth = row["outcome"], row["diagnosis"], row["truth"]
    if not d:
        return "unavailable"
    task = d["task"]
    slots = ("object_target", "parent_target", "mrecep_target", "toggle_target", "object_sliced")
    if task["task_type"] != truth["task_type"] or any(
            task["pddl_params"].get(s) != truth["pddl_params"].get(s) for s in slots):
        return "misparsed"
    if o["end"] in ("max_steps", "max_failures"):
        return "limit"
    if d["subgoal"] >= d["subgoals"]:
        return "plan_done"
    return "interaction" if d["target_seen"] else "not_found"


def _outcome(row: dict[str, Any]) -> EpisodeOutcome:
    return EpisodeOutcome.from_dict(row["outcome"])


def _interval(values: list[np.ndarray], rng: np.random.Generator) -> tuple[float, float]:
    """A 95% percentile-bootstrap interval of the mean over groups of the groups' means (groups resampled each
    within itself: the task types)."""
    draws = np.array([np.mean([v[rng.integers(0, len(v), len(v))].mean() for v in values]) for _ in range(RESAMPLES)])
    return float(np.percentile(draws, 2.5)), float(np.percentile(draws, 97.5))


def per_episode(rows: list[dict[str, Any]], key: str) -> dict[str, np.ndarray]:
    """Per task type, each episode's value of one metric (success, goal-condition share, path-weighted), averaged
    over the seeds of one (split, variant); an unavailable entry counts 0."""
    by: dict[tuple[str, int], list[float]] = defaultdict(list)
    types: dict[tuple[str, int], str] = {}
    for row in rows:
        o = _outcome(row)
        value = 0.0
        if o.drawn:
            gc = o.goal_conditions[0] / o.goal_conditions[1] if o.goal_conditions[1] else 0.0
            value = {"sr": float(o.success), "gc": gc, "plw_sr": float(o.success) * o.path_weight,
                     "plw_gc": gc * o.path_weight}[key]
        by[(o.split, o.index)].append(value)
        types[(o.split, o.index)] = o.task_type
    out: dict[str, list[float]] = defaultdict(list)
    for k, v in sorted(by.items()):
        out[types[k]].append(float(np.mean(v)))
    return {t: np.array(v) for t, v in out.items()}


def table(results: dict[tuple[str, str], list[dict[str, Any]]], splits: list[str], variant: str,
          seeds: list[int]) -> tuple[str, dict[str, Any]]:
    """Table 4's layout for one variant: a row per type and the average; per split SR, GC, PLW-SR, PLW-GC,
    each the mean over the seeds with its 95% interval."""
    rng = np.random.default_rng(0)
    summary: dict[str, Any] = {}
    head = ["Task"] + [f"{s} {m}" for s in splits for m in ("n", "SR", "GC", "PLW-SR", "PLW-GC")]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    cells: dict[str, dict[str, list[str]]] = defaultdict(dict)
    for split in splits:
        rows = results.get((split, variant), [])
        if not rows:
            continue
        values = {k: per_episode(rows, k) for k in ("sr", "gc", "plw_sr", "plw_gc")}
        seed_sr = {s: [float(_outcome(r).success) for r in rows if r["job"]["seed"] == s] for s in seeds}
        summary[split] = {"episodes": len({(r["job"]["index"]) for r in rows}),
                          "seeds": {str(s): float(np.mean(v)) if v else None for s, v in seed_sr.items()}}
        for task_type, label in TABLE4_ROWS + (("__average__", "Average"),):
            row = []
            stats: dict[str, Any] = {}
            for k in ("sr", "gc", "plw_sr", "plw_gc"):
                groups = list(values[k].values()) if task_type == "__average__" else (
                    [values[k][task_type]] if task_type in values[k] else [])
                if not groups:
                    row.append("-")
                    continue
                mean = float(np.mean([g.mean() for g in groups]))
                lo, hi = _interval(groups, rng)
                stats[k] = {"mean": mean, "lo": lo, "hi": hi}
                row.append(f"{mean:.3f} [{lo:.2f}, {hi:.2f}]")
            n = sum(len(g) for g in values["sr"].values()) if task_type == "__average__" else len(
                values["sr"].get(task_type, []))
            cells[label][split] = [str(n)] + row
            summary[split][label] = stats
    for _, label in TABLE4_ROWS + (("__average__", "Average"),):
        line = [label]
        for split in splits:
            line += cells[label].get(split, ["-"] * 5)
        lines.append("| " + " | ".join(line) + " |")
    return "\n".join(lines) + "\n", summary


def differences(results: dict[tuple[str, str], list[dict[str, Any]]], pairs: list[tuple[str, str]],
                variant: str) -> tuple[str, dict[str, Any]]:
    """SR(after) - SR(before) per type and on average for each pair (S -> S+), with a 95% bootstrap interval
    (the two samples resampled independently)."""
    rng = np.random.default_rng(1)
    lines, out = [], {}
    for before, after in pairs:
        a = per_episode(results.get((before, variant), []), "sr")
        b = per_episode(results.get((after, variant), []), "sr")
        if not a or not b:
            continue
        lines.append(f"\n{before} -> {after} ({variant}): SR difference, 95% interval")
        lines.append("| Task | " + f"{before} | {after} | difference |\n|---|---|---|---|")
        out[f"{before}->{after}"] = {}
        for task_type, label in TABLE4_ROWS + (("__average__", "Average"),):
            types = [t for t, _ in TABLE4_ROWS if t in a and t in b] if task_type == "__average__" else (
                [task_type] if task_type in a and task_type in b else [])
            if not types:
                continue
            diff = float(np.mean([b[t].mean() for t in types]) - np.mean([a[t].mean() for t in types]))
            draws = [np.mean([b[t][rng.integers(0, len(b[t]), len(b[t]))].mean() for t in types])
                     - np.mean([a[t][rng.integers(0, len(a[t]), len(a[t]))].mean() for t in types])
                     for _ in range(RESAMPLES)]
            lo, hi = float(np.percentile(draws, 2.5)), float(np.percentile(draws, 97.5))
            out[f"{before}->{after}"][label] = {"difference": diff, "lo": lo, "hi": hi}
            lines.append(f"| {label} | {np.mean([a[t].mean() for t in types]):.3f} | "
                         f"{np.mean([b[t].mean() for t in types]):.3f} | {diff:+.3f} [{lo:+.2f}, {hi:+.2f}] |")
    return "\n".join(lines) + "\n", out


def breakdown(results: dict[tuple[str, str], list[dict[str, Any]]], split: str, variant: str) -> str:
    """Failed episodes per type by first cause (`CAUSES`)."""
    rows = [r for r in results.get((split, variant), []) if not r["outcome"]["success"]]
    by: dict[str, Counter[str]] = defaultdict(Counter)
    for r in rows:
        by[r["outcome"]["task_type"]][cause(r)] += 1
    head = ["Task", "failed"] + list(CAUSES) + ["unavailable"]
    lines = [f"\nFailures by first cause, {split} ({variant}, all seeds)", "| " + " | ".join(head) + " |",
             "|" + "---|" * len(head)]
    for task_type, label in TABLE4_ROWS:
        c = by.get(task_type, Counter())
        lines.append("| " + " | ".join([label, str(sum(c.values()))] + [str(c[k]) for k in CAUSES + ("unavailable",)])
                     + " |")
    return "\n".join(lines) + "\n"


def _cpu() -> str:
    try:
        lines = Path("/proc/cpuinfo").read_text().splitlines()
    except OSError:
        return platform.processor() or "?"
    return next((line.split(":", 1)[1].strip() for line in lines if line.startswith("model name")), "?")


def _act_ms(results: dict[tuple[str, str], list[dict[str, Any]]]) -> float | None:
    """The agent's own CPU time per step (ms), over every episode that recorded it."""
    rows = [r for v in results.values() for r in v if r.get("acts")]
    return 1000 * sum(r["act_cpu_s"] for r in rows) / sum(r["acts"] for r in rows) if rows else None


def paper_rows() -> str:
    lines = ["\nThe paper's Table 4 (SR; AI2-THOR, models trained on ALFRED; quoted, not measured here)",
             "| Task | " + " | ".join(f"{m} {s}" for m in PAPER_SR for s in ("S", "S+", "U", "U+")) + " |",
             "|---|" + "---|" * 12]
    for _, label in TABLE4_ROWS + (("", "Average"),):
        lines.append(f"| {label} | " + " | ".join(f"{v:.3f}" for m in PAPER_SR for v in PAPER_SR[m][label]) + " |")
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--splits", nargs="+", default=["S+", "U+"], choices=["S+", "U+"])
    parser.add_argument("--s-data", type=Path, default=None, metavar="DIR",
                        help="a `luminous dataset build --from-alfred .../valid_seen` folder: the S setting")
    parser.add_argument("--s-from", type=Path, default=None, metavar="ALFRED_SPLIT",
                        help="an ALFRED split folder (<task>/<trial>/traj_data.json) to build into --s-data where "
                             "it is missing (the build resumes)")
    parser.add_argument("--per-type", type=int, default=2, help="the first N entries of each type (0: all)")
    parser.add_argument("--seeds", type=int, nargs="+", default=[0])
    parser.add_argument("--parsers", type=Path, default=None, metavar="DIR",
                        help="parser-seed<N>.pt for each seed N > 0 (`luminous agents train-parser --seed N`); "
                             "seed 0 is the shipped parser")
    parser.add_argument("--variants", nargs="+", default=list(VARIANTS), choices=VARIANTS)
    parser.add_argument("--ablation-seeds", type=int, nargs="+", default=[0],
                        help="the seeds the ablations run with (default 0)")
    parser.add_argument("--track", choices=("privileged", "rgb"), default="privileged",
                        help="privileged: the simulator's depth and segmentation; rgb: predicted from RGB")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    (args.out / "rows").mkdir(parents=True, exist_ok=True)
    if args.s_from is not None:
        if args.s_data is None:
            raise SystemExit("--s-from builds into --s-data: give both")
        build_s(args.s_from, args.s_data, args.workers)

    def parser_file(seed: int) -> str:
        if seed == 0:
            return ""
        if args.parsers is None:
            raise SystemExit(f"seed {seed}: give --parsers DIR with parser-seed{seed}.pt")
        path = args.parsers / f"parser-seed{seed}.pt"
        if not path.is_file():
            raise SystemExit(f"{path}: missing (luminous agents train-parser --seed {seed} --out {path})")
        return str(path)

    places: list[tuple[str, int, str]] = []
    if args.s_data is not None:
        places += [("S", i, path) for i, _, path in _s_sample(args.s_data, args.per_type)]
    for split in args.splits:
        places += [(split, i, "") for i in _sample(split, args.per_type)]
    jobs: list[Job] = []  # seed by seed, so that a run stopped early has every variant of its first seeds
    for seed in sorted(set(args.seeds) | set(args.ablation_seeds)):
        for variant in args.variants:
            if seed in (args.seeds if variant == "parsed" else args.ablation_seeds):
                jobs += [Job(split, i, variant, seed, trial, parser_file(seed), args.track)
                         for split, i, trial in places]
    print(f"{len(jobs)} episodes: {len(places)} entries x variants x seeds; CPU {_cpu()}, "
          f"{os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}", file=sys.stderr)
    start = time.perf_counter()
    results: dict[tuple[str, str], list[dict[str, Any]]] = defaultdict(list)
    for k, row in enumerate(map_local(play_job, [(j, str(args.out)) for j in jobs], args.workers)):
        job = row["job"]
        if job["split"] == "S":
            row["outcome"]["split"] = "S"
        results[(job["split"], job["variant"])].append(row)
        print(f"{k + 1}/{len(jobs)} {job['split']} {job['index']} {job['variant']} seed {job['seed']}: "
              f"{row['outcome']['end']}", file=sys.stderr)
    wall = time.perf_counter() - start
    splits = (["S"] if args.s_data is not None else []) + args.splits
    report: dict[str, Any] = {"per_type": args.per_type, "seeds": args.seeds, "wall_s": round(wall, 1),
                              "cpu": _cpu(), "load_end": round(os.getloadavg()[0], 1),
                              "episode_s_median": float(np.median([r["seconds"] for v in results.values()
                                                                   for r in v])),
                              "act_ms_per_step": _act_ms(results),
                              "track": args.track, "tables": {}, "differences": {}}
    text = []
    for variant in args.variants:
        seeds = args.seeds if variant == "parsed" else args.ablation_seeds
        t, summary = table(results, splits, variant, seeds)
        report["tables"][variant] = summary
        text.append(f"\n## {variant} ({args.track} track, seeds {seeds})\n\n{t}")
        for split in splits:
            text.append(breakdown(results, split, variant))
        d, diff = differences(results, [("S", "S+")], variant)
        report["differences"][variant] = diff
        text.append(d)
    if args.track == "rgb":
        report["agent_frames"] = agent_frame_scores(results)
        text.append("\n\nPerception on the agent's own frames (every fifth), per split and room type:\n"
                    + json.dumps(report["agent_frames"], indent=1))
    text.append(paper_rows())
    print("".join(text))
    write_atomic(args.out / "report.json", json.dumps(report, indent=1) + "\n")
    write_atomic(args.out / "report.md", "".join(text))
    print(f"wall {wall:.0f} s; wrote {args.out / 'report.json'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
