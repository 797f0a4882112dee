"""Reading a built trial back from its files alone (`traj_data.json` and the sidecar `luminous.json` a build
writes beside it), as ALFRED's evaluation restores a trial from its traj_data: the scene (the sidecar's), the
task (traj_data's `task_type` and `pddl_params`), the agent's start (`scene.init_action`), ALFRED's set-up
(`scene.dirty_and_empty`), the annotation the agent reads (`turk_annotations`) and the recorded low-level
actions (`plan.low_actions`, each with its interaction mask)."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any

from luminous_sim.cdf.predicates import to_sexpr
from luminous_sim.errors import LuminousError, json_field, read_json_file
from luminous_sim.fileio import shown
from luminous_sim.limits import MAX_INPUT_BYTES, MAX_LAYOUT_COORDINATE_M
from luminous_sim.scene import Scene
from luminous_sim.tasks import PddlParams, TaskInstance, goal_for, params_problems
from luminous_sim.vocab.agent_body import HORIZON_MAX, HORIZON_MIN
from luminous_sim.world import AgentPose
from luminous_sim.world.agent import GRID
from luminous_sim.world.masks import FRAME_SHAPE, rle_to_mask

TRAJ = "traj_data.json"
SIDECAR = "luminous.json"


class TrialError(LuminousError):
    """A trial folder that cannot be restored; the message names the file and the field."""


@dataclass(frozen=True)
class TrialEpisode:
    """What a trial's files say about its episode."""

    path: Path
    scene: Scene
    task: TaskInstance
    """The task, its instruction the annotation's goal directive."""
    start: AgentPose
    dirty_and_empty: bool
    """ALFRED's set-up for cleaning: every dirtyable object that can be picked up starts dirty."""
    steps: tuple[str, ...]
    """The annotation's step-by-step instructions (ALFRED's `high_descs`)."""
    low_actions: tuple[dict[str, Any], ...]
    """The recorded expert's actions in the agent's form: `{"action": name}`, with `"mask"` for an interaction."""
    api_actions: tuple[dict[str, Any], ...] = ()
    """The same actions as the simulator was sent them (`api_action`, object ids)."""
    recorded_key: str = ""
    """The `episode_key` the build wrote in the sidecar ("" if none); the key is recomputed, never trusted."""
    split: str = ""
    index: int = -1


def _read_json(path: Path) -> Any:
    return read_json_file(path, MAX_INPUT_BYTES, f"a trial's {path.name} (luminous_sim.limits.MAX_INPUT_BYTES)",
                          TrialError)


def _field(data: Any, where: Path, *names: str) -> Any:
    return json_field(data, where, *names, error=TrialError)


_shown = partial(shown, limit=60)

def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value)


def _whole(value: Any) -> bool:
    return _number(value) and float(value).is_integer()


def _start(init: Any, where: Path) -> AgentPose:
    """The agent's start from `scene.init_action`: x and z finite, on the 0.25 m grid and within
    `limits.MAX_LAYOUT_COORDINATE_M`, a quarter-turn rotation and a whole horizon within the camera's limits."""
    if not isinstance(init, dict):
        raise TrialError(f"{where}: field 'scene.init_action': expected an object, got {_shown(init)}")
    for name in ("x", "z"):
        v: Any = init.get(name)
        if not _number(v) or abs(v) > MAX_LAYOUT_COORDINATE_M or abs(v / GRID - round(v / GRID)) > 1e-6:
            raise TrialError(f"{where}: field 'scene.init_action.{name}': expected a finite number on the {GRID} m "
                             f"grid within {MAX_LAYOUT_COORDINATE_M} m (luminous_sim.limits.MAX_LAYOUT_COORDINATE_M),"
                             f" got {_shown(v)}")
    rotation: Any = init.get("rotation")
    horizon: Any = init.get("horizon")
    if not _whole(rotation) or int(rotation) not in (0, 90, 180, 270):
        raise TrialError(f"{where}: field 'scene.init_action.rotation': expected 0, 90, 180 or 270, got "
                         f"{_shown(rotation)}")
    if not _whole(horizon) or not HORIZON_MIN <= int(horizon) <= HORIZON_MAX:
        raise TrialError(f"{where}: field 'scene.init_action.horizon': expected a whole number of degrees from "
                         f"{HORIZON_MIN} to {HORIZON_MAX}, got {_shown(horizon)}")
    return AgentPose(float(init["x"]), float(init["z"]), int(rotation), int(horizon))


