"""ai2thor 2.1.0's `Controller`, the part ALFRED's code uses, on a World: headless, CPU only.

ALFRED's `ThorEnv` (a subclass) calls `__init__(quality=...)`, `start(x_display=..., player_screen_height=...,
player_screen_width=...)`, `reset(scene_name)`, `step(dict)` and `stop()`, and reads `last_event`. The scene:
`reset("FloorPlanN")` only names the floor plan; the generated scene is identified when
`restore_scene` sends `SetObjectPoses` with the trial's `object_poses` (`thor.scenes`), and built then,
with what `Initialize`, `SetObjectToggles` and `SetStateOfAllObjects` asked for before it.

Actions ALFRED issues and what they do here:

| action | here |
|---|---|
| `Initialize` | records `gridSize` (0.25 only), `visibility_distance` and the render flags; succeeds |
| `SetObjectToggles` | checks that each listed type's objects start in the listed state (our scenes are built so) |
| `SetStateOfAllObjects` | `CanBeDirty`: dirtyable pickupable objects start dirty (as our cleaning episodes); |
| | `CanBeFilled`: nothing starts filled |
| `SetObjectPoses` | identifies the trial's scene in `LUMINOUS_ALFRED_DATA` and builds it (or puts a built one back) |
| `MoveAhead`, `RotateLeft/Right`, `LookUp/Down`, `Teleport(Full)`, `Pass` | the World's (render flags dropped) |
| `OpenObject`, `CloseObject`, `PickupObject`, `PutObject`, `ToggleObjectOn/Off`, `SliceObject` | the World's |
| `CleanObject` | a dirty dirtyable object becomes clean (ALFRED sends it after switching a faucet on) |
| `GetReachablePositions` | `metadata["reachablePositions"]` (and `actionReturn`): the agent's grid |

A refused action gives `lastActionSuccess` false and an `errorMessage`, never an exception. The one
exception is a scene that cannot be identified (`ThorSceneError`, one line): nothing can run without it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.errors import LuminousError
from luminous_sim.thor.event import Event, object_color, object_name
from luminous_sim.thor.scenes import SceneIndex, ThorSceneError, Trial

RENDER_KEYS = frozenset({"renderImage", "renderDepthImage", "renderClassImage", "renderObjectImage",
                         "renderNormalsImage", "tempRenderChange", "sequenceId", "agentId"})
"""Keys ai2thor takes on any action that only say what to render (we always render everything)."""
SET_UP_ACTIONS = ("Initialize", "SetObjectToggles", "SetStateOfAllObjects", "SetObjectPoses")
AGENT_Y = 0.9009995
"""THOR's agent height in ALFRED's records (`world.agent_metadata` says the same)."""
GRID = 0.25


class Controller:
    """ai2thor 2.1.0's controller on our World (the part ALFRED's code uses).

    Args:
        quality: ai2thor's render quality name (kept, not used: one renderer here).
        data: dataset folder(s) to identify scenes in; default `LUMINOUS_ALFRED_DATA`.
        **kwargs: other ai2thor constructor arguments (kept in `options`, not used).
    """

    def __init__(self, quality: str = "MediumCloseFitShadows", data: str | Path | list[str | Path] | None = None,
                 **kwargs: Any):
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
        self._visibility = 1.5
        self._toggles: list[dict[str, Any]] = []
        self._dirty = False
        self._names: dict[str, str] = {}
        self._colors: dict[str, tuple[int, int, int]] = {}
        self.last_event = self._blank_event({"action": ""}, True, "")

    # ------------------------------------------------------------------ life cycle (ai2thor's)

    def start(self, port: int = 0, start_unity: bool = True, player_screen_width: int = 300,
              player_screen_height: int = 300, x_display: str | None = None, **kwargs: Any) -> None:
        """ai2thor starts Unity here; we only take the frame size (no display is needed)."""
        self.width, self.height = int(player_screen_width), int(player_screen_height)
        self.x_display = x_display

    def reset(self, scene: str = "FloorPlan1", **kwargs: Any) -> Event:
        """Name the floor plan; the scene itself is built when `SetObjectPoses` identifies the trial."""
        self.scene_name = str(scene)
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
            self.last_event = self._failed(act, f"an action needs an 'action' name, got {name!r}")
            return self.last_event
        try:
            self.last_event = self._dispatch(name, act)
        except ThorSceneError:
            raise
        except (KeyError, ValueError, TypeError, LuminousError) as exc:  # malformed arguments
            self.last_event = self._failed(act, f"invalid arguments for {name}: {type(exc).__name__}: {exc}")
        return self.last_event

    def _dispatch(self, name: str, act: dict[str, Any]) -> Event:
        if name == "Initialize":
            grid = act.get("gridSize", GRID)
            if not math.isclose(float(grid), GRID):
                return self._failed(act, f"Initialize: gridSize must be {GRID} (ALFRED's), not {grid}")
            self._visibility = float(act.get("visibility_distance", act.get("visibilityDistance", self._visibility)))
            return self._current(act)
        if name == "SetObjectToggles":
            self._toggles = [dict(t) for t in act.get("objectToggles") or []]
            return self._check_toggles(act) if self.trial is not None else self._current(act)
        if name == "SetStateOfAllObjects":
            change = act.get("StateChange")
            if change == "CanBeDirty":
                self._dirty = True
            elif change not in ("CanBeFilled", "CanBeUsedUp"):
                return self._failed(act, f"SetStateOfAllObjects: StateChange {change!r} is not modelled "
                                         "(CanBeDirty and CanBeFilled are)")
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

    # ------------------------------------------------------------------ set-up

    def _load(self, act: dict[str, Any]) -> Event:
        if not self.scene_name:
            return self._failed(act, "SetObjectPoses: reset(scene_name) first")
        index = SceneIndex.of(self.data)
        trial = index.find(self.scene_name, act.get("objectPoses") or [])
        scene = trial.scene()
        digest = scene.to_json()
        world = self.world
        if world is None or self._world_scene != digest or not world.reset_to_start():
            from luminous_sim.world import World, WorldConfig

            if world is not None:
                world.close()
            world = World(scene, WorldConfig(width=self.width, height=self.height,
                                             visibility_distance=self._visibility))
            self.world, self._world_scene = world, digest
        self.trial = trial
        if self._dirty:
            from luminous_sim.vocab import abilities

            world.set_up_dirty([oid for oid, st in world.view().state.objects.items()
                                if abilities(st.object_type).dirtyable and abilities(st.object_type).pickupable])
        if self._toggles:
            checked = self._check_toggles(act)
            if not checked.metadata["lastActionSuccess"]:
                return checked
        return self._current(act)

    def _check_toggles(self, act: dict[str, Any]) -> Event:
        states = self.world.view().state.objects
        for t in self._toggles:
            kind, on = t.get("objectType"), bool(t.get("isOn"))
            wrong = sorted(oid for oid, st in states.items() if st.object_type == kind and st.isToggled != on)
            if wrong:
                return self._failed(act, f"SetObjectToggles: {', '.join(wrong)} start {'off' if on else 'on'} in this "
                                         "scene and cannot be switched before the episode here")
        return self._current(act)

    def _clean(self, act: dict[str, Any]) -> Event:
        from luminous_sim.vocab import abilities

        oid = act.get("objectId")
        states = self.world.view().state.objects
        if oid not in states:
            return self._failed(act, f"CleanObject: object ID appears to be invalid: {oid!r}")
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
