"""Export one solved episode in ALFRED's json_2.1.0 layout (spec section 4):
`<task_type>-<object>-<mrecep>-<parent>-<scene_num>/<task_id>/` with `traj_data.json`, `raw_images/`
(one JPEG per recorded frame), `pddl_states/problem_0.pddl` (the starting state and the goal, for our
planner's domain `planning.symbolic.domain_text()`), ALFWorld's problem `initial_state.pddl` when the record has
its receptacles' places (`text.alfworld_problem`), optionally `video.mp4`, and a sidecar `luminous.json`
with what ALFRED has no field for (task and goal, seed, the scene itself, evaluation, replans, package
version), enough to regenerate the trajectory with `run_episode(Scene.from_json(sidecar["scene"]), task_type, seed)`.

`images[].image_name` in `traj_data.json` names a `.png` (`000000000.png`, ...) while `raw_images/` holds
`.jpg` files of the same stem (`000000000.jpg`), exactly as ALFRED's own json_2.1.0 data does; readers swap the
extension, as ALFRED's loaders do.

Where ALFRED records something we cannot know, the value is ALFRED-typed and generated, and the sidecar
says so (`generated`): the task id's timestamp, MTurk assignment ids and votes, object names' hex
suffixes, and the scene number of a room that is no AI2-THOR floor plan.
"""

from __future__ import annotations

import hashlib
import io
import json
import math
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from luminous_sim.data.alfred_language import HumanLanguage, language_note, trial_annotations
from luminous_sim.episode import EpisodeRecord, write_video
from luminous_sim.errors import LuminousError
from luminous_sim.fileio import write_atomic
from luminous_sim.planning import Trajectory
from luminous_sim.scene import Scene
from luminous_sim.scene.ids import type_of_id
from luminous_sim.vocab import abilities

SIDECAR = "luminous.json"
SIDECAR_FORMAT = "luminous-alfred-sidecar/1"
ALFWORLD_PROBLEM = "initial_state.pddl"
"""ALFWorld's PDDL problem of the trial (`text.alfworld_problem`), beside traj_data.json."""
GRID = 0.25
ALFRED_SUBGOALS = ("GotoLocation", "PickupObject", "PutObject", "CleanObject", "HeatObject", "CoolObject",
                   "ToggleObject", "SliceObject")
"""ALFRED's high-level vocabulary besides End; our OpenObject/CloseObject subgoals are folded into these."""
ANNOTATION_VOTES = [1, 1, 1]
"""Generated quality votes for each template annotation (ALFRED: votes of other MTurk workers)."""
JPEG_QUALITY = 90
GENERATED = {
    "task_id": "trial_T + a timestamp derived from the seed, not the generation time (reproducible)",
    "turk_annotations.anns[].assignment_id": "LUMINOUS_<k>_<task_id>: template instructions, no MTurk worker",
    "turk_annotations.anns[].votes": f"{ANNOTATION_VOTES}: no votes were cast",
    "scene.object_poses[].objectName": "type + '_' + 8 hex digits of sha1(our object id)",
    "scene.scene_num": "N of FloorPlanN for an AI2-THOR floor plan, else the scene's seed",
    "images": "one frame at the start and one after each low-level action (ALFRED saves several per action)",
}


class ExportError(LuminousError):
    """The episode cannot be written in ALFRED's format (it failed, or has no subgoal)."""


def _scene_number(scene: Scene) -> tuple[str, int]:
    """(`floor_plan`, `scene_num`): an AI2-THOR floor plan's own, else the room's name and the scene seed."""
    for text in (scene.room.name, scene.room.source):
        m = re.search(r"FloorPlan_?(\d+)", text or "")
        if m:
            return f"FloorPlan{int(m.group(1))}", int(m.group(1))
    return scene.room.name, int(scene.seed)


