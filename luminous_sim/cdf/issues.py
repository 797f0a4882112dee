"""Problems found in a CDF document, one line each: `FILE: KEY.PATH[2]: what was expected`."""

from __future__ import annotations

import difflib
import types
import typing
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ValidationError
from pydantic_core import ErrorDetails

from luminous_sim.errors import CDFError

UNION_TAGS: frozenset[str] = frozenset(
    {"room-name", "room-constraints", "size-scale", "size-dims", "high-level", "low-level"}
)
"""Tags of the discriminated unions in the schema; they appear in pydantic's error locations."""


@dataclass(frozen=True)
class Issue:
    """One problem: where it is (`scene.relations[2].target`) and what was expected."""

    path: str
    message: str

    def render(self, source: str) -> str:
        """`source: path: message` (the path is left out when the whole document is at fault)."""
        where = f"{source}: {self.path}" if self.path else source
        return f"{where}: {self.message}"


class CDFValidationError(CDFError):
    """A CDF document with problems; `issues` lists them, `str()` gives one line each."""

    def __init__(self, source: str, issues: Sequence[Issue]) -> None:
        self.source = source
        self.issues: tuple[Issue, ...] = tuple(issues)
        super().__init__("\n".join(i.render(source) for i in self.issues))


def format_path(loc: Sequence[Any]) -> str:
    """`('scene', 'relations', 2, 'target')` -> `scene.relations[2].target` (union tags dropped)."""
    out = ""
    for part in loc:
        if isinstance(part, int) and not isinstance(part, bool):
            out += f"[{part}]"
        elif isinstance(part, str) and part in UNION_TAGS:
            continue
        else:
            out += f".{part}" if out else str(part)
    return out


def _short(value: Any, n: int = 40) -> str:
    text = repr(value)
    return text if len(text) <= n else text[: n - 3] + "..."


def _model_at(root: type[BaseModel], loc: Sequence[Any]) -> type[BaseModel] | None:
    """The model class whose field sits at `loc` (best effort, for naming the accepted keys)."""
    current: Any = root
    for part in loc:
        if isinstance(part, str) and part in UNION_TAGS:
            continue
        if isinstance(part, int):
            continue
        if not (isinstance(current, type) and issubclass(current, BaseModel)):
            return None
        field = current.model_fields.get(part)
        if field is None:
            return None
        current = _unwrap(field.annotation, loc)
    return current if isinstance(current, type) and issubclass(current, BaseModel) else None


def _unwrap(annotation: Any, loc: Sequence[Any]) -> Any:
    """Reduce an annotation to the model it holds (through Optional, tuple, Annotated, unions)."""
    seen = 0
    while seen < 10:
        seen += 1
        origin = typing.get_origin(annotation)
        if origin is typing.Annotated:
            annotation = typing.get_args(annotation)[0]
        elif origin in (typing.Union, types.UnionType):
            models = [
                a for a in (_unwrap(x, loc) for x in typing.get_args(annotation)) if _is_model(a)
            ]
            tagged = [m for m in models if getattr(m, "union_tag", None) in loc]
            return (tagged or models or [None])[0]
        elif origin in (tuple, list):
            annotation = typing.get_args(annotation)[0]
        else:
            return annotation
    return None


def _is_model(x: Any) -> bool:
    return isinstance(x, type) and issubclass(x, BaseModel)


def _message(err: ErrorDetails, root: type[BaseModel]) -> str:
    kind, msg, loc = err["type"], err["msg"], err["loc"]
    if kind in ("model_type", "dict_type", "model_attributes_type"):
        return f"expected a mapping, got {type(err.get('input')).__name__}"
    if kind == "missing":
        return "required key is missing"
    if kind == "extra_forbidden":
        model = _model_at(root, loc[:-1])
        key = str(loc[-1]) if loc else "?"
        if model is None:
            return "unknown key"
        allowed = sorted(model.model_fields)
        hint = difflib.get_close_matches(key, allowed, n=1)
        extra = f"; did you mean {hint[0]!r}?" if hint else ""
        return f"unknown key {key!r}{extra} (expected one of {', '.join(allowed)})"
    # the schema stores lists as tuples (immutable); a document writes a list, so say "list"
    msg = msg.replace("a valid tuple", "a list").replace("Tuple should", "List should")
    for prefix in ("Value error, ", "Assertion failed, "):
        if msg.startswith(prefix):
            return msg[len(prefix) :]
    if msg.startswith("Input should be "):
        msg = "expected " + msg[len("Input should be ") :]
    elif msg.startswith("Input "):
        msg = msg[0].lower() + msg[1:]
    if (
        "input" in err
        and kind not in ("model_type", "dict_type")
        and not isinstance(err["input"], (dict, list))
    ):
        msg += f" (got {_short(err['input'])})"
    return msg


def from_validation_error(
    exc: ValidationError, source: str, root: type[BaseModel], note: str = ""
) -> CDFValidationError:
    """Turn a pydantic ValidationError into a CDFValidationError with key paths and expectations.

    Args:
        exc: The error pydantic raised while validating a document against `root`.
        source: The file name (or `<string>`) for the messages.
        root: The model the document was validated against.
        note: Appended to every message (e.g. that the document was upgraded from an old version).
    """
    issues = []
    for err in exc.errors(include_url=False):
        issues.append(Issue(format_path(err["loc"]), _message(err, root) + note))
    return CDFValidationError(source, issues)
