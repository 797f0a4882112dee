"""ALFRED's human annotations with the task each describes, as the instruction parser learns from them: every
annotation of every trajectory under a folder (its goal directive, its step instructions), labelled by the
trajectory's `task_type` and `pddl_params`. Torch-free."""

from __future__ import annotations

import hashlib
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError, json_field, read_json_file
from luminous_sim.limits import MAX_INPUT_BYTES
from luminous_sim.vocab import ALFRED_TASK_TYPES

SLOTS: tuple[str, ...] = ("object_target", "parent_target", "mrecep_target", "toggle_target", "object_sliced")
"""ALFRED's five task arguments (`pddl_params`), in the order they are scored."""


LOOK = "look_at_obj_in_light"
MOVABLE = "pick_and_place_with_movable_recep"


def allowed(task_type: str, slot: str, value: Any) -> bool:
    """Whether a slot may hold `value` in a task of the type (ALFRED's task definitions, spec section 4: only
    the lamp task has a lamp and no receptacle; only the movable-receptacle task has a movable receptacle)."""
    if slot == "toggle_target":
        return (value != "") == (task_type == LOOK)
    if slot == "parent_target":
        return (value == "") == (task_type == LOOK)
    if slot == "mrecep_target":
        return (value != "") == (task_type == MOVABLE)
    return True


class AnnotationError(LuminousError):
    """ALFRED data that cannot be read; the message names the file and the field."""


@dataclass(frozen=True)
class Annotated:
    """One human annotation and the task it describes."""

    directive: str
    steps: tuple[str, ...]
    task_type: str
    params: dict[str, Any]
    """The five `SLOTS` of `pddl_params` (strings; `object_sliced` a bool)."""
    task: str
    """The task design's folder name (`pick_and_place_simple-Apple-None-Fridge-1`): its trials share it."""


def trajectory_files(root: Path) -> list[Path]:
    """Every traj_data.json under `root` (itself a file, or a folder at any depth), sorted.

    Raises:
        AnnotationError: `root` is missing or holds none.
    """
    if root.is_file():
        return [root]
    if not root.is_dir():
        raise AnnotationError(f"{root}: no such folder; expected ALFRED's data (a split's folder of "
                              "<task>/<trial>/traj_data.json)")
    found = sorted(Path(here) / "traj_data.json" for here, _, files in os.walk(root) if "traj_data.json" in files)
    if not found:
        raise AnnotationError(f"{root}: holds no traj_data.json")
    return found


def _field(data: Any, path: Path, *names: str) -> Any:
    return json_field(data, path, *names, error=AnnotationError)


def read_trajectory(path: Path) -> list[Annotated]:
    """The annotations of one traj_data.json.

    Raises:
        AnnotationError: unreadable, or a field the parser needs is missing or of the wrong kind.
    """
    data = read_json_file(path, MAX_INPUT_BYTES, "a traj_data.json (luminous_sim.limits.MAX_INPUT_BYTES)",
                          AnnotationError)
    task_type = _field(data, path, "task_type")
    if task_type not in ALFRED_TASK_TYPES:
        raise AnnotationError(f"{path}: field 'task_type': {task_type!r} is not one of ALFRED's seven types")
    raw = _field(data, path, "pddl_params")
    params: dict[str, Any] = {}
    for slot in SLOTS:
        value = _field(raw, path, slot)
        kind = bool if slot == "object_sliced" else str
        if not isinstance(value, kind):
            raise AnnotationError(f"{path}: field 'pddl_params.{slot}': expected a {kind.__name__}, got {value!r}")
        params[slot] = value
    anns = _field(data, path, "turk_annotations", "anns")
    out = []
    for k, ann in enumerate(anns if isinstance(anns, list) else []):
        directive, steps = (ann.get("task_desc"), ann.get("high_descs")) if isinstance(ann, dict) else (None, None)
        if not isinstance(directive, str) or not isinstance(steps, list) or not all(isinstance(s, str) for s in steps):
            raise AnnotationError(f"{path}: field 'turk_annotations.anns[{k}]': expected task_desc (text) and "
                                  "high_descs (a list of texts)")
        out.append(Annotated(directive, tuple(steps), task_type, params, path.parent.parent.name))
    return out


def read_annotations(root: Path) -> list[Annotated]:
    """Every annotation of every trajectory under `root`, in file order.

    Raises:
        AnnotationError: as `trajectory_files` and `read_trajectory`.
    """
    return [a for path in trajectory_files(root) for a in read_trajectory(path)]


def held_apart(examples: Sequence[Annotated], share: float, seed: int) -> tuple[list[Annotated], list[Annotated]]:
    """(kept, held apart): about `share` of the task designs, every annotation of their trials, held apart
    (chosen by a digest of the design's name and the seed, so the split does not depend on the order read)."""
    def apart(task: str) -> bool:
        digest = hashlib.sha256(f"{seed}:{task}".encode()).digest()
        return int.from_bytes(digest[:8], "big") / 2**64 < share

    kept = [e for e in examples if not apart(e.task)]
    return kept, [e for e in examples if apart(e.task)]
