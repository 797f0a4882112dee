"""A generated room in which a task of a given type is feasible: a default room of the room type when
one supports the task, else a room generated for a task drawn from what such a room holds (the
paper's "given the tasks, resolve and generate appropriate scenes")."""

from __future__ import annotations

import numpy as np

from luminous_sim.assets.catalog import Catalog
from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.scene import Scene
from luminous_sim.tasks import (
    TaskError,
    TaskSamplingError,
    cdf_for_task,
    draw_params,
    feasible_params,
    state_from_scene,
)

DEFAULT_ROOM_TRIES = 3
"""Default rooms tried before one is generated for the task."""
TASK_DRAWS = 4
"""Tasks drawn for a room generated for the task before giving up."""
TEMPLATE_TYPE: dict[str, str] = {"pick_two_obj_and_place": "pick_and_place_simple"}
"""Task types whose parameters can be drawn from another type's when no default room has two of a kind."""


def scene_for_task(task_type: str, room_type: str, seed: int, catalog: Catalog | None = None) -> Scene:
    """A room of `room_type` with at least one feasible `task_type` task (same seed, same room).

    Raises:
        TaskSamplingError: neither a default room nor one generated for the task supports it.
        InfeasibleSceneError: CSSG could not lay out the room generated for the task.
    """
    why = ""
    for attempt in range(DEFAULT_ROOM_TRIES):
        scene = generate(empty_cdf(room_type), seed=seed + 100_003 * attempt, catalog=catalog).scene
        try:
            feasible_params(scene, state_from_scene(scene), task_type)
            return scene
        except TaskSamplingError as exc:
            why = str(exc)
    rng = np.random.default_rng(np.random.SeedSequence([seed, 23]))
    template = TEMPLATE_TYPE.get(task_type, task_type)
    try:
        cands = feasible_params(scene, state_from_scene(scene), template)
    except TaskSamplingError as exc:
        raise TaskSamplingError(f"no {room_type} supports a {task_type} task: {why}; {exc}") from exc
    for _ in range(TASK_DRAWS):
        params = draw_params(cands, rng)
        try:
            scene = generate(cdf_for_task(task_type, params, room_type), seed=seed, catalog=catalog).scene
            feasible_params(scene, state_from_scene(scene), task_type)
            return scene
        except (InfeasibleSceneError, TaskError) as exc:  # two boxes on a dresser; two towels on one hook
            why = str(exc)
    raise TaskSamplingError(f"no {room_type} could be generated for a {task_type} task: {why}")
