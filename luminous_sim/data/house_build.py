"""A house split: ALFRED tasks in multi-room houses, built into a dataset like S+/U+ (`data.build.build`:
ALFRED's json_2.1.0 layout, a manifest, resumable).

Episode `i` of the split `houses` is a house generated from a seed derived from `i` (the house of `luminous
generate --house`: a kitchen, a living room, a bedroom and a bathroom, with a front door; its floor plan drawn
anew for each seed), a task of ALFRED's type `i mod 7` whose object lies in another room than its receptacle
(or lamp) where the house has one (`tasks.rooms_apart`), else any task of the type, solved by the oracle; a house
with no task of the type at all is replaced by the next draw's (`HOUSE_DRAWS`, counted in the record). A
house has no AI2-THOR floor plan: its trials name their scene by the house shell's name in `scene.floor_plan`
(`env_house`) and the house seed in `scene.scene_num` (also the last part of the task folder's name), and the
sidecar's `house` says the seed and whether the task crosses rooms; the sidecar's `scene` is the house itself.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.data.alfred_export import ExportError, export_alfred
from luminous_sim.data.backends import Backend
from luminous_sim.data.build import ANNOTATIONS, BuildError, BuildOptions, BuildReport, IndexedJob, JobOutcome, build
from luminous_sim.limits import MAX_BUILD_JOBS
from luminous_sim.vocab import ALFRED_TASK_TYPES

HOUSE_SPLIT = "houses"
HOUSE_CODE = 26
"""Keeps the house split's seeds apart from other streams."""
HOUSE_DRAWS = 8
"""Houses drawn for an episode before it counts as failed: a house without a task of the type (no microwave for
heating, no lamp for examining) is replaced by the next draw's, and the record says how many were drawn."""


def house_seed(index: int, draw: int = 0) -> int:
    """The seed of draw `draw` of episode `index`'s house (and of its task draw and instructions)."""
    return int(np.random.SeedSequence([HOUSE_CODE, index, draw]).generate_state(1)[0] % (2**31))


@dataclass(frozen=True)
class HouseJob(IndexedJob):
    """Episode `index` of the house split (`split` is `HOUSE_SPLIT`)."""

    @property
    def task_type(self) -> str:
        return ALFRED_TASK_TYPES[self.index % len(ALFRED_TASK_TYPES)]

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        from luminous_sim.env.kinds.house_objectnav import house_scene
        from luminous_sim.episode import run_episode
        from luminous_sim.errors import InfeasibleSceneError
        from luminous_sim.tasks import TaskSamplingError

        details: dict[str, Any] = {}
        stage, why = "", ""
        for draw in range(HOUSE_DRAWS):
            seed = house_seed(self.index, draw)
            details = {"house_seed": seed, "house_draws": draw + 1, "cross_room": True}
            try:
                scene = house_scene(seed)
            except InfeasibleSceneError as exc:
                stage, why = "layout", str(exc)
                continue
            try:
                result, record = run_episode(scene, self.task_type, seed, record_frames=options.frames,
                                             extra_annotations=ANNOTATIONS - 1, cross_room=True,
                                             places=options.alfworld)
                break
            except TaskSamplingError:
                details["cross_room"] = False
            try:
                result, record = run_episode(scene, self.task_type, seed, record_frames=options.frames,
                                             extra_annotations=ANNOTATIONS - 1, places=options.alfworld)
                break
            except TaskSamplingError as exc:
                stage, why = "task", str(exc)
        else:
            return JobOutcome(stage=stage, cause=f"{why} (and in {HOUSE_DRAWS - 1} more houses drawn)",
                              details=details)
        traj = record.trajectory
        details.update(goal=result.goal, low_actions=len(traj.low_actions), replans=traj.replans)
        if not result.success:
            return JobOutcome(stage="oracle", cause=result.failure or "the goal is not met", details=details)
        try:
            trial = export_alfred(work, scene, record, seed=seed, video=options.video and options.frames,
                                  sidecar={"house": {"seed": seed, "cross_room": details["cross_room"]}})
        except ExportError as exc:
            return JobOutcome(stage="export", cause=str(exc), details=details)
        return JobOutcome(trial=trial, details=details)


def house_jobs(count: int, start: int = 0) -> list[HouseJob]:
    """Jobs for episodes `start .. start + count - 1` of the house split."""
    if not 0 <= count <= MAX_BUILD_JOBS or start < 0:
        raise BuildError(f"count must be from 0 to {MAX_BUILD_JOBS} (luminous_sim.limits.MAX_BUILD_JOBS) and start "
                         f">= 0, got {count} from {start}")
    return [HouseJob(HOUSE_SPLIT, i) for i in range(start, start + count)]


def build_houses(out: Path, count: int, backend: Backend | None = None, options: BuildOptions | None = None,
                 progress: bool = True) -> BuildReport:
    """Episodes 0 .. count-1 of the house split into the build folder `out` (beside any S+/U+ split there)."""
    return build(out, house_jobs(count), backend, options, progress)
