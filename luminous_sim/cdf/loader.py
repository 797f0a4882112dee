"""Entry points: `load(path)`, `loads(text)`, `from_document(doc)`, `dump(cdf, path)`, `dumps(cdf)`.

Every problem raises CDFValidationError (a CDFError) whose message names the file, the key path and
what was expected; no pydantic, YAML, JSON or OS error escapes.
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from luminous_sim.cdf.bounds import document_issues
from luminous_sim.cdf.issues import CDFValidationError, Issue, from_validation_error
from luminous_sim.cdf.reader import MAX_BYTES, check_tree, parse_text
from luminous_sim.cdf.schema import CDF_VERSION, ChallengeDefinition
from luminous_sim.cdf.upgrade import document_version, upgrade
from luminous_sim.errors import mode_kind

SUFFIXES: dict[str, str] = {".yaml": "yaml", ".yml": "yaml", ".json": "json"}


def format_of(path: str | os.PathLike[str]) -> str:
    """ "yaml" or "json" from a file name's suffix.

    Raises:
        CDFValidationError: Any other suffix.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in SUFFIXES:
        raise CDFValidationError(
            str(path), [Issue("", f"unknown file suffix {suffix!r}; expected .yaml, .yml or .json")]
        )
    return SUFFIXES[suffix]


def read_document(path: str | os.PathLike[str]) -> Any:
    """The plain data of a CDF file (not validated), read safely.

    Only a regular file is read: a FIFO, device or folder is refused before reading (a FIFO would block).

    Raises:
        CDFValidationError: Missing, not a regular file, unreadable, over MAX_BYTES, or not valid YAML/JSON.
    """
    source = str(path)
    try:
        mode = os.stat(path).st_mode
    except OSError:
        mode = None  # reported below, where the file is opened
    if mode is not None and not stat.S_ISREG(mode):
        raise CDFValidationError(source, [Issue("", f"{mode_kind(mode)}; expected a regular CDF file")])
    fmt = format_of(path)
    try:
        # O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
        with open(fd, "rb") as fh:
            mode = os.fstat(fd).st_mode
            if not stat.S_ISREG(mode):
                raise CDFValidationError(source, [Issue("", f"{mode_kind(mode)}; expected a regular CDF file")])
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise CDFValidationError(
            source,
            [
                Issue(
                    "",
                    f"cannot read the file ({exc.strerror or exc}); expected a readable CDF file",
                )
            ],
        ) from None
    if len(raw) > MAX_BYTES:
        raise CDFValidationError(
            source, [Issue("", f"file is larger than {MAX_BYTES} bytes; a CDF file may hold at most {MAX_BYTES} "
                                     "(luminous_sim.limits.MAX_CDF_BYTES)")]
        )
    return parse_text(raw, fmt, source)


def from_document(doc: Any, source: str = "<document>") -> ChallengeDefinition:
    """Validate plain data (of any supported version) into a ChallengeDefinition.

    Raises:
        CDFValidationError: Anything wrong, with key paths relative to the upgraded document.
    """
    check_tree(doc, source)
    version = document_version(doc, source)
    note = (
        f" (in the document upgraded from cdf_version {version})" if version != CDF_VERSION else ""
    )
    current = upgrade(doc, source)
    too_large = document_issues(current)
    if too_large:
        raise CDFValidationError(source, [Issue(i.path, i.message + note) for i in too_large])
    try:
        return ChallengeDefinition.model_validate(current, context={"source": source, "note": note})
    except ValidationError as exc:
        raise from_validation_error(exc, source, ChallengeDefinition, note) from None
    except RecursionError:
        raise CDFValidationError(source, [Issue("", "nested too deeply")]) from None


def load(path: str | os.PathLike[str]) -> ChallengeDefinition:
    """Read and validate a CDF file (.yaml, .yml or .json), upgrading older versions.

    Raises:
        CDFValidationError: Anything wrong; the message names the file and key path.
    """
    return from_document(read_document(path), str(path))


def loads(text: str | bytes, fmt: str = "yaml", source: str = "<string>") -> ChallengeDefinition:
    """Validate CDF text ("yaml" or "json"), upgrading older versions.

    Raises:
        CDFValidationError: Anything wrong; the message names `source` and the key path.
    """
    return from_document(parse_text(text, fmt, source), source)


def to_document(cdf: ChallengeDefinition) -> dict[str, Any]:
    """The plain data of a CDF (current version; defaults and empty values left out)."""
    return cdf.model_dump(mode="json", exclude_none=True, exclude_defaults=True) | {
        "cdf_version": CDF_VERSION
    }


def dumps(cdf: ChallengeDefinition, fmt: str = "yaml") -> str:
    """CDF text that `loads` reads back to an equal ChallengeDefinition."""
    doc = to_document(cdf)
    doc = {"cdf_version": doc.pop("cdf_version"), **doc}
    if fmt == "json":
        return json.dumps(doc, indent=2, ensure_ascii=False) + "\n"
    if fmt == "yaml":
        return yaml.safe_dump(
            doc, sort_keys=False, allow_unicode=True, default_flow_style=False, width=100
        )
    raise CDFValidationError(
        "<dumps>", [Issue("", f"unknown format {fmt!r}; expected yaml or json")]
    )


def dump(cdf: ChallengeDefinition, path: str | os.PathLike[str]) -> Path:
    """Write a CDF to `path` (format from the suffix) and return the path."""
    out = Path(path)
    text = dumps(cdf, format_of(out))
    try:
        out.write_text(text, encoding="utf-8")
    except OSError as exc:
        raise CDFValidationError(
            str(path), [Issue("", f"cannot write the file ({exc.strerror or exc})")]
        ) from None
    return out
