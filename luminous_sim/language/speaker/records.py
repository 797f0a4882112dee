"""One ALFRED traj_data.json as the speaker sees it: subgoals, low-level actions, annotations."""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.language.speaker.errors import SpeakerError, check_regular_file
from luminous_sim.scene.ids import type_of_id


def object_type(object_id: str) -> str:
    """Lower-cased object type of an ALFRED objectId.

    ``Apple|+00.1|+00.9|-01.2`` -> ``apple``; ``Sink|...|SinkBasin`` -> ``sinkbasin``;
    ``Apple|...|AppleSliced_1`` -> ``applesliced``.
    """
    return type_of_id(object_id).lower()


@dataclass(frozen=True)
class Subgoal:
    """A high-level subgoal: planner action and lower-cased object/receptacle names."""

    action: str
    args: tuple[str, ...] = ()

    @classmethod
    def from_alfred(cls, entry: dict[str, Any]) -> Subgoal:
        """From a ``plan.high_pddl[i]`` entry (``planner_action.action``, ``discrete_action.args``).

        Raises:
            KeyError, TypeError: The entry lacks these fields.
        """
        action = entry["planner_action"]["action"]
        args = entry.get("discrete_action", {}).get("args", [])
        if not isinstance(action, str) or not isinstance(args, list):
            raise TypeError(
                "planner_action.action must be a string and discrete_action.args a list"
            )
        return cls(action, tuple(str(a).lower() for a in args))


@dataclass(frozen=True)
class LowAction:
    """A low-level action token (``MoveAhead_25``, ``PutObject``...) and its target's type."""

    action: str
    target: str | None = None

    @classmethod
    def from_alfred(cls, entry: dict[str, Any]) -> LowAction:
        """From a ``plan.low_actions[i]`` entry; PutObject's target is the receptacle."""
        action = entry["discrete_action"]["action"]
        api = entry.get("api_action", {})
        target_id = api.get("receptacleObjectId") or api.get("objectId")
        if not isinstance(action, str):
            raise TypeError("discrete_action.action must be a string")
        return cls(
            action, object_type(target_id) if isinstance(target_id, str) and target_id else None
        )


@dataclass(frozen=True)
class Annotation:
    """One annotator's goal directive and per-subgoal instructions."""

    task_desc: str
    high_descs: tuple[str, ...]


@dataclass
class Trajectory:
    """The parts of a traj_data.json the speaker uses.

    Attributes:
        path: The traj_data.json file.
        task_id: ALFRED's trial id.
        task_type: One of the 7 task types ("" when absent).
        subgoals: Non-End subgoals, in order.
        segments: Low-level actions of each subgoal (same length as ``subgoals``).
        annotations: Human annotations (empty only if loaded with ``require_annotations=False``).
        features: Per-subgoal ``[T_i, D]`` visual features, or None when frames were not loaded.
    """

    path: Path
    task_id: str
    task_type: str
    subgoals: list[Subgoal]
    segments: list[list[LowAction]]
    annotations: list[Annotation]
    features: list[np.ndarray] | None = field(default=None, repr=False)
    low_indices: list[list[int]] = field(default_factory=list, repr=False)

    @property
    def key(self) -> str:
        """A stable identifier: ``<task dir>/<trial>``."""
        return f"{self.path.parent.parent.name}/{self.path.parent.name}"


def _read_json(path: Path) -> dict[str, Any]:
    check_regular_file(path, "a trajectory file (traj_data.json)")
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SpeakerError(f"{path}: trajectory file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SpeakerError(f"{path}: cannot read trajectory ({exc})") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise SpeakerError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
    if not isinstance(data, dict):
        raise SpeakerError(f"{path}: expected a JSON object at the top level")
    return data


def _annotations(data: dict[str, Any], path: Path) -> list[Annotation]:
    anns = data.get("turk_annotations", {})
    anns = anns.get("anns") if isinstance(anns, dict) else None
    if not isinstance(anns, list):
        raise SpeakerError(
            f"{path}: no turk_annotations.anns (the speaker trains on human annotations)"
        )
    out = []
    for i, ann in enumerate(anns):
        desc, highs = (
            (ann.get("task_desc"), ann.get("high_descs")) if isinstance(ann, dict) else (0, 0)
        )
        if (
            not isinstance(desc, str)
            or not isinstance(highs, list)
            or not all(isinstance(h, str) for h in highs)
        ):
            raise SpeakerError(
                f"{path}: turk_annotations.anns[{i}] needs task_desc (str) and "
                "high_descs (list of str)"
            )
        out.append(Annotation(desc, tuple(highs)))
    return out


def parse_trajectory(
    data: dict[str, Any], path: Path, require_annotations: bool = True
) -> Trajectory:
    """Build a :class:`Trajectory` from a loaded traj_data.json object.

    Args:
        data: The parsed JSON.
        path: Where it came from (named in errors).
        require_annotations: Raise when ``turk_annotations`` is missing (False: no annotations).

    Raises:
        SpeakerError: A required key is missing or malformed.
    """
    try:
        high = data["plan"]["high_pddl"]
        low = data["plan"]["low_actions"]
        subgoals = [Subgoal.from_alfred(h) for h in high]
        lows = [(int(a["high_idx"]), LowAction.from_alfred(a)) for a in low]
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        raise SpeakerError(
            f"{path}: malformed or missing plan.high_pddl/plan.low_actions ({exc!r})"
        ) from None
    subgoals = [s for s in subgoals if s.action != "End"]
    segments: list[list[LowAction]] = [[] for _ in subgoals]
    indices: list[list[int]] = [[] for _ in subgoals]
    for low_idx, (high_idx, action) in enumerate(lows):
        if not 0 <= high_idx < len(subgoals):
            raise SpeakerError(
                f"{path}: low action high_idx {high_idx} outside 0..{len(subgoals) - 1}"
            )
        segments[high_idx].append(action)
        indices[high_idx].append(low_idx)
    anns = _annotations(data, path) if require_annotations or "turk_annotations" in data else []
    return Trajectory(
        path,
        str(data.get("task_id", path.parent.name)),
        str(data.get("task_type", "")),
        subgoals,
        segments,
        anns,
        low_indices=indices,
    )


def load_trajectory(
    path: str | Path, features: bool = False, require_annotations: bool = True
) -> Trajectory:
    """Read one traj_data.json.

    Args:
        path: The file.
        features: Also compute per-step visual features from ``raw_images/`` beside it, if any.
        require_annotations: Raise when the file has no ``turk_annotations``.

    Raises:
        SpeakerError: The file is missing, not JSON, or lacks a required field (the message names
            the file).
    """
    path = Path(path)
    data = _read_json(path)
    traj = parse_trajectory(data, path, require_annotations)
    if features:
        from luminous_sim.language.speaker.features import load_step_features

        n_low = sum(len(s) for s in traj.segments)
        images = data.get("images", [])
        per_low = load_step_features(path.parent, images if isinstance(images, list) else [], n_low)
        if per_low is not None:
            traj.features = [per_low[np.asarray(idx, dtype=int)] for idx in traj.low_indices]
    return traj
