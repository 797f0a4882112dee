"""`luminous eval`: a policy on episodes of an evaluation split, with ALFRED's metrics (see luminous_sim.eval)."""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from luminous_sim.cli.args import int_range, output_dir, seed
from luminous_sim.data.backends import BACKENDS
from luminous_sim.limits import MAX_EVAL_EPISODES, MAX_WORKERS

SPLITS: tuple[str, ...] = ("S+", "U+", "U+test")
"""The split names (`luminous_sim.splits.PLUS_SPLITS`; a test keeps the two in step)."""


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser(
        "eval", help="run a policy on S+/U+ episodes: SR, GC, PLW-SR, PLW-GC per task type",
        description="Run a policy on the first N episodes of an evaluation split with ALFRED's limits (1000 "
                    "steps, 10 failed actions) and write report.json, table.md (the paper's Table 4 layout), "
                    "metrics.png and one file per episode (an interrupted run resumes in the same folder).")
    parser.add_argument("--policy", required=True, metavar="POLICY",
                        help="oracle, random, or MODULE:CALLABLE, a factory of your agent (docs/evaluation.md)")
    parser.add_argument("--split", required=True, choices=SPLITS, help="the evaluation split")
    parser.add_argument("--episodes", type=int_range(1, MAX_EVAL_EPISODES), required=True, metavar="N",
                        help=f"evaluate the split's episodes 0 .. N-1 (at most {MAX_EVAL_EPISODES})")
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
    parser.add_argument("--env", type=env_option, action="append", default=[], metavar="KEY=VALUE",
                        help="an env option over ALFRED's (EnvConfig's fields; VALUE as JSON, else a string), "
                             "e.g. --env width=64 --env targets=objects; repeatable")
    parser.set_defaults(func=_run)


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
    from luminous_sim.eval import EpisodeOutcome, EvalReport, check_policy, evaluate, markdown_table, write_reports

    if os.getcwd() not in sys.path:  # MODULE may be a file in the current folder, as with `python -m`
        sys.path.insert(0, os.getcwd())
    check_policy(args.policy)  # a bad spec fails here, before any episode
    if args.backend == "local" and args.address:
        raise LuminousError(f"--address {args.address} is for the ray backend, not local")

    def show(o: EpisodeOutcome) -> None:
        what = o.end if o.drawn else f"unavailable ({o.cause})"
        gc = f"{o.goal_conditions[0]}/{o.goal_conditions[1]}" if o.drawn else "-"
        print(f"{o.split} {o.index:4d} {o.task_type:<34} {what:<22} gc {gc:<5} steps {o.steps:4d} "
              f"expert {o.expert_length:4d}", file=sys.stderr)

    def run(backend: Backend | None) -> EvalReport:
        return evaluate(args.policy, args.split, args.episodes, seed=args.seed, workers=args.workers,
                        out_dir=Path(args.out), progress=show, env_kwargs=dict(args.env), backend=backend)

    if args.backend == "local":
        report = run(None)
    else:  # a local Ray cluster's workers inherit PYTHONPATH: the current folder's agent module too
        os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (os.getcwd(), os.environ.get("PYTHONPATH")) if p)
        with make_backend(args.backend, args.workers, args.address) as backend:
            report = run(backend)
    for why in report.replayed:
        print(f"played again (its file was damaged): {why}", file=sys.stderr)
    paths = write_reports(report, Path(args.out))
    print(markdown_table([report]), end="")
    print(f"wrote {paths['json']}, {paths['table']}, {paths['plot']}")
    return 0
