"""Layer L5: data production on top of the generator and the task layer; for now task-driven generation
(a room generated so that a task of a given type is feasible in it and fits physically) and export of a
solved episode in ALFRED's json_2.1.0 layout.

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
    result, record = run_episode(scene, "pick_heat_then_place_in_recep", seed=0, return_record=True)
    trial_dir = export_alfred(out_root, scene, record, seed=0)
"""

from luminous_sim.data.alfred_designs import (
    AlfredDesign,
    DesignError,
    DesignResult,
    NoDesignScene,
    clear_for_put,
    design_scene,
    design_task,
    read_design,
    read_designs,
    scene_misfit,
    solve_design,
)
from luminous_sim.data.alfred_export import ExportError, alfred_traj_data, export_alfred, fold_subgoals
from luminous_sim.data.alfred_structure import Structure, structure, structure_differences
from luminous_sim.data.task_scenes import physical_misfit, scene_for_task

__all__ = [
    "AlfredDesign",
    "DesignError",
    "DesignResult",
    "ExportError",
    "NoDesignScene",
    "Structure",
    "alfred_traj_data",
    "clear_for_put",
    "design_scene",
    "design_task",
    "export_alfred",
    "fold_subgoals",
    "physical_misfit",
    "read_design",
    "read_designs",
    "scene_for_task",
    "scene_misfit",
    "solve_design",
    "structure",
    "structure_differences",
]