def folder_name(pddl_params: dict[str, Any], scene_num: int) -> str:
    """ALFRED's trajectory folder: `<task_type>-<object>[Sliced]-<mrecep|None>-<parent|toggle>-<scene_num>`
    without the task type (the caller prefixes it)."""
    obj = pddl_params["object_target"] + ("Sliced" if pddl_params["object_sliced"] else "")
    parent = pddl_params["parent_target"] or pddl_params["toggle_target"]
    return f"{obj}-{pddl_params['mrecep_target'] or 'None'}-{parent}-{scene_num}"


class _Coordinates:
    """ALFRED's `coordinateObjectId` values, from where objects were at the start (as ALFRED's planner,
    which plans once from the initial problem, writes them)."""

    def __init__(self, scene: Scene):
        self.objects = {o.id: o for o in scene.objects}

    def source(self, oid: str):
        """The scene object `oid` is, or was cut from (a slice `Apple|...|AppleSliced_1`), or None."""
        return self.objects.get(oid) or self.objects.get("|".join(oid.split("|")[:4]))

    def of(self, oid: str) -> list[Any]:
        o = self.objects.get(oid)
        if o is not None:  # ours: x, depth, height; THOR: x, height, depth
            x, h, d = o.position[0], o.position[2], o.position[1]
        else:  # a slice made during the episode: its id holds THOR's x|height|depth
            x, h, d = (float(v) for v in oid.split("|")[1:4])
        g = [round(x / GRID, 8), round(d / GRID, 8), round(h / GRID, 8)]
        return [type_of_id(oid), [float(g[0]), float(g[0]), float(g[1]), float(g[1]), float(g[2]), float(g[2])]]

    def parent(self, oid: str) -> str | None:
        o = self.source(oid)
        return o.parent if o is not None else None


def _planner_action(pa: dict[str, Any], coords: _Coordinates) -> dict[str, Any]:
    """Our planner_action ({action, objectId, receptacleObjectId}) with ALFRED's keys for that action."""
    act = pa["action"]
    if act in ("GotoLocation", "End"):
        return dict(pa)
    if act not in ("PickupObject", "ToggleObject", "SliceObject", "PutObject", "HeatObject", "CoolObject",
                   "CleanObject"):
        raise ExportError(f"no ALFRED planner_action for {act!r}")
    o: str = pa["objectId"]
    if act == "PickupObject":
        out = {"action": act, "coordinateObjectId": coords.of(o), "forceVisible": True, "objectId": o}
        parent = coords.parent(o)
        if parent is not None:
            out["coordinateReceptacleObjectId"] = coords.of(parent)
        return out
    if act == "ToggleObject":
        return {"action": act, "coordinateObjectId": coords.of(o), "coordinateReceptacleObjectId": coords.of(o),
                "forceVisible": True, "objectId": o}
    if act == "SliceObject":
        return {"action": act, "coordinateObjectId": coords.of(o), "forceVisible": True, "objectId": o}
    r: str = pa["receptacleObjectId"]  # Put's receptacle, Heat/Cool/Clean's device
    if act == "PutObject":
        return {"action": act, "coordinateObjectId": coords.of(o), "coordinateReceptacleObjectId": coords.of(r),
                "forceVisible": True, "objectId": o, "receptacleObjectId": r}
    if act in ("HeatObject", "CoolObject"):
        return {"action": act, "coordinateReceptacleObjectId": coords.of(r), "forceVisible": True, "objectId": r}
    return {"action": act, "cleanObjectId": o, "coordinateObjectId": coords.of(o),
            "coordinateReceptacleObjectId": coords.of(r), "forceVisible": True, "objectId": r}


