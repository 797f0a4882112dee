"""One expert episode end to end: a scene, a sampled ALFRED task (or a given one, with its start pose,
initial state and script), the oracle's trajectory, ALFRED's evaluation, template instructions, and the
files a person looks at (frames, video, top-down path)."""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.catalog import Catalog
from luminous_sim.cdf import AgentPoseSpec, Expr
from luminous_sim.cdf.schema import HighLevelStep, LowLevelStep
from luminous_sim.episodes import EpisodeSpec
from luminous_sim.errors import Failure, FailureCode
from luminous_sim.fileio import atomic_file, write_atomic
from luminous_sim.planning import Trajectory
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskInstance, check_initial, scene_with_initial
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
    failure: str = ""
    """The first cause of failure: the first failed attempt's (later ones often only echo it), else why the
    goal is unmet at the end; "" when nothing failed and the goal holds."""
    failure_code: FailureCode | None = None
    """The first failure's code (None when nothing failed, or when the goal was simply left unmet)."""
    failures: tuple[Failure, ...] = ()
    """Every failed attempt's cause, in order (the oracle replans after each)."""
    notes: tuple[str, ...] = ()
    """What was adjusted to run a given task (an agent start moved onto the reachable grid)."""


@dataclass(frozen=True)
class EpisodeRecord:
    """What an exporter needs beyond the files `run_episode` writes (`run_episode` returns it beside the
    `EpisodeResult`)."""

    task: Any
    """The `TaskInstance` that was solved (after any redraws, or the one given)."""
    trajectory: Trajectory
    start_state: Any
    """The `WorldState` the oracle started from (after ALFRED's set-up, e.g. everything dirty for cleaning)."""
    instructions: list[Any]
    """`Instructions`: first the one written to `instructions.txt`, then `extra_annotations` more, each
    from its own random stream (so the written files do not depend on how many are asked for)."""
    places: Mapping[str, str] | None = None
    """With `places=True`: each fixed receptacle's place to stand at the start (`world.receptacle_places`), as
    ALFRED's `loc|x|z|rotation|horizon` (what ALFWorld's problem needs, `text.alfworld_problem`)."""


def poses_along(traj: Trajectory, start: AgentPose) -> list[AgentPose]:
    """The agent's pose after each low-level action (navigation replayed from the start pose)."""
    pose, out = start, [start]
    for a in traj.low_actions:
        pose = pose.after(a["api_action"]["action"])
        out.append(pose)
    return out


def write_video(frames: list[np.ndarray], path: Path, fps: int = 6) -> Path:
    """An MP4 of the frames (OpenCV, mp4v), written to a temporary name then moved into place."""
    import cv2

    h, w = frames[0].shape[:2]
    with atomic_file(path, suffix=path.suffix) as tmp:  # OpenCV picks the container by the suffix
        writer = cv2.VideoWriter(str(tmp), cv2.VideoWriter.fourcc(*"mp4v"), fps, (w, h))
        for f in frames:
            writer.write(cv2.cvtColor(f, cv2.COLOR_RGB2BGR))
        writer.release()
    return path


def prepared_world(scene: Scene, task_type: str, catalog: Catalog | None = None):
    """A new world of the scene set up as ALFRED sets one up for a task of the type (`episodes.alfred_set_up`)."""
    from luminous_sim.episodes import alfred_set_up
    from luminous_sim.world import World

    world = World(scene, catalog=catalog)
    alfred_set_up(world, task_type)
    return world


def run_spec(spec: EpisodeSpec, seed: int, out_dir: Path | None = None, *, record_frames: bool = True,
             extra_annotations: int = 2, places: bool = False) -> tuple[EpisodeResult, EpisodeRecord]:
    """Solve an episode's task with the oracle from the episode's initial state (`episodes.prepare`: ALFRED's
    set-up and the start), evaluate it, and write the same files as `run_episode`.

    Args:
        spec: the episode (a split entry's `episodes.entry_spec`, say); its goal is a task.
        seed: seeds the instructions' wording.
        out_dir, record_frames, extra_annotations, places: as for `run_episode`.

    Returns:
        `(result, record)`, as `run_episode`.
    """
    from luminous_sim.episodes import prepare
    from luminous_sim.planning import Oracle
    from luminous_sim.world import World

    task = spec.task
    world = prepare(World(spec.scene), spec)
    try:
        start, start_state, at = world.agent, world.view().state, _places(world, places)
        traj = Oracle(world, record_frames=record_frames).run(task.goal, names=dict(task.names) or None)
        rng = np.random.default_rng(np.random.SeedSequence([seed, 11]))
        return _conclude(world, spec.scene, task, traj, _Run(seed, rng, start, start_state, out_dir,
                                                             extra_annotations, places=at))
    finally:
        world.close()


