"""Layer L5: data production on top of the generator and the task layer: task-driven generation (a room
generated so that a task of a given type is feasible in it and fits physically), export of a solved episode
in ALFRED's json_2.1.0 layout, and the ALFRED task parser (traj_data.json -> CDF) with the per-floor-plan
merge and its coverage report.

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
    result, record = run_episode(scene, "pick_heat_then_place_in_recep", seed=0, return_record=True)
    trial_dir = export_alfred(out_root, scene, record, seed=0)

    parse = parse_alfred("valid_seen/<task>/<trial>/traj_data.json")   # parse.cdf, .kept, .dropped
    merged = merge_by_floor_plan(parses)["FloorPlan12"]                 # merged.cdf, .conflicts
"""

from luminous_sim.data.alfred_export import ExportError, alfred_traj_data, export_alfred, fold_subgoals
from luminous_sim.data.alfred_merge import MergeConflict, MergedCDF, merge_by_floor_plan, merge_parses
from luminous_sim.data.alfred_parser import AlfredParse, AlfredParseError, ParseNote, parse_alfred
from luminous_sim.data.alfred_report import CoverageReport, Realisation, parse_directory, realise, write_report
from luminous_sim.data.alfred_structure import Structure, structure, structure_differences
from luminous_sim.data.task_scenes import physical_misfit, scene_for_task, task_misfit

__all__ = [
    "AlfredParse",
    "AlfredParseError",
    "CoverageReport",
    "ExportError",
    "MergeConflict",
    "MergedCDF",
    "ParseNote",
    "Realisation",
    "Structure",
    "alfred_traj_data",
    "export_alfred",
    "fold_subgoals",
    "merge_by_floor_plan",
    "merge_parses",
    "parse_alfred",
    "parse_directory",
    "physical_misfit",
    "realise",
    "scene_for_task",
    "structure",
    "structure_differences",
    "task_misfit",
    "write_report",
]
