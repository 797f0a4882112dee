"""Layer L5: data production on top of the generator and the task layer; for now task-driven generation
(a room generated so that a task of a given type is feasible in it and fits physically) and export of a
solved episode in ALFRED's json_2.1.0 layout; oracle demonstrations of a registered env as a Minari dataset
(offline RL; needs the `minari` extra, imported only when `export_minari` runs).

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
    result, record = run_episode(scene, "pick_heat_then_place_in_recep", seed=0, return_record=True)
    trial_dir = export_alfred(out_root, scene, record, seed=0)
"""

from luminous_sim.data.alfred_export import ExportError, alfred_traj_data, export_alfred, fold_subgoals
from luminous_sim.data.alfred_structure import Structure, structure, structure_differences
from luminous_sim.data.minari_export import (
    MinariExport,
    MinariExportError,
    default_minari_id,
    export_minari,
    minari_dataset_path,
)
from luminous_sim.data.task_scenes import physical_misfit, scene_for_task, task_misfit

__all__ = [
    "ExportError",
    "MinariExport",
    "MinariExportError",
    "Structure",
    "alfred_traj_data",
    "default_minari_id",
    "export_alfred",
    "export_minari",
    "fold_subgoals",
    "minari_dataset_path",
    "physical_misfit",
    "scene_for_task",
    "structure",
    "structure_differences",
    "task_misfit",
]
