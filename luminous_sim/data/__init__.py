"""Layer L5: data production on top of the generator and the task layer; for now task-driven generation
(a room generated so that a task of a given type is feasible in it).

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
"""

from luminous_sim.data.task_scenes import scene_for_task

__all__ = ["scene_for_task"]
