"""ai2thor 2.1.0's `Controller`, the part ALFRED's code uses, on a World: headless, CPU only.

ALFRED's `ThorEnv` (a subclass) calls `__init__(quality=...)`, `start(x_display=..., player_screen_height=...,
player_screen_width=...)`, `reset(scene_name)`, `step(dict)` and `stop()`, and reads `last_event`. The scene:
`reset("FloorPlanN")` only names the floor plan; the generated scene is identified when
`restore_scene` sends `SetObjectPoses` with the trial's `object_poses` (`thor.scenes`), and built then,
with what `Initialize`, `SetObjectToggles` and `SetStateOfAllObjects` asked for before it.

Actions ALFRED issues and what they do here:

| action | here |
|---|---|
| `Initialize` | checks and records its values (`INITIALIZE_KEYS`): `gridSize` 0.25 only, `cameraY` 0.75 only, |
| | `fieldOfView` 60 only, `visibility_distance` (or `visibilityDistance`) a number in (0, 5] m, render |
| | flags true or false; anything else is a failed event naming the key |
| `SetObjectToggles` | checks that each listed type's objects start in the listed state (our scenes are built so) |
| `SetStateOfAllObjects` | `CanBeDirty`: dirtyable pickupable objects start dirty (as our cleaning episodes); |
| | `CanBeFilled`: nothing starts filled |
| `SetObjectPoses` | identifies the trial's scene in `LUMINOUS_ALFRED_DATA` and builds it (or puts a built one back) |
| `MoveAhead`, `RotateLeft/Right`, `LookUp/Down`, `Teleport(Full)`, `Pass` | the World's (render flags dropped) |
| `OpenObject`, `CloseObject`, `PickupObject`, `PutObject`, `ToggleObjectOn/Off`, `SliceObject` | the World's |
| `CleanObject` | a dirty dirtyable object, visible and within reach, becomes clean (ALFRED sends it after |
| | switching a faucet on) |
| `GetReachablePositions` | `metadata["reachablePositions"]` (and `actionReturn`): the agent's grid |

A refused action gives `lastActionSuccess` false and an `errorMessage`, never an exception: an unknown
key, a value of the wrong type or out of its range, an object out of view or beyond `visibility_distance`
(every interaction, whatever `forceAction` or `forceVisible` say: ALFRED's rule). The one exception is
`ThorSceneError` (one line): a scene that cannot be identified (nothing can run without it), or a bad
argument to `Controller(...)`, `start(...)` or `reset(...)` (a frame size outside 16..1024 pixels, a
scene name that is not `FloorPlanN`), which ai2thor also raises for.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.env.config import IMAGE_SIZE
from luminous_sim.errors import LuminousError
from luminous_sim.fileio import one_line, shown
from luminous_sim.thor.event import Event, object_color, object_name
from luminous_sim.thor.scenes import SceneIndex, ThorSceneError, Trial, poses_key
from luminous_sim.world.arguments import number

RENDER_FLAGS = frozenset({"renderImage", "renderDepthImage", "renderClassImage", "renderObjectImage",
                          "renderNormalsImage", "tempRenderChange"})
"""Flags ai2thor takes on any action that only say what to render (we always render everything): true or false."""
RENDER_KEYS = RENDER_FLAGS | {"sequenceId", "agentId"}
"""Keys ai2thor takes on any action and that change nothing here (`sequenceId` a count, `agentId` 0: one agent)."""
SET_UP_ACTIONS = ("Initialize", "SetObjectToggles", "SetStateOfAllObjects", "SetObjectPoses")
AGENT_Y = 0.9009995
"""THOR's agent height in ALFRED's records (`world.agent_metadata` says the same)."""
GRID = 0.25
CAMERA_Y = 0.75
"""`Initialize`'s `cameraY`, ALFRED's (`CAMERA_HEIGHT_OFFSET`): the World's camera stands where it puts it."""
FIELD_OF_VIEW = 60.0
"""Degrees: the World's camera (`WorldConfig.fov`, and `metadata["fov"]`)."""
VISIBILITY_DEFAULT = 1.5
"""Metres: ALFRED's `VISIBILITY_DISTANCE`, the reach of every interaction until `Initialize` says otherwise."""
MAX_VISIBILITY_DISTANCE = 5.0
"""Metres: the largest `visibility_distance` taken (ALFRED's is 1.5, RoboTHOR's 1.0); beyond a few metres
"within reach" would take in most of a room."""
SCREEN_SIZE = IMAGE_SIZE
"""Least and most pixels a side of the frame (`start(player_screen_width=..., player_screen_height=...)`):
the environments' range (`env.config.IMAGE_SIZE`, 16..1024)."""
QUALITY_SETTINGS = ("DONOTUSE", "High", "High WebGL", "Low", "Medium", "MediumCloseFitShadows", "Ultra",
                    "Very High", "Very Low")
