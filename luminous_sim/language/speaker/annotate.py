"""A learned speaker's instructions in place of the templates' in a written trial (`luminous dataset build
--speaker PATH`): its `turk_annotations` are rewritten, annotation k decoded with beam width `BEAMS[k]`.

Torch is imported on first use, so importing this module (and a build without a speaker) does not need it.
"""

from __future__ import annotations

import hashlib
import json
from functools import cache
from pathlib import Path
from typing import Any

from luminous_sim.fileio import write_atomic
from luminous_sim.language.speaker.errors import SpeakerError, check_checkpoint_path

BEAMS = (3, 1, 5)
"""Beam width of each annotation's decoding (a trial has three; more reuse the last)."""


def checkpoint_digest(path: str | Path) -> str:
    """The sha256 of a checkpoint file, which a build records so that it resumes with the same speaker.

    Raises:
        SpeakerError: the file is missing.
    """
    p = Path(path)
    check_checkpoint_path(p)
    return hashlib.sha256(p.read_bytes()).hexdigest()


@cache
def _speaker(path: str, digest: str) -> Any:
    """The speaker of a checkpoint, loaded once per process (and again when the file changes)."""
    try:
        from luminous_sim.language.speaker.generate import Speaker
    except ModuleNotFoundError as exc:
        if exc.name == "torch":
            raise SpeakerError("the learned speaker needs PyTorch: pip install torch==2.13.0") from None
        raise
    return Speaker.load(path)


def check_speaker(path: str | Path, frames: bool) -> None:
    """Load a checkpoint as a build would, before the build starts.

    Raises:
        SpeakerError: no torch, not a checkpoint, or a speaker trained on visual features for a build without
            frames.
    """
    speaker = _speaker(str(path), checkpoint_digest(path))
    if speaker.feat_dim > 0 and not frames:
        raise SpeakerError(f"{path}: this speaker was trained with visual features; it needs a build with frames")


def annotate_trial(traj_data: Path, speaker_path: str | Path) -> None:
    """Rewrite a trial's `turk_annotations` with the speaker's goal directive and step instructions.

    Raises:
        SpeakerError: the checkpoint cannot be loaded, or the trial has no annotations to replace.
    """
    speaker = _speaker(str(speaker_path), checkpoint_digest(speaker_path))
    data = json.loads(traj_data.read_text())
    anns = data.get("turk_annotations", {}).get("anns", [])
    if not anns:
        raise SpeakerError(f"{traj_data}: no turk_annotations to replace")
    from luminous_sim.language.speaker.records import parse_trajectory

    traj = parse_trajectory(data, traj_data, require_annotations=False)
    if speaker.feat_dim > 0:
        from luminous_sim.language.speaker.records import load_trajectory

        traj = load_trajectory(traj_data, features=True, require_annotations=False)
    for k, ann in enumerate(anns):
        goal, steps = speaker.describe_trajectory(traj, beam_width=BEAMS[min(k, len(BEAMS) - 1)])
        ann["task_desc"], ann["high_descs"] = goal, steps
    write_atomic(traj_data, json.dumps(data, sort_keys=True, indent=4))
