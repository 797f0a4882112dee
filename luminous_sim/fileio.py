"""Writing files so that nothing is torn, and messages that fit on one line (layer L0, the one copy of each).

- `atomic_file` / `write_atomic`: a file is replaced whole or not at all; a reader sees the old content or the
  new, never half of it, and an error or a kill mid-write leaves the old file as it was.
- `one_line`: text for a one-line error message (a path or a parser's message may hold newlines), cut to a limit;
  `shown`: a value as such a message shows it (its repr, on one line, cut).
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any


@contextlib.contextmanager
def atomic_file(path: Path, suffix: str = ".tmp") -> Iterator[Path]:
    """A temporary file beside `path` for a writer (of `suffix`, for writers that pick a format by it), moved
    onto `path` when the block ends without an error (removed when it raises): readers see the old file or the
    new one, never a torn one."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=suffix)
    os.close(fd)
    try:
        yield Path(tmp)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes 0600; written files should read like any other
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def write_atomic(path: Path, text: str | bytes) -> None:
    """Write a file so that readers see the old or the new content, never a torn one."""
    data = text.encode() if isinstance(text, str) else text
    with atomic_file(Path(path)) as tmp, open(tmp, "wb") as fh:
        fh.write(data)


def one_line(text: str, limit: int = 1000) -> str:
    """`text` on one line (whitespace runs, newlines included, become one space), cut to `limit` characters with
    "..." where it was cut."""
    flat = " ".join(text.split())
    return flat if len(flat) <= limit else flat[:limit - 3] + "..."


def shown(value: Any, limit: int = 60) -> str:
    """A value as a message shows it: its repr on one line, cut to `limit` characters."""
    try:
        text = repr(value)
    except ValueError:  # an int too long for a string
        text = f"an integer of {value.bit_length()} bits"
    return one_line(text, limit)