def _low_action(a: Any, where: Path, k: int) -> dict[str, Any]:
    try:
        name = a["api_action"]["action"]
        args = a["discrete_action"].get("args") or {}
    except (TypeError, KeyError, AttributeError):
        raise TrialError(f"{where}: field 'plan.low_actions[{k}]': expected api_action.action and "
                         "discrete_action") from None
    if not isinstance(name, str):
        raise TrialError(f"{where}: field 'plan.low_actions[{k}].api_action.action': expected a name")
    if not isinstance(args, dict):
        raise TrialError(f"{where}: field 'plan.low_actions[{k}].discrete_action.args': expected an object, got "
                         f"{_shown(args)}")
    out: dict[str, Any] = {"action": name}
    if args.get("mask") is not None:
        try:
            rle_to_mask(args["mask"])
        except (ValueError, TypeError, OverflowError) as exc:
            raise TrialError(f"{where}: field 'plan.low_actions[{k}].discrete_action.args.mask': expected ALFRED's "
                             f"run-length encoding of a {FRAME_SHAPE[0]}x{FRAME_SHAPE[1]} mask ({exc})") from None
        out["mask"] = args["mask"]
    return out


def _sidecar_task(doc: Any, where: Path) -> TaskInstance:
    """The sidecar's task, every field of the kind `TaskInstance.to_dict` writes (none converted silently)."""
    if not isinstance(doc, dict):
        raise TrialError(f"{where}: field 'task': expected an object, got {_shown(doc)}")
    kinds: dict[str, tuple[type, ...]] = {"task_type": (str,), "goal": (str,), "pddl_params": (dict,),
                                          "scene_seed": (int,), "instruction": (str,), "custom": (bool,),
                                          "names": (dict,)}
    for name, kind in kinds.items():
        if name not in doc:
            if name in ("instruction", "custom", "names"):
                continue
            raise TrialError(f"{where}: field 'task.{name}' is missing")
        value: Any = doc[name]
        whole = isinstance(value, int) and not isinstance(value, bool) and value >= 0
        if not (whole if kind == (int,) else isinstance(value, kind)):
            raise TrialError(f"{where}: field 'task.{name}': expected "
                             f"{'a whole number >= 0' if kind == (int,) else 'a ' + kind[0].__name__}, got "
                             f"{_shown(value)}")
    names = doc.get("names", {})
    if not all(isinstance(k, str) and isinstance(v, str) for k, v in names.items()):
        raise TrialError(f"{where}: field 'task.names': expected object names and ids (strings)")
    return TaskInstance.from_dict(doc)


def task_problems(task: TaskInstance, scene: Scene) -> list[str]:
    """Why `task` cannot be done in `scene` as its files restore it (empty when it can): parameters ALFRED could
    never draw (`tasks.params_problems`), a goal that is not the one of its type and parameters, or an object
    type, receptacle, movable receptacle or lamp that `pddl_params` names and the scene lacks."""
    if task.custom:
        return []
    try:
        out = params_problems(task.task_type, task.params)
        expected = to_sexpr(goal_for(task.params, task.task_type))
    except LuminousError as exc:
        return [str(exc)]
    if to_sexpr(task.goal) != expected:
        out.append(f"its goal {_shown(to_sexpr(task.goal))} is not the goal of {task.task_type} with these "
                   f"pddl_params ({_shown(expected)})")
    present = {o.type for o in scene.objects}
    p = task.params
    for slot, value in (("object_target", p.object_target), ("parent_target", p.parent_target),
                        ("mrecep_target", p.mrecep_target), ("toggle_target", p.toggle_target)):
        if value and value not in present and not (slot == "object_target" and p.object_type in present):
            out.append(f"pddl_params.{slot} {value!r}: the scene holds no {value}")
    return out


def trial_folders(root: Path, limit: int | None = None) -> tuple[list[Path], list[Path]]:
    """The folders under `root` (itself included) that hold an entry named traj_data.json, sorted, found without
    following any symbolic link to a folder; and those links (not walked). The one walk over a dataset folder
    (`luminous eval --data`, the thor controller's scene index).

    Raises:
        TrialError: more than `limit` such folders.
    """
    import os

    found: list[Path] = []
    linked: list[Path] = []
    for here, dirs, files in os.walk(root, followlinks=False):
        dirs.sort()
        linked += [Path(here) / d for d in dirs if os.path.islink(os.path.join(here, d))]
        if TRAJ in files or TRAJ in dirs:
            found.append(Path(here))
            if limit is not None and len(found) > limit:
                raise TrialError(f"{root}: holds more than {limit} trials")
    return sorted(found), sorted(linked)


