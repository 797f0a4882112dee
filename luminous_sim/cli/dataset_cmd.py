"""`luminous dataset`: oracle demonstrations at scale. `build`: an S+/U+/U+test split (method (a)) or the
designs of an ALFRED split folder (method (b)) in ALFRED's layout (see luminous_sim.data.build and
.alfred_build); `minari`: a registered env's oracle episodes as a Minari dataset for offline RL
(`luminous_sim.data.minari_export`; the `minari` package is imported only when that action runs); `perception`:
frames with exact depth and labels for learning perception (`luminous_sim.data.perception_frames`).
"""

from __future__ import annotations

import argparse
import sys
import tomllib
from pathlib import Path
from typing import Any

from luminous_sim.cli.args import int_range, limited, output_dir, seed
from luminous_sim.data.backends import BACKENDS
from luminous_sim.limits import MAX_BUILD_JOBS, MAX_MINARI_EPISODES, MAX_MINARI_SEEDS, MAX_WORKERS
from luminous_sim.splits import PLUS_SPLITS

EPILOG = ("example: luminous dataset minari --env Luminous-NavToObject-64-v1 --episodes 100 --out out/minari   "
          "(read back: minari.MinariDataset('out/minari/luminous/NavToObject-64-v1/oracle-v0/data'))")


def env_option(text: str) -> tuple[str, Any]:
    """`NAME=VALUE`, the value read as TOML (`max_steps=100`, `targets="objects"`; a bare word is a string)."""
    name, sep, value = text.partition("=")
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE (e.g. max_steps=100), got {text!r}")
    try:
        return name, tomllib.loads(f"v = {value}")["v"]
    except tomllib.TOMLDecodeError:
        return name, value


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("dataset", help="expert demonstrations: ALFRED's format (build), Minari (minari); "
                                               "perception frames (perception)")
    actions = parser.add_subparsers(dest="action", required=True, metavar="ACTION")
    b = actions.add_parser(
        "build", help="build episodes 0..N-1 of a split, or re-solve the designs of an ALFRED split folder "
                      "(resumable: rerun the same command after a stop)",
        description="--split: episode i of the frozen split (luminous_sim.benchmark: its layout, task, start and "
                    "initial state, the episode `luminous eval` and the env play) solved by the oracle (method "
                    "(a)); the manifest records each episode's episode_key. --from-alfred: each task "
                    "design (traj_data.json) of your own copy of an ALFRED split, solved in a scene generated in "
                    "its own floor plan's room shell (method (b)). Trials are written under OUT/<split>/ in "
                    "ALFRED's json_2.1.0 layout; OUT/manifest.jsonl records each episode (built, or failed and "
                    "why), OUT/splits.json lists the trials in ALFRED's oct21.json layout. A stopped or killed "
                    "build resumes where it stopped when run again with the same options.")
    source = b.add_mutually_exclusive_group(required=True)  # --split, --houses or --from-alfred
    source.add_argument("--split", choices=list(PLUS_SPLITS), help="which split (method (a))")
    source.add_argument("--houses", type=int_range(1, MAX_BUILD_JOBS), default=None, metavar="N",
                        help="the house split's episodes 0..N-1: ALFRED tasks across the rooms of houses generated "
                             "per episode, under OUT/houses/ (docs/houses.md)")
    source.add_argument("--from-alfred", type=Path, default=None, metavar="ALFRED_SPLIT_DIR",
                        help="an ALFRED split folder of <task>/<trial>/traj_data.json, e.g. valid_seen (method "
                             "(b)); its trials are written under OUT/<its folder name>/")
    b.add_argument("--count", type=int_range(0, MAX_BUILD_JOBS), default=None,
                   help=f"episodes 0..COUNT-1 of the split (default: all of it; at most {MAX_BUILD_JOBS}); with "
                        "--from-alfred, the first COUNT designs in path order (default all). A rerun may extend a "
                        "build, never shrink it")
    b.add_argument("--out", required=True, type=output_dir, help="build folder (new, empty, or an earlier build)")
    b.add_argument("--workers", type=int_range(1, MAX_WORKERS), default=1,
                   help=f"worker processes (default 1; at most {MAX_WORKERS})")
    b.add_argument("--backend", choices=BACKENDS, default="local",
                   help="local processes, or Ray tasks (needs luminous-sim[cluster]) (default local)")
    b.add_argument("--address", default=None,
                   help="a running Ray cluster's address (ray backend; default: start a local cluster of "
                        "WORKERS CPUs). Every node must see OUT and have luminous_sim installed")
    b.add_argument("--no-frames", action="store_true",
                   help="no raw_images/ and no video (ALFRED's loaders need raw_images; for quick checks)")
    b.add_argument("--no-video", action="store_true", help="no video.mp4 beside the raw images")
    b.add_argument("--no-alfworld", action="store_true",
                   help="no initial_state.pddl (ALFWorld's problem of the trial, read by `alfworld-generate`) "
                        "beside each traj_data.json")
    b.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    b.add_argument("--speaker", type=Path, default=None, metavar="PATH",
                   help="a learned speaker's checkpoint (`luminous speaker train`): its instructions replace the "
                        "templates' in every trial (needs PyTorch)")
    b.add_argument("--language", choices=("human", "templates"), default=None,
                   help="--from-alfred: each trial keeps its design's human annotations (human; the default "
                        "without --speaker; steps the templates' where ALFRED's subgoals are not ours, as the "
                        "sidecar says), or gets template instructions (templates)")
    b.add_argument("--seed", type=int_range(0, 2**31 - 1), default=None,
                   help="--from-alfred: the seed of every design's scene and instructions (default 0, the seed S "
                        "is built with; another for a training set)")
    b.set_defaults(func=_build, build_parser=b)
    _register_perception(actions)
    p = actions.add_parser("minari", help="roll out the oracle in a registered env and write a Minari dataset",
                       epilog=EPILOG)
    p.add_argument("--env", required=True, help="a registered id, e.g. Luminous-NavToObject-64-v1")
    p.add_argument("--episodes", type=int_range(1, MAX_MINARI_EPISODES), required=True,
                   help=f"episodes to write (at most {MAX_MINARI_EPISODES})")
    p.add_argument("--out", type=output_dir, required=True,
                   help="a new folder: the Minari datasets root the dataset is written under")
    p.add_argument("--seed", type=seed, default=0, help="first episode's seed, a whole number >= 0 (default 0)")
    p.add_argument("--dataset-id", default=None, help="Minari dataset id (default luminous/<env>/oracle-v0)")
    p.add_argument("--env-kwarg", type=env_option, action="append", default=[], metavar="NAME=VALUE",
                   help="env option (repeatable), e.g. targets=objects or max_steps=100")
    p.add_argument("--token-length", type=limited(1, "MAX_INSTRUCTION_TOKENS"), default=32,
                   help="instruction tokens (default 32)")
    p.add_argument("--max-seeds", type=int_range(1, MAX_MINARI_SEEDS), default=None,
                   help=f"give up after this many seeds (default 10 * episodes + 10; at most {MAX_MINARI_SEEDS})")
    p.add_argument("--jpeg", action="store_true", help="store images JPEG-encoded (lossy, smaller)")
    p.add_argument("--resume", action="store_true", help="go on from the <out>.partial/ an interrupted run left")
    p.set_defaults(func=cmd_minari)


