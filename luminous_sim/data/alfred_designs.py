"""Method (b) of the paper: ALFRED's own task designs re-solved in generated scenes.

A design is what a real `traj_data.json` asks for: the task type, its `pddl_params` and the floor plan.
`design_scene` generates a scene for it in that floor plan's own room shell (`cdf_for_task` + CSSG) in
which the task is feasible, symbolically and physically, and its goal does not already hold;
`solve_design` runs the oracle on exactly that task and evaluates ALFRED's goal conditions.
"""

from __future__ import annotations

from collections.abc import Collection, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.catalog import Catalog
from luminous_sim.cdf import ChallengeDefinition
from luminous_sim.data.alfred_language import HumanLanguage
from luminous_sim.data.alfred_parser import AlfredParseError, read_traj
from luminous_sim.errors import InfeasibleSceneError, LuminousError
from luminous_sim.scene import Scene
from luminous_sim.tasks import (
    PddlParams,
    TaskError,
    TaskInstance,
    TaskSamplingError,
    cdf_for_task,
    feasible_params,
    goal_for,
)

SCENE_TRIES = 6
"""Layouts generated for one design (each from a seed derived from the caller's) before giving up."""


class DesignError(LuminousError):
    """A traj_data.json that is not a usable task design (the message names the file and the field)."""


class NoDesignScene(TaskSamplingError):
    """No layout tried for a design passed; `cause` names the check the last one failed."""

    def __init__(self, message: str, cause: str):
        super().__init__(message)
        self.cause = cause


@dataclass(frozen=True)
class AlfredDesign:
    """One ALFRED task design: what a trajectory's traj_data.json asks for, without how it was done."""

    task_type: str
    params: PddlParams
    floor_plan: str
    scene_num: int
    path: Path
    language: HumanLanguage | None = field(default=None, compare=False)
    """Its people's annotations and ALFRED's subgoals they describe; None where it has none (a test split)."""

    @property
    def name(self) -> str:
        """`<task dir>/<trial>`, as ALFRED's split files name a trajectory."""
        return f"{self.path.parent.parent.name}/{self.path.parent.name}"

    @property
    def room_type(self) -> str:
        """Kitchen, LivingRoom, Bedroom or Bathroom, from the scene number."""
        from luminous_sim.rooms import scene_room_type

        return scene_room_type(self.scene_num)


def read_design(path: str | Path) -> AlfredDesign:
    """The design of one ALFRED traj_data.json.

    Raises:
        DesignError: unreadable JSON or a missing or malformed field (named with the file).
    """
    path = Path(path)
    try:
        data = read_traj(path)  # the reader `luminous alfred parse` uses: the same refusals
    except AlfredParseError as exc:
        raise DesignError(str(exc)) from None
    except OSError as exc:
        raise DesignError(f"{path}: not a readable traj_data.json ({exc})") from exc
    try:
        scene = data["scene"]
        params = PddlParams.from_json(data["pddl_params"])
        floor_plan, scene_num, task_type = scene["floor_plan"], scene["scene_num"], data["task_type"]
    except KeyError as exc:
        raise DesignError(f"{path}: missing field {exc.args[0]!r}") from exc
    except TaskError as exc:
        raise DesignError(f"{path}: {exc}") from exc
    if not isinstance(scene_num, int) or floor_plan != f"FloorPlan{scene_num}":
        raise DesignError(f"{path}: scene.floor_plan {floor_plan!r} does not match scene.scene_num {scene_num!r}")
    from luminous_sim.vocab import ALFRED_TASK_TYPES

    if task_type not in ALFRED_TASK_TYPES:
        raise DesignError(f"{path}: task_type {task_type!r} is not one of ALFRED's: {', '.join(ALFRED_TASK_TYPES)}")
    return AlfredDesign(str(task_type), params, floor_plan, scene_num, path, _language(data, path))