def read_trial(path: Path, annotation: int = 0) -> TrialEpisode:
    """The episode of the trial folder `path` (annotation `annotation` of its `turk_annotations`).

    Raises:
        TrialError: a file missing, not a regular file, over `limits.MAX_INPUT_BYTES` or not JSON; a field
            missing, of the wrong kind or out of range; a sidecar task that disagrees with traj_data's; a task
            that cannot be done in the restored scene (`task_problems`); the message names the file and the
            field.
    """
    path = Path(path)
    traj_path, side_path = path / TRAJ, path / SIDECAR
    traj, side = _read_json(traj_path), _read_json(side_path)
    if not isinstance(side, dict):
        raise TrialError(f"{side_path}: expected a JSON object (the sidecar of a build), got {type(side).__name__}")
    task_type = _field(traj, traj_path, "task_type")
    params_doc = _field(traj, traj_path, "pddl_params")
    init = _field(traj, traj_path, "scene", "init_action")
    dirty = _field(traj, traj_path, "scene", "dirty_and_empty")
    floor_plan = _field(traj, traj_path, "scene", "floor_plan")
    anns = _field(traj, traj_path, "turk_annotations", "anns")
    low = _field(traj, traj_path, "plan", "low_actions")
    if not isinstance(task_type, str):
        raise TrialError(f"{traj_path}: field 'task_type': expected a task type (a string), got {_shown(task_type)}")
    if not isinstance(floor_plan, str):
        raise TrialError(f"{traj_path}: field 'scene.floor_plan': expected a floor plan's name, got "
                         f"{_shown(floor_plan)}")
    if not isinstance(params_doc, dict):
        raise TrialError(f"{traj_path}: field 'pddl_params': expected an object, got {_shown(params_doc)}")
    if not isinstance(dirty, bool):
        raise TrialError(f"{traj_path}: field 'scene.dirty_and_empty': expected true or false, got {_shown(dirty)}")
    if not isinstance(anns, list) or not 0 <= annotation < len(anns):
        raise TrialError(f"{traj_path}: field 'turk_annotations.anns': no annotation {annotation}")
    if not isinstance(low, list):
        raise TrialError(f"{traj_path}: field 'plan.low_actions': expected a list")
    start = _start(init, traj_path)
    try:
        params = PddlParams.from_json(params_doc)
        task = _sidecar_task(_field(side, side_path, "task"), side_path)
    except (TypeError, KeyError, ValueError, LuminousError) as exc:
        if isinstance(exc, TrialError):
            raise
        raise TrialError(f"{path}: cannot read the task ({type(exc).__name__}: {exc})") from None
    if task.task_type != task_type or task.params != params:
        raise TrialError(f"{side_path}: field 'task' ({task.task_type} {task.params.to_json()}) disagrees with "
                         f"{TRAJ}'s task_type and pddl_params ({task_type} {params_doc})")
    ann = anns[annotation]
    goal_text, steps = _field(ann, traj_path, "task_desc"), _field(ann, traj_path, "high_descs")
    if not isinstance(goal_text, str) or not isinstance(steps, list) or not all(isinstance(s, str) for s in steps):
        raise TrialError(f"{traj_path}: field 'turk_annotations.anns[{annotation}]': expected task_desc and "
                         "high_descs text")
    try:
        scene = Scene.from_json(json.dumps(_field(side, side_path, "scene")), where=str(side_path))
    except LuminousError as exc:
        raise TrialError(f"{side_path}: field 'scene': {exc}") from None
    problems = task_problems(task, scene)
    if problems:
        raise TrialError(f"{path}: the task ({task_type} {params_doc}) cannot be done in the trial's scene: "
                         f"{'; '.join(problems)}")
    bench = side.get("benchmark", {})
    if not isinstance(bench, dict):
        raise TrialError(f"{side_path}: field 'benchmark': expected an object, got {_shown(bench)}")
    for name, ok, want in (("episode_key", isinstance(bench.get("episode_key", ""), str), "a string"),
                           ("split", isinstance(bench.get("split", ""), str), "a string"),
                           ("index", _whole(bench.get("index", -1)) and bench.get("index", -1) >= -1,
                            "a whole number >= 0")):
        if not ok:
            raise TrialError(f"{side_path}: field 'benchmark.{name}': expected {want}, got {_shown(bench.get(name))}")
    from dataclasses import replace

    return TrialEpisode(path, scene, replace(task, instruction=goal_text), start, dirty, tuple(steps),
                        tuple(_low_action(a, traj_path, k) for k, a in enumerate(low)),
                        tuple(dict(a["api_action"]) for a in low),
                        str(bench.get("episode_key", "")), str(bench.get("split", "")), int(bench.get("index", -1)))
