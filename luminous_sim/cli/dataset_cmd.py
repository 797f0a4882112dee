"""`luminous dataset minari`: oracle demonstrations of a registered env as a Minari dataset (offline RL).

A thin shell over `luminous_sim.data.minari_export.export_minari`; the `minari` package is imported only when
the command runs (`pip install 'luminous-sim[minari]'`).
"""

from __future__ import annotations

import argparse
import tomllib
from typing import Any

from luminous_sim.cli.args import int_range, output_dir, positive_int, seed

EPILOG = ("example: luminous dataset minari --env Luminous-NavToObject-64-v0 --episodes 100 --out out/minari   "
          "(read back: minari.MinariDataset('out/minari/luminous/NavToObject-64-v0/oracle-v0/data'))")


def env_option(text: str) -> tuple[str, Any]:
    """`NAME=VALUE`, the value read as TOML (`max_steps=100`, `targets="objects"`; a bare word is a string)."""
    name, sep, value = text.partition("=")
    if not sep or not name.isidentifier():
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE (e.g. max_steps=100), got {text!r}")
    try:
        return name, tomllib.loads(f"v = {value}")["v"]
    except tomllib.TOMLDecodeError:
        return name, value


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the `dataset` subcommand and its action `minari`."""
    parser = subparsers.add_parser("dataset", help="export oracle demonstrations (Minari format for offline RL)")
    sub = parser.add_subparsers(dest="dataset_command", required=True)
    p = sub.add_parser("minari", help="roll out the oracle in a registered env and write a Minari dataset",
                       epilog=EPILOG)
    p.add_argument("--env", required=True, help="a registered id, e.g. Luminous-NavToObject-64-v0")
    p.add_argument("--episodes", type=positive_int, required=True, help="episodes to write")
    p.add_argument("--out", type=output_dir, required=True,
                   help="a new folder: the Minari datasets root the dataset is written under")
    p.add_argument("--seed", type=seed, default=0, help="first episode's seed, a whole number >= 0 (default 0)")
    p.add_argument("--dataset-id", default=None, help="Minari dataset id (default luminous/<env>/oracle-v0)")
    p.add_argument("--env-kwarg", type=env_option, action="append", default=[], metavar="NAME=VALUE",
                   help="env option (repeatable), e.g. targets=objects or max_steps=100")
    p.add_argument("--token-length", type=int_range(1, 1000), default=32, help="instruction tokens (default 32)")
    p.add_argument("--max-seeds", type=positive_int, default=None,
                   help="give up after this many seeds (default 10 * episodes + 10)")
    p.add_argument("--jpeg", action="store_true", help="store images JPEG-encoded (lossy, smaller)")
    p.add_argument("--resume", action="store_true", help="go on from the <out>.partial/ an interrupted run left")
    p.set_defaults(func=cmd_minari)


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
