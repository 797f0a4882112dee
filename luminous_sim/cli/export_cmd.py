"""`luminous export`: a generated room or house, as it is, to glTF (.glb), USD or MJCF (MuJoCo)."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cli.args import output_file
from luminous_sim.export import FORMATS, SUFFIXES

EPILOG = (
    "example: luminous export out/scene --format glb --out out/scene.glb   (formats: glb for any glTF viewer, "
    "usd for USD tools (needs usd-core), mjcf for MuJoCo; doors open and things sliced as scene.json says)"
)


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("export", help="export a scene to glTF (.glb), USD or MJCF (MuJoCo)", epilog=EPILOG)
    parser.add_argument("scene_dir", type=Path, metavar="SCENE_DIR",
                        help="a scene folder written by `luminous generate` (or its scene.json)")
    parser.add_argument("--format", choices=FORMATS, required=True, help="glb, usd or mjcf")
    suffixes = tuple(s for group in SUFFIXES.values() for s in group)
    parser.add_argument("--out", type=output_file(suffixes, "an export"), required=True,
                        help="file to write: .glb; .usd, .usdc (binary) or .usda (text); .xml (MJCF)")
    parser.add_argument("--no-ceiling", action="store_true",
                        help="leave the ceiling and its light out (to look in from above)")
    parser.add_argument("--check", action="store_true",
                        help="with --format mjcf: load the file in MuJoCo, step it 2 s and report how far "
                        "anything moved (needs mujoco)")
    parser.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from luminous_sim.export import ExportError, check_format, export

    check_format(args.format, args.out)
    if args.check and args.format != "mjcf":
        raise ExportError("--check is for --format mjcf (MuJoCo's settle check)")
    result = export(args.scene_dir, args.format, args.out, ceiling=not args.no_ceiling)
    print(f"wrote {result.path} ({result.format}, {result.objects} bodies, {result.bytes / 1e6:.2f} MB, "
          f"{result.seconds:.2f} s)")
    if args.check:
        from luminous_sim.export.mjcf import SETTLE_ANGLE, SETTLE_SLIDE, SETTLE_XY, SETTLE_Z, settle_check

        c = settle_check(result.path)
        print(f"MuJoCo, {c.seconds:g} s: largest move {c.xy[0] * 100:.2f} cm sideways ({c.xy[1] or '-'}), "
              f"{c.z[0] * 100:.2f} cm vertically ({c.z[1] or '-'}), joints {c.angle[0]:.4f} rad ({c.angle[1] or '-'}),"
              f" {c.slide[0] * 100:.2f} cm ({c.slide[1] or '-'}); tolerance {SETTLE_XY * 100:g} cm / "
              f"{SETTLE_Z * 100:g} cm / {SETTLE_ANGLE:g} rad / {SETTLE_SLIDE * 100:g} cm: "
              f"{'ok' if c.ok else 'MOVED'}")
        return 0 if c.ok else 1
    return 0
