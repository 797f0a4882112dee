"""`luminous cdf`: validate Challenge Definition Format files, export the CDF JSON Schema, copy out the shipped
example CDFs."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cdf import CDF_VERSION, export_schema, from_document, read_document, summarize
from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cli.args import output_dir
from luminous_sim.errors import CDFError, RoomError


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    """Add the `cdf` command and its `validate`, `schema` and `examples` subcommands."""
    parser = subparsers.add_parser("cdf", help="validate CDF files, export the CDF JSON Schema, copy the examples")
    sub = parser.add_subparsers(dest="cdf_command", required=True)
    validate = sub.add_parser(
        "validate", help="check CDF files (.yaml, .yml, .json) and summarise them"
    )
    validate.add_argument("files", nargs="+", type=Path, metavar="FILE", help="CDF files to check")
    validate.set_defaults(func=run_validate)
    schema = sub.add_parser("schema", help=f"write cdf-v{CDF_VERSION}.schema.json")
    schema.add_argument("--out", type=output_dir, required=True, metavar="DIR", help="output folder")
    schema.set_defaults(func=run_schema)
    examples = sub.add_parser("examples", help="copy the example CDFs that ship with the package into a folder",
                              epilog="example: luminous cdf examples --out my_cdfs && luminous generate --cdf "
                                     "my_cdfs/kitchen_apple_fridge.yaml --seed 0 --out out/apple")
    examples.add_argument("--out", type=output_dir, required=True, metavar="DIR",
                          help="folder to copy them into (new or empty: nothing there is overwritten)")
    examples.set_defaults(func=run_examples)


def _check_sizes(cdf, path: Path) -> None:
    """Sizes that no asset of the type meets (generate would refuse them too)."""
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg.attributes import check_sizes

    try:
        check_sizes(cdf, default_catalog())
    except CDFError as exc:
        raise CDFError(f"{path}: {exc}") from None


def _check_start(cdf, path: Path) -> None:
    """An agent start outside the named library room (procedural rooms are drawn at generation time)."""
    from luminous_sim.cssg import start_outside
    from luminous_sim.rooms.library import is_procedural, load_room

    room = cdf.scene.room
    if cdf.task is None or cdf.task.agent is None or not isinstance(room, str) or is_procedural(room):
        return
    try:
        shell = load_room(room)
    except RoomError as exc:
        raise CDFValidationError(str(path), [Issue("scene.room", str(exc))]) from None
    outside = start_outside(cdf, shell)
    if outside:
        raise CDFValidationError(str(path), [Issue("task.agent.position", outside)])


def run_validate(args: argparse.Namespace) -> int:
    """Validate each file; print a summary of each valid one, raise one error listing the others."""
    issues: list[str] = []
    for path in args.files:
        try:
            doc = read_document(path)
            cdf = from_document(doc, str(path))
            _check_sizes(cdf, path)
            _check_start(cdf, path)
        except CDFError as exc:
            issues.append(str(exc))
            continue
        version = doc.get("cdf_version") if isinstance(doc, dict) else None
        upgraded = f", upgraded from v{version}" if version != CDF_VERSION else ""
        print(f"{path}: OK (cdf v{CDF_VERSION}{upgraded})")
        for line in summarize(cdf).splitlines():
            print(f"  {line}")
    if issues:
        raise CDFError("\n".join(issues))  # each line already names its file and key path
    return 0


def run_schema(args: argparse.Namespace) -> int:
    """Write the JSON Schema of the current CDF version into `--out`."""
    try:
        path = export_schema(args.out)
    except OSError as exc:
        raise CDFValidationError(
            str(args.out), [Issue("", f"cannot write the schema ({exc.strerror or exc})")]
        ) from None
    print(path)
    return 0


def run_examples(args: argparse.Namespace) -> int:
    """Copy the shipped example CDFs (`luminous_sim.resources.examples_dir`) into `--out`, which must be new or
    empty (a copy never overwrites a file of the user's)."""
    import shutil

    from luminous_sim.errors import LuminousError
    from luminous_sim.resources import examples_dir

    out: Path = args.out
    if out.is_symlink() or (out.exists() and (not out.is_dir() or any(out.iterdir()))):
        raise LuminousError(f"--out {out}: expected a new or empty folder (nothing there is overwritten)")
    source = examples_dir()
    files = sorted(p for p in source.rglob("*.yaml") if p.is_file())
    if not files:
        raise LuminousError(f"no example CDFs in {source}: the package is incomplete; reinstall luminous-sim")
    for path in files:
        target = out / path.relative_to(source)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(path, target)
        print(target)
    print(f"copied {len(files)} example CDFs from {source} to {out}")
    return 0