def _register_perception(actions: argparse._SubParsersAction) -> None:
    q = actions.add_parser(
        "perception", help="frames with exact depth and labels for learning the rgb track's perception (resumable)",
        description="Renders frames from the agent's camera along expert and exploratory paths, with exact depth "
                    "and instance/type labels, into OUT/shards/ (one npz per episode) with OUT/manifest.jsonl and "
                    "OUT/perception.json (docs/perception.md). A training dataset's episodes are generated in "
                    "CSSG's own room shapes (in no split) and, with --trials, restored from a build's trials (e.g. "
                    "ALFRED's train designs re-solved; trials in U+/U+test structures are refused). --split makes "
                    "an evaluation dataset of a frozen split's entries instead (train-perception refuses it). The "
                    "same options give the same shards; a stopped run resumes when run again.")
    q.add_argument("--out", required=True, type=output_dir, help="dataset folder (new, empty, or an earlier run)")
    q.add_argument("--count", type=int_range(0, MAX_BUILD_JOBS), default=100,
                   help="generated episodes (default 100); with --split, entries spread evenly over the split")
    q.add_argument("--trials", type=Path, action="append", default=[], metavar="BUILD",
                   help="a `luminous dataset build` folder whose built trials are rendered too (repeatable)")
    q.add_argument("--trial-stride", type=int_range(1, MAX_BUILD_JOBS), default=1, metavar="K",
                   help="every K-th built trial of each --trials build, in its manifest's order (default 1: all)")
    q.add_argument("--split", choices=list(PLUS_SPLITS), default=None,
                   help="an evaluation dataset: COUNT entries of this frozen split (U+: structures never trained on)")
    q.add_argument("--seed", type=int_range(0, 2**31 - 1), default=0, help="dataset seed (default 0)")
    q.add_argument("--size", type=int_range(32, 600), default=300, help="frame side in pixels (default 300, ALFRED's)")
    q.add_argument("--workers", type=int_range(1, MAX_WORKERS), default=1,
                   help=f"worker processes (default 1; at most {MAX_WORKERS})")
    q.add_argument("--backend", choices=BACKENDS, default="local", help="local processes, or Ray (default local)")
    q.add_argument("--address", default=None, help="a running Ray cluster's address (ray backend)")
    q.add_argument("--no-progress", action="store_true", help="no progress on stderr")
    q.set_defaults(func=_perception, perception_parser=q)


