"""Reading a built trial back from its files alone (`traj_data.json` and the sidecar `luminous.json` a build
writes beside it), as ALFRED's evaluation restores a trial from its traj_data: the scene (the sidecar's), the
task (traj_data's `task_type` and `pddl_params`), the agent's start (`scene.init_action`), ALFRED's set-up
(`scene.dirty_and_empty`), the annotation the agent reads (`turk_annotations`) and the recorded low-level
actions (`plan.low_actions`, each with its interaction mask)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError, read_json_file
from luminous_sim.limits import MAX_INPUT_BYTES
from luminous_sim.scene import Scene
from luminous_sim.tasks import PddlParams, TaskInstance
from luminous_sim.world import AgentPose

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
    value = data
    for k, name in enumerate(names):
        if not isinstance(value, dict) or name not in value:
            raise TrialError(f"{where}: field {'.'.join(names[:k + 1])!r} is missing")
        value = value[name]
    return value


def _low_action(a: Any, where: Path, k: int) -> dict[str, Any]:
    try:
        name = a["api_action"]["action"]
        args = a["discrete_action"].get("args") or {}
    except (TypeError, KeyError, AttributeError):
        raise TrialError(f"{where}: field 'plan.low_actions[{k}]': expected api_action.action and "
                         "discrete_action") from None
    if not isinstance(name, str):
        raise TrialError(f"{where}: field 'plan.low_actions[{k}].api_action.action': expected a name")
    out: dict[str, Any] = {"action": name}
    if isinstance(args, dict) and args.get("mask") is not None:
        out["mask"] = args["mask"]
    return out


def read_trial(path: Path, annotation: int = 0) -> TrialEpisode:
    """The episode of the trial folder `path` (annotation `annotation` of its `turk_annotations`).

    Raises:
        TrialError: a file missing or not JSON, a field missing or of the wrong kind, a sidecar task that
            disagrees with traj_data's; the message names the file and the field.
    """
    path = Path(path)
    traj_path, side_path = path / TRAJ, path / SIDECAR
    traj, side = _read_json(traj_path), _read_json(side_path)
    task_type = _field(traj, traj_path, "task_type")
    params_doc = _field(traj, traj_path, "pddl_params")
    init = _field(traj, traj_path, "scene", "init_action")
    anns = _field(traj, traj_path, "turk_annotations", "anns")
    low = _field(traj, traj_path, "plan", "low_actions")
    if not isinstance(anns, list) or not 0 <= annotation < len(anns):
        raise TrialError(f"{traj_path}: field 'turk_annotations.anns': no annotation {annotation}")
    if not isinstance(low, list):
        raise TrialError(f"{traj_path}: field 'plan.low_actions': expected a list")
    try:
        params = PddlParams.from_json(params_doc)
        start = AgentPose(float(init["x"]), float(init["z"]), int(init["rotation"]) % 360, int(init["horizon"]))
        task_doc = _field(side, side_path, "task")
        task = TaskInstance.from_dict(task_doc)
    except (TypeError, KeyError, ValueError, LuminousError) as exc:
        raise TrialError(f"{path}: cannot read the task or the start ({type(exc).__name__}: {exc})") from None
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
    bench = side.get("benchmark") if isinstance(side.get("benchmark"), dict) else {}
    from dataclasses import replace

    return TrialEpisode(path, scene, replace(task, instruction=goal_text), start,
                        bool(_field(traj, traj_path, "scene", "dirty_and_empty")), tuple(steps),
                        tuple(_low_action(a, traj_path, k) for k, a in enumerate(low)),
                        tuple(dict(a["api_action"]) for a in low),
                        str(bench.get("episode_key", "")), str(bench.get("split", "")), int(bench.get("index", -1)))
