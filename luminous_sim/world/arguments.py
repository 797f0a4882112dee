"""What each low-level action accepts, checked before it runs: the keys, their types and their values.

ALFRED's agent is discrete (spec section 2.1): it moves 0.25 m, turns 90 degrees and tilts its camera
15 degrees within -30..60, and it teleports only to points of the 0.25 m grid. An argument that asks
for anything else is refused with `FailureCode.INVALID_ARGUMENT`, never ignored or rounded; so is a
key the action does not take. A number is an int or a finite float (numpy's too), never a bool.

Some keys are taken because ALFRED's own records carry them, and change nothing here (the table is in
docs/failure_codes.md): `forceAction` on every action; on a teleport THOR's `y`, the height of
the agent (within 0..2 m), who always stands on the floor; on interactions the planner's bookkeeping
(`coordinateObjectId`, `coordinateReceptacleObjectId` as `[type, [6 grid coordinates]]`, `cleanObjectId`,
`forceVisible`), which the Heat and Clean expansions leave on their ToggleObjectOn/Off.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.fileio import shown
from luminous_sim.vocab import INTERACTION_ACTIONS, TELEPORT_ACTIONS
from luminous_sim.world.agent import GRID, HORIZON_MAX, HORIZON_MIN, HORIZON_STEP, ROTATE_STEP, AgentPose
from luminous_sim.world.navigation import NavGrid

GRID_TOLERANCE = 1e-6
"""Metres a teleport target may be off a grid point (floating-point noise; 3.6 is not 3.5)."""
MAX_COORDINATE = 1e4
"""Metres: a teleport coordinate beyond this is no place in any room (and would overflow on the grid)."""

AGENT_Y_MAX = 2.0
"""Metres: THOR's agent height `y` is taken up to this (ALFRED's records hold 0.87..1.12)."""

_COMMON = frozenset({"action", "forceAction"})
_TELEPORT = _COMMON | {"x", "y", "z", "rotation", "horizon", "rotateOnTeleport"}
_INTERACTION = _COMMON | {"objectId", "mask", "point", "forceVisible", "coordinateObjectId",
                          "coordinateReceptacleObjectId", "cleanObjectId"}

ACCEPTED: dict[str, frozenset[str]] = {
    "MoveAhead": _COMMON | {"moveMagnitude"},
    "RotateLeft": _COMMON | {"degrees"},
    "RotateRight": _COMMON | {"degrees"},
    "LookUp": _COMMON | {"degrees"},
    "LookDown": _COMMON | {"degrees"},
    "Teleport": _TELEPORT,
    "TeleportFull": _TELEPORT,
    "Pass": _COMMON,
    "NoOp": _COMMON,
    **{name: _INTERACTION for name in INTERACTION_ACTIONS},
    "PutObject": _INTERACTION | {"receptacleObjectId", "placeStationary"},
    "OpenObject": _INTERACTION | {"moveMagnitude"},
}
"""Action -> the keys it takes."""

STEP_SIZES: dict[str, tuple[str, float, str]] = {
    "MoveAhead": ("moveMagnitude", GRID, f"MoveAhead moves {GRID} m"),
    "RotateLeft": ("degrees", ROTATE_STEP, f"RotateLeft turns {ROTATE_STEP} degrees"),
    "RotateRight": ("degrees", ROTATE_STEP, f"RotateRight turns {ROTATE_STEP} degrees"),
    "LookUp": ("degrees", HORIZON_STEP, f"LookUp tilts the camera {HORIZON_STEP} degrees"),
    "LookDown": ("degrees", HORIZON_STEP, f"LookDown tilts the camera {HORIZON_STEP} degrees"),
    "OpenObject": ("moveMagnitude", 1.0, "OpenObject opens all the way"),
}
"""Action -> its step-size argument, the one value it may take (ALFRED's), and what the action does."""


def number(value: Any) -> int | float | None:
    """The value as a number if it is one (an int of any size, or a finite float), else None."""
    if isinstance(value, bool | np.bool_):
        return None
    if isinstance(value, int | np.integer):
        return int(value)
    if isinstance(value, float | np.floating) and math.isfinite(value):
        return float(value)
    return None




def _invalid(message: str) -> Failure:
    return Failure(FailureCode.INVALID_ARGUMENT, message)


def argument_failure(act: dict[str, Any], frame_shape: tuple[int, int]) -> Failure | None:
    """Why the action's arguments are not acceptable, or None; `act["action"]` is a known action."""
    name = act["action"]
    accepted = ACCEPTED[name]
    unknown = [k for k in act if k not in accepted]
    if unknown:
        return _invalid(f"{name} takes no {', '.join(map(shown, unknown))} (it takes {', '.join(sorted(accepted))})")
    for key in ("forceAction", "forceVisible", "placeStationary", "rotateOnTeleport"):
        if key in act and not isinstance(act[key], bool):
            return _invalid(f"{name}: {key} must be true or false, not {shown(act[key])}")
    if act.get("placeStationary") is False:
        return _invalid("PutObject: placeStationary=false (dropping with physics) is not modelled; puts are stationary")
    if name in STEP_SIZES:
        why = _step_size_failure(name, act)
        if why:
            return why
    if name in INTERACTION_ACTIONS:
        return _target_failure(name, act, frame_shape)
    if name in TELEPORT_ACTIONS:
        return _teleport_failure(name, act)
    return None


def _step_size_failure(name: str, act: dict[str, Any]) -> Failure | None:
    key, only, does = STEP_SIZES[name]
    value = number(act[key]) if key in act else only
    if value is None or abs(value) > 2 * only or abs(value - only) > GRID_TOLERANCE:  # a huge int: no float
        return _invalid(f"{does}: {key} must be {only:g}, not {shown(act[key])}")
    return None


def _target_failure(name: str, act: dict[str, Any], frame_shape: tuple[int, int]) -> Failure | None:
    for key in ("objectId", "receptacleObjectId", "cleanObjectId"):
        if act.get(key) is not None and (not isinstance(act[key], str) or not act[key]):
            return _invalid(f"{name}: {key} must be an object id (a non-empty string), not {shown(act[key])}")
    for key in ("coordinateObjectId", "coordinateReceptacleObjectId"):
        if act.get(key) is not None and not _is_coordinate_id(act[key]):
            return _invalid(f"{name}: {key} must be ALFRED's [type, [6 grid coordinates]], not {shown(act[key])}")
    target_keys = ["receptacleObjectId", "mask", "point"] if name == "PutObject" else ["objectId", "mask", "point"]
    given = [k for k in target_keys if act.get(k) is not None]
    if len(given) > 1:
        return _invalid(f"{name}: give one of {', '.join(target_keys)} to name the target, not {' and '.join(given)}")
    if act.get("mask") is not None:
        return _mask_failure(name, act["mask"], frame_shape)
    if act.get("point") is not None:
        point = act["point"]
        coords = point.tolist() if isinstance(point, np.ndarray) and point.ndim == 1 else point
        if not isinstance(coords, Sequence) or isinstance(coords, str) or len(coords) != 2 \
                or not all(isinstance(number(v), int) for v in coords):
            return _invalid(f"{name}: point must be two integer pixel coordinates [x, y], not {shown(point)}")
    return None


def _is_coordinate_id(value: Any) -> bool:
    """ALFRED's `[TypeName, [x, x, z, z, y, y]]` (grid units) naming an object by type and place."""
    if not isinstance(value, list | tuple) or len(value) != 2 or not isinstance(value[0], str):
        return False
    coords = value[1]
    return isinstance(coords, list | tuple) and len(coords) == 6 and all(number(v) is not None for v in coords)


def _mask_failure(name: str, mask: Any, frame_shape: tuple[int, int]) -> Failure | None:
    """A mask is a bool or integer array of the frame's shape, or ALFRED's run-length pairs within the frame."""
    if isinstance(mask, np.ndarray):
        if mask.shape != tuple(frame_shape) or mask.dtype.kind not in "biu":
            return _invalid(f"{name}: a mask array must be bool or integer of shape {tuple(frame_shape)}, "
                            f"not {mask.dtype} {mask.shape}")
        return None
    pixels = frame_shape[0] * frame_shape[1]
    if not isinstance(mask, Sequence) or isinstance(mask, str):
        return _invalid(f"{name}: mask must be a list of [start, length] runs, not {type(mask).__name__}")
    for run in mask:
        if isinstance(run, np.ndarray):
            run = run.tolist() if run.ndim == 1 else None
        values = [number(v) for v in run] if isinstance(run, Sequence) and not isinstance(run, str) else []
        start, length = values if len(values) == 2 else (None, None)
        if not isinstance(start, int) or not isinstance(length, int):
            return _invalid(f"{name}: mask runs must be pairs of integers [start, length], not {shown(run)}")
        if start < 0 or length < 0 or start + length > pixels:
            return _invalid(f"{name}: mask run {shown(run)} is not within the {frame_shape[0]}x{frame_shape[1]} frame")
    return None


def _teleport_failure(name: str, act: dict[str, Any]) -> Failure | None:
    if "x" not in act or "z" not in act:
        return _invalid(f"{name} needs x and z (THOR's axes: y is up)")
    given: dict[str, int | float] = {}
    for key in ("x", "y", "z", "rotation", "horizon"):
        if key in act:
            value = number(act[key])
            if value is None:
                return _invalid(f"{name}: {key} must be a finite number, not {shown(act[key])}")
            given[key] = value
    for key in ("x", "z"):
        if abs(given[key]) > MAX_COORDINATE:
            return _invalid(f"{name}: {key}={shown(act[key])} m is no place in a room")
    if not 0 <= given.get("y", 0) <= AGENT_Y_MAX:
        return _invalid(f"{name}: y, the agent's height, must be within 0..{AGENT_Y_MAX} m, not {shown(act['y'])}")
    if "rotation" in given:
        if act.get("rotateOnTeleport") is False:
            return _invalid(f"{name}: a rotation with rotateOnTeleport=false (leave rotation out to keep the heading)")
        if given["rotation"] % ROTATE_STEP:
            return _invalid(f"{name}: rotation must be a multiple of {ROTATE_STEP} degrees, "
                            f"not {shown(act['rotation'])}")
    horizon = given.get("horizon", HORIZON_MIN)
    if horizon % HORIZON_STEP or not HORIZON_MIN <= horizon <= HORIZON_MAX:
        return _invalid(f"{name}: horizon must be a multiple of {HORIZON_STEP} degrees within "
                        f"{HORIZON_MIN}..{HORIZON_MAX}, not {shown(act['horizon'])}")
    return None


def teleport_pose(act: dict[str, Any], current: AgentPose, nav: NavGrid) -> AgentPose | Failure:
    """The pose a checked teleport asks for (`argument_failure` found nothing wrong), or why it is not a
    grid point, naming the nearest ones."""
    x, z = float(act["x"]), float(act["z"])
    gx, gz = round(x / GRID), round(z / GRID)
    if abs(x - gx * GRID) > GRID_TOLERANCE or abs(z - gz * GRID) > GRID_TOLERANCE:
        message = (f"{act['action']} target ({x:g}, {z:g}) is off the {GRID} m grid: the nearest grid point is "
                   f"({gx * GRID:g}, {gz * GRID:g})")
        points = nav.points()
        if (gx, gz) not in nav and len(points):
            rx, rz = points[int(np.argmin(np.hypot(points[:, 0] - x, points[:, 1] - z)))]
            message += f", the nearest reachable one ({rx:g}, {rz:g})"
        return _invalid(message)
    rotation = int(act.get("rotation", current.rotation)) % 360
    horizon = int(act.get("horizon", current.horizon))
    return AgentPose(round(x, 4), round(z, 4), rotation, horizon)
