"""Entry point of the `luminous` console script.

Each subcommand lives in its own module exposing `register(subparsers)`; the parser it adds sets
`func(args) -> int`. A LuminousError or an OSError (a file that cannot be read or written) becomes a
one-line message on stderr and exit status 2; bad arguments are refused by argparse, also with status 2.
A reader that stops reading (`luminous rooms list --json | head`) ends the command quietly.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import os
import sys

from luminous_sim.errors import LuminousError

DESCRIPTION = (
    "Luminous-Sim: generate indoor scenes from Challenge Definition Format (CDF) files, simulate them in "
    "PyBullet with ALFRED's agent and actions, and produce ALFRED-style tasks, expert demonstrations and "
    "instructions."
)
EPILOG = "Run `luminous COMMAND --help` for a command's options; `make demo` shows the whole pipeline."

SUBCOMMAND_MODULES: tuple[str, ...] = (
    "luminous_sim.cli.agents_cmd",
    "luminous_sim.cli.alfred_cmd",
    "luminous_sim.cli.assets_cmd",
    "luminous_sim.cli.bc_cmd",
    "luminous_sim.cli.cdf_cmd",
    "luminous_sim.cli.dataset_cmd",
    "luminous_sim.cli.demo_cmd",
    "luminous_sim.cli.eval_cmd",
    "luminous_sim.cli.export_cmd",
    "luminous_sim.cli.generate_cmd",
    "luminous_sim.cli.layout_cmd",
    "luminous_sim.cli.rooms_cmd",
    "luminous_sim.cli.run_cmd",
    "luminous_sim.cli.speaker_cmd",
    "luminous_sim.cli.view_cmd",
)


def build_parser() -> argparse.ArgumentParser:
    """The `luminous` parser with every subcommand registered."""
    parser = argparse.ArgumentParser(prog="luminous", description=DESCRIPTION, epilog=EPILOG)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for name in SUBCOMMAND_MODULES:
        importlib.import_module(name).register(sub)
    return parser


def _quiet_stdout() -> None:
    """Point stdout at /dev/null so that flushing it at exit raises no second BrokenPipeError."""
    with contextlib.suppress(OSError, ValueError):  # stdout without a file descriptor (captured in tests)
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())


def _os_message(exc: OSError) -> str:
    where = exc.filename if exc.filename is not None else ""
    what = exc.strerror or str(exc)
    return f"{where}: {what}" if where else what


def main(argv: list[str] | None = None) -> int:
    """Run `luminous` with `argv` (default: the process's arguments); the exit status."""
    args = build_parser().parse_args(argv)
    try:
        code = int(args.func(args) or 0)
        sys.stdout.flush()  # inside the try: a closed pipe shows here, not as a message at exit
        return code
    except LuminousError as exc:
        print(f"luminous {args.command}: error: {exc}", file=sys.stderr)
    except BrokenPipeError:
        _quiet_stdout()
        return 0  # the reader had all it wanted (`| head`): not a failure of this command
    except OSError as exc:
        print(f"luminous {args.command}: error: {_os_message(exc)}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