"""ai2thor 2.1.0's render quality names (`Controller(quality=...)`; kept, not used: one renderer here)."""
INITIALIZE_KEYS = frozenset({"action", "gridSize", "cameraY", "fieldOfView", "visibility_distance",
                             "visibilityDistance", "makeAgentsVisible", "forceAction"}) | RENDER_KEYS
"""The keys `Initialize` takes."""
SET_UP_KEYS: dict[str, frozenset[str]] = {
    "SetObjectToggles": frozenset({"action", "objectToggles", "forceAction"}) | RENDER_KEYS,
    "SetStateOfAllObjects": frozenset({"action", "StateChange", "forceAction"}) | RENDER_KEYS,
    "SetObjectPoses": frozenset({"action", "objectPoses", "forceAction", "placeStationary"}) | RENDER_KEYS,
    "GetReachablePositions": frozenset({"action", "forceAction"}) | RENDER_KEYS,
    "CleanObject": frozenset({"action", "objectId", "forceAction", "forceVisible", "coordinateObjectId",
                              "coordinateReceptacleObjectId", "cleanObjectId"}) | RENDER_KEYS,
}
"""The keys each action the controller runs itself takes (the World checks its own actions' keys)."""
STATE_CHANGES = ("CanBeDirty", "CanBeFilled", "CanBeUsedUp")
CLEANING = "pick_clean_then_place_in_recep"
"""The task type whose set-up ALFRED's `SetStateOfAllObjects` `CanBeDirty` is (everything dirtyable dirty)."""
"""`SetStateOfAllObjects`'s `StateChange` values modelled."""
SCENE_NAME = re.compile(r"FloorPlan([1-9][0-9]{0,4})(_physics)?")
"""The scene names `reset` takes: AI2-THOR's floor plans (ai2thor's `_physics` suffix is the same scene)."""


def _is_bool(value: Any) -> bool:
    return isinstance(value, bool | np.bool_)


def _size(name: str, value: Any) -> int:
    """A frame side given to `start`, checked: an int (not a bool) within `SCREEN_SIZE`."""
    lo, hi = SCREEN_SIZE
    n = number(value)
    if not isinstance(n, int) or not lo <= n <= hi:
        raise ThorSceneError(f"start: {name} must be a whole number of pixels in {lo}..{hi}, not {shown(value)}")
    return n


