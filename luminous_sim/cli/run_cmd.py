"""`luminous run`: a CDF's own task, end to end (see luminous_sim.cdf_episode.run_cdf).

Exit status 0 when the task is done, 1 when it is not (the summary gives the first cause), 2 on bad input.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cli.args import output_dir, seed

EPILOG = ("example: luminous run --cdf cdf/examples/kitchen_apple_fridge.yaml --seed 0 --out out/apple   "
          "(exit status: 0 task done, 1 task not done, 2 bad input)")


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("run", help="generate a CDF's scene and run its own task (or its execution script)",
                            epilog=EPILOG)
    parser.add_argument("--cdf", type=Path, required=True, help="challenge definition with a task section")
    parser.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    parser.add_argument("--room", help="a room-library name (see `luminous rooms list`) instead of the CDF's room")
    parser.add_argument("--out", type=output_dir, required=True,
                        help="output folder: trajectory.json, frames/, video.mp4, top_down.png, instructions.txt")
    parser.add_argument("--plan", action="store_true",
                        help="let the oracle plan the goal even when the CDF has an execution script")
    parser.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from luminous_sim.cdf_episode import run_cdf

    ran = run_cdf(args.cdf, args.seed, args.out, room=args.room, follow_script=not args.plan)
    r = ran.result
    how = "following its execution script" if ran.scripted else "planned by the oracle"
    where = "house" if ran.scene.room.house is not None else "room"
    print(f"{args.cdf}: {'task done' if r.success else 'task NOT done'} in {where} {ran.scene.room.name} "
          f"(seed {args.seed}), {how}")
    print(f"  goal: {r.goal}")
    print(f"  goal conditions: {r.goal_conditions[0]}/{r.goal_conditions[1]}; {r.low_actions} low-level actions")
    if r.failure:
        code = f"[{r.failure_code}] " if r.failure_code else ""
        later = f" ({len(r.failures) - 1} later failures in trajectory.json)" if len(r.failures) > 1 else ""
        print(f"  first failure: {code}{r.failure}{later}")
    for note in r.notes:
        print(f"  note: {note}")
    print(f"  wrote {args.out}/ (trajectory.json, frames/, video.mp4, top_down.png, instructions.txt)")
    return 0 if r.success else 1
