"""Argument types for the `luminous` command: each refuses a bad value at parse time with a one-line message.

argparse turns the ArgumentTypeError these raise into `luminous CMD: error: argument --flag: message` and
exit status 2, so a negative seed, a zero count or an output path that names a folder never reach the
library (where they would give a traceback or silently do nothing).
"""

from __future__ import annotations

import argparse
import math
import os
from collections.abc import Callable, Iterable
from pathlib import Path

from luminous_sim import limits

MAX_SEED = 2**63 - 1
"""Largest seed accepted (numpy takes any non-negative integer; this keeps folder names and JSON sane)."""


def _int(text: str) -> int:
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None


def _float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return value


def int_range(lo: int, hi: int | None = None, limit: str | None = None) -> Callable[[str], int]:
    """An integer type accepting lo <= value (<= hi); `limit` names the constant of luminous_sim.limits that `hi`
    is, for the message (`expected a whole number from 1 to 10000 (luminous_sim.limits.MAX_EPOCHS), got 0`)."""

    def parse(text: str) -> int:
        value = _int(text)
        if value < lo or (hi is not None and value > hi):
            top = "2**63-1" if hi == MAX_SEED else str(hi)
            want = f"from {lo} to {top}" if hi is not None else f"at least {lo}"
            named = f" (luminous_sim.limits.{limit})" if limit else ""
            raise argparse.ArgumentTypeError(f"expected a whole number {want}{named}, got {text}")
        return value

    parse.__name__ = "whole number"
    return parse


def limited(lo: int, limit: str) -> Callable[[str], int]:
    """`int_range(lo, limits.<limit>)`, the limit named in the message."""
    return int_range(lo, int(getattr(limits, limit)), limit)


seed = int_range(0, MAX_SEED)
"""A random seed: a non-negative integer."""


def positive_float(text: str) -> float:
    """A finite number greater than zero (a mass, a scale, a learning rate)."""
    value = _float(text)
    if value <= 0:
        raise argparse.ArgumentTypeError(f"expected a number greater than 0, got {text}")
    return value


def fraction(text: str) -> float:
    """A finite number from 0 (inclusive) to 1 (exclusive)."""
    value = _float(text)
    if not 0 <= value < 1:
        raise argparse.ArgumentTypeError(f"expected a fraction from 0 up to (not including) 1, got {text}")
    return value


def output_dir(text: str) -> Path:
    """A folder to write into: it may exist (as a folder) or not yet."""
    path = Path(text)
    if not text:
        raise argparse.ArgumentTypeError("expected a folder name, got an empty string")
    if path.exists() and not path.is_dir():
        raise argparse.ArgumentTypeError(f"{path} exists and is not a folder; expected a folder to write into")
    return path


def output_file(suffixes: Iterable[str], what: str) -> Callable[[str], Path]:
    """A file to write: not an existing folder, with one of `suffixes` (lower case, with the dot; empty: any).

    `what` names the kind with its article ("a PNG", "an image") for the messages.
    """
    allowed = tuple(suffixes)

    def parse(text: str) -> Path:
        path = Path(text)
        if not text or text.endswith(os.sep):
            raise argparse.ArgumentTypeError(f"expected {what} file name, got {text!r}")
        if path.is_dir():
            raise argparse.ArgumentTypeError(f"{path} is a folder; expected {what} file name")
        if allowed and path.suffix.lower() not in allowed:
            raise argparse.ArgumentTypeError(
                f"{path}: expected {what} file name ending in {' or '.join(allowed)}, got {path.suffix or 'none'!r}"
            )
        return path

    parse.__name__ = f"{what.split()[-1]} file"
    return parse