def fold_subgoals(actions: list[str]) -> list[int]:
    """For each of our non-End subgoals, the index of the ALFRED subgoal it becomes part of.

    ALFRED has no Open/Close subgoals: an open joins the next interaction (else the one before), a close
    the interaction before (else the next), as its expansions open and close inside Pickup/Put/Slice;
    between two walks, it joins the walk that brought the agent there.
    Joining an immediate neighbour keeps the low actions' `high_idx` non-decreasing.
    """
    kept = [i for i, a in enumerate(actions) if a in ALFRED_SUBGOALS]
    if not kept:
        raise ExportError(f"no ALFRED subgoal among {actions}")
    rank = {i: k for k, i in enumerate(kept)}
    out = []
    for i, a in enumerate(actions):
        if i in rank:
            out.append(rank[i])
            continue
        prev = next((j for j in reversed(kept) if j < i), None)
        nxt = next((j for j in kept if j > i), None)
        order = [nxt, prev] if a == "OpenObject" else [prev, nxt]
        interaction = [j for j in order if j is not None and actions[j] != "GotoLocation"]
        walks = [j for j in (prev, nxt) if j is not None]  # not empty: `kept` is not
        out.append(rank[(interaction or walks)[0]])
    return out


def merge_walks(actions: list[str]) -> list[int]:
    """For each ALFRED subgoal, the index of the subgoal it becomes once each run of consecutive
    GotoLocations is one walk (to where the last of them leads). ALFRED's plans never hold two walks in a
    row (none of valid_seen's 251 does), and its dense reward reads a Heat/Cool's object two subgoals
    ahead, where it expects the PutObject after the one walk."""
    out: list[int] = []
    for k, a in enumerate(actions):
        joins = k > 0 and a == "GotoLocation" and actions[k - 1] == "GotoLocation"
        out.append(out[-1] if joins else (out[-1] + 1 if out else 0))
    return out


def _goto_args(high: list[dict[str, Any]], k: int, fallback: list[str]) -> list[str]:
    """ALFRED names a GotoLocation by the next subgoal's receptacle coordinate, else its object's."""
    if k + 1 >= len(high):
        return fallback
    pa = high[k + 1]["planner_action"]
    named = pa.get("coordinateReceptacleObjectId") or pa.get("coordinateObjectId")
    return [named[0].lower()] if named else fallback


def _object_poses(scene: Scene) -> list[dict[str, Any]]:
    """Every pickupable object where it starts, in THOR's axes and rotation convention."""
    out = []
    for o in scene.objects:
        try:
            if not abilities(o.type).pickupable:
                continue
        except LuminousError:  # a type outside ALFRED's vocabulary is not pickupable there
            continue
        digest = hashlib.sha1(o.id.encode()).hexdigest()[:8]
        yaw = round((-math.degrees(o.yaw)) % 360.0, 4) + 0.0  # ours: CCW about z from +y; THOR: CW from +z
        out.append({"objectName": f"{o.type}_{digest}",
                    "position": {"x": float(o.position[0]), "y": float(o.position[2]), "z": float(o.position[1])},
                    "rotation": {"x": 0.0, "y": float(yaw), "z": 0.0}})
    return out


def _task_id(seed: int) -> str:
    """`trial_T` + a `YYYYMMDD_HHMMSS_ffffff`-shaped stamp derived from the seed (reproducible)."""
    return f"trial_T20000101_{(seed // 1_000_000) % 1_000_000:06d}_{seed % 1_000_000:06d}"


def first_cause(traj: Trajectory) -> str:
    """Why a trajectory failed: its first failed attempt's message (later ones often only echo it after a
    replan), or that the goal was left unmet when no attempt failed."""
    if traj.failures:
        return traj.failures[0]
    done, total = traj.goal_conditions
    return f"the goal is not met at the end: {done} of {total} goal conditions hold"


