"""`luminous eval`: a policy on the trials of a built dataset (`--data`), of the canonical build of a frozen
split (`--split`, built where missing), or on a split's entries played live (`--live`), with ALFRED's metrics
(see luminous_sim.eval)."""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from pathlib import Path
from typing import TYPE_CHECKING

from luminous_sim.cli.args import int_range, output_dir, seed
from luminous_sim.data.backends import BACKENDS
from luminous_sim.fileio import one_line
from luminous_sim.limits import MAX_AGENT_MEMORY_MB, MAX_EVAL_EPISODES, MAX_STEP_TIMEOUT_S, MAX_WORKERS

if TYPE_CHECKING:
    from luminous_sim.eval import AgentCrashed, EvalReport

SPLITS: tuple[str, ...] = ("S+", "U+", "U+test")
TRACKS: tuple[str, ...] = ("rgb", "privileged")
"""`luminous_sim.eval.tracks.TRACKS` (kept here so that `luminous --help` imports no simulator; a test keeps the
two in step)."""
"""The split names (`luminous_sim.splits.PLUS_SPLITS`; a test keeps the two in step)."""
DEFAULT_STEP_TIMEOUT, DEFAULT_AGENT_MEMORY_MB, MIN_AGENT_MEMORY_MB = 10.0, 16384, 1024
"""`luminous_sim.eval.sandbox`'s (kept here so that `luminous --help` imports no simulator; a test keeps them in
step)."""


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser(
        "eval", help="run a policy on S+/U+ (or a built dataset's trials): SR, GC, PLW-SR, PLW-GC per task type",
        description="Evaluate a policy with ALFRED's limits (1000 steps, 10 failed actions) as ALFRED's evaluation "
                    "does: over the trials of a built dataset (--data DIR, each restored from its traj_data.json "
                    "and sidecar), or over the canonical build of a frozen split (--split S+|U+: built into "
                    "--build, default $LUMINOUS_CACHE/benchmark-v1 or ~/.cache/luminous/benchmark-v1, where "
                    "missing, resumable). The oracle replays each trial's recorded actions through the agent "
                    "interface. --live plays the split's entries in the env instead (the oracle then replans "
                    "live). Writes report.json, table.md (the paper's Table 4 layout), metrics.png and one file "
                    "per episode (an interrupted run resumes in the same folder).")
    parser.add_argument("--policy", required=True, metavar="POLICY",
                        help="oracle, random, or MODULE:CALLABLE, a factory of your agent (docs/evaluation.md)")
    parser.add_argument("--split", choices=SPLITS, default=None,
                        help="the frozen split (with --data: only that split's trials)")
    parser.add_argument("--data", type=Path, default=None, metavar="DIR",
                        help="a built dataset folder (`luminous dataset build` output) to evaluate on")
    parser.add_argument("--build", type=output_dir, default=None, metavar="DIR",
                        help="where the canonical build of --split is kept (default: the cache folder)")
    parser.add_argument("--rebuild", action="store_true",
                        help="build the asked entries of the canonical build (or --build) again from scratch")
    parser.add_argument("--live", action="store_true",
                        help="play the split's entries live in the env (no build; the oracle replans live)")
    parser.add_argument("--episodes", type=int_range(1, MAX_EVAL_EPISODES), default=None, metavar="N",
                        help=f"the first N episodes (trials) only (default all; at most {MAX_EVAL_EPISODES})")
    parser.add_argument("--out", type=output_dir, required=True,
                        help="output folder: new, empty, or one this same evaluation was run in (it resumes)")
    parser.add_argument("--workers", type=int_range(1, MAX_WORKERS), default=1,
                        help=f"worker processes, or Ray CPUs of a local cluster (default 1; at most {MAX_WORKERS})")
    parser.add_argument("--backend", choices=BACKENDS, default="local",
                        help="local processes, or Ray tasks (needs luminous-sim[cluster]); the same outcomes "
                             "either way (default local)")
    parser.add_argument("--address", default=None,
                        help="a running Ray cluster's address (ray backend; default: start a local cluster of "
                             "WORKERS CPUs). Every node needs luminous_sim and your agent's module installed")
    parser.add_argument("--seed", type=seed, default=0, help="seed of the agents' randomness (default 0)")
    parser.add_argument("--step-timeout", type=positive_seconds, default=DEFAULT_STEP_TIMEOUT, metavar="SECONDS",
                        help="time limit of each reset() or act() call of your agent; a call over it ends its "
                             f"episode as agent_timeout, a failure (default {DEFAULT_STEP_TIMEOUT:g})")
    parser.add_argument("--agent-memory", default=DEFAULT_AGENT_MEMORY_MB,
                        type=int_range(MIN_AGENT_MEMORY_MB, MAX_AGENT_MEMORY_MB, "MAX_AGENT_MEMORY_MB"),
                        metavar="MB", help="memory limit (address space, MiB) of your agent's process; going past "
                                       f"it stops the evaluation (default {DEFAULT_AGENT_MEMORY_MB})")
    parser.add_argument("--track", choices=TRACKS, default="rgb",
                        help="rgb: ALFRED's rules (RGB and language in; the default); privileged: with the "
                             "simulator's depth, instance segmentation and instance types (docs/evaluation.md)")
    parser.add_argument("--env", type=env_option, action="append", default=[], metavar="KEY=VALUE",
                        help="an env option over ALFRED's (EnvConfig's fields; VALUE as JSON, else a string), "
                             "e.g. --env width=64 --env targets=objects; repeatable")
    parser.add_argument("--mode", choices=("embodied", "text"), default="embodied",
                        help="embodied (default), or text: a language-model agent's act(observation, admissible) -> "
                             "command over the split's text games (Luminous-Text-v0; --policy MODULE:CALLABLE, expert "
                             "or random; no track: its own column; docs/text.md)")
    parser.set_defaults(func=_run)


