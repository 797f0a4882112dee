"""The agents' torch checkpoints on disk: written atomically (the same payload, the same bytes), read back with
every failure of foreign bytes turned into the caller's error naming the file."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import torch

from luminous_sim.errors import LuminousError
from luminous_sim.fileio import write_atomic


def save_checkpoint(payload: dict[str, Any], path: Path) -> None:
    """Write `payload` with `torch.save` to `path` atomically (a temporary file beside it, then renamed)."""
    buffer = io.BytesIO()
    torch.save(payload, buffer)
    write_atomic(Path(path), buffer.getvalue())


def load_checkpoint(path: Path, fmt: str, what: str, made_by: str, error: type[LuminousError]) -> dict[str, Any]:
    """The checkpoint at `path` (tensors only: `weights_only`), which must be a dict of format `fmt`.

    Raises:
        error: missing ("no such `what` checkpoint (`made_by` writes one)"), unreadable, or of another format.
    """
    from luminous_sim.language.speaker.checkpoint import torch_reason

    path = Path(path)
    if not path.is_file():
        raise error(f"{path}: no such {what} checkpoint ({made_by} writes one)")
    try:
        data = torch.load(path, map_location="cpu", weights_only=True)
    except Exception as exc:  # torch's unpickler raises any type on foreign bytes
        raise error(f"{path}: not a readable {what} checkpoint ({torch_reason(exc)})") from None
    if not isinstance(data, dict) or data.get("format") != fmt:
        raise error(f"{path}: not a{'n' if what[0] in 'aeiou' else ''} {what} checkpoint (expected format {fmt})")
    return data
