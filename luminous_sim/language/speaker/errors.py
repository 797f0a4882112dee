"""The speaker's error type, and the checks of the paths it reads (torch-free)."""

from __future__ import annotations

import os

from luminous_sim.errors import LuminousError, path_kind


class SpeakerError(LuminousError):
    """Unreadable training data, a bad checkpoint, or a speaker asked for something it cannot do."""


def check_regular_file(path: str | os.PathLike[str], expected: str) -> None:
    """Raise unless `path` is a regular file, naming what it is instead (missing, a folder, a FIFO, a device);
    never opens it (opening a FIFO would block).

    Raises:
        SpeakerError: `{path}: a FIFO (named pipe); expected {expected}`.
    """
    kind = path_kind(path)
    if kind != "a regular file":
        raise SpeakerError(f"{path}: {kind}; expected {expected}")


def check_checkpoint_path(path: str | os.PathLike[str]) -> None:
    """`check_regular_file` for a speaker checkpoint.

    Raises:
        SpeakerError: `path` is not a regular file.
    """
    check_regular_file(path, "a speaker checkpoint file (written by `speaker train`)")
