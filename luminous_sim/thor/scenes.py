"""Which generated scene an ALFRED trial means: `reset("FloorPlanN")` + `restore_scene(object_poses, ...)`.

ALFRED names a scene by its AI2-THOR floor plan and then moves every pickupable object to where the
trial's `scene.object_poses` says. Ours are generated scenes, so the floor plan alone does not say which
one: the dataset folder named by `LUMINOUS_ALFRED_DATA` (a build of `luminous dataset build`) holds, per
trial, `traj_data.json` (its `object_poses`, written by `data.export_alfred` from the scene) beside the
sidecar `luminous.json` (the scene itself). The scene whose trial lists exactly these object poses in
this floor plan is the one.

Trials are read once per process and folder (`SceneIndex.of`); the sidecar's scene only when matched.
The walk stays inside each dataset folder: it follows no symbolic link (to a folder or a file), and every
file it reads is a regular file inside the folder once links are resolved, of at most
`luminous_sim.limits.MAX_INPUT_BYTES`, checked before it is opened (`errors.read_json_file`). A trial
whose files are refused is left out of the index, and the refusal is named when no trial matches.
"""

from __future__ import annotations

import functools
import json
import math
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.benchmark import trial_folders
from luminous_sim.errors import LuminousError, link_or_kind, read_json_file
from luminous_sim.fileio import one_line
from luminous_sim.limits import MAX_INPUT_BYTES
from luminous_sim.scene import Scene

DATA_VAR = "LUMINOUS_ALFRED_DATA"
"""The environment variable naming the dataset folder(s) (several joined by the path separator)."""
SIDECAR = "luminous.json"
TRAJ = "traj_data.json"
POSITION_DECIMALS = 3
"""Object positions are compared rounded to a millimetre (a JSON round trip keeps them exact anyway)."""
TRAJ_WHAT = f"a trial's {TRAJ} (at most luminous_sim.limits.MAX_INPUT_BYTES)"
SIDECAR_WHAT = f"a trial's {SIDECAR} sidecar (at most luminous_sim.limits.MAX_INPUT_BYTES)"

PosesKey = tuple[tuple[str, float, float, float], ...]


class ThorSceneError(LuminousError):
    """The scene ALFRED asks for cannot be identified (no dataset folder, no trial with these object
    poses in this floor plan, or several different scenes with them). The message is one line."""




def _coordinate(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"{where} must be a number, not {type(value).__name__}")
    try:
        number = float(value)
    except OverflowError:
        raise ValueError(f"{where} is an integer too large for a coordinate") from None
    if not math.isfinite(number):
        raise ValueError(f"{where} must be finite, not {number}")
    return round(number, POSITION_DECIMALS) + 0.0


def poses_key(object_poses: Iterable[Mapping[str, Any]]) -> PosesKey:
    """A trial's `object_poses` as a comparable value: sorted (name, x, y, z), rounded to a millimetre.

    Raises:
        ValueError: not a list of poses, each a mapping with a string `objectName` and a `position` of
            finite numbers `x`, `y`, `z` (the message says which entry and field).
    """
    if not isinstance(object_poses, list | tuple):
        raise ValueError(f"objectPoses must be a list of poses, not {type(object_poses).__name__}")
    out: list[tuple[str, float, float, float]] = []
    for i, p in enumerate(object_poses):
        if not isinstance(p, Mapping) or not isinstance(p.get("objectName"), str) \
                or not isinstance(p.get("position"), Mapping):
            raise ValueError(f"objectPoses[{i}] must be a mapping with a string objectName and a position")
        pos = p["position"]
        x, y, z = (_coordinate(pos.get(k), f"objectPoses[{i}].position.{k}") for k in "xyz")
        out.append((p["objectName"], x, y, z))
    return tuple(sorted(out))


@dataclass(frozen=True)
class Trial:
    """One built trial: its folder, floor plan, task type and object poses."""

    path: Path
    floor_plan: str
    task_type: str
    poses: PosesKey

    def scene(self) -> Scene:
        """The generated scene the trial was solved in (from its sidecar)."""
        sidecar = self.path / SIDECAR
        try:
            data = read_json_file(sidecar, MAX_INPUT_BYTES, SIDECAR_WHAT, ThorSceneError)
        except ThorSceneError as exc:
            raise ThorSceneError(one_line(str(exc))) from None
        try:
            return Scene.from_json(json.dumps(data["scene"]), where=str(sidecar))
        except (ValueError, KeyError, TypeError, RecursionError, LuminousError) as exc:
            raise ThorSceneError(one_line(f"{sidecar}: cannot read the trial's scene ({type(exc).__name__}: "
                                          f"{exc})")) from None


