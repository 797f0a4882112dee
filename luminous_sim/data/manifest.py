"""A build's manifest: one JSON line per finished job, appended and fsync'd only after the job's files
are in place, so that a build killed at any moment knows exactly which jobs are done.

A line cut short by a kill (bytes after the last newline) is dropped on load; a complete line that is
not a JSON record is corruption and refused. `sorted_rewrite` replaces the file at the end of a build
with its records in job order (atomically), so that a finished build's manifest does not depend on the
order in which workers finished.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

from luminous_sim.assets.objio import write_atomic
from luminous_sim.errors import LuminousError

Record = dict[str, Any]


class ManifestError(LuminousError):
    """A manifest that cannot be read: a broken line before the last, a record without a key, or two
    different records under one key."""


def _line(record: Record) -> str:
    return json.dumps(record, sort_keys=True, separators=(",", ":")) + "\n"


class Manifest:
    """The finished jobs of a build, by key, backed by a JSON-lines file."""

    def __init__(self, path: Path):
        self.path = Path(path)
        self._records: dict[str, Record] = {}
        if self.path.exists():
            self._load()

    def _load(self) -> None:
        raw = self.path.read_bytes()
        *complete, tail = raw.split(b"\n")  # `tail`: bytes after the last newline (a line cut short)
        for number, line in enumerate(complete, 1):
            try:
                record = json.loads(line)
            except ValueError as exc:
                raise ManifestError(f"{self.path}: line {number} is not a JSON record ({exc}); "
                                    "the manifest is corrupt") from None
            self._add(record, f"{self.path}: line {number}")
        if tail:  # drop it so that the next append starts a fresh line
            with open(self.path, "r+b") as fh:
                fh.truncate(len(raw) - len(tail))
                fh.flush()
                os.fsync(fh.fileno())

    def _add(self, record: Record, where: str) -> None:
        key = record.get("key") if isinstance(record, dict) else None
        if not isinstance(key, str):
            raise ManifestError(f"{where}: a record without a string 'key'")
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
        with open(self.path, "ab") as fh:
            fh.write(_line(record).encode())
            fh.flush()
            os.fsync(fh.fileno())

    def sorted_rewrite(self, order: Callable[[Record], Any]) -> None:
        """Replace the file with the records sorted by `order` (atomically)."""
        write_atomic(self.path, "".join(_line(r) for r in sorted(self._records.values(), key=order)))
