"""One expert episode end to end: a scene, a sampled ALFRED task, the oracle's trajectory, ALFRED's
evaluation, template instructions, and the files a person looks at (frames, video, top-down path)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.catalog import Catalog
from luminous_sim.assets.objio import write_atomic
from luminous_sim.errors import FailureCode
from luminous_sim.planning import Trajectory
from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose

TASK_REDRAWS = 3
"""Tasks redrawn when the sampled one cannot be done in this scene (ALFRED's generator drops those too)."""
REDRAW_ON = frozenset({FailureCode.GOAL_UNREACHABLE, FailureCode.NO_POSE, FailureCode.RECEPTACLE_FULL,
                       FailureCode.PLAN_BUDGET})
"""Failures that say the task, not the oracle, is the problem: a goal the planner proves impossible or
finds no plan for in its budget, an object nobody can see, a receptacle with no room left."""


@dataclass(frozen=True)
class EpisodeResult:
    task_type: str
    goal: str
    success: bool
    goal_conditions: tuple[int, int]
    low_actions: int
    planning_seconds: float
    out_dir: Path | None


@dataclass(frozen=True)
class EpisodeRecord:
    """What an exporter needs beyond the files `run_episode` writes (`return_record=True`)."""

    task: Any
    """The `TaskInstance` that was solved (after any redraws)."""
    trajectory: Trajectory
    start_state: Any
    """The `WorldState` the oracle started from (after ALFRED's set-up, e.g. everything dirty for cleaning)."""
    instructions: list[Any]
    """`Instructions`: first the one written to `instructions.txt`, then `extra_annotations` more, each
    from its own random stream (so the written files do not depend on how many are asked for)."""


def poses_along(traj: Trajectory, start: AgentPose) -> list[AgentPose]:
    """The agent's pose after each low-level action (navigation replayed from the start pose)."""
    pose, out = start, [start]
    for a in traj.low_actions:
        name = a["api_action"]["action"]
        if name == "MoveAhead":
            pose = pose.moved()
        elif name in ("RotateLeft", "RotateRight"):
            pose = pose.rotated(-1 if name == "RotateLeft" else 1)
        elif name in ("LookUp", "LookDown"):
            pose = pose.looked(-1 if name == "LookUp" else 1) or pose
        out.append(pose)
    return out


def write_video(frames: list[np.ndarray], path: Path, fps: int = 6) -> Path:
    """An MP4 of the frames (OpenCV, mp4v), written to a temporary name then moved into place."""
    import os

    import cv2

    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.tmp{path.suffix}")
    h, w = frames[0].shape[:2]
    writer = cv2.VideoWriter(str(tmp), cv2.VideoWriter_fourcc(*"mp4v"), fps, (w, h))
    for f in frames:
        writer.write(cv2.cvtColor(f, cv2.COLOR_RGB2BGR))
    writer.release()
    os.replace(tmp, path)
    return path


def prepared_world(scene: Scene, task_type: str, catalog: Catalog | None = None):
    """The world as ALFRED sets a scene up for a task: for cleaning, everything dirtyable is dirty."""
    from luminous_sim.vocab import abilities
    from luminous_sim.world import World

    world = World(scene, catalog=catalog)
    if task_type == "pick_clean_then_place_in_recep":
        world.set_up_dirty([oid for oid, st in world.view().state.objects.items()
                            if abilities(st.object_type).dirtyable and abilities(st.object_type).pickupable])
    return world


def run_episode(scene: Scene, task_type: str, seed: int, out_dir: Path | None = None,
                record_frames: bool = True, return_trajectory: bool = False, return_record: bool = False,
                extra_annotations: int = 2):
    """Sample a `task_type` task in `scene`, solve it with the oracle, evaluate it, and write the files.

    Returns the `EpisodeResult`; with `return_trajectory`, `(result, trajectory)`; with `return_record`,
    `(result, EpisodeRecord)` holding the task, the trajectory and `1 + extra_annotations` instructions.
    """
    from luminous_sim.cdf.predicates import to_sexpr
    from luminous_sim.language import Describer
    from luminous_sim.planning import Oracle, draw_task
    from luminous_sim.tasks.errors import TaskSamplingError
    from luminous_sim.tasks.templates import task_description

    rng = np.random.default_rng(np.random.SeedSequence([seed, 11]))
    world = prepared_world(scene, task_type)
    unreachable: set[str] = set()
    full: set[str] = set()
    try:
        task = draw_task(scene, world.view(), task_type, rng)
        start, start_state = world.agent, world.view().state
        traj = Oracle(world, record_frames=record_frames).run(task.goal)
        for _ in range(TASK_REDRAWS):  # ALFRED's generator also drops tasks its expert cannot do
            if traj.success or not REDRAW_ON.intersection(traj.failure_codes):
                break
            unreachable.update(traj.unreachable)
            full.update(traj.full)
            fresh = prepared_world(scene, task_type)
            try:
                redrawn = draw_task(scene, fresh.view(), task_type, rng, excluded=unreachable, full=full)
            except TaskSamplingError:  # nothing else to draw: the failed episode stands
                fresh.close()
                break
            world.close()
            world, task = fresh, redrawn
            start_state = world.view().state
            traj = Oracle(world, record_frames=record_frames).run(task.goal)
        view = world.view()
        visible = set(view.visible_objects())
        done, total = task.conditions().alfred_counts(view.state, visible)
        traj.goal_conditions = (done, total)
        traj.success = traj.success and done == total
        text = Describer(view, rng).describe(traj, task_description(task, rng))
        texts = [text]
        if return_record:
            for k in range(extra_annotations):
                more = np.random.default_rng(np.random.SeedSequence([seed, 12, k]))
                texts.append(Describer(view, more).describe(traj, task_description(task, more)))
        if out_dir is not None:
            _write(Path(out_dir), scene, task, traj, text, start, view)
    finally:
        world.close()
    result = EpisodeResult(task_type, to_sexpr(task.goal), traj.success, (done, total), len(traj.low_actions),
                           traj.planning_seconds, Path(out_dir) if out_dir else None)
    if return_record:
        return result, EpisodeRecord(task, traj, start_state, texts)
    return (result, traj) if return_trajectory else result


def _write(out: Path, scene: Scene, task, traj: Trajectory, text, start: AgentPose, view) -> None:
    from luminous_sim.assets.objio import png_bytes

    record = {
        "task": task.to_dict(), "task_desc": text.task_desc, "high_descs": text.high_descs,
        "init_action": traj.init_action, "plan": {"high_pddl": traj.high_pddl, "low_actions": traj.low_actions},
        "images": traj.images, "success": traj.success, "goal_conditions": list(traj.goal_conditions),
        "replans": traj.replans, "failure": traj.failure, "scene": scene.room.name,
    }
    write_atomic(out / "trajectory.json", json.dumps(record, indent=1, sort_keys=True) + "\n")
    for i, frame in enumerate(traj.frames):
        write_atomic(out / "frames" / f"{i:09d}.png", png_bytes(frame))
    if traj.frames:
        write_video(traj.frames, out / "video.mp4")
    path = np.array([[p.x, p.y] for p in poses_along(traj, start)])
    write_atomic(out / "top_down.png", png_bytes(view.top_down(path=path)))
    write_atomic(out / "instructions.txt", "\n".join([text.task_desc, ""] + text.high_descs) + "\n")

