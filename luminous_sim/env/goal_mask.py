"""The `goal_mask` observation: where the goal's object type shows in the frame.

A semantic sensor reduced to the goal's category (ObjectNav's ground-truth semantics setting): 255 on every
pixel of an object of the goal's type, 0 elsewhere. It is privileged (it names what a detector would have to
find), so a policy that reads it is compared with the baselines that read the segmentation too
(`bench_nav_baselines.py`'s `walk-seg` policies), and a figure of such a policy says so.
"""

from __future__ import annotations

import numpy as np

from luminous_sim.episodes import Goal
from luminous_sim.world import World


def goal_type(goal: Goal) -> str:
    """The type the goal is about: its `object_type` (navigation and pick-up goals), else its task's
    (`pddl_params.object_target`, `AppleSliced` for a sliced one); "" when it names none."""
    object_type = getattr(goal, "object_type", None)
    if isinstance(object_type, str):
        return object_type
    task = getattr(goal, "task", None)
    return task.params.object_type if task is not None else ""


def goal_mask(world: World, object_type: str) -> np.ndarray:
    """(H, W, 1) uint8 mask of the current frame: 255 where an object of `object_type` shows."""
    state = world.view().state
    bodies = [loaded.body for oid, loaded in world.built.objects.items()
              if oid in state.objects and state.objects[oid].object_type == object_type]
    mask = np.isin(world.instance_ids(), bodies)  # all False where the type has no object
    return (mask.astype(np.uint8) * 255)[..., None]