class SceneIndex:
    """The trials of one or more dataset folders, by floor plan."""

    def __init__(self, roots: Sequence[Path]):
        self.roots = tuple(Path(r).resolve() for r in roots)
        self.trials: dict[str, list[Trial]] = {}
        self.refused: list[str] = []
        """One line per trial left out: its file and why (a link, a FIFO, too large, not JSON, ...)."""
        for root in self.roots:
            if not root.is_dir():
                raise ThorSceneError(f"{DATA_VAR}: {root} is not a folder (expected a `luminous dataset build` "
                                     "output)")
            folders, linked = trial_folders(root)
            self.refused += [one_line(f"{d}: a symbolic link to a folder; not walked (the index stays inside {root})")
                             for d in linked]
            for folder in folders:
                traj = folder / TRAJ
                if not os.path.lexists(folder / SIDECAR):
                    continue  # an ALFRED trial of its own, not one of ours
                try:
                    for path in (traj, folder / SIDECAR):
                        _confined(path, root)
                    self.trials.setdefault((trial := _read_trial(traj)).floor_plan, []).append(trial)
                except ThorSceneError as exc:
                    self.refused.append(one_line(str(exc)))

    @classmethod
    def of(cls, roots: str | os.PathLike[str] | Sequence[str | os.PathLike[str]] | None = None) -> SceneIndex:
        """The index of `roots` (default: the folders `LUMINOUS_ALFRED_DATA` names), read once per process."""
        if roots is None:
            value = os.environ.get(DATA_VAR, "")
            if not value.strip():
                raise ThorSceneError(f"{DATA_VAR} is not set: set it to a dataset folder built by `luminous dataset "
                                     "build` (or run under `python -m luminous_sim.thor --data DIR`)")
            roots = [p for p in value.split(os.pathsep) if p]
        elif isinstance(roots, str | os.PathLike):
            roots = [roots]
        if not isinstance(roots, list | tuple) or not roots \
                or not all(isinstance(r, str | os.PathLike) and str(r) for r in roots):
            raise ThorSceneError(one_line(f"the dataset folder(s) must be a path or a list of paths, not {roots!r}"
                                          [:300]))
        try:
            resolved = tuple(str(Path(r).resolve()) for r in roots)
        except (OSError, ValueError, RuntimeError) as exc:
            raise ThorSceneError(one_line(f"dataset folder {roots!r}: {exc}"[:300])) from None
        return _index(resolved)

    def size(self) -> int:
        return sum(len(v) for v in self.trials.values())

    def candidates(self, floor_plan: str) -> list[Trial]:
        return list(self.trials.get(floor_plan, ()))

    def find(self, floor_plan: str, object_poses: Iterable[Mapping[str, Any]]) -> Trial:
        """The trial of `floor_plan` whose object poses are `object_poses` (one of them when several trials
        share the scene).

        Raises:
            ThorSceneError: none matches, or trials with different scenes do.
        """
        where = ", ".join(str(r) for r in self.roots)
        trials = self.candidates(floor_plan)
        if not trials:
            raise ThorSceneError(one_line(f"no trial of {floor_plan} in {where} ({self.size()} trials indexed): build "
                                          "one with `luminous dataset build` or point LUMINOUS_ALFRED_DATA at the "
                                          f"folder that has it{self._refusals()}"))
        key = poses_key(object_poses)
        found = [t for t in trials if t.poses == key]
        if not found:
            raise ThorSceneError(one_line(f"no trial of {floor_plan} in {where} has these {len(key)} object poses "
                                          f"({len(trials)} trials of {floor_plan} checked): is traj_data.json from "
                                          f"this dataset, unedited?{self._refusals()}"))
        return found[0]

    def _refusals(self) -> str:
        """The trials left out, for an error message: how many, and the first one's reason."""
        if not self.refused:
            return ""
        return f" ({len(self.refused)} trial(s) left out of the index, e.g. {self.refused[0]})"


def _confined(path: Path, root: Path) -> None:
    """Refuse `path` unless it is a regular file (not a link) inside `root` once links are resolved."""
    if os.path.islink(path) or not os.path.isfile(path):
        raise ThorSceneError(f"{path}: {link_or_kind(path)}; expected a regular file inside {root} (links are "
                             "not followed)")
    try:
        path.resolve(strict=True).relative_to(root)
    except (OSError, ValueError):
        raise ThorSceneError(f"{path}: resolves outside the dataset folder {root}") from None


def _read_trial(traj: Path) -> Trial:
    """The trial of `traj` (a confined traj_data.json): its floor plan, task type and object poses."""
    data = read_json_file(traj, MAX_INPUT_BYTES, TRAJ_WHAT, ThorSceneError)
    try:
        scene = data["scene"]
        floor_plan, task_type = scene["floor_plan"], data.get("task_type", "")
        if not isinstance(floor_plan, str) or not isinstance(task_type, str):
            raise ValueError("scene.floor_plan and task_type must be strings")
        return Trial(traj.parent, floor_plan, task_type, poses_key(scene["object_poses"]))
    except (KeyError, TypeError, AttributeError, ValueError) as exc:
        raise ThorSceneError(f"{traj}: not a trial of `luminous dataset build` ({type(exc).__name__}: "
                             f"{one_line(str(exc), 200)})") from None


@functools.lru_cache(maxsize=8)
def _index(roots: tuple[str, ...]) -> SceneIndex:
    return SceneIndex([Path(r) for r in roots])
