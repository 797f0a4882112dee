"""`luminous dataset build`: oracle demonstrations of an S+/U+/U+test split in ALFRED's layout
(see luminous_sim.data.build)."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cli.args import non_negative_int, output_dir, positive_int
from luminous_sim.data.backends import BACKENDS
from luminous_sim.splits import PLUS_SPLITS


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("dataset", help="build datasets of expert demonstrations in ALFRED's format")
    actions = parser.add_subparsers(dest="action", required=True, metavar="ACTION")
    b = actions.add_parser(
        "build", help="build episodes 0..N-1 of a split (resumable: rerun the same command after a stop)",
        description="Episode i of the split: its room structure's shared layout, a task of the episode's type "
                    "drawn with its seed and solved by the oracle, written under OUT/<split>/ in ALFRED's "
                    "json_2.1.0 layout; OUT/manifest.jsonl records each episode (built, or failed and why), "
                    "OUT/splits.json lists the trials in ALFRED's oct21.json layout. A stopped or killed build "
                    "resumes where it stopped when run again with the same options.")
    b.add_argument("--split", required=True, choices=list(PLUS_SPLITS), help="which split")
    b.add_argument("--count", required=True, type=non_negative_int, help="episodes 0..COUNT-1 of the split")
    b.add_argument("--out", required=True, type=output_dir, help="build folder (new, empty, or an earlier build)")
    b.add_argument("--workers", type=positive_int, default=1, help="worker processes (default 1)")
    b.add_argument("--backend", choices=BACKENDS, default="local",
                   help="local processes, or Ray tasks (needs luminous-sim[cluster]) (default local)")
    b.add_argument("--address", default=None,
                   help="a running Ray cluster's address (ray backend; default: start a local cluster of "
                        "WORKERS CPUs). Every node must see OUT and have luminous_sim installed")
    b.add_argument("--no-frames", action="store_true",
                   help="no raw_images/ and no video (ALFRED's loaders need raw_images; for quick checks)")
    b.add_argument("--no-video", action="store_true", help="no video.mp4 beside the raw images")
    b.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")
    b.set_defaults(func=_build)


def _build(args: argparse.Namespace) -> int:
    from luminous_sim.data import BuildOptions, build_split, make_backend

    options = BuildOptions(frames=not args.no_frames, video=not args.no_video)
    with make_backend(args.backend, args.workers, args.address) as backend:
        report = build_split(Path(args.out), args.split, args.count, backend, options,
                             progress=not args.no_progress)
    print(f"{args.split}: episodes 0..{args.count - 1} in {report.out}/ ({report.built} built, "
          f"{report.failed} failed; {report.ran} run now)")
    print(report.summary())
    print(f"trials listed in {report.out / 'splits.json'}; every episode's record in {report.out / 'manifest.jsonl'}")
    return 0
