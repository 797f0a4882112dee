"""`luminous alfred parse DIR [--merge] --out OUT`: ALFRED trajectories -> CDFs, merged CDFs and a report."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from luminous_sim.cli.args import output_dir, seed


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the `alfred` subcommand and its actions."""
    parser = subparsers.add_parser("alfred", help="ALFRED data: parse trajectories into CDFs")
    sub = parser.add_subparsers(dest="alfred_command", required=True)
    p = sub.add_parser(
        "parse",
        help="parse every traj_data.json under DIR into a CDF (and merge per floor plan), realise each with CSSG "
        "in its own floor plan's shell, and write report.json / report.md",
        description="Parse every traj_data.json under DIR into a CDF (and merge per floor plan), realise each with "
        "CSSG in its own floor plan's shell, and write report.json / report.md.",
        epilog="Exit status: 0 when at least one trajectory parsed, 1 when none did (the reports are written all "
        "the same and say why), 2 for a bad argument or a folder without traj_data.json.",
    )
    p.add_argument("dir", type=Path, help="folder with ALFRED trajectories (.../traj_data.json), e.g. valid_seen")
    p.add_argument("--out", required=True, type=output_dir, help="folder to write cdf/, merged/ and the reports")
    p.add_argument("--merge", action="store_true", help="also merge the trajectories of each floor plan")
    p.add_argument("--no-realise", dest="realise", action="store_false",
                   help="skip generating each CDF's scene with CSSG (parse and merge only)")
    p.add_argument("--seed", type=seed, default=0, help="CSSG's seed for the realisation (default 0)")
    p.set_defaults(func=cmd_parse)


def _bar(items: Iterable[Any], desc: str) -> Iterable[Any]:
    from tqdm import tqdm

    listed = list(items)
    return tqdm(listed, desc=desc, unit="file", disable=len(listed) < 10, leave=False)


def cmd_parse(args: argparse.Namespace) -> int:
    from luminous_sim.data import parse_directory, write_report

    report = parse_directory(args.dir, merge=args.merge, realise_scenes=args.realise, seed=args.seed,
                             progress=_bar)
    write_report(report, args.out)
    print(report.summary())
    print(f"wrote {args.out / 'report.json'} and {args.out / 'report.md'}")
    if report.parsed == 0:
        first = next((f.error for f in report.files if f.error), None)
        why = f" (the first: {first.splitlines()[0]})" if first else ""
        print(f"luminous alfred parse: none of the {len(report.files)} trajectories under {args.dir} parsed{why}",
              file=sys.stderr)
        return 1
    return 0
