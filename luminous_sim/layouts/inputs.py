"""Reading the files the layout importers take, and checking each field they read, as strictly as the CDF
validator checks a CDF: a problem is one line naming the file, the field's path and what was expected
(`scene.json: furniture[4].size[1]: expected a positive number, got -0.3`).

The bounds (`limits.MAX_INPUT_BYTES`, `MAX_LAYOUT_SIDE_M`, `MAX_LAYOUT_COORDINATE_M`, `MAX_ANGLE`) are checked
before anything is built from the file.
"""

from __future__ import annotations

import json
import math
import os
import stat
from functools import partial
from typing import Any

import numpy as np

from luminous_sim.errors import LuminousError, mode_kind
from luminous_sim.fileio import shown
from luminous_sim.limits import MAX_INPUT_BYTES, MAX_LAYOUT_COORDINATE_M, MAX_LAYOUT_SIDE_M

__all__ = ["MAX_ANGLE", "Fields", "LayoutError", "read_bytes", "read_json", "short"]

MAX_ANGLE = 4 * math.pi
"""Largest |angle| (radians) an input may give: two turns either way; importers normalise it to [-pi, pi)."""


class LayoutError(LuminousError):
    """A layout file (or an input to an importer) that cannot be read: the message names the file and field."""


short = partial(shown, limit=40)
"""`repr(value)`, cut to 40 characters."""

class TypeName(str):
    """A type's name in a message: shown as is, not quoted like a value."""

    def __repr__(self) -> str:
        return self[:]


def type_name(value: Any) -> TypeName:
    """The JSON-ish name of `value`'s type (dict, list, int, str, ...)."""
    return TypeName(type(value).__name__)


def read_bytes(path: str | os.PathLike[str], what: str) -> bytes:
    """The bytes of a regular file within `limits.MAX_INPUT_BYTES`.

    A folder, a device, a FIFO or a socket is named as such and never opened (opening a FIFO would block).

    Raises:
        LayoutError: missing, not a regular file, unreadable or too large; the message names the file and `what`
            was expected.
    """
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        raise LayoutError(f"{path}: no such file; expected {what}") from None
    except OSError as exc:
        raise LayoutError(f"{path}: cannot read ({exc.strerror or exc}); expected {what}") from None
    if not stat.S_ISREG(mode):
        raise LayoutError(f"{path}: {mode_kind(mode)}; expected {what}")
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_INPUT_BYTES + 1)
    except OSError as exc:
        raise LayoutError(f"{path}: cannot read ({exc.strerror or exc}); expected {what}") from None
    if len(raw) > MAX_INPUT_BYTES:
        raise LayoutError(f"{path}: more than {MAX_INPUT_BYTES} bytes; {what} may hold at most {MAX_INPUT_BYTES} "
                    "(luminous_sim.limits.MAX_INPUT_BYTES)")
    return raw


def _no_constants(token: str) -> float:
    raise ValueError(f"{token} is not a number JSON allows")


def read_json(path: str | os.PathLike[str], what: str) -> Any:
    """The parsed JSON of a regular file (`read_bytes`); NaN and Infinity are refused.

    Raises:
        LayoutError: as `read_bytes`, or not UTF-8 JSON (with the line and column).
    """
    raw = read_bytes(path, what)
    try:
        return json.loads(raw.decode("utf-8"), parse_constant=_no_constants)
    except UnicodeDecodeError as exc:
        raise LayoutError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); expected {what}") from None
    except RecursionError:
        raise LayoutError(f"{path}: nested too deeply; expected {what}") from None
    except ValueError as exc:
        raise LayoutError(f"{path}: not JSON ({exc}); expected {what}") from None


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))


