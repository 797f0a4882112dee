"""`luminous generate`: CSSG from a CDF to scene files, one folder per scene."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from luminous_sim.cli.args import int_range, output_dir, seed
from luminous_sim.errors import CDFError, InfeasibleSceneError
from luminous_sim.limits import MAX_GENERATE_SCENES
from luminous_sim.resources import default_house
from luminous_sim.vocab import ROOM_TYPES

EPILOG = (
    "example: luminous generate --cdf cdf/examples/kitchen_coffee_mug.yaml --room FloorPlan1 --seed 0 "
    "--out out/scene   (`luminous rooms list` names the rooms; --room must be of a room type the CDF allows)"
)


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("generate", help="generate scenes from a CDF with CSSG", epilog=EPILOG)
    parser.add_argument("--cdf", type=Path, help="challenge definition (YAML/JSON); default: an empty one")
    parser.add_argument("--room-type", default="Kitchen", choices=ROOM_TYPES, help="room type when no CDF is given")
    parser.add_argument("--seed", type=seed, default=0, help="random seed, a whole number >= 0 (default 0)")
    parser.add_argument("--count", type=int_range(1, MAX_GENERATE_SCENES), default=1,
                        help=f"number of scenes, with seeds seed, seed+1, ... (default 1; at most "
                             f"{MAX_GENERATE_SCENES})")
    parser.add_argument("--out", type=output_dir, required=True,
                        help="output folder (with --count > 1: one scene_NNNNN/ folder per scene in it)")
    parser.add_argument("--room", help="a room-library name (e.g. FloorPlan1, kitchen_L; see `luminous rooms list`); "
                        "overrides the CDF's room")
    parser.add_argument("--method", choices=("cssg", "uniform", "learned"), default="cssg",
                        help="cssg (default); uniform: the uniform-random baseline; learned: furniture by the "
                        "learned layout model (needs torch), repaired and furnished by CSSG, the CDF giving only "
                        "the room and the small objects it names (not its relations)")
    parser.add_argument("--baseline", action="store_true", help="the same as --method uniform")
    parser.add_argument("--model", type=Path, help="with --method learned: a checkpoint of `luminous train-layouts` "
                        "(default: the shipped model)")
    parser.add_argument("--no-physics", action="store_true", help="skip the PyBullet settling check")
    parser.add_argument("--house", type=Path, nargs="?", const=DEFAULT_HOUSE, metavar="HOUSE.yaml",
                        help="generate a multi-room house from a CDF with a scene.house section (alone: the "
                        "default house, the shipped example houses/default_house.yaml, which `luminous cdf "
                        "examples` copies out); not with --cdf, --room or --method")
    parser.set_defaults(func=_run)


DEFAULT_HOUSE = default_house()
"""The house `--house` generates when given no file."""


def check_room_type(room_type: str, allowed: tuple[str, ...] | list[str], room: str, cdf: Path | None) -> None:
    """Refuse a --room whose type the CDF does not allow (its objects would never fit the room's purpose).

    Raises:
        CDFError: naming the room, its type and the CDF's room types.
    """
    if room_type in allowed:
        return
    source = f"CDF {cdf} (scene.room_type)" if cdf else "--room-type"
    raise CDFError(f"--room {room} is a {room_type}, but {source} asks for {' or '.join(allowed)}; "
                   f"pick a room of that type (`luminous rooms list`) or leave --room out")


def _check_sizes(doc, source: Path | None) -> None:
    """The CDF's sizes against the library (generate() checks too, but cannot name the file)."""
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg.attributes import check_sizes

    try:
        check_sizes(doc, default_catalog())
    except CDFError as exc:
        raise CDFError(f"{source or 'the CDF'}: {exc}") from None


def _run(args: argparse.Namespace) -> int:
    if args.house is not None:
        return _run_house(args)
    import numpy as np
    from tqdm import tqdm

    from luminous_sim import cdf as cdf_mod
    from luminous_sim.cssg import Generated, empty_cdf, generate, sample_uniform
    from luminous_sim.scene_outputs import summary_lines, write_scene_outputs

    doc = cdf_mod.load(args.cdf) if args.cdf else empty_cdf(args.room_type)
    if doc.scene.house is not None:  # a house CDF given as --cdf: the same as --house
        args.house, args.cdf = args.cdf, None
        return _run_house(args)
    _check_sizes(doc, args.cdf)
    shell = None
    if args.room:
        from luminous_sim.rooms.library import shell_for

        shell = shell_for(args.room, np.random.default_rng(args.seed))
        check_room_type(shell.room_type, list(doc.scene.room_type), args.room, args.cdf)
    failures = 0
    for k in tqdm(range(args.count), desc="scenes", unit="scene", disable=args.count == 1):
        seed = args.seed + k
        if args.method == "learned":
            generated = _learned(doc, shell, seed, args.model)
        elif args.baseline or args.method == "uniform":
            from luminous_sim.assets.catalog import default_catalog
            from luminous_sim.cssg import choose_room

            rng = np.random.default_rng(np.random.SeedSequence([seed, 0]))
            room = shell or choose_room(doc, rng)
            draft, layout = sample_uniform(doc, room, rng, default_catalog())
            generated = Generated(draft.to_scene("uniform", seed, source=doc.name or ""), layout)
        else:
            try:
                generated = generate(doc, seed=seed, room=shell)
            except InfeasibleSceneError as exc:
                if args.room:  # the named room may be too small or crowded for what the CDF asks
                    raise InfeasibleSceneError(f"{exc} (in --room {args.room}; try another room or leave "
                                               "--room out)") from None
                raise
        sub = args.out if args.count == 1 else args.out / f"scene_{seed:05d}"
        report = write_scene_outputs(generated, sub, physics=not args.no_physics)
        ok = report["satisfies_cdf"] and report.get("physics", {}).get("ok", True)
        failures += not ok
        for line in summary_lines(sub, report):
            print(line, file=sys.stderr)
        for name, keys in report["layout"].get("ignored_attributes", {}).items():
            kind = next((o.type for o in generated.scene.objects if o.name == name), "fixture")
            print(f"note: {sub}: {name} is the room's own {kind}; its attributes {', '.join(keys)} were not applied")
        if args.count == 1:
            print(f"wrote {sub}/scene.json ({len(generated.scene.objects)} objects, room {generated.scene.room.name}), "
                  f"report.json (valid: {ok}), top_down.png, egocentric.png")
    if args.count > 1:
        print(f"wrote {args.count} scenes under {args.out} ({args.count - failures} fully valid)")
    return 0


def _learned(doc, shell, seed: int, model: Path | None):
    """The learned generator's scene for `seed` in `shell` (else a room the CDF allows), with the CDF's
    small objects required."""
    import numpy as np

    from luminous_sim.cssg import choose_room
    from luminous_sim.layouts import LearnedLayouts, realize
    from luminous_sim.vocab import abilities

    room = shell or choose_room(doc, np.random.default_rng(np.random.SeedSequence([seed, 0])))
    required = tuple(sorted({o.type for o in doc.scene.objects if abilities(o.type).pickupable}))
    realized = realize(LearnedLayouts(model).layout(room, seed), seed, required=required)
    for problem in realized.problems():
        print(f"note: seed {seed}: learned layout: {problem}")
    return realized.given.generated


def _run_house(args: argparse.Namespace) -> int:
    """`generate --house`: one house per seed, with the same files as a room."""
    from tqdm import tqdm

    from luminous_sim import cdf as cdf_mod
    from luminous_sim.cssg import generate_house
    from luminous_sim.scene_outputs import summary_lines, write_scene_outputs

    clashes = [flag for flag, given in (("--cdf", args.cdf), ("--room", args.room),
                                        ("--method", args.method != "cssg" or args.baseline)) if given]
    if clashes:
        raise CDFError(f"--house takes no {', '.join(clashes)}: a house's CDF gives its rooms, and CSSG furnishes them")
    doc = cdf_mod.load(args.house)
    if doc.scene.house is None:
        raise CDFError(f"{args.house}: scene.house is not set; expected a house (scene.house.rooms, ...), e.g. "
                       f"{DEFAULT_HOUSE.name}")
    failures = 0
    for k in tqdm(range(args.count), desc="houses", unit="house", disable=args.count == 1):
        seed = args.seed + k
        generated = generate_house(doc, seed=seed)
        sub = args.out if args.count == 1 else args.out / f"scene_{seed:05d}"
        report = write_scene_outputs(generated, sub, physics=not args.no_physics)
        ok = report["satisfies_cdf"] and report.get("physics", {}).get("ok", True)
        failures += not ok
        for line in summary_lines(sub, report):
            print(line, file=sys.stderr)
        if args.count == 1:
            rooms = ", ".join(f"{r.name} ({r.room_type})" for r in generated.plan.shell.house.rooms)  # type: ignore[union-attr]
            print(f"wrote {sub}/scene.json ({len(generated.scene.objects)} objects, house {generated.scene.room.name}: "
                  f"{rooms}), report.json (valid: {ok}), top_down.png, egocentric.png")
    if args.count > 1:
        print(f"wrote {args.count} houses under {args.out} ({args.count - failures} fully valid)")
    return 0
