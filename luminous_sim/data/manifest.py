"""A build's manifest: one JSON line per finished job, appended and fsync'd only after the job's files
are in place, so that a build killed at any moment knows exactly which jobs are done.

A line cut short by a kill (bytes after the last newline) is dropped on load. A manifest is input like
any other file (a forged `"trial": "../../elsewhere"` must never make a build write or delete outside its
folder), so every complete line is checked: it must be a JSON record whose fields are what a build writes
(`check_record`: a plain split name, a whole-number order, a trial path of two plain folder names, a
sha256 of 64 hex digits...) and whose `check` (a digest of the record's other fields, written with it)
matches, so that an altered line is told from a record. A line that fails is refused with the line and
field named (`ManifestError`), or with `repair=True` (what a build does) set aside in `rejected` and
left out of the file: its job has no record, so the build does it again. `sorted_rewrite` replaces the
file at the end of a build with its records in job order (atomically), so that a finished build's
manifest does not depend on the order in which workers finished.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from collections.abc import Callable, Collection, Iterator
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError, read_file_bytes
from luminous_sim.fileio import write_atomic

Record = dict[str, Any]
STATUSES = ("built", "failed")
MAX_BYTES = 1 << 30
"""Largest manifest read (1 GiB: about two million records); a bigger file is refused before it is read."""
_HEX64 = re.compile(r"[0-9a-f]{64}")


class ManifestError(LuminousError):
    """A manifest that cannot be read: a broken line before the last, a record without a key, or two
    different records under one key."""


CHECK = "check"
"""The field that holds a record's digest (of its other fields): written with each line, verified on load."""


def _digest(record: Record) -> str:
    canonical = json.dumps(record, sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode()).hexdigest()[:16]


def _line(record: Record) -> str:
    return json.dumps({**record, CHECK: _digest(record)}, sort_keys=True, separators=(",", ":")) + "\n"


class Manifest:
    """The finished jobs of a build, by key, backed by a JSON-lines file."""

    def __init__(self, path: Path, repair: bool = False):
        """Read the manifest at `path` (none yet: empty).

        Raises:
            ManifestError: the file is not a regular file or is too big; or, without `repair`, a line that
                is not a record a build wrote (with `repair` such lines are listed in `rejected` instead
                and the file is rewritten without them).
        """
        self.path = Path(path)
        self._records: dict[str, Record] = {}
        self.rejected: list[str] = []
        """With `repair`: why each line left out was refused (file, line, field)."""
        self._repair = repair
        self._torn_at: int | None = None
        """Where a last line cut short by a kill starts (None: the file ends with a whole line)."""
        if self.path.exists() or self.path.is_symlink():
            self._load()

    def _load(self) -> None:
        raw = read_file_bytes(self.path, MAX_BYTES, "the build's manifest", ManifestError)
        *complete, tail = raw.split(b"\n")  # `tail`: bytes after the last newline (a line cut short)
        twice: set[str] = set()
        for number, line in enumerate(complete, 1):
            where = f"{self.path}: line {number}"
            try:
                try:
                    record = json.loads(line)
                except (ValueError, RecursionError) as exc:
                    raise ManifestError(f"{where} is not a JSON record ({exc}); the manifest is corrupt") from None
                record = _checked(record, where)
                if record["key"] in self._records and self._records[record["key"]] != record:
                    twice.add(record["key"])
                    raise ManifestError(f"{where}: a second, different record for {record['key']!r}")
                self._records[record["key"]] = record
            except ManifestError as exc:
                if not self._repair:
                    raise
                self.rejected.append(str(exc))
        for key in twice:  # neither of two different records of one job can be trusted
            self._records.pop(key, None)
        if self.rejected:
            write_atomic(self.path, "".join(_line(r) for r in self._records.values()))
        elif tail:  # the next append drops it first, to start a fresh line (a reader alone never writes)
            self._torn_at = len(raw) - len(tail)

    def _add(self, record: Record, where: str) -> None:
        check_record(record, where)
        key = record["key"]
        if key in self._records and self._records[key] != record:
            raise ManifestError(f"{where}: a second, different record for {key!r}")
        self._records[key] = record

    def __contains__(self, key: object) -> bool:
        return key in self._records

    def __getitem__(self, key: str) -> Record:
        return self._records[key]

    def __len__(self) -> int:
        return len(self._records)

    def __iter__(self) -> Iterator[Record]:
        return iter(list(self._records.values()))

    def append(self, record: Record) -> None:
        """Add a finished job's record and make it durable (written, flushed and fsync'd) before returning."""
        self._add(record, str(self.path))
        self.path.parent.mkdir(parents=True, exist_ok=True)
        if self._torn_at is not None:
            with open(self.path, "r+b") as fh:
                fh.truncate(self._torn_at)
                fh.flush()
                os.fsync(fh.fileno())
            self._torn_at = None
        with open(self.path, "ab") as fh:
            fh.write(_line(record).encode())
            fh.flush()
            os.fsync(fh.fileno())

    def remove(self, keys: Collection[str]) -> None:
        """Drop the records of `keys` (jobs to be done again) and rewrite the file without them (atomically)."""
        if not keys:
            return
        for key in keys:
            self._records.pop(key, None)
        write_atomic(self.path, "".join(_line(r) for r in self._records.values()))
        self._torn_at = None

    def sorted_rewrite(self, order: Callable[[Record], Any]) -> None:
        """Replace the file with the records sorted by `order` (atomically)."""
        write_atomic(self.path, "".join(_line(r) for r in sorted(self._records.values(), key=order)))
        self._torn_at = None


