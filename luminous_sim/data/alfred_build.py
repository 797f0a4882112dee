"""Method (b) as a dataset build: each task design of a user's own ALFRED split folder
(`<task>/<trial>/traj_data.json`, e.g. ALFRED's valid_seen) solved in a scene generated in its own floor
plan's room shell (`design_scene`) and exported in ALFRED's json_2.1.0 layout.

`DesignJob` is a `build.Job`, so such a build has everything a split build has: the manifest, atomic
trials, resumption after a kill, the same files whatever the workers or backend, failures recorded with
their first cause. A trial keeps its design's own folder names (`<task>/<trial>`), so the built
`<split>/` mirrors the source split; the source's files are only read.

Typical use::

    from luminous_sim.data import build_from_alfred, make_backend
    with make_backend("local", workers=2) as backend:
        report = build_from_alfred(Path("out/valid_seen_b"), Path("alfred/valid_seen"), backend=backend)
    print(report.summary())
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from luminous_sim.data.alfred_designs import AlfredDesign, NoDesignScene, design_scene, design_task, read_designs
from luminous_sim.data.alfred_export import GENERATED, ExportError, export_alfred
from luminous_sim.data.backends import Backend
from luminous_sim.data.build import ANNOTATIONS, BuildError, BuildOptions, BuildReport, JobOutcome, build
from luminous_sim.errors import LuminousError
from luminous_sim.limits import MAX_BUILD_JOBS

DESIGN_SEED = 0
"""The seed of every design's scene and instructions by default (`benchmarks/bench_alfred_designs.py`'s)."""
LAYOUT_CAUSES = frozenset({"no_layout"})
"""`NoDesignScene` causes that say CSSG found no layout (stage `layout`); the others say the task does not
fit (stage `task`: no CDF states it for the room type, or in every layout the goal already held, an object
was unseen or the put had no room)."""
REGENERATE = ("luminous_sim.episode.run_task(Scene.from_json(json.dumps(scene)), luminous_sim.data.design_task("
              "luminous_sim.data.read_design(<the design's traj_data.json>), scene['seed']), seed, "
              "return_record=True)")


@dataclass(frozen=True)
class DesignJob:
    """Design `index` (in path order) of an ALFRED split folder, written under the build's `split` folder."""

    split: str
    index: int
    design: AlfredDesign
    seed: int = DESIGN_SEED

    @property
    def key(self) -> str:
        return f"{self.split}/{self.design.name}"

    @property
    def order(self) -> int:
        return self.index

    @property
    def task_type(self) -> str:
        return self.design.task_type

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        from luminous_sim.episode import run_task

        design = self.design
        details: dict[str, Any] = {"design": design.name, "floor_plan": design.floor_plan, "seed": self.seed}

        def failed(stage: str, cause: str) -> JobOutcome:
            return JobOutcome(stage=stage, cause=cause, details=details)

        try:
            scene = design_scene(design, self.seed)
        except NoDesignScene as exc:
            details["scene_cause"] = exc.cause
            return failed("layout" if exc.cause in LAYOUT_CAUSES else "task", str(exc) or exc.cause)
        except LuminousError as exc:  # e.g. a floor plan the room library lacks
            return failed("layout", f"{design.name}: {exc}")
        details["scene_seed"] = scene.seed
        result, record = run_task(scene, design_task(design, scene.seed), self.seed, record_frames=options.frames,
                                  return_record=True, extra_annotations=ANNOTATIONS - 1, places=options.alfworld)
        traj = record.trajectory
        details.update(goal=result.goal, low_actions=len(traj.low_actions), replans=traj.replans)
        if not result.success:
            return failed("oracle", result.failure or "the goal is not met at the end")
        human = design.language if options.human_language else None
        generated = {**GENERATED, "task_id": "the ALFRED design's own trial folder name"}
        if human is not None:
            generated = {k: v for k, v in generated.items() if not k.startswith("turk_annotations")}
            details["annotations"] = len(human.annotations)
        extra = {"regenerate": REGENERATE, "alfred_design": {"name": design.name, "task_type": design.task_type,
                                                             "floor_plan": design.floor_plan},
                 "generated": generated}
        try:
            trial = export_alfred(work, scene, record, seed=self.seed, task_id=design.path.parent.name,
                                  video=options.video and options.frames, sidecar=extra, human=human)
        except ExportError as exc:
            return failed("export", str(exc))
        return JobOutcome(trial=trial, details=details)


def design_jobs(split_dir: Path, count: int | None = None, seed: int = DESIGN_SEED) -> list[DesignJob]:
    """Jobs for the first `count` designs (all by default) of the ALFRED split folder `split_dir`, in path
    order, written under a build folder named like `split_dir`.

    Raises:
        DesignError: the folder is missing or empty, or a traj_data.json in it is malformed (named).
        BuildError: a negative count.
    """
    if count is not None and not 0 <= count <= MAX_BUILD_JOBS:
        raise BuildError(f"count must be from 0 to {MAX_BUILD_JOBS} (luminous_sim.limits.MAX_BUILD_JOBS), got {count}")
    split_dir = Path(split_dir)
    designs = read_designs(split_dir)[:count]
    split = split_dir.resolve().name
    return [DesignJob(split, i, d, seed) for i, d in enumerate(designs)]


def build_from_alfred(out: Path, split_dir: Path, count: int | None = None, backend: Backend | None = None,
                      options: BuildOptions | None = None, progress: bool = True,
                      seed: int = DESIGN_SEED) -> BuildReport:
    """Method (b): the first `count` designs (all by default) of the ALFRED split folder `split_dir`, each
    re-solved in its own floor plan's shell, into the build folder `out` (under `out/<split folder name>/`).
    With `options.human_language`, a trial keeps its design's human annotations (`alfred_language`).

    Raises:
        DesignError: see `design_jobs`.
        BuildError, ManifestError: see `build.build`; also a speaker asked for with the human language.
    """
    options = replace(options or BuildOptions(), design_seed=seed)
    if options.human_language and options.speaker is not None:
        raise BuildError("a learned speaker replaces the templates' instructions; with the designs' own human "
                         "annotations there are none to replace (use one or the other)")
    return build(out, design_jobs(split_dir, count, seed), backend, options, progress)