def positive_seconds(text: str) -> float:
    """A finite number of seconds above 0."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of seconds, got {text!r}") from None
    if not math.isfinite(value) or value <= 0 or value > MAX_STEP_TIMEOUT_S:
        raise argparse.ArgumentTypeError(f"expected a number of seconds above 0 and at most {MAX_STEP_TIMEOUT_S:g} "
                                         f"(luminous_sim.limits.MAX_STEP_TIMEOUT_S), got {text!r}")
    return value


def env_option(text: str) -> tuple[str, object]:
    """KEY=VALUE with VALUE read as JSON (a number, true, a list) or else kept as a string."""
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    try:
        return key, json.loads(value)
    except json.JSONDecodeError:
        return key, value


def _run(args: argparse.Namespace) -> int:
    from luminous_sim.data import Backend, make_backend
    from luminous_sim.errors import LuminousError
    from luminous_sim.eval import (
        AgentCrashed,
        AgentLimits,
        EpisodeOutcome,
        check_policy,
        evaluate,
        evaluate_data,
        markdown_table,
        write_reports,
    )

    if os.getcwd() not in sys.path:  # MODULE may be a file in the current folder, as with `python -m`
        sys.path.insert(0, os.getcwd())
    limits = AgentLimits(step_timeout=args.step_timeout, memory_mb=args.agent_memory)
    if args.mode == "text":
        return _run_text(args, limits)
    try:
        check_policy(args.policy, limits)  # a bad spec fails here, before any episode (the module imported in a child)
    except AgentCrashed as exc:
        return _crashed(exc, Path(args.out))
    if args.backend == "local" and args.address:
        raise LuminousError(f"--address {args.address} is for the ray backend, not local")

    def show(o: EpisodeOutcome) -> None:
        what = o.end if o.drawn else f"unavailable ({o.cause})"
        gc = f"{o.goal_conditions[0]}/{o.goal_conditions[1]}" if o.drawn else "-"
        why = "" if o.drawn or not o.detail else f"  {one_line(o.detail, 200)}"
        print(f"{o.split} {o.index:4d} {o.task_type:<34} {what:<22} gc {gc:<5} steps {o.steps:4d} "
              f"expert {o.expert_length:4d}{why}", file=sys.stderr)

    if args.data is None and args.split is None:
        raise LuminousError("give --split (a frozen split) or --data (a built dataset folder)")
    if args.data is not None and (args.build is not None or args.live or args.rebuild):
        raise LuminousError("--data evaluates the folder it names; leave out --build, --rebuild and --live")
    if args.live and (args.build is not None or args.rebuild):
        raise LuminousError("--live plays the split's entries without a build; leave out --build and --rebuild")

    def run(backend: Backend | None) -> EvalReport:
        common = {"seed": args.seed, "workers": args.workers, "out_dir": Path(args.out), "progress": show,
                  "env_kwargs": dict(args.env), "backend": backend, "limits": limits, "track": args.track}
        if args.live:
            from luminous_sim.benchmark import benchmark_size

            return evaluate(args.policy, args.split, args.episodes or benchmark_size(args.split), **common)
        data = args.data
        if data is None:
            data = _canonical_build(args, backend)
        return evaluate_data(args.policy, Path(data), split=args.split, episodes=args.episodes, **common)

    try:
        if args.backend == "local":
            report = run(None)
        else:  # a local Ray cluster's workers inherit PYTHONPATH: the current folder's agent module too
            os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (os.getcwd(), os.environ.get("PYTHONPATH")) if p)
            with make_backend(args.backend, args.workers, args.address) as backend:
                report = run(backend)
    except AgentCrashed as exc:
        return _crashed(exc, Path(args.out))
    for why in report.replayed:
        print(f"played again (its file was damaged): {why}", file=sys.stderr)
    paths = write_reports(report, Path(args.out))
    print(markdown_table([report]), end="")
    print(f"wrote {paths['json']}, {paths['table']}, {paths['plot']}")
    return _incomplete(report)


def _run_text(args: argparse.Namespace, limits: object) -> int:
    """`--mode text`: the policy over the split's text games; Table 4's rows, won per type."""
    from luminous_sim.benchmark import benchmark_size
    from luminous_sim.errors import LuminousError
    from luminous_sim.eval import AgentCrashed, TextOutcome, evaluate_text

    if args.split is None or args.data is not None or args.build is not None or args.live or args.rebuild:
        raise LuminousError("--mode text plays a frozen split's text games: give --split, and leave out --data, "
                            "--build, --rebuild and --live")
    if args.backend != "local" or args.workers != 1:
        raise LuminousError("--mode text runs in one process (thousands of steps a second): leave out --workers and "
                            "--backend")

    def show(o: TextOutcome) -> None:
        print(f"{o.split} {o.index:4d} {o.task_type:<34} {o.end:<14} steps {o.steps:3d}", file=sys.stderr)

    try:
        report = evaluate_text(args.policy, args.split, args.episodes or benchmark_size(args.split), seed=args.seed,
                               out_dir=Path(args.out), limits=limits, progress=show)  # type: ignore[arg-type]
    except AgentCrashed as exc:
        return _crashed(exc, Path(args.out))
    print(report.markdown(), end="")
    print(f"wrote {Path(args.out) / 'report.json'}, {Path(args.out) / 'table.md'}")
    return 0


def _incomplete(report: EvalReport) -> int:
    """1 (and each cause on stderr) when entries are unavailable because of a crash, not of the task (the
    population is then incomplete), or because their trial is broken (`BROKEN_TRIAL`); else 0."""
    from luminous_sim.eval import crashed_build
    from luminous_sim.eval.metrics import BROKEN_TRIAL

    outcomes = report.outcomes
    crashed = [o for o in outcomes if crashed_build(o)]
    unavailable = [o for o in outcomes if not o.drawn]
    for o in unavailable:
        print(f"unavailable: {o.split} {o.index} ({o.cause}): {one_line(o.detail or o.cause, 400)}", file=sys.stderr)
    if crashed:
        print(f"error: {len(crashed)} of {len(outcomes)} entries are unavailable because their build crashed or "
              "made another episode than the frozen split (not a task failure): the population is incomplete; fix "
              "the cause above and run again (crashed builds are retried)", file=sys.stderr)
        return 1
    broken = [o for o in outcomes if not o.drawn and o.cause == BROKEN_TRIAL]
    if broken:
        names = ", ".join(o.trial or f"{o.split} {o.index}" for o in broken[:5]) + (" ..." if len(broken) > 5 else "")
        print(f"error: {len(broken)} of {len(outcomes)} entries are broken trials ({names}): their files cannot "
              "be played (the cause of each is above); they count as failures in SR all", file=sys.stderr)
        return 1
    return 0


def _crashed(exc: AgentCrashed, out: Path) -> int:
    """1, and on stderr the cause of an agent's crash (`AgentCrashed`) and what the output folder kept: the
    evaluation stopped there, and the same command resumes it."""
    episodes = out / "episodes"
    kept = len(list(episodes.glob("*.json"))) if episodes.is_dir() else 0
    print(f"luminous eval: error: {exc}", file=sys.stderr)
    print(f"error: the evaluation stopped: the agent crashed ({exc.cause}); {kept} finished "
          f"episode{'s' if kept != 1 else ''} kept in {episodes} (no report written); fix the agent and run the same "
          "command again to resume", file=sys.stderr)
    return 1


def _canonical_build(args: argparse.Namespace, backend: object) -> Path:
    """The canonical build of `args.split` (at least its first `args.episodes`), built where missing (without
    frames: evaluation renders its own), resumable; its folder. The output folder is checked first."""
    from luminous_sim.benchmark import benchmark_size, canonical_build_dir
    from luminous_sim.data import BuildOptions, build_split, built_count, make_backend
    from luminous_sim.eval import AgentLimits, check_output, data_run

    out = Path(args.build) if args.build is not None else canonical_build_dir(args.split)
    check_output(Path(args.out), data_run(args.policy, out, args.split, args.seed, dict(args.env),
                                          AgentLimits(step_timeout=args.step_timeout, memory_mb=args.agent_memory),
                                          args.track))
    want = max(args.episodes or benchmark_size(args.split), built_count(out, args.split))
    options = BuildOptions(frames=False, video=False)
    if backend is None:
        with make_backend("local", args.workers, None) as local:
            report = build_split(out, args.split, want, local, options, progress=True, rebuild=args.rebuild)
    else:
        report = build_split(out, args.split, want, backend, options, progress=True,  # type: ignore[arg-type]
                             rebuild=args.rebuild)
    print(f"canonical {args.split} build: {report.built} trials in {out} ({report.ran} built now)", file=sys.stderr)
    if report.retried or report.crashed:
        print(report.summary(), file=sys.stderr)
    return out
