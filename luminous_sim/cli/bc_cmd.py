"""`luminous bc`: behaviour cloning from oracle demonstrations (see luminous_sim.bc; needs torch, the `learn`
extra): `collect` oracle demonstrations of a task family (`pickup`, or `alfred`: the split's own episodes) on a
split, `train` a policy on them, `eval` a policy on that family's episodes of S+ or U+ with ALFRED's metrics."""

from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from luminous_sim.cli.args import (
    int_range,
    limited,
    output_dir,
    output_file,
    positive_float,
    seed,
)
from luminous_sim.limits import MAX_EVAL_EPISODES

SPLITS: tuple[str, ...] = ("S+", "U+", "U+test")
FAMILIES: tuple[str, ...] = ("pickup", "alfred")
"""`luminous_sim.bc.FAMILIES` (not imported here: that package needs torch)."""


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("bc", help="behaviour cloning: collect oracle demos, train, evaluate (needs torch)",
                            description="Behaviour cloning from oracle demonstrations of picking up a named "
                                        "object in the layouts of S+/U+ (docs: README, 'Imitation').")
    bc = parser.add_subparsers(dest="bc_command", required=True, metavar="STEP")
    collect = bc.add_parser("collect", help="record the oracle on episodes of a split (resumable)")
    collect.add_argument("--split", choices=SPLITS, default="S+", help="the split (default S+)")
    collect.add_argument("--family", choices=FAMILIES, default="pickup",
                         help="pickup (pick up a named object in the entry's layout; default) or alfred (the entry's "
                              "own ALFRED episode)")
    collect.add_argument("--start", type=limited(0, "MAX_EPISODE_INDEX"), default=28,
                         help="first episode index (default 28: S+ 0-27 are kept for evaluation)")
    collect.add_argument("--episodes", type=int_range(1, MAX_EVAL_EPISODES), required=True, metavar="N",
                         help=f"episodes to record (at most {MAX_EVAL_EPISODES})")
    collect.add_argument("--out", type=output_dir, required=True, help="demonstrations folder")
    collect.set_defaults(func=_collect)
    train = bc.add_parser("train", help="train a policy on demonstrations; write a checkpoint")
    train.add_argument("--demos", type=Path, required=True, help="demonstrations folder (`luminous bc collect`)")
    train.add_argument("--out", type=output_file((".pt",), "a .pt checkpoint"), required=True,
                       help="checkpoint file to write")
    train.add_argument("--epochs", type=limited(1, "MAX_EPOCHS"), default=20, help="passes over the demos (default 20)")
    train.add_argument("--batch-size", type=limited(1, "MAX_BATCH_SIZE"), default=64, help="batch size (default 64)")
    train.add_argument("--lr", type=positive_float, default=1e-3, help="Adam's learning rate (default 0.001)")
    train.add_argument("--seed", type=seed, default=0, help="seed of the weights and shuffling (default 0)")
    train.add_argument("--threads", type=limited(1, "MAX_THREADS"), default=1, help="torch threads (default 1)")
    train.set_defaults(func=_train)
    evaluate = bc.add_parser("eval", help="a policy on episodes of a split: SR, GC, PLW-SR, PLW-GC")
    evaluate.add_argument("--family", choices=FAMILIES, default="pickup",
                          help="the episodes: pickup (default) or alfred (the split's own, with ALFRED's limits)")
    evaluate.add_argument("--policy", required=True,
                          help="oracle, random, or MODULE:CALLABLE (the clone: luminous_sim.bc:bc_agent)")
    evaluate.add_argument("--checkpoint", type=Path, help="the clone's checkpoint (sets LUMINOUS_BC_CHECKPOINT)")
    evaluate.add_argument("--split", choices=SPLITS, required=True, help="the split")
    evaluate.add_argument("--start", type=limited(0, "MAX_EPISODE_INDEX"), default=0,
                          help="first episode index (default 0)")
    evaluate.add_argument("--episodes", type=int_range(1, MAX_EVAL_EPISODES), required=True, metavar="N",
                          help=f"episodes to play (at most {MAX_EVAL_EPISODES})")
    evaluate.add_argument("--seed", type=seed, default=0, help="seed of the agent's randomness (default 0)")
    evaluate.add_argument("--out", type=output_file((".json",), "a JSON file"),
                          help="write the outcomes and metrics to this JSON file")
    evaluate.set_defaults(func=_eval)


def _collect(args: argparse.Namespace) -> int:
    from luminous_sim.bc import collect_demos

    def show(index: int, demo: object, cause: str) -> None:
        print(f"{args.split} {index}: " + (f"unavailable ({cause})" if demo is None else "recorded"), file=sys.stderr)

    summary = collect_demos(Path(args.out), args.split, range(args.start, args.start + args.episodes), show,
                            family=args.family)
    print(json.dumps(summary, indent=1))
    return 0


def _train(args: argparse.Namespace) -> int:
    from luminous_sim.bc import train_bc

    result = train_bc(args.demos, args.out, epochs=args.epochs, batch_size=args.batch_size, lr=args.lr,
                      seed=args.seed, threads=args.threads,
                      progress=lambda e, loss: print(f"epoch {e + 1}: loss {loss:.4f}", file=sys.stderr))
    print(f"trained on {result.samples} steps of {result.demos} demos: final loss {result.losses[-1]:.4f}, "
          f"training accuracy {result.accuracy:.3f}; wrote {result.checkpoint}")
    return 0


def _eval(args: argparse.Namespace) -> int:
    from luminous_sim.bc import ALFRED_ENV, CHECKPOINT_VAR, evaluate_pickup
    from luminous_sim.eval import check_policy, evaluate, metrics
    from luminous_sim.fileio import write_atomic

    if args.checkpoint is not None:
        os.environ[CHECKPOINT_VAR] = str(args.checkpoint)
    check_policy(args.policy)
    indices = list(range(args.start, args.start + args.episodes))
    if args.family == "alfred":
        outcomes = list(evaluate(args.policy, args.split, indices, seed=args.seed, env_kwargs=ALFRED_ENV,
                                 track="privileged").outcomes)  # object slots: the privileged track
    else:
        outcomes = evaluate_pickup(args.policy, args.split, indices, seed=args.seed)
    result = metrics(outcomes)
    print(json.dumps(result.to_dict()))
    if args.out is not None:
        write_atomic(args.out, json.dumps({"policy": args.policy, "split": args.split, "metrics": result.to_dict(),
                                           "episodes": [o.to_dict() for o in outcomes]}, indent=1) + "\n")
    return 0
