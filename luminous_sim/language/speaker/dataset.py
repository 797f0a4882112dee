"""ALFRED-format folders -> speaker examples (source tokens, target words, optional features).

A step example pairs one subgoal (planner action, object names, its low-level actions) with one
annotator's ``high_descs[i]``; a goal example pairs the whole subgoal sequence with ``task_desc``.
"""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from luminous_sim.errors import path_kind
from luminous_sim.language.speaker.errors import SpeakerError
from luminous_sim.language.speaker.records import LowAction, Subgoal, Trajectory, load_trajectory
from luminous_sim.language.speaker.text import tokenize
from luminous_sim.vocab import DISCRETE_NAVIGATION

STEP, GOAL, SEP = "<step>", "<goal>", "<sep>"
NAV_ACTIONS = frozenset(DISCRETE_NAVIGATION.values())
"""ALFRED's discrete navigation tokens (`MoveAhead_25`, ...): runs of one are merged into a count."""
MAX_COUNT = 10


@dataclass(frozen=True)
class Example:
    """One training pair.

    Attributes:
        kind: ``"step"`` or ``"goal"``.
        src: Source tokens (see :func:`encode_step`, :func:`encode_goal`).
        tgt: Target words.
        key: ``(trajectory key, subgoal index or -1 for the goal)``; annotations of the same key are
            alternative references.
        features: ``[len(src), D]`` features aligned with ``src``, or None.
    """

    kind: str
    src: tuple[str, ...]
    tgt: tuple[str, ...]
    key: tuple[str, int]
    features: np.ndarray | None = None


def _count_token(n: int) -> str:
    return f"x{n}" if n < MAX_COUNT else f"x{MAX_COUNT}+"


def encode_step(
    subgoal: Subgoal, low_actions: Sequence[LowAction], features: np.ndarray | None = None
) -> tuple[list[str], np.ndarray | None]:
    """Source tokens of one subgoal, with repeated navigation actions run-length coded.

    ``GotoLocation(countertop)`` with ``RotateLeft, MoveAhead x3`` becomes
    ``<step> GotoLocation countertop <sep> RotateLeft_90 MoveAhead_25 x3``; interactions add the
    target's type (``PickupObject apple``).

    Args:
        subgoal: The high-level subgoal.
        low_actions: Its low-level actions.
        features: ``[len(low_actions), D]`` per-step features, or None.

    Returns:
        The tokens and, when ``features`` is given, ``[len(tokens), D]`` features aligned with them:
        an action token carries the mean of its run's steps; other tokens carry zeros.

    Raises:
        SpeakerError: ``features`` does not have one row per low-level action.
    """
    tokens = [STEP, subgoal.action, *subgoal.args, SEP]
    if features is not None:
        features = np.asarray(features, dtype=np.float32)
        if features.ndim != 2 or features.shape[0] != len(low_actions):
            raise SpeakerError(
                f"features must have shape [{len(low_actions)}, D] (one row per low action), "
                f"got {list(features.shape)}"
            )
    rows: list[np.ndarray | None] = [None] * len(tokens)
    i = 0
    while i < len(low_actions):
        act = low_actions[i]
        j = i + 1
        if act.action in NAV_ACTIONS:
            while j < len(low_actions) and low_actions[j] == act:
                j += 1
        tokens.append(act.action)
        rows.append(None if features is None else features[i:j].mean(axis=0))
        extra = ([act.target] if act.target else []) + ([_count_token(j - i)] if j - i > 1 else [])
        tokens += extra
        rows += [None] * len(extra)
        i = j
    if features is None:
        return tokens, None
    zero = np.zeros(features.shape[1], dtype=np.float32)
    return tokens, np.stack([zero if r is None else r for r in rows]).astype(np.float32)


def encode_goal(subgoals: Sequence[Subgoal]) -> list[str]:
    """Source tokens of a trajectory: ``<goal>``, then each non-End subgoal's action and names."""
    tokens = [GOAL]
    for sg in subgoals:
        if sg.action != "End":
            tokens += [sg.action, *sg.args]
    return tokens