def _perception(args: argparse.Namespace) -> int:
    from luminous_sim.data import build_perception, built_trials, evaluation_jobs, make_backend, perception_jobs

    if args.split is not None:
        if args.trials:
            args.perception_parser.error("--trials is for a training dataset; --split makes an evaluation one")
        from luminous_sim.benchmark import benchmark_size

        size = benchmark_size(args.split)
        entries = sorted({min(size - 1, (k * size) // max(args.count, 1)) for k in range(min(args.count, size))})
        jobs = evaluation_jobs(args.split, entries, args.seed, args.size)
    else:
        trials = [t for build in args.trials for t in built_trials(build)[::args.trial_stride]]
        jobs = perception_jobs(args.seed, args.count, trials, args.size)
    with make_backend(args.backend, args.workers, args.address) as backend:
        report = build_perception(Path(args.out), jobs, backend, progress=not args.no_progress)
    print(f"{args.out}: {report.summary()}")
    print(f"shards under {Path(args.out) / 'shards'}; records in {Path(args.out) / 'manifest.jsonl'}")
    return 0


def _build(args: argparse.Namespace) -> int:
    from luminous_sim.data import DESIGN_SEED, BuildOptions, build_from_alfred, build_houses, build_split, make_backend

    if args.houses is not None and args.count is not None:
        args.build_parser.error("--count is for --split and --from-alfred; --houses N gives the count itself")
    if args.from_alfred is None and (args.language is not None or args.seed is not None):
        args.build_parser.error("--language and --seed are for --from-alfred (a split's episodes have their own)")
    if args.language == "human" and args.speaker is not None:
        args.build_parser.error("--speaker replaces template instructions; --language human keeps the designs' "
                                "own (give one or the other)")
    if args.split is not None and args.count is None:
        from luminous_sim.benchmark import benchmark_size

        args.count = benchmark_size(args.split)
    speaker = None
    if args.speaker is not None:
        from luminous_sim.language.speaker.annotate import check_speaker

        check_speaker(args.speaker, frames=not args.no_frames)
        speaker = str(args.speaker.resolve())
    human = args.from_alfred is not None and (args.language or ("templates" if speaker else "human")) == "human"
    options = BuildOptions(frames=not args.no_frames, video=not args.no_video, speaker=speaker, human_language=human,
                           alfworld=not args.no_alfworld)
    with make_backend(args.backend, args.workers, args.address) as backend:
        if args.split is not None:
            report = build_split(Path(args.out), args.split, args.count, backend, options,
                                 progress=not args.no_progress)
        elif args.houses is not None:
            report = build_houses(Path(args.out), args.houses, backend, options, progress=not args.no_progress)
        else:
            report = build_from_alfred(Path(args.out), args.from_alfred, args.count, backend, options,
                                       progress=not args.no_progress,
                                       seed=DESIGN_SEED if args.seed is None else args.seed)
    if args.split is not None or args.houses is not None:
        name, count = (args.split, args.count) if args.split is not None else ("houses", args.houses)
        print(f"{name}: episodes 0..{count - 1} in {report.out}/ ({report.built} built, "
              f"{report.failed} failed; {report.ran} run now)")
    else:
        print(f"{args.from_alfred}: {len(report.records)} designs in {report.out}/ ({report.built} built, "
              f"{report.failed} failed; {report.ran} run now)")
    print(report.summary())
    print(f"trials listed in {report.out / 'splits.json'}; every episode's record in {report.out / 'manifest.jsonl'}")
    if report.crashed:  # the installation failed, not the tasks: the next run does these jobs again
        print(f"error: {len(report.crashed)} job(s) crashed (see above); fix the cause and run the same command "
              "again", file=sys.stderr)
        return 1
    return 0


def cmd_minari(args: argparse.Namespace) -> int:
    from luminous_sim.data.minari_export import export_minari

    done = export_minari(args.env, args.episodes, args.out, seed=args.seed, dataset_id=args.dataset_id,
                         env_kwargs=dict(args.env_kwarg), token_length=args.token_length, jpeg=args.jpeg,
                         resume=args.resume, max_seeds=args.max_seeds, progress=True)
    print(f"wrote {done.episodes} oracle episodes ({done.steps} steps) of {args.env} as Minari dataset "
          f"{done.dataset_id} to {done.path}/")
    if done.skipped_seeds:
        print(f"  {len(done.skipped_seeds)} of {done.seeds_tried} seeds left out (the oracle needed an action outside "
              "the discrete space); listed in the dataset's metadata")
    print(f"  read back: minari.MinariDataset('{done.path}/data')")
    return 0