def _checked(record: object, where: str) -> Record:
    """`record` without its `check` field, which must match the digest of its other fields."""
    if not isinstance(record, dict):
        raise ManifestError(f"{where}: expected a JSON object (a job's record), got {type(record).__name__}; "
                            "the manifest is corrupt")
    rest = {k: v for k, v in record.items() if k != CHECK}
    check_record(rest, where)
    if record.get(CHECK) != _digest(rest):
        raise _field(where, CHECK, "the digest of the record's other fields (the line was altered)", record.get(CHECK))
    return rest


def plain_name(text: object) -> bool:
    """Whether `text` is one plain folder name: not empty, no separator, not `.`-led (no `..`, no hidden
    name), no NUL, and short enough for any filesystem."""
    return (isinstance(text, str) and 0 < len(text) <= 255 and "/" not in text and "\\" not in text
            and "\0" not in text and not text.startswith("."))


def _field(where: str, name: str, expected: str, got: object) -> ManifestError:
    shown = repr(got)
    shown = shown if len(shown) <= 80 else shown[:77] + "..."
    return ManifestError(f"{where}: field {name!r}: expected {expected}, got {shown}; the manifest is corrupt")


def check_record(record: object, where: str) -> None:
    """Refuse a record that is not what a build writes, naming `where` (file and line) and the field.

    Raises:
        ManifestError: not an object, or a field missing or of the wrong kind (see the module docstring).
    """
    if not isinstance(record, dict):
        raise ManifestError(f"{where}: expected a JSON object (a job's record), got {type(record).__name__}; "
                            "the manifest is corrupt")
    key = record.get("key")
    if not isinstance(key, str) or not key or len(key) > 1000:
        raise _field(where, "key", "a job's key (a string)", key)
    if not plain_name(record.get("split")):
        raise _field(where, "split", "a plain folder name", record.get("split"))
    order = record.get("order")
    if not isinstance(order, int) or isinstance(order, bool) or order < 0:
        raise _field(where, "order", "a whole number >= 0", order)
    if not isinstance(record.get("task_type"), str):
        raise _field(where, "task_type", "a task type (a string)", record.get("task_type"))
    status = record.get("status")
    if status not in STATUSES:
        raise _field(where, "status", " or ".join(repr(s) for s in STATUSES), status)
    trial = record.get("trial")
    if status == "failed":
        if trial is not None:
            raise _field(where, "trial", "null for a failed job", trial)
        for name in ("stage", "cause"):
            if not isinstance(record.get(name), str):
                raise _field(where, name, "a string for a failed job", record.get(name))
        return
    parts = trial.split("/") if isinstance(trial, str) else []
    if len(parts) != 2 or not all(plain_name(p) for p in parts):
        raise _field(where, "trial", "<task>/<trial>, two plain folder names inside the split's folder", trial)
    files = record.get("files")
    if not isinstance(files, int) or isinstance(files, bool) or files < 1:
        raise _field(where, "files", "a whole number >= 1", files)
    digest = record.get("sha256")
    if not isinstance(digest, str) or not _HEX64.fullmatch(digest):
        raise _field(where, "sha256", "64 hex digits", digest)