class Controller:
    """ai2thor 2.1.0's controller on our World (the part ALFRED's code uses).

    Args:
        quality: ai2thor's render quality name (kept, not used: one renderer here).
        data: dataset folder(s) to identify scenes in; default `LUMINOUS_ALFRED_DATA`.
        **kwargs: other ai2thor constructor arguments (kept in `options`, not used).
    """

    def __init__(self, quality: str = "MediumCloseFitShadows", data: str | Path | list[str | Path] | None = None,
                 **kwargs: Any):
        if not isinstance(quality, str) or quality not in QUALITY_SETTINGS:
            raise ThorSceneError(f"Controller: quality must be one of ai2thor's {', '.join(QUALITY_SETTINGS)}, not "
                                 f"{shown(quality)}")
        if data is not None and not isinstance(data, str | os.PathLike) and not (
                isinstance(data, list | tuple) and data and all(isinstance(d, str | os.PathLike) for d in data)):
            raise ThorSceneError(f"Controller: data must be a dataset folder or a list of them, not {shown(data)}")
        self.quality = quality
        self.options = dict(kwargs)
        self.data = data
        self.local_executable_path: str | None = None
        self.width = 300
        self.height = 300
        self.x_display: str | None = None
        self.scene_name: str | None = None
        self.trial: Trial | None = None
        self.world: Any = None
        self._world_scene: str | None = None
        self._visibility = VISIBILITY_DEFAULT
        self._toggles: list[dict[str, Any]] = []
        self._dirty = False
        self._names: dict[str, str] = {}
        self._colors: dict[str, tuple[int, int, int]] = {}
        self.last_event = self._blank_event({"action": ""}, True, "")

    # ------------------------------------------------------------------ life cycle (ai2thor's)

    def start(self, port: int = 0, start_unity: bool = True, player_screen_width: int = 300,
              player_screen_height: int = 300, x_display: str | None = None, **kwargs: Any) -> None:
        """ai2thor starts Unity here; we only take the frame size (no display is needed).

        Raises:
            ThorSceneError: a frame side that is not a whole number in 16..1024 (`SCREEN_SIZE`), an `x_display`
                that is not a string, a `port` that is not one, `start_unity` not true or false.
        """
        width, height = _size("player_screen_width", player_screen_width), _size("player_screen_height",
                                                                               player_screen_height)
        if x_display is not None and not isinstance(x_display, str):
            raise ThorSceneError(f"start: x_display must be a display name (a string), not {shown(x_display)}")
        if not isinstance(number(port), int) or not 0 <= port <= 65535:
            raise ThorSceneError(f"start: port must be a port number in 0..65535, not {shown(port)}")
        if not _is_bool(start_unity):
            raise ThorSceneError(f"start: start_unity must be true or false, not {shown(start_unity)}")
        if self.world is not None and (width, height) != (self.width, self.height):
            self.stop()  # its frames have the old size; the next SetObjectPoses builds the scene again
        self.width, self.height = width, height
        self.x_display = x_display

    def reset(self, scene: str = "FloorPlan1", **kwargs: Any) -> Event:
        """Name the floor plan; the scene itself is built when `SetObjectPoses` identifies the trial.

        Raises:
            ThorSceneError: `scene` is not an AI2-THOR floor plan's name (`FloorPlanN`), or an argument that
                ai2thor 2.1.0's `reset` does not take.
        """
        match = SCENE_NAME.fullmatch(scene) if isinstance(scene, str) else None
        if match is None:
            raise ThorSceneError(f"reset: the scene must be an AI2-THOR floor plan's name (FloorPlanN), not "
                                 f"{shown(scene)}")
        if kwargs:
            raise ThorSceneError(f"reset takes only the scene name, not {', '.join(map(shown, sorted(kwargs)))}")
        self.scene_name = f"FloorPlan{match.group(1)}"
        self.trial = None
        self._toggles, self._dirty = [], False
        self.last_event = self._blank_event({"action": "Reset"}, True, "")
        return self.last_event

    def stop(self) -> None:
        if self.world is not None:
            self.world.close()
        self.world, self._world_scene, self.trial = None, None, None

    def __enter__(self) -> Controller:
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    # ------------------------------------------------------------------ actions

    def step(self, action: str | Mapping[str, Any] | None = None, **kwargs: Any) -> Event:
        """Run one action, `step({"action": ..., ...})` or `step(action=..., ...)`; the new `last_event`."""
        if isinstance(action, Mapping):
            act = {**action, **kwargs}
        elif action is None:
            act = dict(kwargs)
        else:
            act = {"action": action, **kwargs}
        name = act.get("action")
        if not isinstance(name, str):
            self.last_event = self._failed(act, f"an action needs an 'action' name, got {shown(name)}")
            return self.last_event
        try:
            why = self._common_failure(name, act)
            self.last_event = self._failed(act, why) if why else self._dispatch(name, act)
        except ThorSceneError:
            raise
        except (KeyError, ValueError, TypeError, ArithmeticError, LuminousError) as exc:  # malformed arguments
            self.last_event = self._failed(act, f"invalid arguments for {name}: {type(exc).__name__}: "
                                                f"{one_line(str(exc), 300)}")
        return self.last_event

    @staticmethod
    def _common_failure(name: str, act: dict[str, Any]) -> str | None:
        """Why the keys every action may carry are not acceptable (render flags, `sequenceId`, `agentId`,
        `forceAction`), or why a key is not one the controller's own action takes; None if they are fine."""
        for key in RENDER_FLAGS | {"forceAction"}:
            if key in act and not _is_bool(act[key]):
                return f"{name}: {key} must be true or false, not {shown(act[key])}"
        if "sequenceId" in act and (not isinstance(number(act["sequenceId"]), int) or act["sequenceId"] < 0):
            return f"{name}: sequenceId must be a whole number >= 0, not {shown(act['sequenceId'])}"
        if "agentId" in act and (not isinstance(number(act["agentId"]), int) or act["agentId"] != 0):
            return f"{name}: agentId must be 0 (one agent), not {shown(act['agentId'])}"
        accepted = INITIALIZE_KEYS if name == "Initialize" else SET_UP_KEYS.get(name)
        if accepted is not None:
            unknown = sorted(str(k) for k in act if k not in accepted)
            if unknown:
                return (f"{name} takes no {', '.join(map(shown, unknown))} (it takes "
                        f"{', '.join(sorted(accepted))})")
        return None

    def _dispatch(self, name: str, act: dict[str, Any]) -> Event:
        if name == "Initialize":
            return self._initialize(act)
        if name == "SetObjectToggles":
            toggles = act.get("objectToggles")
            why = _toggles_failure(toggles)
            if why:
                return self._failed(act, f"SetObjectToggles: {why}")
            self._toggles = [dict(t) for t in toggles or []]
            return self._check_toggles(act) if self.trial is not None else self._current(act)
        if name == "SetStateOfAllObjects":
            change = act.get("StateChange")
            if not isinstance(change, str) or change not in STATE_CHANGES:
                return self._failed(act, f"SetStateOfAllObjects: StateChange {shown(change)} is not modelled "
                                         f"({', '.join(STATE_CHANGES)} are)")
            if change == "CanBeDirty":
                self._dirty = True
            return self._current(act)
        if name == "SetObjectPoses":
            return self._load(act)
        if self.world is None or self.trial is None:
            return self._failed(act, f"{name}: no scene is loaded: after reset('{self.scene_name or 'FloorPlanN'}'), "
                                     "restore_scene(...) (SetObjectPoses) names the trial's scene")
        if name == "GetReachablePositions":
            points = [{"x": float(x), "y": AGENT_Y, "z": float(z)} for x, z in self.world.nav.points()]
            return self._current(act, extra={"reachablePositions": points, "actionReturn": points})
        if name == "CleanObject":
            return self._clean(act)
        world_act = {k: v for k, v in act.items() if k not in RENDER_KEYS}
        result = self.world.step(world_act)
        return self._event(act, result.success, result.error)

    def _initialize(self, act: dict[str, Any]) -> Event:
        """`Initialize`: every value checked before any is taken (a refusal changes nothing)."""
        fixed = (("gridSize", GRID, "ALFRED's; the agent moves on a 0.25 m grid"),
                 ("cameraY", CAMERA_Y, "ALFRED's; the World's camera height is fixed"),
                 ("fieldOfView", FIELD_OF_VIEW, "the World's camera"))
        for key, only, why in fixed:
            if key in act:
                value = number(act[key])
                if value is None or not math.isclose(value, only, abs_tol=1e-6):
                    return self._failed(act, f"Initialize: {key} must be {only:g} ({why}), not {shown(act[key])}")
        given = [k for k in ("visibility_distance", "visibilityDistance") if k in act]
        visibility = self._visibility
        for key in given:
            value = number(act[key])
            if value is None or not 0.0 < value <= MAX_VISIBILITY_DISTANCE:
                return self._failed(act, f"Initialize: {key} must be a number of metres in (0, "
                                         f"{MAX_VISIBILITY_DISTANCE:g}] (ALFRED's is {VISIBILITY_DEFAULT}), not "
                                         f"{shown(act[key])}")
            visibility = float(value)
        if len(given) == 2 and not math.isclose(float(act[given[0]]), float(act[given[1]])):
            return self._failed(act, f"Initialize: visibility_distance {shown(act[given[0]])} and visibilityDistance "
                                     f"{shown(act[given[1]])} differ")
        if "makeAgentsVisible" in act and not _is_bool(act["makeAgentsVisible"]):
            return self._failed(act, f"Initialize: makeAgentsVisible must be true or false, not "
                                     f"{shown(act['makeAgentsVisible'])}")
        self._visibility = visibility
        self._apply_visibility()
        return self._current(act)

    def _apply_visibility(self) -> None:
        """Give the built World (if any) the recorded visibility distance, the reach of every interaction."""
        world = self.world
        if world is not None and world.config.visibility_distance != self._visibility:
            world.config = dataclasses.replace(world.config, visibility_distance=self._visibility)
            world.invalidate_frame()  # what is visible depends on it

    # ------------------------------------------------------------------ set-up

    def _load(self, act: dict[str, Any]) -> Event:
        if not self.scene_name:
            return self._failed(act, "SetObjectPoses: reset(scene_name) first")
        poses: Any = act.get("objectPoses")
        try:
            poses_key(poses)
        except ValueError as exc:
            return self._failed(act, f"SetObjectPoses: {exc}")
        index = SceneIndex.of(self.data)
        trial = index.find(self.scene_name, poses)
        scene = trial.scene()
        digest = scene.to_json()
        world = self.world
        size = (self.width, self.height)
        if world is None or self._world_scene != digest or (world.config.width, world.config.height) != size \
                or not world.reset_to_start():
            from luminous_sim.world import World, WorldConfig

            if world is not None:
                world.close()
            world = World(scene, WorldConfig(width=self.width, height=self.height,
                                             visibility_distance=self._visibility))
            self.world, self._world_scene = world, digest
        self._apply_visibility()
        self.trial = trial
        if self._dirty:  # SetStateOfAllObjects CanBeDirty is ALFRED's set-up for cleaning
            from luminous_sim.episodes import alfred_set_up

            alfred_set_up(world, CLEANING)
        if self._toggles:
            checked = self._check_toggles(act)
            if not checked.metadata["lastActionSuccess"]:
                return checked
        return self._current(act)

    def _check_toggles(self, act: dict[str, Any]) -> Event:
        states = self.world.view().state.objects
        for t in self._toggles:
            kind, on = t["objectType"], bool(t["isOn"])
            wrong = sorted(oid for oid, st in states.items() if st.object_type == kind and st.isToggled != on)
            if wrong:
                return self._failed(act, f"SetObjectToggles: {', '.join(wrong)} start {'off' if on else 'on'} in this "
                                         "scene and cannot be switched before the episode here")
        return self._current(act)

    def _clean(self, act: dict[str, Any]) -> Event:
        """`CleanObject`: ALFRED's rule, as for every interaction: the object visible and within reach."""
        from luminous_sim.vocab import abilities
        from luminous_sim.world.reach import reach_failure

        oid = act.get("objectId")
        if "forceVisible" in act and not _is_bool(act["forceVisible"]):
            return self._failed(act, "CleanObject: forceVisible must be true or false, not "
                                     f"{shown(act['forceVisible'])}")
        if not isinstance(oid, str) or not oid:
            return self._failed(act, f"CleanObject needs an objectId (a string), not {shown(oid)}")
        state = self.world.view().state
        states = state.objects
        if oid not in states:
            return self._failed(act, f"CleanObject: object ID appears to be invalid: {shown(oid)}")
        why = reach_failure(self.world, state, oid)
        if why is not None:
            return self._failed(act, f"CleanObject: {why.message}")
        if not abilities(states[oid].object_type).dirtyable:
            return self._failed(act, f"CleanObject: {oid} is not dirtyable")
        self.world.interactions.set_dirty(oid, False)
        self.world.invalidate_frame()
        return self._current(act)

    # ------------------------------------------------------------------ events

    def _current(self, act: dict[str, Any], extra: dict[str, Any] | None = None) -> Event:
        """The event of an action that succeeded without a World step (the world's current state)."""
        if self.world is None or self.trial is None:
            return self._blank_event(act, True, "", extra)
        return self._event(act, True, "", extra)

    def _failed(self, act: dict[str, Any], error: str) -> Event:
        if self.world is None or self.trial is None:
            return self._blank_event(act, False, error)
        return self._event(act, False, error)

    def _base_metadata(self, act: dict[str, Any], success: bool, error: str) -> dict[str, Any]:
        return {
            "sceneName": self.scene_name or "", "screenWidth": self.width, "screenHeight": self.height,
            "lastAction": str(act.get("action", "")), "lastActionSuccess": bool(success), "errorMessage": error,
            "errorCode": "", "actionReturn": None, "reachablePositions": [], "collided": False,
            "collidedObjects": [], "agentId": 0, "sequenceId": 0, "fov": 60.0, "thirdPartyCameras": [],
            "colorBounds": [],
        }

    def _blank_event(self, act: dict[str, Any], success: bool, error: str,
                     extra: dict[str, Any] | None = None) -> Event:
        md = self._base_metadata(act, success, error)
        md.update({"agent": {"name": "agent", "position": {"x": 0.0, "y": AGENT_Y, "z": 0.0},
                             "rotation": {"x": 0.0, "y": 0.0, "z": 0.0}, "cameraHorizon": 0.0},
                   "objects": [], "inventoryObjects": [], "colors": []})
        md.update(extra or {})
        h, w = self.height, self.width
        return Event(md, np.zeros((h, w, 3), np.uint8), np.zeros((h, w), np.float32), np.zeros((h, w, 3), np.uint8))

    def _event(self, act: dict[str, Any], success: bool, error: str, extra: dict[str, Any] | None = None) -> Event:
        """The event of the world as it is now, reporting `act`'s outcome."""
        from luminous_sim.world.client import body_aabb

        world = self.world
        md = world.metadata()
        md.update(self._base_metadata(act, success, error))
        md["agent"] = {"name": "agent", **md["agent"]}
        md["cameraPosition"] = {"x": md["agent"]["position"]["x"], "y": AGENT_Y + 0.675,
                                "z": md["agent"]["position"]["z"]}
        for obj in md["objects"]:
            oid = obj["objectId"]
            obj["name"] = self._name(oid, obj["objectType"])
            lo, hi = body_aabb(world.client, world.built.objects[oid].body)
            center, size = (lo + hi) / 2, hi - lo
            corners = [[float(x), float(z), float(y)] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                       for z in (lo[2], hi[2])]
            obj["axisAlignedBoundingBox"] = {
                "cornerPoints": corners,
                "center": {"x": float(center[0]), "y": float(center[2]), "z": float(center[1])},
                "size": {"x": float(size[0]), "y": float(size[2]), "z": float(size[1])}}
        for inv in md["inventoryObjects"]:
            inv["name"] = self._name(inv["objectId"], inv["objectType"])
        md.update(extra or {})
        frame = world.frame()
        names = world.body_to_object()
        bodies = world.instance_ids()
        colors = {oid: self._color(oid) for oid in names.values()}
        lut = np.zeros((max([int(bodies.max()), *names]) + 2, 3), np.uint8)
        for body, oid in names.items():
            lut[body + 1] = colors[oid]
        seg = lut[bodies + 1]
        md["colors"] = [{"name": oid, "color": list(c)} for oid, c in sorted(colors.items())]
        boxes = {oid: np.array(box) for oid, box in world.boxes().items()}
        return Event(md, frame.rgb, (frame.depth * 1000.0).astype(np.float32), seg,
                     {c: oid for oid, c in colors.items()}, world.instance_masks(), boxes)

    def _name(self, oid: str, kind: str) -> str:
        if oid not in self._names:
            self._names[oid] = object_name(oid, kind)
        return self._names[oid]

    def _color(self, oid: str) -> tuple[int, int, int]:
        if oid not in self._colors:
            self._colors[oid] = object_color(oid, set(self._colors.values()))
        return self._colors[oid]


def _toggles_failure(toggles: Any) -> str | None:
    """Why `SetObjectToggles`'s `objectToggles` is not a list of {objectType: str, isOn: bool}, or None."""
    if toggles is None:
        return None
    if not isinstance(toggles, list | tuple):
        return f"objectToggles must be a list of {{objectType, isOn}}, not {shown(toggles)}"
    for i, t in enumerate(toggles):
        if not isinstance(t, Mapping) or set(t) != {"objectType", "isOn"} or not isinstance(t["objectType"], str) \
                or not _is_bool(t["isOn"]):
            return f"objectToggles[{i}] must be {{objectType: a type name, isOn: true or false}}, not {shown(t)}"
    return None