def _language(data: Any, path: Path) -> HumanLanguage | None:
    """The design's human annotations, or None where it has no `turk_annotations` (or none in it).

    Raises:
        DesignError: an annotation without text `task_desc` and `high_descs` (named).
    """
    turk = data.get("turk_annotations")
    if turk is None:
        return None
    anns = turk.get("anns") if isinstance(turk, dict) else None
    if not isinstance(anns, list):
        raise DesignError(f"{path}: field 'turk_annotations.anns': expected a list of annotations")
    for k, ann in enumerate(anns):
        steps = ann.get("high_descs") if isinstance(ann, dict) else None
        if not (isinstance(ann, dict) and isinstance(ann.get("task_desc"), str) and isinstance(steps, list)
                and all(isinstance(s, str) for s in steps)):
            raise DesignError(f"{path}: field 'turk_annotations.anns[{k}]': expected task_desc and high_descs text")
    plan = []
    for k, h in enumerate(data["plan"]["high_pddl"]):
        action = h.get("discrete_action") if isinstance(h, dict) else None
        name = action.get("action") if isinstance(action, dict) else None
        if not isinstance(name, str):
            raise DesignError(f"{path}: field 'plan.high_pddl[{k}].discrete_action.action': expected a subgoal name")
        if name != "NoOp":
            plan.append(name)
    return HumanLanguage(tuple(anns), tuple(plan)) if anns else None


def read_designs(split_dir: str | Path) -> list[AlfredDesign]:
    """Every design of an ALFRED split folder (`<task dir>/<trial>/traj_data.json`), in path order.

    Raises:
        DesignError: the folder is missing or holds no traj_data.json, or one is malformed.
    """
    split_dir = Path(split_dir)
    if not split_dir.exists():
        raise DesignError(f"{split_dir}: no such ALFRED split folder")
    if not split_dir.is_dir():
        raise DesignError(f"{split_dir}: not a folder (an ALFRED split is a folder of <task>/<trial>/traj_data.json)")
    paths = sorted(split_dir.glob("*/*/traj_data.json"))
    if not paths:
        raise DesignError(f"{split_dir}: no <task>/<trial>/traj_data.json files")
    return [read_design(p) for p in paths]


def design_task(design: AlfredDesign, scene_seed: int = 0) -> TaskInstance:
    """The task the design states, with ALFRED's goal for its parameters."""
    return TaskInstance(design.task_type, design.params, goal_for(design.params, design.task_type), scene_seed)


def _layout_seeds(seed: int, tries: int) -> Iterator[int]:
    for seq in np.random.SeedSequence([seed, 41]).spawn(tries):
        yield int(seq.generate_state(1, dtype=np.uint32)[0])


def scene_misfit(scene: Scene, design: AlfredDesign, catalog: Catalog | None = None) -> tuple[str, str] | None:
    """(cause, message) when the design's task is not a fair task in `scene`, else None.

    Causes: `goal_at_start` (the goal already holds), `infeasible` (an object or receptacle missing or
    seen from no reachable pose), `no_room` (no free, stable spot for the put within reach), `no_pose`
    (too few of a type the task needs are in the agent's picture from any pose the oracle would walk to:
    a potato a sight line grazes past the coffee machine in front of it). The world is built as an
    episode builds it (for cleaning, everything dirtyable is dirty).
    """
    from luminous_sim.episode import prepared_world
    from luminous_sim.planning import physically_feasible, unseeable

    world = prepared_world(scene, design.task_type, catalog)
    try:
        view = world.view()
        state = view.state
        task = design_task(design)
        if task.conditions().success(state):
            return "goal_at_start", f"{design.name}: the goal already holds at the start"
        hidden = unseeable(view)
        try:
            cands = feasible_params(scene, state.without(hidden), design.task_type, judged_alike=False)
        except TaskSamplingError as exc:
            return "infeasible", str(exc)
        if design.params not in cands:
            unseen = sorted(state.objects[o].object_type for o in hidden)
            return "infeasible", (f"{design.name}: not feasible with what is seen from reachable poses "
                                  f"(unseeable: {', '.join(unseen) or 'none'})")
        two = design.task_type == "pick_two_obj_and_place"
        if not physically_feasible(view, design.params, hidden, two=two):
            return "no_room", f"{design.name}: no free, stable spot for the put within reach"
        unposed = _unposed(view, design, hidden)
        if unposed:
            return "no_pose", f"{design.name}: no pose from which enough of {unposed} are seen within reach"
        return None
    finally:
        world.close()


