"""Layer L5: data production on top of the generator and the task layer: task-driven generation (a room
generated so that a task of a given type is feasible in it and fits physically), export of a solved episode
in ALFRED's json_2.1.0 layout, the ALFRED task parser (traj_data.json -> CDF) with the per-floor-plan
merge and its coverage report, and dataset builds (S+/U+ splits, method (a); a user's ALFRED split
re-solved design by design, method (b)) that resume after a kill and run on local worker processes or a
Ray cluster through a small reusable backend interface,
and oracle demonstrations of a registered env as a Minari dataset (offline RL; needs the `minari` extra,
imported only when `export_minari` runs), and perception datasets: frames with exact depth and labels
(`build_perception`; docs/perception.md).

Typical use::

    from luminous_sim.data import scene_for_task
    scene = scene_for_task("pick_heat_then_place_in_recep", "Kitchen", seed=0)
    result, record = run_episode(scene, "pick_heat_then_place_in_recep", seed=0)
    trial_dir = export_alfred(out_root, scene, record, seed=0)

    parse = parse_alfred("valid_seen/<task>/<trial>/traj_data.json")   # parse.cdf, .kept, .dropped
    merged = merge_by_floor_plan(parses)["FloorPlan12"]                 # merged.cdf, .conflicts

    from luminous_sim.data import build_split, make_backend
    with make_backend("local", workers=2) as backend:
        report = build_split(Path("out/splus"), "S+", 100, backend)
        report_b = build_from_alfred(Path("out/valid_seen"), Path("alfred/valid_seen"), backend=backend)
    print(report.summary())
"""

from luminous_sim.data.alfred_build import DESIGN_SEED, DesignJob, build_from_alfred, design_jobs
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
from luminous_sim.data.alfred_language import HumanLanguage
from luminous_sim.data.alfred_merge import MergeConflict, MergedCDF, merge_by_floor_plan, merge_parses
from luminous_sim.data.alfred_parser import AlfredParse, AlfredParseError, ParseNote, parse_alfred
from luminous_sim.data.alfred_report import CoverageReport, Realisation, parse_directory, realise, write_report
from luminous_sim.data.alfred_structure import Structure, structure, structure_differences
from luminous_sim.data.backends import Backend, BackendError, LocalBackend, RayBackend, make_backend, map_jobs
from luminous_sim.data.build import (
    RETRIED_STAGES,
    BuildError,
    BuildOptions,
    BuildReport,
    Job,
    JobOutcome,
    SplitJob,
    build,
    build_split,
    built_count,
    retried,
    split_jobs,
)
from luminous_sim.data.house_build import HOUSE_SPLIT, HouseJob, build_houses, house_jobs
from luminous_sim.data.manifest import Manifest, ManifestError
from luminous_sim.data.minari_export import (
    MinariExport,
    MinariExportError,
    default_minari_id,
    export_minari,
    minari_dataset_path,
)
from luminous_sim.data.perception_frames import (
    PerceptionDataError,
    PerceptionJob,
    PerceptionReport,
    build_perception,
    built_trials,
    evaluation_jobs,
    iter_shards,
    leaks,
    perception_jobs,
    read_header,
    read_manifest,
)
from luminous_sim.data.task_scenes import physical_misfit, scene_for_task, task_misfit

__all__ = [
    "DESIGN_SEED",
    "HOUSE_SPLIT",
    "RETRIED_STAGES",
    "AlfredDesign",
    "AlfredParse",
    "AlfredParseError",
    "Backend",
    "BackendError",
    "BuildError",
    "BuildOptions",
    "BuildReport",
    "CoverageReport",
    "DesignError",
    "DesignJob",
    "DesignResult",
    "ExportError",
    "HouseJob",
    "HumanLanguage",
    "Job",
    "JobOutcome",
    "LocalBackend",
    "Manifest",
    "ManifestError",
    "MergeConflict",
    "MergedCDF",
    "MinariExport",
    "MinariExportError",
    "NoDesignScene",
    "ParseNote",
    "PerceptionDataError",
    "PerceptionJob",
    "PerceptionReport",
    "RayBackend",
    "Realisation",
    "SplitJob",
    "Structure",
    "alfred_traj_data",
    "build",
    "build_from_alfred",
    "build_houses",
    "build_perception",
    "build_split",
    "built_count",
    "built_trials",
    "clear_for_put",
    "default_minari_id",
    "design_jobs",
    "design_scene",
    "design_task",
    "evaluation_jobs",
    "export_alfred",
    "export_minari",
    "fold_subgoals",
    "house_jobs",
    "iter_shards",
    "leaks",
    "make_backend",
    "map_jobs",
    "merge_by_floor_plan",
    "merge_parses",
    "minari_dataset_path",
    "parse_alfred",
    "parse_directory",
    "perception_jobs",
    "physical_misfit",
    "read_design",
    "read_designs",
    "read_header",
    "read_manifest",
    "realise",
    "retried",
    "scene_for_task",
    "scene_misfit",
    "solve_design",
    "split_jobs",
    "structure",
    "structure_differences",
    "task_misfit",
    "write_report",
]
