"""A generated room in which a task of a given type (or one given task) is feasible, symbolically and
physically: a default room of the room type when one supports the task, else a room generated for a task
drawn from what such a room holds, or for the given task (the paper's "given the tasks, resolve and
generate appropriate scenes"); in a room structure of the type, or in one named room.

"Physically" is the test `run_episode` draws its task with (`planning.draw_task` in the world the
episode builds): the task's put has a free, stable spot within reach and view, and its objects are seen
from some reachable pose. A room that passes it is one in which `run_episode` finds a task.
"""

from __future__ import annotations

import numpy as np

from luminous_sim.assets.catalog import Catalog
from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.rooms import RoomShell, shell_for
from luminous_sim.scene import Scene
from luminous_sim.tasks import (
    PddlParams,
    TaskError,
    TaskSamplingError,
    cdf_for_task,
    draw_params,
    feasible_params,
    state_from_scene,
)

DEFAULT_ROOM_TRIES = 3
"""Default rooms tried before one is generated for the task."""
TASK_DRAWS = 6
"""Rooms generated for drawn tasks (each a fresh draw and a fresh layout seed) before giving up."""
TEMPLATE_TYPE: dict[str, str] = {"pick_two_obj_and_place": "pick_and_place_simple"}
"""Task types whose parameters can be drawn from another type's when no default room has two of a kind."""
FIT_SEED = 0
"""Seed of the task drawn by the physical check (which task is drawn does not matter, only whether one is)."""
CAUSES_SHOWN = 3
"""Causes named in the error when no room fits."""


def physical_misfit(scene: Scene, task_type: str, catalog: Catalog | None = None) -> str | None:
    """Why no `task_type` task fits `scene` physically, or None when one does.

    Builds the world once, set up as `run_episode` sets it up, and draws a task through its read-only
    view with `planning.draw_task`, the episode's own test.
    """
    from luminous_sim.episode import prepared_world
    from luminous_sim.planning import draw_task

    world = prepared_world(scene, task_type, catalog)
    try:
        draw_task(scene, world.view(), task_type, np.random.default_rng(FIT_SEED))
    except TaskSamplingError as exc:
        return str(exc)
    finally:
        world.close()
    return None


def task_misfit(scene: Scene, task_type: str, params: PddlParams, catalog: Catalog | None = None) -> str | None:
    """Why the task `task_type` with `params` is not feasible in `scene` or does not fit physically, or None.

    The same tests as `physical_misfit`, for this task rather than any of its type: ALFRED's constraints
    allow it and its goal is unmet, its objects are seen from some reachable pose, and its put has a free,
    stable spot (`planning.physically_feasible`) in the world `run_task` builds.
    """
    from luminous_sim.episode import prepared_world
    from luminous_sim.planning import physically_feasible, unseeable

    name = _task_name(task_type, params)
    try:
        if params not in feasible_params(scene, state_from_scene(scene), task_type):
            return f"{name} is not feasible here (an object it needs is missing, or its goal already holds)"
    except TaskSamplingError as exc:
        return str(exc)
    world = prepared_world(scene, task_type, catalog)
    try:
        view = world.view()
        hidden = unseeable(view)
        try:
            seen = feasible_params(scene, view.state.without(hidden), task_type)
        except TaskSamplingError as exc:
            return f"{name}: {exc}"
        if params not in seen:
            return f"{name}: an object it needs is seen from no reachable pose ({', '.join(sorted(hidden))})"
        if not physically_feasible(view, params, hidden, two=task_type == "pick_two_obj_and_place"):
            return f"{name}: no free, stable spot for its put"
    finally:
        world.close()
    return None


def _misfit(scene: Scene, task_type: str, catalog: Catalog | None) -> str | None:
    """Why no `task_type` task is feasible in `scene`, symbolically first (cheap), then physically."""
    try:
        feasible_params(scene, state_from_scene(scene), task_type)
    except TaskSamplingError as exc:
        return str(exc)
    return physical_misfit(scene, task_type, catalog)


def _layout_seed(seq: np.random.SeedSequence) -> int:
    return int(seq.generate_state(1, dtype=np.uint32)[0])


