"""`luminous import-layout`, `export-layout` and `train-layouts`: layouts from other methods (3D-FRONT, ATISS)
or our own format into scenes, scenes into the layout format, and the learned generator's training
(docs/layouts.md)."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from luminous_sim.cli.args import limited, output_dir, output_file, seed
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.vocab import ROOM_TYPES

DEFAULT_EPOCHS = 16
DEFAULT_ROOMS = 80
EPILOG = ("example: luminous import-layout tests/layouts/fixtures/front_kitchen.json --format front "
          "--model-info tests/layouts/fixtures/front_model_info.json --out out/imported")


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("import-layout", help="make a scene of a layout from 3D-FRONT, ATISS or our own format",
                            description="Read a layout, match its objects to the asset library by category and "
                            "size, repair it with CSSG (or reject it with the reasons), add small objects, and "
                            "write the same files as `luminous generate` plus repair_report.json and layout.json.",
                            epilog=EPILOG)
    parser.add_argument("file", type=Path, help="the layout file (JSON; ATISS also .npz)")
    parser.add_argument("--format", required=True, choices=("front", "atiss", "luminous"),
                        help="front: a 3D-FRONT scene JSON; atiss: an ATISS/3D-SLN object list; "
                        "luminous: our luminous-layout/1")
    parser.add_argument("--out", type=output_dir, required=True, help="output folder")
    parser.add_argument("--seed", type=seed, default=None,
                        help="seed of the object layer's draws (default: the layout's own, else 0)")
    parser.add_argument("--room", help="front: the room's instanceid (default: the first furnished room)")
    parser.add_argument("--model-info", type=Path, help="front: 3D-FUTURE's model_info.json (jid -> category)")
    parser.add_argument("--room-type", choices=ROOM_TYPES, help="our room type, overriding the file's")
    parser.add_argument("--require", action="append", default=[], metavar="TYPE",
                        help="an object type the scene must hold (repeatable), e.g. Apple")
    parser.add_argument("--no-repair", action="store_true", help="validate only: move nothing")
    parser.add_argument("--no-physics", action="store_true", help="skip the PyBullet settling check")
    parser.set_defaults(func=_run_import)
    export = sub.add_parser("export-layout", help="write a scene (scene.json) in the layout format",
                            description="Write a Luminous scene as a luminous-layout/1 file; importing it back "
                            "(--format luminous) gives the same scene.")
    export.add_argument("scene", type=Path, help="a scene.json written by `luminous generate`")
    export.add_argument("--out", type=output_file([".json"], "a JSON"), required=True, help="layout file to write")
    export.set_defaults(func=_run_export)
    train = sub.add_parser("train-layouts", help="train the learned layout generator (needs torch)",
                           description="Train the ATISS-like layout model on CSSG's layouts in procedural rooms and "
                           "in the rooms converted from AI2-THOR, on the CPU, and write its checkpoint. The same "
                           "arguments give the same model; the defaults remake the shipped one (a few minutes).",
                           epilog="example: luminous train-layouts --out model.pt; then "
                           "luminous generate --method learned --model model.pt --out out/l")
    train.add_argument("--out", type=output_file([".pt"], "a .pt"), required=True, help="checkpoint to write")
    train.add_argument("--epochs", type=limited(1, "MAX_EPOCHS"), default=DEFAULT_EPOCHS,
                       help=f"passes over the training views (default {DEFAULT_EPOCHS})")
    train.add_argument("--rooms", type=limited(1, "MAX_LAYOUT_ROOMS"), default=DEFAULT_ROOMS,
                       help=f"training rooms per room type (default {DEFAULT_ROOMS})")
    train.add_argument("--seed", type=seed, default=0, help="seed of the training draws (default 0)")
    train.add_argument("--no-augment", action="store_true", help="no quarter-turned and mirrored views")
    train.add_argument("--quiet", action="store_true", help="no loss per epoch")
    train.set_defaults(func=_run_train)


def _require(types: list[str]) -> tuple[str, ...]:
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.layouts import LayoutError

    known = default_catalog().types()
    bad = [t for t in types if t not in known]
    if bad:
        raise LayoutError(f"--require {bad[0]}: not an object type of the asset library")
    return tuple(types)


def _run_import(args: argparse.Namespace) -> int:
    from luminous_sim import layouts
    from luminous_sim.fileio import write_atomic
    from luminous_sim.scene_outputs import write_scene_outputs

    required = _require(args.require)
    if args.format == "front":
        layout = layouts.import_front(args.file, room=args.room, model_info=args.model_info, room_type=args.room_type)
    elif args.format == "atiss":
        layout = layouts.import_atiss(args.file, room_type=args.room_type)
    else:
        layout = layouts.load(args.file)
        if args.room_type:
            layout = layout.model_copy(update={"room": layout.room.model_copy(update={"room_type": args.room_type})})
    realized = layouts.realize(layout, args.seed, repair=not args.no_repair, required=required, where=str(args.file))
    layout.save(args.out / "layout.json")
    write_atomic(args.out / "repair_report.json", json.dumps(realized.to_dict(), indent=1, sort_keys=True) + "\n")
    if not realized.ok:
        raise InfeasibleSceneError(f"{args.file}: layout rejected: {'; '.join(realized.problems()[:4])} "
                                   f"(details in {args.out / 'repair_report.json'})")
    generated = realized.given.generated
    report = write_scene_outputs(generated, args.out, physics=not args.no_physics)
    ok = report["layout"]["ok"] and report.get("physics", {}).get("ok", True)
    moved = sum(r.action == "moved" for r in realized.given.repairs)
    added = sum(r.action == "placed" for r in realized.given.repairs)
    dropped = realized.dropped
    print(f"wrote {args.out}/scene.json ({len(generated.scene.objects)} objects: {len(realized.matches)} matched, "
          f"{len(realized.unmatched)} left out, {moved} moved, {added} added), report.json (valid: {ok}), "
          "repair_report.json, layout.json, top_down.png, egocentric.png")
    if dropped:
        shown = "; ".join(f"{d.get('entry')} ({d.get('reason')})" for d in dropped[:5])
        more = f"; ... ({len(dropped)} in all)" if len(dropped) > 5 else ""
        print(f"dropped {len(dropped)} entr{'y' if len(dropped) == 1 else 'ies'} of {args.file}: {shown}{more} "
              f"(all in {args.out / 'repair_report.json'}, 'dropped')")
    return 0


def _run_export(args: argparse.Namespace) -> int:
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.layouts import LayoutError, layout_of_scene
    from luminous_sim.scene import Scene

    layout = layout_of_scene(Scene.load(args.scene), default_catalog(), where=f"{args.scene} (as a layout)")
    try:
        layout.save(args.out)
    except OSError as exc:
        raise LayoutError(f"--out {args.out}: cannot write ({exc.strerror or exc})") from None
    print(f"wrote {args.out} ({len(layout.objects)} objects, room {layout.room.name})")
    return 0


def _run_train(args: argparse.Namespace) -> int:
    from luminous_sim.layouts import train_layouts

    def progress(epoch: int, loss: float) -> None:
        if not args.quiet:
            print(f"epoch {epoch}/{args.epochs}: loss {loss:.3f}", flush=True)

    result = train_layouts(args.out, per_type=args.rooms, epochs=args.epochs, seed=args.seed,
                           augment=not args.no_augment, progress=progress)
    print(f"wrote {result.path} (trained on {result.layouts} CSSG layouts, {result.examples} views, final loss "
          f"{result.losses[-1]:.3f}, {result.seconds:.0f} s)")
    return 0