def run_episode(scene: Scene, task_type: str, seed: int, out_dir: Path | None = None,
                record_frames: bool = True, extra_annotations: int = 2,
                cross_room: bool = False, places: bool = False) -> tuple[EpisodeResult, EpisodeRecord]:
    """Sample a `task_type` task in `scene`, solve it with the oracle, evaluate it, and write the files.

    Args:
        scene: the scene.
        task_type: an ALFRED task type.
        seed: seeds the task draw and the instructions' wording.
        out_dir: where to write trajectory.json, frames/, video.mp4, top_down.png, instructions.txt (None:
            nothing is written).
        record_frames: render a frame after each action (for the files and the record's trajectory).
        extra_annotations: instructions the record holds beyond the one written, each from its own stream.
        cross_room: (a house only) the task's object and its receptacle (or lamp) are in different rooms
            (`tasks.rooms_apart`).
        places: record each fixed receptacle's place to stand at the start (`EpisodeRecord.places`).

    Returns:
        `(result, record)`: the `EpisodeResult`, and the `EpisodeRecord` holding the task, the trajectory
        and `1 + extra_annotations` instructions.
    """
    from luminous_sim.planning import Oracle, draw_task
    from luminous_sim.tasks.errors import TaskSamplingError

    rng = np.random.default_rng(np.random.SeedSequence([seed, 11]))
    world = prepared_world(scene, task_type)
    unreachable: set[str] = set()
    full: set[str] = set()
    keep = None
    if cross_room:
        from luminous_sim.tasks import rooms_apart

        keep = rooms_apart(scene, world.view().state)
    try:
        task = draw_task(scene, world.view(), task_type, rng, keep=keep)
        start, start_state, at = world.agent, world.view().state, _places(world, places)
        traj = Oracle(world, record_frames=record_frames).run(task.goal)
        for _ in range(TASK_REDRAWS):  # ALFRED's generator also drops tasks its expert cannot do
            if traj.success or not REDRAW_ON.intersection(traj.failure_codes):
                break
            unreachable.update(traj.unreachable)
            full.update(traj.full)
            fresh = prepared_world(scene, task_type)
            try:
                redrawn = draw_task(scene, fresh.view(), task_type, rng, excluded=unreachable, full=full, keep=keep)
            except TaskSamplingError:  # nothing else to draw: the failed episode stands
                fresh.close()
                break
            world.close()
            world, task = fresh, redrawn
            start_state, at = world.view().state, _places(world, places)
            traj = Oracle(world, record_frames=record_frames).run(task.goal)
        return _conclude(world, scene, task, traj, _Run(seed, rng, start, start_state, out_dir, extra_annotations,
                                                        places=at))
    finally:
        world.close()


def run_task(scene: Scene, task: TaskInstance, seed: int, out_dir: Path | None = None, *,
             start: AgentPoseSpec | None = None, initial: Expr | None = None,
             script: Sequence[HighLevelStep | LowLevelStep] | None = None, record_frames: bool = True,
             return_record: bool = False, extra_annotations: int = 2, places: bool = False):
    """Solve a given task in `scene` (no redraws), evaluate it, and write the same files as `run_episode`.

    Args:
        scene: the scene; `task.names` maps the goal's (and the script's) object names to its ids.
        task: the task, e.g. `tasks.task_from_cdf(doc, names)` or a `TaskInstance` of ALFRED parameters.
        seed: seeds the instructions' wording.
        out_dir: where to write trajectory.json, frames/, video.mp4, top_down.png, instructions.txt.
        start: the agent's start (a CDF's `task.agent`); a position off the reachable grid is moved to
            the nearest reachable point (said in `EpisodeResult.notes`); unset parts keep the default.
        initial: ground literals that hold at the start (a CDF's `task.initial`): object states (isOpen,
            isToggled, isDirty, isFilled, isHot, isCool) are set, then every literal is checked.
        script: steps to follow instead of the oracle's plan (a CDF's `execution`); the goal is judged
            after them.
        record_frames, extra_annotations, places: as for `run_episode`.
        return_record: return the `EpisodeRecord` too.

    Returns:
        The `EpisodeResult`, or with `return_record` `(result, EpisodeRecord)`.

    Raises:
        TaskError: a literal of `initial` does not hold in the scene, or names an unknown object.
        PlanningError: the script names an object the scene lacks or cannot be followed at all.
    """
    from luminous_sim.planning import Oracle, ScriptOracle, script_from_cdf

    names = dict(task.names)
    world = prepared_world(scene_with_initial(scene, initial, names), task.task_type)
    try:
        check_initial(world.view().state, initial, names)
        notes = _place_agent(world, start)
        start_pose, start_state, at = world.agent, world.view().state, _places(world, places)
        if script is not None:
            oracle = ScriptOracle(world, record_frames=record_frames)
            traj = oracle.execute(script_from_cdf(script, names, start_state))
        else:
            traj = Oracle(world, record_frames=record_frames).run(task.goal, names=names or None)
        rng = np.random.default_rng(np.random.SeedSequence([seed, 11]))
        extra = extra_annotations if return_record else 0
        result, record = _conclude(world, scene, task, traj, _Run(seed, rng, start_pose, start_state, out_dir,
                                                                  extra, notes, at))
    finally:
        world.close()
    return (result, record) if return_record else result


