"""Per-step visual features: a joint RGB colour histogram of each frame, downsampled to 64x64.

No learned parameters, so features can be computed once and cached; the model learns a projection.
ALFRED stores frames in ``<trial>/raw_images/`` (``images[]`` in traj_data.json maps each frame to
the ``low_idx`` of its low-level action); a step's feature is the mean over (up to 3 of) its frames.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from luminous_sim.language.speaker.errors import SpeakerError

BINS = 4
"""Histogram bins per colour channel."""
FEATURE_DIM = BINS**3
"""Length of one frame's feature vector."""
SIDE = 64
"""Frames are downsampled (nearest pixel) to SIDE x SIDE before counting."""


def frame_features(frames: np.ndarray) -> np.ndarray:
    """Colour histograms of frames.

    Args:
        frames: ``[N, H, W, 3]`` RGB, uint8 0..255 or float 0..1 (or one ``[H, W, 3]`` frame).

    Returns:
        ``[N, FEATURE_DIM]`` float32, each row summing to 1.

    Raises:
        SpeakerError: The array is not a stack of RGB frames.
    """
    arr = np.asarray(frames)
    if arr.ndim == 3:
        arr = arr[None]
    if arr.ndim != 4 or arr.shape[-1] != 3 or arr.shape[1] == 0 or arr.shape[2] == 0:
        raise SpeakerError(f"frames must have shape [N, H, W, 3], got {list(arr.shape)}")
    if arr.dtype != np.uint8:
        arr = np.clip(np.rint(arr.astype(np.float64) * 255.0), 0, 255).astype(np.uint8)
    rows = np.linspace(0, arr.shape[1] - 1, SIDE).round().astype(int)
    cols = np.linspace(0, arr.shape[2] - 1, SIDE).round().astype(int)
    small = arr[:, rows][:, :, cols]  # [N, SIDE, SIDE, 3]
    q = (small.astype(np.int64) * BINS) // 256
    idx = (q[..., 0] * BINS + q[..., 1]) * BINS + q[..., 2]
    out = np.zeros((arr.shape[0], FEATURE_DIM), dtype=np.float32)
    for n in range(arr.shape[0]):
        out[n] = np.bincount(idx[n].ravel(), minlength=FEATURE_DIM)
    return out / float(SIDE * SIDE)


def _frame_file(image_dir: Path, image_name: str) -> Path | None:
    """The frame an `images` entry names, inside `image_dir` (only the name's stem is used, never a path).

    Raises:
        SpeakerError: the file there is a link, not a regular file (a FIFO, a device) or over MAX_INPUT_BYTES.
    """
    import os

    from luminous_sim.errors import link_or_kind
    from luminous_sim.limits import MAX_INPUT_BYTES

    stem = Path(str(image_name)).stem
    for ext in (".jpg", ".png", ".jpeg"):
        candidate = image_dir / f"{stem}{ext}"
        if not (candidate.exists() or candidate.is_symlink()):
            continue
        if candidate.is_symlink() or not candidate.is_file():
            raise SpeakerError(f"{candidate}: {link_or_kind(candidate)}; expected a frame (a regular image file)")
        if os.stat(candidate).st_size > MAX_INPUT_BYTES:
            raise SpeakerError(f"{candidate}: over {MAX_INPUT_BYTES} bytes (luminous_sim.limits.MAX_INPUT_BYTES); "
                               "expected a frame")
        return candidate
    return None


def load_step_features(
    trial_dir: Path, images: list[dict], n_low: int, max_frames_per_step: int = 3
) -> np.ndarray | None:
    """Features for every low-level action of one trajectory, from its ``raw_images/`` frames.

    Args:
        trial_dir: The folder holding traj_data.json.
        images: The trajectory's ``images`` list (``image_name``, ``low_idx``).
        n_low: Number of low-level actions.
        max_frames_per_step: Frames averaged per action (first, middle, last when there are more).

    Returns:
        ``[n_low, FEATURE_DIM]`` float32 (zeros for actions without frames), or None when the
        trajectory has no ``raw_images`` folder.

    Raises:
        SpeakerError: A frame listed in ``images`` exists but cannot be decoded.
    """
    from PIL import Image, UnidentifiedImageError

    image_dir = Path(trial_dir) / "raw_images"
    if not image_dir.is_dir():
        return None
    by_step: dict[int, list[str]] = {}
    for entry in images:
        low = entry.get("low_idx") if isinstance(entry, dict) else None
        if isinstance(low, int) and 0 <= low < n_low and isinstance(entry.get("image_name"), str):
            by_step.setdefault(low, []).append(entry["image_name"])
    out = np.zeros((n_low, FEATURE_DIM), dtype=np.float32)
    for low, names in by_step.items():
        if len(names) > max_frames_per_step:
            picks = np.linspace(0, len(names) - 1, max_frames_per_step).round().astype(int)
            names = [names[i] for i in picks]
        frames = []
        for name in names:
            path = _frame_file(image_dir, name)
            if path is None:
                continue
            try:
                with Image.open(path) as img:
                    frames.append(np.asarray(img.convert("RGB")))
            except (OSError, UnidentifiedImageError) as exc:
                raise SpeakerError(f"{path}: cannot read frame ({exc})") from None
        if frames:
            out[low] = np.mean([frame_features(f)[0] for f in frames], axis=0)
    return out