def _unposed(view, design: AlfredDesign, hidden: Collection[str]) -> str | None:
    """The first object type the task needs of which fewer than it needs have an interaction pose (the
    oracle's own test: seen in the rendered picture from a pose on the grid; for a thing in a closed
    container, the container), or None."""
    from luminous_sim.states import enclosing_closed
    from luminous_sim.tasks import required_objects

    state = view.state
    for object_type, count in required_objects(design.task_type, design.params):
        ids = [i for i in state.of_type(object_type) if i not in hidden]
        posed = 0
        for i in ids:
            if view.interaction_pose(enclosing_closed(state, i) or i) is not None:
                posed += 1
                if posed >= count:
                    break
        if posed < count:
            return object_type
    return None


def clear_for_put(scene: Scene, params: PddlParams, declared: Collection[str]) -> Scene | None:
    """The scene without the small things the room added by default (not the CDF's `declared` objects)
    resting in or on the task's receptacles, and what they hold: a scene generated for a task leaves room
    for its put. None when there is nothing to clear."""
    from luminous_sim.vocab import abilities

    def default(o) -> bool:  # a counted object is named name#2, name#3 ...
        return not o.name or o.name.split("#")[0] not in declared

    kinds = {params.parent_target, params.mrecep_target} - {""}
    hosts = {o.id for o in scene.objects if o.type in kinds}
    drop = {o.id for o in scene.objects
            if o.parent in hosts and default(o) and o.layer == "object" and abilities(o.type).pickupable}
    if not drop:
        return None
    grown = True
    while grown:  # and whatever those hold
        more = {o.id for o in scene.objects if o.parent in drop and default(o)} - drop
        grown = bool(more)
        drop |= more
    kept = tuple(o for o in scene.objects if o.id not in drop)
    notes = {**scene.notes, "cleared_for_task": sorted(drop)}
    return scene.model_copy(update={"objects": kept, "notes": notes})


def design_scene(design: AlfredDesign, seed: int, catalog: Catalog | None = None,
                 tries: int = SCENE_TRIES) -> Scene:
    """A scene generated for the design in its own floor plan's room shell, in which its task is feasible
    (objects seen from reachable poses, room for the put) and its goal is unmet. Layout seeds are derived
    from `seed`; at most `tries` layouts are generated.

    Raises:
        NoDesignScene: no layout passed; the message names the design, the seed and each try's cause.
    """
    from luminous_sim.cssg import generate
    from luminous_sim.rooms import load_room

    try:
        cdf = cdf_for_task(design.task_type, design.params, design.room_type)
    except TaskError as exc:
        raise NoDesignScene(f"{design.name}: {exc}", "no_cdf") from exc
    room = load_room(design.floor_plan)
    causes: list[tuple[str, str]] = []
    avoid: set[str] = set()
    for layout_seed in _layout_seeds(seed, tries):
        try:
            scene = generate(cdf, seed=layout_seed, room=room, catalog=catalog).scene
        except InfeasibleSceneError as exc:
            causes.append(("no_layout", str(exc)))
            cdf, avoid = _without_surfaces(cdf, design, avoid, exc.unplaced)
            continue
        why = scene_misfit(scene, design, catalog)
        if why is not None and why[0] == "no_room":
            cleared = clear_for_put(scene, design.params, {o.name for o in cdf.scene.objects})
            if cleared is not None:
                scene, why = cleared, scene_misfit(cleared, design, catalog)
        if why is None:
            return scene
        causes.append(why)
    shown = "; ".join(f"[{c}] {m}" for c, m in causes[:3])
    raise NoDesignScene(f"{design.name} (seed {seed}): no scene in {len(causes)} layouts: {shown}", causes[-1][0])