def scene_for_task(task_type: str, room_type: str, seed: int, catalog: Catalog | None = None, *,
                   room: str | RoomShell | None = None, params: PddlParams | None = None) -> Scene:
    """A room of `room_type` in which some `task_type` task (or the task of `params`) is feasible and fits
    physically, so that `run_episode(scene, task_type, ...)` finds a task (same seed, same room).

    Tries `DEFAULT_ROOM_TRIES` default rooms, then up to `TASK_DRAWS` rooms generated for a task drawn
    from what the first default room that has such tasks holds (for the given task, when `params` is
    given), each draw and layout seed derived from `seed`. A CDF cannot ask CSSG to keep area free on a
    receptacle, so a room generated for a task is tested like a default one, and one that leaves no room
    for the put (two pillows on an ottoman) gives way to the next draw.

    Args:
        room: a room-library name (loaded with `rooms.shell_for`) or a room shell: every room tried has
            this structure; by default each draws its own structure of `room_type`.
        params: the task to support (checked by `task_misfit`); by default any task of the type.

    Raises:
        TaskSamplingError: no room tried supports such a task; the message names the task type, the
            room type, the seed and the first causes.
        TaskError: `room` is not of `room_type`, or `params` are not a task ALFRED would draw for the type.
    """
    shell = _shell(room, room_type, seed)
    if params is None:
        def misfit(scene: Scene) -> str | None:
            return _misfit(scene, task_type, catalog)
    else:
        def misfit(scene: Scene) -> str | None:
            return task_misfit(scene, task_type, params, catalog)
    causes: list[str] = []
    template = TEMPLATE_TYPE.get(task_type, task_type)
    cands: list[PddlParams] = [] if params is None else [params]
    if params is not None:
        cdf_for_task(task_type, params, room_type)  # refuses parameters ALFRED would not draw, up front
    for attempt in range(DEFAULT_ROOM_TRIES):
        scene = generate(empty_cdf(room_type), seed=seed + 100_003 * attempt, room=shell, catalog=catalog).scene
        why = misfit(scene)
        if why is None:
            return scene
        causes.append(f"default room {attempt}: {why}")
        if not cands:  # tasks to generate a room for: what the first room that has some holds
            try:
                cands = feasible_params(scene, state_from_scene(scene), template)
            except TaskSamplingError as exc:
                if template != task_type:
                    causes.append(f"default room {attempt}: {exc}")
    if not cands:
        raise _no_scene(task_type, room_type, seed, causes, params, shell)
    draws_seq, *layout_seqs = np.random.SeedSequence([seed, 23]).spawn(1 + TASK_DRAWS)
    rng = np.random.default_rng(draws_seq)
    for layout_seq in layout_seqs:
        drawn = draw_params(cands, rng)
        try:
            cdf = cdf_for_task(task_type, drawn, room_type)
            scene = generate(cdf, seed=_layout_seed(layout_seq), room=shell, catalog=catalog).scene
        except (InfeasibleSceneError, TaskError) as exc:  # two boxes on a dresser; two towels on one hook
            causes.append(f"room for {_task_name(task_type, drawn)}: {exc}")
            continue
        why = misfit(scene)
        if why is None:
            return scene
        causes.append(f"room for {_task_name(task_type, drawn)}: {why}")
    raise _no_scene(task_type, room_type, seed, causes, params, shell)


def _shell(room: str | RoomShell | None, room_type: str, seed: int) -> RoomShell | None:
    """The named room (its type checked), or None: each room draws its own structure."""
    if room is None:
        return None
    shell = shell_for(room, np.random.default_rng(seed)) if isinstance(room, str) else room
    if shell.room_type != room_type:
        raise TaskError(f"room {shell.name} is a {shell.room_type}, not a {room_type}")
    return shell


def _task_name(task_type: str, params: PddlParams) -> str:
    """A short name of a drawn task for messages: type-object-mrecep-receptacle."""
    return "-".join([task_type, params.object_type, params.mrecep_target or "None",
                     params.parent_target or params.toggle_target])


def _no_scene(task_type: str, room_type: str, seed: int, causes: list[str], params: PddlParams | None = None,
              shell: RoomShell | None = None) -> TaskSamplingError:
    shown = "; ".join(causes[:CAUSES_SHOWN]) + (f"; and {len(causes) - CAUSES_SHOWN} more"
                                                if len(causes) > CAUSES_SHOWN else "")
    task = f"a {task_type} task" if params is None else f"the task {_task_name(task_type, params)}"
    where = room_type if shell is None else f"{room_type} in room {shell.name}"
    return TaskSamplingError(f"no {where} (seed {seed}) supports {task} that fits "
                             f"physically, in {len(causes)} rooms tried: {shown}")
