"""`luminous cdf`: validate Challenge Definition Format files and export the CDF JSON Schema."""

from __future__ import annotations

import argparse
from pathlib import Path

from luminous_sim.cdf import CDF_VERSION, export_schema, from_document, read_document, summarize
from luminous_sim.cdf.issues import CDFValidationError, Issue
from luminous_sim.cli.args import output_dir
from luminous_sim.errors import CDFError, RoomError


def register(subparsers: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    """Add the `cdf` command and its `validate` and `schema` subcommands."""
    parser = subparsers.add_parser("cdf", help="validate CDF files, export the CDF JSON Schema")
    sub = parser.add_subparsers(dest="cdf_command", required=True)
    validate = sub.add_parser(
        "validate", help="check CDF files (.yaml, .yml, .json) and summarise them"
    )
    validate.add_argument("files", nargs="+", type=Path, metavar="FILE", help="CDF files to check")
    validate.set_defaults(func=run_validate)
    schema = sub.add_parser("schema", help=f"write cdf-v{CDF_VERSION}.schema.json")
    schema.add_argument("--out", type=output_dir, required=True, metavar="DIR", help="output folder")
    schema.set_defaults(func=run_schema)


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
