"""`luminous assets build|list|sheet|import|digest`: the asset library from the command line."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from luminous_sim.cli.args import int_range, limited, output_dir, output_file, positive_float


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("assets", help="build, list, preview and import assets")
    cmds = parser.add_subparsers(dest="assets_command", required=True)

    build = cmds.add_parser("build", help="regenerate the asset library deterministically")
    build.add_argument("--types", nargs="*", help="only these object types (default: all)")
    build.add_argument("--out", type=output_dir,
                       help="library folder (default: the library in use, the shipped one unless LUMINOUS_ASSETS "
                       "names another; a rebuild changes its digest: see `luminous assets digest`)")
    build.add_argument("--jobs", type=limited(1, "MAX_WORKERS"), default=2, help="worker processes (default 2)")
    build.set_defaults(func=_build)

    ls = cmds.add_parser("list", help="print the catalog")
    ls.add_argument("--json", action="store_true", help="the full catalog as JSON")
    ls.add_argument("--type", help="only this object type (an ALFRED type, e.g. Mug)")
    ls.set_defaults(func=_list)

    sheet = cmds.add_parser("sheet", help="render a contact sheet of every asset")
    sheet.add_argument("--out", type=output_file([".png"], "a PNG"), required=True, help="PNG file to write")
    sheet.add_argument("--types", nargs="*", help="only these object types")
    sheet.add_argument("--tile", type=int_range(16, 1024), default=128,
                       help="thumbnail size in pixels, 16 to 1024 (default 128)")
    sheet.add_argument("--states-on", action="store_true", help="open joints, switch things on, show dirt")
    sheet.set_defaults(func=_sheet)

    digest = cmds.add_parser("digest", help="the digest of an asset library (what LUMINOUS_ASSETS_DIGEST names)")
    digest.add_argument("library", type=Path, nargs="?", default=None,
                        help="library folder (default: the one in use)")
    digest.set_defaults(func=_digest)

    imp = cmds.add_parser("import", help="add your own OBJ/GLB/STL/PLY mesh to the user catalog")
    imp.add_argument("mesh", type=Path, help="the mesh file (.obj, .glb, .gltf, .stl, .ply, .off)")
    imp.add_argument("--type", required=True, dest="object_type", help="ALFRED object type, e.g. Mug")
    imp.add_argument("--scale", type=positive_float, default=1.0,
                     help="multiply coordinates (0.01 for centimetres, 0.001 for millimetres; default 1)")
    imp.add_argument("--up", choices=["y", "z"], default="y", help="the mesh's up axis (glTF/OBJ: y)")
    imp.add_argument("--mass", type=positive_float, help="kg (default: from the volume)")
    imp.add_argument("--any-size", action="store_true",
                     help="accept a size far from the catalog's for this type (a toy car, a giant mug)")
    imp.set_defaults(func=_import)


def _digest(args: argparse.Namespace) -> int:
    """Print a library's digest and whether it is the shipped library's."""
    from luminous_sim.resources import ASSET_LIBRARY_SHA256, asset_library_dir, library_digest

    root = args.library if args.library is not None else asset_library_dir()
    got = library_digest(root)
    same = "the shipped library's" if got == ASSET_LIBRARY_SHA256 else "not the shipped library's"
    print(f"{got}  {root} ({same})")
    return 0


def _build(args: argparse.Namespace) -> int:
    from luminous_sim.assets.build import build_library

    report = build_library(out_dir=args.out, types=args.types, jobs=args.jobs)
    print(f"built {report.assets} assets in {report.seconds:.1f} s "
          f"({report.decompositions_computed} new convex decompositions, {report.decompositions_in_cache} cached); "
          f"catalog: {report.catalog}")
    return 0


def _list(args: argparse.Namespace) -> int:
    from luminous_sim.assets.catalog import Catalog

    if args.type:
        from luminous_sim.vocab import check_type

        check_type(args.type, where="--type")
    catalog = Catalog.load()
    entries = [e for e in catalog.to_json() if not args.type or e["type"] == args.type]
    if args.json:
        print(json.dumps(entries, indent=1, sort_keys=True))
        return 0
    for e in entries:
        dims = "x".join(f"{d:.2f}" for d in e["dims"])
        extra = ", ".join(k for k, v in e["abilities"].items() if v)
        print(f"{e['id']:<28} {e['category']:<10} {dims:>16} m  {extra}")
    print(f"{len(entries)} assets, {len({e['type'] for e in entries})} types")
    return 0


def _sheet(args: argparse.Namespace) -> int:
    from luminous_sim.assets.catalog import Catalog
    from luminous_sim.world.asset_sheet import render_sheet

    entries = [e for e in Catalog.load() if not args.types or e.type in args.types]
    if not entries:
        from luminous_sim.errors import AssetError, VocabularyError
        from luminous_sim.vocab import check_type

        try:
            for t in args.types or ():
                check_type(t, where="--types")
        except VocabularyError as exc:
            raise AssetError(f"no assets match: {exc}") from None
        raise AssetError("no assets match; run `luminous assets build` or check --types")
    out = render_sheet(entries, args.out, tile=args.tile, states_on=args.states_on)
    print(f"wrote {out} ({len(entries)} assets)")
    return 0


def _import(args: argparse.Namespace) -> int:
    from luminous_sim.assets.importer import import_mesh

    result = import_mesh(args.mesh, args.object_type, scale=args.scale, up=args.up, mass=args.mass,
                         any_size=args.any_size)
    dims = "x".join(f"{d:.2f}" for d in result.entry["dims"])
    print(f"imported {args.mesh} as {result.asset_id} ({dims} m, {result.entry['collision_hulls']} convex parts) "
          f"into {result.catalog}")
    return 0
