"""Hand-made ALFRED trajectories in json_2.1.0's shape, for parser and merge tests that need no real data."""

from __future__ import annotations

from typing import Any

from luminous_sim.rooms import load_room


def oid(object_type: str, x: float, y: float, z: float, part: str = "") -> str:
    """An AI2-THOR objectId `Type|+x|+y|+z[|Part]`."""
    return f"{object_type}|{x:+06.2f}|{y:+06.2f}|{z:+06.2f}" + (f"|{part}" if part else "")


def coord(object_type: str, x: float, y: float, z: float) -> list[Any]:
    """ALFRED's `coordinate*ObjectId`: [Type, [x, x, z, z, y, y]] in 0.25 m grid units."""
    return [object_type, [x / 0.25, x / 0.25, z / 0.25, z / 0.25, y / 0.25, y / 0.25]]


def goto(arg: str) -> dict[str, Any]:
    return {"action": "GotoLocation", "location": "loc|0|0|0|30", "_arg": arg}


def pickup(object_id: str, source: list[Any] | None) -> dict[str, Any]:
    step: dict[str, Any] = {"action": "PickupObject", "objectId": object_id, "forceVisible": True,
                            "coordinateObjectId": [object_id.split("|")[0], [0, 0, 0, 0, 0, 0]]}
    if source is not None:
        step["coordinateReceptacleObjectId"] = source
    return step


def put(object_id: str, receptacle_id: str) -> dict[str, Any]:
    return {"action": "PutObject", "objectId": object_id, "receptacleObjectId": receptacle_id, "forceVisible": True,
            "coordinateObjectId": [object_id.split("|")[0], [0, 0, 0, 0, 0, 0]],
            "coordinateReceptacleObjectId": [receptacle_id.split("|")[0], [0, 0, 0, 0, 0, 0]]}


def inside(floor_plan: str) -> tuple[float, float]:
    """A point on the floor of the floor plan's room shell."""
    p = load_room(floor_plan).polygon().representative_point()
    return (round(p.x, 2), round(p.y, 2))


def traj(
    task_type: str, params: dict[str, Any], floor_plan: str, high: list[dict[str, Any]],
    low: list[dict[str, Any]] | None = None, *, toggles: list[dict[str, Any]] | None = None,
    dirty: bool = False, start: tuple[float, float] | None = None, task_id: str = "trial_T0",
) -> dict[str, Any]:
    """A traj_data.json dict: `high` planner actions (each gets its low-level api action unless `low` is
    given as (high_idx-tagged) api actions), ALFRED's scene dict and pddl_params."""
    x, z = start if start is not None else inside(floor_plan)
    high_pddl = []
    low_actions = []
    for i, step in enumerate(high):
        step = dict(step)
        arg = step.pop("_arg", None)
        args = [arg] if arg else [str(step.get("objectId", "")).split("|")[0].lower()]
        high_pddl.append({"discrete_action": {"action": step["action"], "args": args}, "high_idx": i,
                          "planner_action": step})
        if low is None and step["action"] in ("PickupObject", "PutObject"):
            api = {k: step[k] for k in ("objectId", "receptacleObjectId") if k in step}
            low_actions.append({"api_action": {"action": step["action"], **api}, "discrete_action":
                                {"action": step["action"], "args": {}}, "high_idx": i})
    for entry in low or []:
        low_actions.append({"api_action": {k: v for k, v in entry.items() if k != "high_idx"},
                            "discrete_action": {"action": entry["action"], "args": {}},
                            "high_idx": entry.get("high_idx", 0)})
    full = {"mrecep_target": "", "object_sliced": False, "object_target": "", "parent_target": "",
            "toggle_target": ""} | params
    return {
        "images": [],
        "pddl_params": full,
        "plan": {"high_pddl": high_pddl, "low_actions": low_actions},
        "scene": {"dirty_and_empty": dirty, "floor_plan": floor_plan,
                  "init_action": {"action": "TeleportFull", "horizon": 30, "rotateOnTeleport": True,
                                  "rotation": 90, "x": x, "y": 0.9, "z": z},
                  "object_poses": [], "object_toggles": toggles or [], "random_seed": 1,
                  "scene_num": int(floor_plan.removeprefix("FloorPlan"))},
        "task_id": task_id,
        "task_type": task_type,
        "turk_annotations": {"anns": []},
    }
