"""`luminous rooms ...`: list, convert, show and generate room structures."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from luminous_sim.cli.args import limited, output_dir, output_file, seed
from luminous_sim.errors import RoomError, path_kind
from luminous_sim.rooms.alfred_convert import convert_all
from luminous_sim.rooms.generate import SHAPES, generate_shell
from luminous_sim.rooms.library import check_name, room_files, room_names, shell_for
from luminous_sim.rooms.shell import load_shell, save_shell
from luminous_sim.vocab import ROOM_TYPES

IMAGE_SUFFIXES = (".png", ".svg", ".pdf", ".jpg", ".jpeg")
"""Formats `rooms show` writes (matplotlib picks the format from the suffix)."""


def register(subparsers: argparse._SubParsersAction) -> None:
    """Add the `rooms` subcommand and its actions."""
    parser = subparsers.add_parser(
        "rooms", help="room structures: list, convert ALFRED layouts, show, generate"
    )
    sub = parser.add_subparsers(dest="rooms_command", required=True)

    p = sub.add_parser("list", help="list the room library (files and procedural names)")
    p.add_argument("--json", action="store_true", help="print a JSON list instead of a table")
    p.set_defaults(func=cmd_list)

    p = sub.add_parser(
        "convert", help="convert ALFRED FloorPlan<N>-layout.npy files to room JSON files"
    )
    p.add_argument(
        "--layouts", required=True, type=Path, help="folder with FloorPlan<N>-layout.npy files"
    )
    p.add_argument("--out", required=True, type=output_dir, help="output folder for FloorPlan<N>.json")
    p.add_argument(
        "--scene", type=limited(1, "MAX_FLOOR_PLAN"), action="append",
        help="convert only this scene number (repeatable)"
    )
    p.set_defaults(func=cmd_convert)

    p = sub.add_parser("show", help="draw a room from above into an image file")
    p.add_argument(
        "name", help="library room name (e.g. FloorPlan1) or procedural name (e.g. kitchen_L)"
    )
    p.add_argument("--out", required=True, type=output_file(IMAGE_SUFFIXES, "an image"),
                   help=f"image file to write (e.g. room.png; {', '.join(IMAGE_SUFFIXES)})")
    p.add_argument("--seed", type=seed, default=0, help="seed for procedural names, a whole number >= 0 (default 0)")
    p.set_defaults(func=cmd_show)

    p = sub.add_parser(
        "generate",
        help="generate a procedural room and write its JSON (use it through LUMINOUS_ROOM_LIBRARY)",
        description="Generate a procedural room and write its JSON. To use it in scenes, put the file in a "
        "folder and point LUMINOUS_ROOM_LIBRARY at that folder (several folders: separated by ':'); its rooms "
        "then join the library (`luminous rooms list`), named by their file names without .json, and "
        "`luminous generate --room NAME` or a CDF's `room: NAME` can use them.",
    )
    p.add_argument("room_type", choices=ROOM_TYPES, help="the room type")
    p.add_argument("--shape", choices=SHAPES, default=None, help="outline shape (default: drawn at random)")
    p.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    p.add_argument("--name", default=None, help="room name (default <type>_<shape>)")
    p.add_argument("--out", required=True, type=output_file([".json"], "a JSON"), help="JSON file to write")
    p.set_defaults(func=cmd_generate)


def cmd_list(args: argparse.Namespace) -> int:
    """Print every room name with its type, shape, area and source."""
    rows: list[dict[str, str | float]] = []
    files = room_files()
    for name in room_names():
        if name not in files:
            rows.append({"name": name, "kind": "procedural"})
            continue
        shell = load_shell(files[name])
        rows.append(
            {
                "name": name,
                "kind": "file",
                "room_type": shell.room_type,
                "shape": shell.shape,
                "area": round(shell.area, 2),
                "source": shell.source,
                "path": str(files[name]),
            }
        )
    if args.json:
        print(json.dumps(rows, indent=1))
        return 0
    for r in rows:
        if r["kind"] == "procedural":
            print(f"{r['name']:<24} procedural")
        else:
            print(
                f"{r['name']:<24} {r['room_type']:<11} {r['shape']:<12} "
                f"{r['area']:>6.1f} m2  {r['source']}"
            )
    return 0


def cmd_convert(args: argparse.Namespace) -> int:
    """Convert ALFRED layouts, with a progress bar on stderr."""
    kind = path_kind(args.layouts)
    if kind != "a folder":
        what = "no such layouts folder" if kind == "no such file or folder" else kind
        raise RoomError(f"{args.layouts}: {what}; expected a folder of FloorPlan<N>-layout.npy files")
    total = len(args.scene) if args.scene else len(list(args.layouts.glob("FloorPlan*-layout.npy")))
    try:
        from tqdm import tqdm

        bar = tqdm(total=total, desc="converting", unit="scene", file=sys.stderr, disable=None)
    except ImportError:  # pragma: no cover - tqdm is a dependency
        bar = None
    written = convert_all(
        args.layouts,
        args.out,
        scenes=args.scene,
        progress=(lambda n: bar.update(1)) if bar else None,
    )
    if bar is not None:
        bar.close()
    print(f"wrote {len(written)} rooms and splits.json to {args.out}")
    return 0


def cmd_show(args: argparse.Namespace) -> int:
    """Draw a room (library or procedural) into an image file."""
    from luminous_sim.rooms.plot import plot_shell

    shell = shell_for(args.name, np.random.default_rng(args.seed))
    out = plot_shell(shell, args.out)
    print(f"wrote {out}")
    return 0


def cmd_generate(args: argparse.Namespace) -> int:
    """Generate a procedural room and save it as JSON."""
    if args.name is not None:
        check_name(args.name)
    shell = generate_shell(
        args.room_type, np.random.default_rng(args.seed), args.shape, name=args.name
    )
    out = save_shell(shell, args.out)
    print(f"wrote {out} ({shell.shape}, {shell.area:.1f} m2)")
    if _is_room_name(out.stem):
        print(f"use it: LUMINOUS_ROOM_LIBRARY={out.parent.resolve()} luminous generate --room {out.stem} ...")
    return 0


def _is_room_name(stem: str) -> bool:
    try:
        check_name(stem)
    except RoomError:
        return False
    return True
