"""Which generated scene an ALFRED trial means: `reset("FloorPlanN")` + `restore_scene(object_poses, ...)`.

ALFRED names a scene by its AI2-THOR floor plan and then moves every pickupable object to where the
trial's `scene.object_poses` says. Ours are generated scenes, so the floor plan alone does not say which
one: the dataset folder named by `LUMINOUS_ALFRED_DATA` (a build of `luminous dataset build`) holds, per
trial, `traj_data.json` (its `object_poses`, written by `data.export_alfred` from the scene) beside the
sidecar `luminous.json` (the scene itself). The scene whose trial lists exactly these object poses in
this floor plan is the one.

Trials are read once per process and folder (`SceneIndex.of`); the sidecar's scene only when matched.
"""

from __future__ import annotations

import functools
import json
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError
from luminous_sim.scene import Scene

DATA_VAR = "LUMINOUS_ALFRED_DATA"
"""The environment variable naming the dataset folder(s) (several joined by the path separator)."""
SIDECAR = "luminous.json"
TRAJ = "traj_data.json"
POSITION_DECIMALS = 3
"""Object positions are compared rounded to a millimetre (a JSON round trip keeps them exact anyway)."""

PosesKey = tuple[tuple[str, float, float, float], ...]


class ThorSceneError(LuminousError):
    """The scene ALFRED asks for cannot be identified (no dataset folder, no trial with these object
    poses in this floor plan, or several different scenes with them). The message is one line."""


def poses_key(object_poses: Iterable[Mapping[str, Any]]) -> PosesKey:
    """A trial's `object_poses` as a comparable value: sorted (name, x, y, z), rounded to a millimetre."""
    out: list[tuple[str, float, float, float]] = []
    for p in object_poses:
        pos = p["position"]
        x, y, z = (round(float(pos[k]), POSITION_DECIMALS) + 0.0 for k in "xyz")
        out.append((str(p["objectName"]), x, y, z))
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
            data = json.loads(sidecar.read_text())
            return Scene.from_json(json.dumps(data["scene"]), where=str(sidecar))
        except (OSError, ValueError, KeyError) as exc:
            raise ThorSceneError(f"{sidecar}: cannot read the trial's scene ({type(exc).__name__}: {exc})") from None


class SceneIndex:
    """The trials of one or more dataset folders, by floor plan."""

    def __init__(self, roots: Sequence[Path]):
        self.roots = tuple(Path(r) for r in roots)
        self.trials: dict[str, list[Trial]] = {}
        for root in self.roots:
            if not root.is_dir():
                raise ThorSceneError(f"{DATA_VAR}: {root} is not a folder (expected a `luminous dataset build` "
                                     "output)")
            for traj in sorted(root.rglob(TRAJ)):
                if not (traj.parent / SIDECAR).is_file():
                    continue  # an ALFRED trial of its own, not one of ours
                try:
                    data = json.loads(traj.read_text())
                    scene = data["scene"]
                    trial = Trial(traj.parent, str(scene["floor_plan"]), str(data.get("task_type", "")),
                                  poses_key(scene["object_poses"]))
                except (OSError, ValueError, KeyError, TypeError):
                    continue
                self.trials.setdefault(trial.floor_plan, []).append(trial)

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
        return _index(tuple(str(Path(r).resolve()) for r in roots))

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
            raise ThorSceneError(f"no trial of {floor_plan} in {where} ({self.size()} trials indexed): build one with "
                                 "`luminous dataset build` or point LUMINOUS_ALFRED_DATA at the folder that has it")
        key = poses_key(object_poses)
        found = [t for t in trials if t.poses == key]
        if not found:
            raise ThorSceneError(f"no trial of {floor_plan} in {where} has these {len(key)} object poses "
                                 f"({len(trials)} trials of {floor_plan} checked): is traj_data.json from this "
                                 "dataset, unedited?")
        return found[0]


@functools.lru_cache(maxsize=8)
def _index(roots: tuple[str, ...]) -> SceneIndex:
    return SceneIndex([Path(r) for r in roots])
