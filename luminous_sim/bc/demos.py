"""Oracle demonstrations of a task family (`pickup` or `alfred`, `luminous_sim.bc.family`), recorded for
behaviour cloning.

One file per episode, `<dir>/<split>-<index>.npz`, written atomically as it finishes (an interrupted
collection resumes: finished episodes are kept, not replayed). Per step t: the observation the oracle
acted on (`rgb` (T, H, W, 3) uint8, `objects` (T, S) the type in each object slot), the action it took
(`actions` (T,), a discrete index, or -1 where the oracle's target was in no slot and it acted in the
ALFRED dict form: such a step is played but is no training label) and whether the action before it failed
(`failed` (T,)). Per episode: the instruction (`instruction`) and its token ids (`tokens`, the env's fixed
vocabulary). `collection.json` in the folder records the env options, so demos of another env are refused.
"""

from __future__ import annotations

import io
import json
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.bc.family import Unavailable, family_env, reset_episode
from luminous_sim.env import LuminousEnv
from luminous_sim.env.vocabulary import encode
from luminous_sim.errors import LuminousError
from luminous_sim.fileio import write_atomic

TOKENS = 16
"""Instruction tokens kept ("pick up the spray bottle" is 5)."""


@dataclass(frozen=True)
class Demo:
    """One oracle episode (see the module docstring for the arrays)."""

    split: str
    index: int
    instruction: str
    tokens: np.ndarray
    rgb: np.ndarray
    objects: np.ndarray
    actions: np.ndarray
    failed: np.ndarray
    success: bool

    @property
    def labelled(self) -> int:
        """Steps with a discrete label."""
        return int((self.actions >= 0).sum())

    def to_bytes(self) -> bytes:
        buf = io.BytesIO()
        np.savez_compressed(buf, split=self.split, index=self.index, instruction=self.instruction,
                            tokens=self.tokens, rgb=self.rgb, objects=self.objects, actions=self.actions,
                            failed=self.failed, success=self.success)
        return buf.getvalue()

    @classmethod
    def load(cls, path: Path) -> Demo:
        try:
            with np.load(path, allow_pickle=False) as z:
                return cls(str(z["split"]), int(z["index"]), str(z["instruction"]), z["tokens"], z["rgb"],
                           z["objects"], z["actions"], z["failed"], bool(z["success"]))
        except (OSError, KeyError, ValueError) as exc:
            raise LuminousError(f"{path}: not a demonstration file ({exc})") from None


def record(env: LuminousEnv, split: str, index: int) -> Demo:
    """The oracle's episode `index` of `split` in `env`, recorded.

    Raises:
        Unavailable: the entry has no pickup episode.
    """
    obs, _ = reset_episode(env, split, index)
    rgb, objects, actions, failed = [], [], [], []
    last_failed, done, info = False, False, {"success": False}
    try:
        while not done:
            action = env.expert_action()
            rgb.append(obs["rgb"])
            objects.append(obs["objects"])
            actions.append(action if isinstance(action, int) else -1)
            failed.append(last_failed)
            obs, _, terminated, truncated, info = env.step(action)
            last_failed = info["failure_code"] is not None
            done = terminated or truncated
    finally:
        env.close()
    instruction = str(env.episode.goal.instruction) if env.episode is not None else ""
    return Demo(split, index, instruction, np.array(encode(instruction, TOKENS), np.int64),
                np.stack(rgb).astype(np.uint8), np.stack(objects).astype(np.int64),
                np.array(actions, np.int64), np.array(failed, bool), bool(info["success"]))


def collect_demos(out_dir: Path, split: str, indices: Iterable[int],
                  progress: Callable[[int, Demo | None, str], None] | None = None,
                  family: str = "pickup") -> dict[str, Any]:
    """Record the oracle on episodes `indices` of `split` in `family` into `out_dir` (resumable).

    Returns a summary: episodes asked, recorded, unavailable (index -> cause), steps, labelled steps.

    Raises:
        LuminousError: `out_dir` holds demonstrations of another env (or family); an unknown family.
    """
    env = family_env(family)
    claim = {"env": env.config.to_kwargs(), "tokens": TOKENS}
    marker = out_dir / "collection.json"
    if marker.is_file():
        if json.loads(marker.read_text()) != claim:
            raise LuminousError(f"{out_dir} holds demonstrations of another env; choose another folder")
    else:
        write_atomic(marker, json.dumps(claim, indent=1) + "\n")
    summary: dict[str, Any] = {"asked": 0, "recorded": 0, "unavailable": {}, "steps": 0, "labelled": 0}
    for index in indices:
        summary["asked"] += 1
        path = out_dir / f"{split}-{index}.npz"
        skipped = out_dir / f"{split}-{index}.unavailable"
        if skipped.is_file():
            summary["unavailable"][index] = skipped.read_text().strip()
            continue
        if path.is_file():
            demo = Demo.load(path)
        else:
            try:
                demo = record(env, split, index)
            except Unavailable as exc:
                write_atomic(skipped, exc.cause + "\n")
                summary["unavailable"][index] = exc.cause
                if progress is not None:
                    progress(index, None, exc.cause)
                continue
            write_atomic(path, demo.to_bytes())
        summary["recorded"] += 1
        summary["steps"] += len(demo.actions)
        summary["labelled"] += demo.labelled
        if progress is not None:
            progress(index, demo, "")
    return summary


def demos_env(folder: Path) -> dict[str, Any]:
    """The env options the demonstrations in `folder` were recorded in (its `collection.json`).

    Raises:
        LuminousError: the folder has no readable `collection.json`.
    """
    from luminous_sim.errors import read_json_file

    claim = read_json_file(folder / "collection.json", 1 << 20, "the collection record of `luminous bc collect`")
    env = claim.get("env") if isinstance(claim, dict) else None
    if not isinstance(env, dict):
        raise LuminousError(f"{folder / 'collection.json'}: no `env` object; re-collect with `luminous bc collect`")
    return env


def load_demos(folder: Path) -> list[Demo]:
    """Every demonstration in a folder, in a fixed order (split, then index).

    Raises:
        LuminousError: no demonstration there, or a file that is not one.
    """
    if folder.exists() and not folder.is_dir():
        raise LuminousError(f"{folder}: not a folder; expected the demonstrations folder of `luminous bc collect`")
    paths = sorted(folder.glob("*.npz"))
    if not paths:
        raise LuminousError(f"{folder}: no demonstrations (*.npz); run `luminous bc collect` first")
    demos = [Demo.load(p) for p in paths]
    return sorted(demos, key=lambda d: (d.split, d.index))