def alfred_traj_data(scene: Scene, record: EpisodeRecord, seed: int, task_id: str | None = None,
                     human: HumanLanguage | None = None) -> tuple[dict[str, Any], list[int]]:
    """The traj_data.json content of a solved episode, and the map from our high_idx to ALFRED's. `human`: the
    design's own annotations, in place of the templates' (`alfred_language.trial_annotations`)."""
    traj, task = record.trajectory, record.task
    if not traj.success:
        raise ExportError(f"only solved episodes are exported (this one failed: {first_cause(traj)})")
    coords = _Coordinates(scene)
    ours = [h for h in traj.high_pddl if h["planner_action"]["action"] != "End"]
    fold = fold_subgoals([h["planner_action"]["action"] for h in ours])
    kept = [i for i, h in enumerate(ours) if h["planner_action"]["action"] in ALFRED_SUBGOALS]
    merge = merge_walks([ours[i]["planner_action"]["action"] for i in kept])
    fold = [merge[k] for k in fold]
    kept = [i for k, i in enumerate(kept) if k + 1 == len(kept) or merge[k + 1] != merge[k]]
    high = [{"discrete_action": ours[i]["discrete_action"], "high_idx": k,
             "planner_action": _planner_action(ours[i]["planner_action"], coords)} for k, i in enumerate(kept)]
    for k, h in enumerate(high):
        if h["planner_action"]["action"] == "GotoLocation":
            h["discrete_action"] = {"action": "GotoLocation",
                                    "args": _goto_args(high, k, h["discrete_action"]["args"])}
    high.append({"discrete_action": {"action": "NoOp", "args": []}, "high_idx": len(high),
                 "planner_action": {"action": "End", "value": 1}})
    new_idx = {h["high_idx"]: fold[i] for i, h in enumerate(ours)}
    low = []
    for a in traj.low_actions:
        k = new_idx[a["high_idx"]]
        api = dict(a["api_action"])
        pa = high[k]["planner_action"]
        if api["action"] in ("ToggleObjectOn", "ToggleObjectOff") and pa["action"] in (
                "HeatObject", "CoolObject", "CleanObject"):  # ALFRED passes the subgoal's keys along
            api.update({key: v for key, v in pa.items() if key not in ("action", "objectId")})
        low.append({"api_action": api, "discrete_action": a["discrete_action"], "high_idx": k})
    images = [{"high_idx": low[im["low_idx"]]["high_idx"] if low else 0, "image_name": im["image_name"],
               "low_idx": im["low_idx"]} for im in traj.images]
    tid = task_id or _task_id(seed)
    anns = []
    for n, text in enumerate(record.instructions):
        if len(text.high_descs) != len(ours):
            raise ExportError(f"annotation {n} has {len(text.high_descs)} steps for {len(ours)} subgoals")
        anns.append({"assignment_id": f"LUMINOUS_{n}_{tid}", "high_descs": [text.high_descs[i] for i in kept],
                     "task_desc": text.task_desc, "votes": list(ANNOTATION_VOTES)})
    if human is not None:
        anns = trial_annotations(human, [h["discrete_action"]["action"] for h in high[:-1]], anns)
    params = task.params.to_json()
    floor_plan, scene_num = _scene_number(scene)
    init = traj.init_action
    data = {
        "images": images,
        "pddl_params": params,
        "plan": {"high_pddl": high, "low_actions": low},
        "scene": {
            "dirty_and_empty": task.task_type == "pick_clean_then_place_in_recep",
            "floor_plan": floor_plan,
            "init_action": {"action": "TeleportFull", "horizon": int(init["horizon"]), "rotateOnTeleport": True,
                            "rotation": int(init["rotation"]), "x": float(init["x"]), "y": float(init["y"]),
                            "z": float(init["z"])},
            "object_poses": _object_poses(scene),
            "object_toggles": [{"isOn": False, "objectType": params["toggle_target"]}]
            if params["toggle_target"] else [],
            "random_seed": int(seed),
            "scene_num": scene_num,
        },
        "task_id": tid,
        "task_type": task.task_type,
        "turk_annotations": {"anns": anns},
    }
    return data, [new_idx[h["high_idx"]] for h in ours]


