"""`luminous demo`: the main job (see luminous_sim.demo)."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cli.args import output_dir, seed
from luminous_sim.vocab import ROOM_TYPES


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("demo", help="generate and furnish rooms, build them in PyBullet, write pictures")
    parser.add_argument("--out", type=output_dir, default=Path("out/demo"), help="output folder (default out/demo)")
    parser.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    parser.add_argument("--room-types", nargs="*", default=None, choices=ROOM_TYPES, metavar="ROOM_TYPE",
                        help=f"room types to generate (default: all of {', '.join(ROOM_TYPES)})")
    parser.add_argument("--no-episode", action="store_true", help="skip the task + oracle episode")
    parser.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from luminous_sim.demo import run_demo, run_demo_episode

    rooms = run_demo(args.out, args.seed, tuple(args.room_types or ROOM_TYPES))
    for r in rooms:
        print(f"{r.room_type:<11} {r.objects:3d} objects  {r.out_dir}/  (scene.json, report.json: "
              f"{'valid' if r.valid else 'NOT valid'}, {r.moved} moved while settling; top_down.png, egocentric.png)")
    if not args.no_episode:
        ep = run_demo_episode(args.out / "episode", args.seed)
        gc = f"{ep.goal_conditions[0]}/{ep.goal_conditions[1]}"
        print(f"episode    {ep.task_type}: {'solved' if ep.success else 'NOT solved'} ({gc} goal conditions, "
              f"{ep.low_actions} low-level actions) -> {ep.out_dir}/ (trajectory.json, frames/, video.mp4, "
              f"top_down.png, instructions.txt, scene.json)")
        print(f"view       luminous view {ep.out_dir} --trajectory {ep.out_dir}   (the scene and the episode in the "
              "browser; needs the `view` extra)")
    return 0
