"""`luminous speaker ...`: train a learned speaker, describe a trajectory, score held-out BLEU.

PyTorch is imported only when a speaker action runs, so the rest of the CLI works without it.
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from pathlib import Path
from types import ModuleType

from luminous_sim.cli.args import fraction, int_range, limited, output_file, positive_float, seed
from luminous_sim.language.speaker.errors import SpeakerError


def _speaker_module(name: str) -> ModuleType:
    try:
        return importlib.import_module(f"luminous_sim.language.speaker.{name}")
    except ModuleNotFoundError as exc:
        if exc.name == "torch":
            raise SpeakerError(
                "the learned speaker needs PyTorch: pip install torch==2.13.0"
            ) from None
        raise


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the `speaker` subcommand and its actions (train, describe, evaluate)."""
    parser = subparsers.add_parser(
        "speaker", help="learned speaker: train, describe trajectories, BLEU"
    )
    sub = parser.add_subparsers(dest="speaker_command", required=True)

    p = sub.add_parser(
        "train", help="train on ALFRED-format traj_data.json files (any depth under --data)"
    )
    p.add_argument("--data", required=True, type=Path, help="folder with traj_data.json files")
    p.add_argument(
        "--out", required=True, type=output_file((), "a checkpoint"),
        help="checkpoint file to write (e.g. speaker.pt)",
    )
    p.add_argument("--epochs", type=limited(1, "MAX_EPOCHS"), default=10, help="total epochs (default 10)")
    p.add_argument("--batch-size", type=limited(1, "MAX_BATCH_SIZE"), default=32,
                   help="examples per batch (default 32)")
    p.add_argument("--lr", type=positive_float, default=2e-3, help="learning rate (default 0.002)")
    p.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    p.add_argument(
        "--held-out",
        type=fraction,
        default=0.1,
        help="fraction of trajectories held out (default 0.1)",
    )
    p.add_argument(
        "--max-examples", type=limited(1, "MAX_TRAIN_EXAMPLES"), default=None,
        help="train on a seeded sample of N examples"
    )
    p.add_argument(
        "--max-trajectories", type=limited(1, "MAX_TRAJECTORIES"), default=None, help="use the first N trajectories"
    )
    p.add_argument("--emb-dim", type=int_range(1, 4096), default=64, help="word embedding size (default 64)")
    p.add_argument("--hid-dim", type=int_range(1, 4096), default=128, help="LSTM hidden size (default 128)")
    p.add_argument(
        "--features", action="store_true", help="use raw_images/ colour features where present"
    )
    p.add_argument(
        "--resume", action="store_true", help="continue from --out up to --epochs in total"
    )
    p.add_argument(
        "--eval-beam", type=int_range(0, 64), default=1, help="beam width for the held-out BLEU (0: skip)"
    )
    p.add_argument("--quiet", action="store_true", help="no per-epoch lines")
    p.set_defaults(func=cmd_train)

    p = sub.add_parser("describe", help="goal directive and step instructions for a traj_data.json")
    p.add_argument(
        "--model", required=True, type=Path, help="checkpoint written by `speaker train`"
    )
    p.add_argument(
        "--traj", required=True, type=Path, help="traj_data.json (annotations not needed)"
    )
    p.add_argument("--beam", type=int_range(1, 64), default=3, help="beam width (1: greedy; default 3)")
    p.add_argument("--json", action="store_true", help="print {task_desc, high_descs} JSON")
    _no_repeat_option(p)
    p.set_defaults(func=cmd_describe)

    p = sub.add_parser("evaluate", help="BLEU-4 on the trajectories the checkpoint held out")
    p.add_argument("--model", required=True, type=Path, help="checkpoint written by `speaker train`")
    p.add_argument("--data", required=True, type=Path, help="the folder the model was trained from")
    p.add_argument("--beam", type=int_range(1, 64), default=3, help="beam width (1: greedy; default 3)")
    p.add_argument("--all", action="store_true", help="score every trajectory under --data instead")
    _no_repeat_option(p)
    p.set_defaults(func=cmd_evaluate)


def _no_repeat_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--no-repeat-ngram",
        type=limited(0, "MAX_NGRAM"),
        default=3,
        help="never repeat an n-gram of this length (0: off; default 3)",
    )


def cmd_train(args: argparse.Namespace) -> int:
    """Train, print the report as JSON."""
    train = _speaker_module("train").train
    report = train(
        args.data,
        args.out,
        epochs=args.epochs,
        batch_size=args.batch_size,
        lr=args.lr,
        seed=args.seed,
        max_examples=args.max_examples,
        progress=not args.quiet,
        resume=args.resume,
        held_out=args.held_out,
        max_trajectories=args.max_trajectories,
        features=args.features,
        dims={"emb_dim": args.emb_dim, "hid_dim": args.hid_dim},
        eval_beam=args.eval_beam or None,
    )
    out = {
        "checkpoint": str(args.out),
        "epochs": len(report.losses),
        "epochs_run": report.epochs_run,
        "losses": [round(x, 4) for x in report.losses],
        "examples": report.examples,
        "vocab_size": report.vocab_size,
        "seconds": round(report.seconds, 1),
        "held_out_trajectories": report.held_out,
    }
    if report.evaluation is not None:
        ev = report.evaluation
        out.update(
            bleu4_steps=round(ev.bleu_steps, 4),
            bleu4_goals=round(ev.bleu_goals, 4),
            eval_beam=ev.beam_width,
        )
    print(json.dumps(out, indent=2))
    return 0


def cmd_describe(args: argparse.Namespace) -> int:
    """Print the generated goal directive and numbered step instructions."""
    speaker = _speaker_module("generate").Speaker.load(
        args.model, beam_width=args.beam, no_repeat_ngram=args.no_repeat_ngram
    )
    goal, steps = speaker.describe_trajectory(args.traj)
    if args.json:
        print(json.dumps({"task_desc": goal, "high_descs": steps}, indent=2))
    else:
        print(f"Goal: {goal}")
        for i, step in enumerate(steps, 1):
            print(f"{i:>2}. {step}")
    return 0


def cmd_evaluate(args: argparse.Namespace) -> int:
    """Score held-out (or all) trajectories and print BLEU-4 as JSON."""
    generate = _speaker_module("generate")
    checkpoint = _speaker_module("checkpoint")
    dataset = _speaker_module("dataset")
    evaluate = _speaker_module("evaluate").evaluate
    keys = set(checkpoint.load_checkpoint(args.model).get("held_out_keys", []))
    trajs = dataset.load_trajectories(args.data)
    if not args.all:
        trajs = [t for t in trajs if t.key in keys]
        if not trajs:
            raise SpeakerError(
                f"{args.data}: none of the checkpoint's held-out trajectories are here (use --all)"
            )
    speaker = generate.Speaker.load(
        args.model, beam_width=args.beam, no_repeat_ngram=args.no_repeat_ngram
    )
    ev = evaluate(speaker, trajs, beam_width=args.beam)
    print(
        json.dumps(
            {
                "trajectories": len(trajs),
                "beam": ev.beam_width,
                "bleu4_steps": round(ev.bleu_steps, 4),
                "bleu4_goals": round(ev.bleu_goals, 4),
                "subgoals": ev.n_steps,
            },
            indent=2,
        )
    )
    for kind, hyp, ref in ev.samples:
        print(f"[{kind}] {hyp}  |  ref: {ref}", file=sys.stderr)
    return 0