def _write_alfworld(trial: Path, data: Mapping[str, Any], record: EpisodeRecord) -> dict[str, Any]:
    """Write ALFWorld's problem (`ALFWORLD_PROBLEM`) beside traj_data.json; what the sidecar says of it: the
    PDDL identifier of each of our object ids, or why there is no problem."""
    from luminous_sim.text import ProblemError, alfworld_problem
    from luminous_sim.world import AgentPose

    init = data["scene"]["init_action"]
    start = AgentPose(init["x"], init["z"], init["rotation"], init["horizon"]).location_string()
    assert record.places is not None
    try:
        problem = alfworld_problem(record.start_state, record.places, start, data["task_type"], data["pddl_params"],
                                   name=f"plan_{data['task_id'].lower()}")
    except ProblemError as exc:
        return {"problem": None, "cause": str(exc)}
    write_atomic(trial / ALFWORLD_PROBLEM, problem.text)
    return {"problem": ALFWORLD_PROBLEM, "domain": "alfred (alfworld.info.ALFRED_PDDL_PATH)", "ids": dict(problem.ids)}


def _jpeg(frame) -> bytes:
    from PIL import Image

    buf = io.BytesIO()
    Image.fromarray(frame).save(buf, format="JPEG", quality=JPEG_QUALITY)
    return buf.getvalue()


def export_alfred(out_root: Path, scene: Scene, record: EpisodeRecord, seed: int, task_id: str | None = None,
                  video: bool = False, sidecar: Mapping[str, Any] | None = None,
                  human: HumanLanguage | None = None) -> Path:
    """Write a solved episode (`run_episode(scene, task_type, seed)`) under `out_root`
    in ALFRED's layout and return its trial folder. `sidecar` adds keys to (or replaces keys of) the
    sidecar file, e.g. how to regenerate an episode that `run_episode` did not make; `human`: the design's
    annotations in place of the templates' (the sidecar's `language` says where each one's steps come from).

    Raises:
        ExportError: the episode failed, or its plan has no ALFRED subgoal.
    """
    from luminous_sim import __version__

    data, high_map = alfred_traj_data(scene, record, seed, task_id, human)
    _, scene_num = _scene_number(scene)
    trial = Path(out_root) / f"{data['task_type']}-{folder_name(data['pddl_params'], scene_num)}" / data["task_id"]
    traj = record.trajectory
    write_atomic(trial / "traj_data.json", json.dumps(data, sort_keys=True, indent=4))
    for im, frame in zip(traj.images, traj.frames, strict=True):
        write_atomic(trial / "raw_images" / im["image_name"].replace(".png", ".jpg"), _jpeg(frame))
    from luminous_sim.planning.symbolic import to_pddl_problem

    problem = to_pddl_problem(record.start_state, record.task.goal, name=data["task_id"].lower())
    write_atomic(trial / "pddl_states" / "problem_0.pddl", problem)
    alfworld = _write_alfworld(trial, data, record) if record.places is not None else None
    if video and traj.frames:
        write_video(traj.frames, trial / "video.mp4")
    sidecar = {
        "format": SIDECAR_FORMAT, "alfred_format": "json_2.1.0", "luminous_version": __version__,
        "seed": int(seed), "task": record.task.to_dict(), "success": traj.success,
        "goal_conditions": list(traj.goal_conditions), "replans": traj.replans, "failures": list(traj.failures),
        "high_idx_map": high_map, "luminous_high_pddl": traj.high_pddl, "generated": GENERATED,
        "regenerate": "luminous_sim.episode.run_episode(Scene.from_json(json.dumps(scene)), "
                      "task['task_type'], seed)",
        "scene": json.loads(scene.to_json()),
        **({"language": language_note(human, data["turk_annotations"]["anns"])} if human is not None else {}),
        **({"alfworld": alfworld} if alfworld is not None else {}),
        **(sidecar or {}),
    }
    write_atomic(trial / SIDECAR, json.dumps(sidecar, sort_keys=True, indent=1) + "\n")
    return trial
