"""The speaker's error type, and the checks of the paths it reads (torch-free)."""

from __future__ import annotations

import os

from luminous_sim.errors import LuminousError, path_kind
from luminous_sim.limits import MAX_CHECKPOINT_BYTES, MAX_INPUT_BYTES


class SpeakerError(LuminousError):
    """Unreadable training data, a bad checkpoint, or a speaker asked for something it cannot do."""


def check_regular_file(path: str | os.PathLike[str], expected: str, limit: int = MAX_INPUT_BYTES,
                       limit_name: str = "MAX_INPUT_BYTES") -> None:
    """Raise unless `path` is a regular file of at most `limit` bytes, naming what it is instead (missing, a
    folder, a FIFO, a device, too large); never opens it (opening a FIFO would block).

    Raises:
        SpeakerError: `{path}: a FIFO (named pipe); expected {expected}`, or its size over the limit.
    """
    kind = path_kind(path)
    if kind != "a regular file":
        raise SpeakerError(f"{path}: {kind}; expected {expected}")
    size = os.path.getsize(path)
    if size > limit:
        raise SpeakerError(f"{path}: {size:,} bytes; expected {expected} of at most {limit:,} bytes "
                           f"(luminous_sim.limits.{limit_name})")


def check_checkpoint_path(path: str | os.PathLike[str]) -> None:
    """`check_regular_file` for a speaker checkpoint.

    Raises:
        SpeakerError: `path` is not a regular file.
    """
    check_regular_file(path, "a speaker checkpoint file (written by `speaker train`)", MAX_CHECKPOINT_BYTES,
                       "MAX_CHECKPOINT_BYTES")
