"""Entry point of the `luminous` console script.

Each subcommand lives in its own module exposing `register(subparsers)`; the parser it adds sets
`func(args) -> int`. A LuminousError becomes a one-line message on stderr and exit status 2.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from luminous_sim.errors import LuminousError

SUBCOMMAND_MODULES: tuple[str, ...] = (
    "luminous_sim.cli.assets_cmd",
    "luminous_sim.cli.cdf_cmd",
    "luminous_sim.cli.demo_cmd",
    "luminous_sim.cli.generate_cmd",
    "luminous_sim.cli.rooms_cmd",
    "luminous_sim.cli.speaker_cmd",
)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="luminous", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    for name in SUBCOMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except LuminousError as exc:
        print(f"luminous {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