def _without_surfaces(cdf: ChallengeDefinition, design: AlfredDesign, avoid: set[str],
                      unplaced: Collection[str]) -> tuple[ChallengeDefinition, set[str]]:
    """The design's CDF with its things starting elsewhere than on the surfaces that could not be placed
    (a dining table in a small U-shaped kitchen) or that what stands on them could not be placed on (a
    microwave on counters full of burners and sink), and the surface types now avoided; the same CDF when
    there is no such surface."""
    names = {n.split("#")[0] for n in unplaced}
    types = {o.name: o.type for o in cdf.scene.objects}
    surfaces = {types[r.target] for r in cdf.scene.relations
                if r.relation == "on" and r.target in types and (r.target in names or r.subject in names)}
    surfaces -= {design.params.parent_target, design.params.mrecep_target, design.params.toggle_target}
    if not surfaces - avoid:
        return cdf, avoid
    try:
        return cdf_for_task(design.task_type, design.params, design.room_type, avoid | surfaces), avoid | surfaces
    except TaskError:
        return cdf, avoid


@dataclass(frozen=True)
class DesignResult:
    """What solving one design gave. `cause` is the first failure's code (the oracle's `FailureCode`
    value) or, where no scene passed, `no_scene:<cause of the last layout>`; "" on success."""

    design: str
    task_type: str
    success: bool
    goal_conditions: tuple[int, int]
    cause: str = ""
    message: str = ""
    low_actions: int = 0
    failures: tuple[str, ...] = field(default_factory=tuple)

    def to_json(self) -> dict[str, Any]:
        return {"design": self.design, "task_type": self.task_type, "success": self.success,
                "goal_conditions": list(self.goal_conditions), "cause": self.cause, "message": self.message,
                "low_actions": self.low_actions, "failures": list(self.failures)}


def solve_design(design: AlfredDesign, seed: int, catalog: Catalog | None = None,
                 tries: int = SCENE_TRIES) -> DesignResult:
    """Generate the design's scene (`design_scene`) and solve exactly its task with the oracle.

    Success needs the oracle to finish and every one of ALFRED's goal conditions to hold at the end. A
    design with no scene is a failed result (never an exception), so that rates count every design.
    """
    from luminous_sim.episode import prepared_world
    from luminous_sim.planning import Oracle

    task = design_task(design)
    total = task.conditions().alfred_counts(_empty_state())[1]
    try:
        scene = design_scene(design, seed, catalog, tries)
    except NoDesignScene as exc:
        return DesignResult(design.name, design.task_type, False, (0, total), f"no_scene:{exc.cause}", str(exc))
    task = design_task(design, scene.seed)
    world = prepared_world(scene, design.task_type, catalog)
    try:
        traj = Oracle(world, record_frames=False).run(task.goal)
        view = world.view()
        done, total = task.conditions().alfred_counts(view.state, set(view.visible_objects()))
    finally:
        world.close()
    success = traj.success and done == total
    cause, message = "", ""
    if traj.failure_codes:
        cause, message = traj.failure_codes[0].value, traj.failures[0]
    elif not success:
        cause, message = "goal_unmet", f"{design.name}: the oracle finished but {done}/{total} conditions hold"
    if success:
        cause, message = "", ""
    return DesignResult(design.name, design.task_type, success, (done, total), cause, message,
                        len(traj.low_actions), tuple(traj.failures))


def _empty_state():
    from luminous_sim.states import WorldState

    return WorldState.of([])