class Fields:
    """Checks of the fields read from one file; each failure raises LayoutError naming the file and field path."""

    def __init__(self, source: str | os.PathLike[str]) -> None:
        self.source = str(source)

    def fail(self, path: str, expected: str, got: Any = ...) -> LayoutError:
        """The error for `path` (`furniture[4].size[1]`): `expected ...[, got ...]`."""
        tail = "" if got is ... else f", got {short(got)}"
        where = f"{self.source}: {path}" if path else self.source
        return LayoutError(f"{where}: expected {expected}{tail}")

    def get(self, mapping: Any, key: str, path: str) -> Any:
        """`mapping[key]`; `path` names the mapping."""
        if not isinstance(mapping, dict):
            raise self.fail(path, "a JSON object", type_name(mapping))
        if key not in mapping:
            raise LayoutError(f"{self.source}: {_join(path, key)}: missing")
        return mapping[key]

    def string(self, value: Any, path: str) -> str:
        if not isinstance(value, str) or not value or len(value) > 256:
            raise self.fail(path, "a non-empty string (at most 256 characters)", value)
        return value

    def boolean(self, value: Any, path: str) -> bool:
        if not isinstance(value, bool):
            raise self.fail(path, "true or false", value)
        return value

    def items(self, value: Any, path: str, limit: int | None = None) -> list[Any]:
        if not isinstance(value, list):
            raise self.fail(path, "a list", type_name(value))
        if limit is not None and len(value) > limit:
            raise LayoutError(f"{self.source}: {path}: {len(value)} entries; at most {limit} are read")
        return value

    def number(self, value: Any, path: str, kind: str = "coordinate") -> float:
        """A finite number; `kind` bounds it: "coordinate" (|v| <= MAX_LAYOUT_COORDINATE_M), "size" (positive,
        <= MAX_LAYOUT_SIDE_M), "scale" (positive, <= 100), "angle" (|v| <= MAX_ANGLE), "any" (finite)."""
        if not _is_number(value) or not math.isfinite(float(value)):
            raise self.fail(path, "a finite number", value)
        v = float(value)
        if kind == "size" and not 0 < v <= MAX_LAYOUT_SIDE_M:
            raise self.fail(path, f"a positive number of at most {MAX_LAYOUT_SIDE_M:g} m "
                            "(luminous_sim.limits.MAX_LAYOUT_SIDE_M)", value)
        if kind == "scale" and not 0 < v <= 100:
            raise self.fail(path, "a positive scale of at most 100", value)
        if kind == "coordinate" and abs(v) > MAX_LAYOUT_COORDINATE_M:
            raise self.fail(path, f"a coordinate within +-{MAX_LAYOUT_COORDINATE_M:g} m "
                            "(luminous_sim.limits.MAX_LAYOUT_COORDINATE_M)", value)
        if kind == "angle" and abs(v) > MAX_ANGLE:
            raise self.fail(path, "an angle within +-4 pi radians", value)
        return v

    def vector(self, value: Any, n: int, path: str, kind: str = "coordinate") -> np.ndarray:
        """`n` numbers, each checked by `number` (the first bad one is named: `pos[1]`)."""
        if not isinstance(value, (list, tuple)) or len(value) != n:
            raise self.fail(path, f"a list of {n} numbers", value)
        return np.array([self.number(v, f"{path}[{i}]", kind) for i, v in enumerate(value)], dtype=float)

    def rows(self, value: Any, width: int, path: str, kind: str, limit: int | None = None,
             row_path: Any = None) -> np.ndarray:
        """A list of rows of `width` numbers (or a flat list of `width`-multiples), each checked by `number`;
        `row_path(i, j)` names element j of row i (default `path[i][j]`)."""
        name = row_path or (lambda i, j: f"{path}[{i}][{j}]" if width > 1 else f"{path}[{i}]")
        if isinstance(value, np.ndarray):
            value = value.tolist()
        if not isinstance(value, list):
            raise self.fail(path, f"a list of rows of {width} numbers", type_name(value))
        flat = bool(value) and not isinstance(value[0], list)
        if flat and width > 1:
            if len(value) % width:
                raise self.fail(path, f"a multiple of {width} numbers", f"{len(value)} numbers")
            value = [value[k:k + width] for k in range(0, len(value), width)]
        if limit is not None and len(value) > limit:
            raise LayoutError(f"{self.source}: {path}: {len(value)} rows; at most {limit} are read")
        out = np.empty((len(value), width), dtype=float)
        for i, row in enumerate(value):
            cells = [row] if width == 1 and not isinstance(row, list) else row
            if not isinstance(cells, list) or len(cells) != width:
                raise self.fail(name(i, 0).rsplit("[", 1)[0] if width > 1 else name(i, 0),
                                f"{width} numbers", row)
            for j, v in enumerate(cells):
                out[i, j] = self.number(v, name(i, j), kind)
        return out

    def indices(self, value: Any, path: str, count: int) -> np.ndarray:
        """Triangles: rows of 3 whole numbers, each an index into `count` vertices."""
        tris = self.rows(value, 3, path, "any")
        for (i, j), v in np.ndenumerate(tris):
            if v != int(v) or not 0 <= v < count:
                raise self.fail(f"{path}[{i}][{j}]", f"a vertex index, a whole number 0..{count - 1}", value_at(
                    value, i, j))
        return tris.astype(int)


def value_at(value: Any, i: int, j: int) -> Any:
    """Element j of row i of a (possibly flat) list of rows of 3, for messages."""
    try:
        return value[i][j] if isinstance(value[0], list) else value[3 * i + j]
    except (IndexError, TypeError, KeyError):
        return None


def _join(path: str, key: str) -> str:
    return f"{path}.{key}" if path else key