@dataclass(frozen=True)
class _Run:
    """What concluding an episode needs beyond the world, the task and the trajectory."""

    seed: int
    rng: np.random.Generator
    start: AgentPose
    start_state: Any
    out_dir: Path | None
    extra_annotations: int
    notes: tuple[str, ...] = ()
    places: Mapping[str, str] | None = None


def _conclude(world, scene: Scene, task, traj: Trajectory, run: _Run) -> tuple[EpisodeResult, EpisodeRecord]:
    """Score the trajectory by the task's goal conditions, describe it, write the files."""
    from luminous_sim.cdf.predicates import to_sexpr
    from luminous_sim.language import Describer
    from luminous_sim.tasks.templates import task_description

    view = world.view()
    visible = set(view.visible_objects())
    done, total = task.conditions().alfred_counts(view.state, visible)
    traj.goal_conditions = (done, total)
    traj.success = traj.success and done == total
    text = Describer(view, run.rng).describe(traj, task_description(task, run.rng))
    texts = [text]
    for k in range(run.extra_annotations):
        more = np.random.default_rng(np.random.SeedSequence([run.seed, 12, k]))
        texts.append(Describer(view, more).describe(traj, task_description(task, more)))
    failures = tuple(Failure(c, m) for c, m in zip(traj.failure_codes, traj.failures, strict=True))
    first = failures[0].message if failures else "" if traj.success else (
        f"the goal is not met at the end: {done} of {total} goal conditions hold")
    if run.out_dir is not None:
        _write(Path(run.out_dir), scene, task, traj, text, run.start, view, first)
    result = EpisodeResult(task.task_type, to_sexpr(task.goal), traj.success, (done, total), len(traj.low_actions),
                           traj.planning_seconds, Path(run.out_dir) if run.out_dir else None, first,
                           failures[0].code if failures else None, failures, run.notes)
    return result, EpisodeRecord(task, traj, run.start_state, texts, run.places)


def _places(world, wanted: bool) -> dict[str, str] | None:
    """Each fixed receptacle's place to stand now (`world.receptacle_places`) as `loc|...` strings, when
    wanted."""
    if not wanted:
        return None
    from luminous_sim.world import receptacle_places

    return {oid: pose.location_string() for oid, pose in receptacle_places(world).items()}


def _place_agent(world, start: AgentPoseSpec | None) -> tuple[str, ...]:
    """Put the agent at `start` (`episodes.start_pose`: the reachable point nearest its position, unset parts
    from the default start); notes on what had to be moved."""
    from luminous_sim.episodes import start_pose

    pose = start_pose(world, start)
    if pose is None:
        return ()
    world.set_start(pose)
    if start is None or start.position is None or np.allclose((pose.x, pose.y), start.position):
        return ()
    want = np.array(start.position, dtype=float)
    return (f"task.agent.position ({want[0]:g}, {want[1]:g}) is not on the agent's reachable grid; "
            f"started at the nearest reachable point ({pose.x:g}, {pose.y:g})",)


def _write(out: Path, scene: Scene, task, traj: Trajectory, text, start: AgentPose, view, first: str) -> None:
    """The episode's files; trajectory.json's `failure` is the first cause, and when an attempt failed,
    `failure_code` is its code and `failures` lists every attempt's code and message in order."""
    from luminous_sim.assets.objio import png_bytes

    record: dict[str, Any] = {
        "task": task.to_dict(), "task_desc": text.task_desc, "high_descs": text.high_descs,
        "init_action": traj.init_action, "plan": {"high_pddl": traj.high_pddl, "low_actions": traj.low_actions},
        "images": traj.images, "success": traj.success, "goal_conditions": list(traj.goal_conditions),
        "replans": traj.replans, "failure": first, "scene": scene.room.name,
        "scene_key": scene.content_key(),  # the viewer plays an episode only in the scene of this key
    }
    if traj.failures:
        record["failure_code"] = str(traj.failure_codes[0])
        record["failures"] = [{"code": str(c), "message": m} for c, m in zip(traj.failure_codes, traj.failures,
                                                                             strict=True)]
    write_atomic(out / "trajectory.json", json.dumps(record, indent=1, sort_keys=True) + "\n")
    for i, frame in enumerate(traj.frames):
        write_atomic(out / "frames" / f"{i:09d}.png", png_bytes(frame))
    if traj.frames:
        write_video(traj.frames, out / "video.mp4")
    path = np.array([[p.x, p.y] for p in poses_along(traj, start)])
    write_atomic(out / "top_down.png", png_bytes(view.top_down(path=path)))
    write_atomic(out / "instructions.txt", "\n".join([text.task_desc, ""] + text.high_descs) + "\n")