def find_trajectory_files(root: str | Path) -> list[Path]:
    """Every ``traj_data.json`` under ``root`` (any depth), sorted.

    Raises:
        SpeakerError: ``root`` does not exist or holds no traj_data.json.
    """
    root = Path(root)
    kind = path_kind(root)
    if kind == "a regular file":
        return [root]
    if kind != "a folder":
        raise SpeakerError(f"{root}: {kind}; expected a data folder of traj_data.json files (or one such file)")
    files = sorted(root.rglob("traj_data.json"))
    if not files:
        raise SpeakerError(f"{root}: no traj_data.json files under this folder")
    return files


def load_trajectories(
    root: str | Path, features: bool = False, max_trajectories: int | None = None
) -> list[Trajectory]:
    """Load the trajectories under ``root`` (the first ``max_trajectories`` in sorted order).

    Raises:
        SpeakerError: The folder is empty or a file is unreadable (its path is in the message).
    """
    files = find_trajectory_files(root)
    if max_trajectories is not None:
        files = files[:max_trajectories]
    return [load_trajectory(f, features=features) for f in files]


def split_trajectories(
    trajectories: Sequence[Trajectory], held_out: float = 0.1, seed: int = 0
) -> tuple[list[Trajectory], list[Trajectory]]:
    """Seeded split into (train, held-out).

    Whole task folders (trials of the same task) are held out together, so no held-out task is
    trained on; about ``held_out`` of the trajectories (at least one when ``held_out > 0``) are
    held out.
    """
    if not 0.0 <= held_out < 1.0:
        raise SpeakerError(f"held_out must be in [0, 1), got {held_out}")
    groups: dict[str, list[int]] = {}
    for i, traj in enumerate(trajectories):
        groups.setdefault(traj.path.parent.parent.name, []).append(i)
    names = sorted(groups)
    random.Random(seed).shuffle(names)
    target = max(1, round(len(trajectories) * held_out)) if held_out > 0 and len(names) > 1 else 0
    held: set[int] = set()
    for name in names:
        if len(held) >= target:
            break
        held.update(groups[name])
    return (
        [t for i, t in enumerate(trajectories) if i not in held],
        [t for i, t in enumerate(trajectories) if i in held],
    )


def aligned_descs(traj: Trajectory, high_descs: Sequence[str]) -> list[tuple[int, str]]:
    """(subgoal index, instruction) pairs one annotation supports.

    When an annotation has one instruction fewer than subgoals (ALFRED merged the last two), its
    last instruction is left out; other mismatches give nothing.
    """
    n = len(traj.subgoals)
    if len(high_descs) == n:
        return list(enumerate(high_descs))
    if len(high_descs) == n - 1:
        return list(enumerate(high_descs[:-1]))
    return []


def build_examples(
    trajectories: Sequence[Trajectory], kinds: Sequence[str] = ("step", "goal")
) -> list[Example]:
    """Examples for each (trajectory, annotation, subgoal) and (trajectory, annotation) goal."""
    out: list[Example] = []
    for traj in trajectories:
        encoded = [
            encode_step(sg, seg, None if traj.features is None else traj.features[i])
            for i, (sg, seg) in enumerate(zip(traj.subgoals, traj.segments))
        ]
        goal_src = tuple(encode_goal(traj.subgoals))
        for ann in traj.annotations:
            if "step" in kinds:
                for i, desc in aligned_descs(traj, ann.high_descs):
                    words = tokenize(desc)
                    if words:
                        src, feats = encoded[i]
                        out.append(Example("step", tuple(src), tuple(words), (traj.key, i), feats))
            if "goal" in kinds:
                words = tokenize(ann.task_desc)
                if words:
                    out.append(Example("goal", goal_src, tuple(words), (traj.key, -1)))
    return out
