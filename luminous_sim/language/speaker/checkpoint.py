"""Speaker checkpoints: one ``torch.save`` file, written atomically, read with ``weights_only``."""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

import torch

from luminous_sim.fileio import atomic_file
from luminous_sim.language.speaker.errors import SpeakerError, check_checkpoint_path

FORMAT = "luminous-speaker/1"
REQUIRED = ("format", "config", "model", "src_vocab", "tgt_vocab", "epoch", "losses", "train_args")


def save_checkpoint(path: str | Path, payload: dict[str, Any]) -> None:
    """Write ``payload`` to ``path`` via a temporary file in the same folder and ``os.replace``.

    A crash mid-write leaves the previous checkpoint intact.
    """
    with atomic_file(Path(path)) as tmp, open(tmp, "wb") as fh:
        torch.save({"format": FORMAT, **payload}, fh)
        fh.flush()
        os.fsync(fh.fileno())


def torch_reason(exc: BaseException) -> str:
    """Why `torch.load` refused a file, in one short line: the `WeightsUnpickler error` of a weights-only refusal
    (not torch's paragraph about `weights_only=False`), else the first line of the message, or the error's type."""
    text = re.sub(r"\x1b\[[0-9;]*m", "", str(exc))
    found = re.search(r"WeightsUnpickler error: ([^\n]*?)(?:\. |\.?$)", text, re.MULTILINE)
    line = found.group(1) if found else next((ln.strip() for ln in text.splitlines() if ln.strip()), "")
    line = line or type(exc).__name__
    return line if len(line) <= 160 else line[:157] + "..."


def load_checkpoint(path: str | Path) -> dict[str, Any]:
    """Read a checkpoint written by :func:`save_checkpoint`.

    Raises:
        SpeakerError: The file is missing, unreadable, or not a speaker checkpoint.
    """
    path = Path(path)
    check_checkpoint_path(path)
    try:
        data = torch.load(path, map_location="cpu", weights_only=True)
    except Exception as exc:  # torch's unpickler raises any type on foreign bytes (IndexError on /etc/passwd)
        raise SpeakerError(f"{path}: not a readable speaker checkpoint ({torch_reason(exc)})") from None
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise SpeakerError(f"{path}: not a speaker checkpoint (expected format {FORMAT!r})")
    missing = [k for k in REQUIRED if k not in data]
    if missing:
        raise SpeakerError(f"{path}: speaker checkpoint lacks {missing}")
    return data
