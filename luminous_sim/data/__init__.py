"""Layer L5: data production on top of the generator and the task layer; for now task-driven generation
(a room generated so that a task of a given type is feasible in it and fits physically).

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
"""

from luminous_sim.data.task_scenes import physical_misfit, scene_for_task

__all__ = ["physical_misfit", "scene_for_task"]
