"""`luminous agents ...`: the reference agent's parts. `train-parser` trains the instruction parser on ALFRED's
train annotations (the same bytes for the same data and seed); `parse` reads directives, one per line, and
prints one JSON object per line (`task_type`, `pddl_params`); `train-perception` trains the rgb track's depth
and segmentation on perception datasets (the same bytes for the same data, seed, threads and torch);
`score-perception` scores a perception network on a perception dataset's frames (per room type). PyTorch is
imported only when one runs."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path
from typing import Any

from luminous_sim.cli.args import int_range, limited, output_file, seed
from luminous_sim.errors import LuminousError


def _agents() -> Any:
    try:
        import torch  # noqa: F401  (the parser is a torch model)
    except ModuleNotFoundError:
        raise LuminousError("the instruction parser and perception need PyTorch: pip install torch==2.13.0") from None
    import luminous_sim.agents as agents

    return agents


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the `agents` subcommand and its actions (train-parser, parse, train-perception, score-perception)."""
    parser = subparsers.add_parser("agents", help="the reference agent's parts: the instruction parser, perception")
    sub = parser.add_subparsers(dest="agents_command", required=True)

    p = sub.add_parser("train-parser", help="train the instruction parser on ALFRED's train annotations")
    p.add_argument("--alfred", required=True, type=Path,
                   help="ALFRED's train split (a folder of <task>/<trial>/traj_data.json)")
    p.add_argument("--out", required=True, type=output_file((".pt",), "a .pt checkpoint"),
                   help="the checkpoint to write")
    p.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    p.add_argument("--epochs", type=limited(1, "MAX_EPOCHS"), default=8, help="epochs (default 8)")
    p.add_argument("--quiet", action="store_true", help="no per-epoch lines")
    p.set_defaults(func=cmd_train_parser)

    p = sub.add_parser("train-perception", help="train the rgb track's depth and segmentation on perception datasets")
    p.add_argument("--data", required=True, type=Path, action="append", metavar="DIR",
                   help="a `luminous dataset perception` folder (repeatable; never an evaluation one)")
    p.add_argument("--out", required=True, type=output_file((".pt",), "a .pt checkpoint"),
                   help="the checkpoint to write")
    p.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    p.add_argument("--epochs", type=limited(1, "MAX_EPOCHS"), default=None, help="epochs (default the shipped one's)")
    p.add_argument("--threads", type=limited(1, "MAX_THREADS"), default=None,
                   help="torch threads (default the shipped one's; part of what makes the bytes)")
    p.add_argument("--max-frames", type=limited(0, "MAX_TRAIN_EXAMPLES"), default=0,
                   help="train on the first N frames only (0: all; for quick checks)")
    p.add_argument("--side", type=int_range(16, 1024), default=None,
                   help="the network's input side in pixels (default the shipped one's)")
    p.add_argument("--quiet", action="store_true", help="no per-epoch lines")
    p.set_defaults(func=cmd_train_perception)

    p = sub.add_parser("score-perception", help="a perception network's IoU and depth error on a dataset's frames")
    p.add_argument("--data", required=True, type=Path, help="a `luminous dataset perception` folder (e.g. of U+)")
    p.add_argument("--perception", type=Path, default=None,
                   help="a checkpoint of train-perception (default: the shipped one)")
    p.set_defaults(func=cmd_score_perception)

    p = sub.add_parser("parse", help="directives (one per line) to task type and pddl_params (JSON lines)")
    p.add_argument("file", type=Path, help="a text file of directives, one per line ('-': standard input)")
    p.add_argument("--parser", type=Path, default=None, help="a checkpoint of train-parser (default: the shipped one)")
    p.set_defaults(func=cmd_parse)


def cmd_train_parser(args: argparse.Namespace) -> int:
    """Train and write the checkpoint; print what training recorded (JSON)."""
    agents = _agents()
    parser = agents.train_parser(args.alfred, agents.TrainSettings(seed=args.seed, epochs=args.epochs),
                                 progress=not args.quiet)
    parser.save(args.out)
    print(json.dumps({"out": str(args.out), **parser.record}, indent=1))
    return 0


def cmd_parse(args: argparse.Namespace) -> int:
    """Parse each line of the file (or standard input); one JSON object per line."""
    agents = _agents()
    if str(args.file) == "-":
        lines = sys.stdin.read().splitlines()
    else:
        from luminous_sim.errors import read_file_bytes
        from luminous_sim.limits import MAX_INPUT_BYTES

        data = read_file_bytes(args.file, MAX_INPUT_BYTES, "a file of directives (luminous_sim.limits.MAX_INPUT_BYTES)")
        try:
            lines = data.decode("utf-8").splitlines()
        except UnicodeDecodeError as exc:
            raise LuminousError(f"{args.file}: not UTF-8 text (byte {exc.start}); expected directives, one per "
                                "line") from None
    parser = agents.InstructionParser.load(args.parser) if args.parser else agents.default_parser()
    for task in parser.parse_many([(line, ()) for line in lines]):
        print(json.dumps(task.to_dict(), sort_keys=True))
    return 0


def cmd_train_perception(args: argparse.Namespace) -> int:
    """Train and write the perception checkpoint; print what training recorded (JSON)."""
    from dataclasses import replace

    agents = _agents()
    settings = agents.PerceptionSettings(seed=args.seed, max_frames=args.max_frames)
    for name in ("epochs", "threads", "side"):
        if getattr(args, name) is not None:
            settings = replace(settings, **{name: getattr(args, name)})
    import time

    # the command that makes these bytes again: every option as it was resolved
    command = " ".join(["luminous agents train-perception", *(f"--data {d}" for d in args.data), f"--out {args.out}",
                        f"--seed {settings.seed}", f"--epochs {settings.epochs}", f"--threads {settings.threads}",
                        f"--side {settings.side}", f"--max-frames {settings.max_frames}"])
    cpu, wall = time.process_time(), time.perf_counter()
    perception = agents.train_perception(args.data, settings, command=command, progress=not args.quiet)
    perception.save(args.out)
    print(json.dumps({"out": str(args.out), **perception.record}, indent=1))
    # the cost is not in the checkpoint (its bytes depend on the data and settings only)
    print(f"trained in {time.process_time() - cpu:.0f} CPU-s ({time.perf_counter() - wall:.0f} s wall, "
          f"{settings.threads} threads)", file=sys.stderr)
    return 0


def cmd_score_perception(args: argparse.Namespace) -> int:
    """Score the network on every frame of the dataset, at the frames' own size; print JSON per room type."""
    agents = _agents()
    from luminous_sim.agents.perception_scores import score_dataset

    perception = agents.Perception.load(args.perception) if args.perception else agents.default_perception()
    print(json.dumps(score_dataset(perception, args.data), indent=1, sort_keys=True))
    return 0
