"""A World: one scene in one PyBullet client, ALFRED's agent in it, and its low-level actions.

Every action returns a StepResult; a failed or invalid action never raises and leaves the world as
it was (lastActionSuccess false, errorMessage set), as AI2-THOR does. Arguments are checked first
(`arguments`): one that ALFRED's discrete agent cannot honour is refused, never ignored.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterable
from dataclasses import dataclass
from functools import partial
from typing import TYPE_CHECKING, Any, cast

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.errors import FailureCode
from luminous_sim.fileio import shown
from luminous_sim.scene.model import Scene
from luminous_sim.vocab import AGENT_ACTIONS, INTERACTION_ACTIONS, TELEPORT_ACTIONS
from luminous_sim.world.agent import AgentPose
from luminous_sim.world.arguments import argument_failure, teleport_pose
from luminous_sim.world.camera import Frame, render
from luminous_sim.world.client import BulletClient, body_aabb
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.frame_facts import FrameFacts, body_ids
from luminous_sim.world.interaction import Interactions
from luminous_sim.world.navigation import NavGrid
from luminous_sim.world.raster_scene import UnsupportedGeometry
from luminous_sim.world.results import StepResult
from luminous_sim.world.scene_builder import BuiltScene, build_scene
from luminous_sim.world.view import LiveView, WorldView

if TYPE_CHECKING:
    from luminous_sim.world.raster_scene import CompiledRenderer


@dataclass(frozen=True)
class KeptFrame:
    """A frame with the agent pose it was rendered at and the poses of what the agent held (`World.keep_frame`)."""

    pose: AgentPose
    held: tuple[Any, ...]
    facts: FrameFacts


def _action_dict(action: str | dict[str, Any], kwargs: dict[str, Any]) -> dict[str, Any]:
    if isinstance(action, str):
        return {"action": action, **kwargs}
    if isinstance(action, dict) and isinstance(action.get("action"), str):
        return {**action, **kwargs}
    return {"action": shown(action)}


class World:
    """A scene built in its own PyBullet client, with an agent and ALFRED's action set."""

    def __init__(self, scene: Scene, config: WorldConfig | None = None, catalog: Catalog | None = None,
                 agent: AgentPose | None = None):
        self.config = config or WorldConfig()
        self.catalog = catalog or default_catalog()
        self.scene = scene
        from luminous_sim.world.client import new_client, resolve_renderer

        client = new_client(renderer=resolve_renderer(self.config.renderer))
        self.built: BuiltScene = build_scene(scene, self.catalog, client=client, settle_steps=self.config.settle_steps,
                                             lod=self.config.use_lod, structure_last=self.config.structure_last)
        self.client = self.built.client
        self.nav = NavGrid.from_scene(scene)
        self.agent = agent or self.default_start()
        self._facts: FrameFacts | None = None
        self._kept: KeptFrame | None = None
        self._scene_digest: str | None = None
        from luminous_sim.world.culling import CullingClient, FrustumCuller

        room = scene.room if self.config.cull_outdoors else None
        self.eye_guard = FrustumCuller(self.client, self.built.objects, room, self.built.outdoors)
        """Knows the scene's triangles: every render of this World passes it as `guard` (`world.eye_plane`)."""
        self._culler = self.eye_guard if self.config.cull else None
        self._compiled = self._compiled_renderer()
        # everyone but the culled render sees every link as it is; the guard hears of every move
        self.built.client = self.client = cast(BulletClient, CullingClient(self.client, self.eye_guard))
        self.last = StepResult(True, "", {"action": "Initialize"})
        self.interactions = Interactions(self)
        self._view = LiveView(self)
        self._started = False
        from luminous_sim.world.restore import WatchedClient, take_snapshot

        self._start = take_snapshot(self)
        self.client = WatchedClient(self.built.client)  # notes a touch of the physics (see `reset_to_start`)

    def scene_digest(self) -> str:
        """sha256 of the scene's JSON (computed once): worlds built from equal scenes share it."""
        if self._scene_digest is None:
            from luminous_sim.world.sightlines import scene_digest

            self._scene_digest = scene_digest(self.scene)
        return self._scene_digest

    def view(self) -> WorldView:
        """The world's read-only face: states, poses, visibility, reachable poses, dry-run puts."""
        return self._view

    # ------------------------------------------------------------------ life cycle

    def close(self) -> None:
        if self.client is not None:
            self.client.disconnect()
            self.client = None

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def reset_to_start(self) -> bool:
        """Put the world back exactly as it was built (agent pose, object states and their visuals, what
        `set_up_dirty` did, the put stream, the last action), ready for set-up and a new episode, without
        building it again; True when done. Only a world whose physics was never touched can be: no body
        or link moved (a pick-up, an opening, a put, or a planner trying a door's swing), since PyBullet's
        restoreState would leave hidden state behind that steers later physics (see `world.restore`).
        Otherwise False, and nothing changes: build a new World."""
        from luminous_sim.world.restore import restore

        if self.client is None or self.client.touched:
            return False
        restore(self, self._start)
        self.invalidate_frame()
        self.last = StepResult(True, "", {"action": "Initialize"})
        self._started = False
        return True

    def set_up_dirty(self, object_ids: Iterable[str]) -> None:
        """Scene set-up before the first action: make these objects dirty (pure state and visuals), as
        ALFRED's `dirty_and_empty` initialisation does for a cleaning task. Not an action: it raises
        once the episode has started (ids that are not objects in the world are skipped)."""
        if self._started:
            from luminous_sim.errors import LuminousError

            raise LuminousError("set_up_dirty is scene set-up: call it before the first World.step")
        for oid in object_ids:
            self.interactions.set_dirty(oid, True)
        self.invalidate_frame()

    def set_up_sliced(self, object_ids: Iterable[str]) -> None:
        """Scene set-up before the first action: slice these objects (a scene's `isSliced` initial state; no
        knife needed), replacing each by its slices as `SliceObject` does. Not an action: it raises once the
        episode has started (ids that are not sliceable objects in the world are skipped)."""
        if self._started:
            from luminous_sim.errors import LuminousError

            raise LuminousError("set_up_sliced is scene set-up: call it before the first World.step")
        for oid in object_ids:
            self.interactions.set_sliced(oid)
        self.invalidate_frame()

    def set_start(self, pose: AgentPose) -> None:
        """Scene set-up before the first action: the agent starts at `pose` (e.g. a CDF's `task.agent`). Not
        an action: it raises once the episode has started (`reset_to_start` puts the world back first)."""
        if self._started:
            from luminous_sim.errors import LuminousError

            raise LuminousError("set_start is scene set-up: call it before the first World.step (or after "
                                "World.reset_to_start); to move the agent during an episode, step it (e.g. "
                                "TeleportFull)")
        self.agent = pose
        self.invalidate_frame()

    def default_start(self) -> AgentPose:
        """The reachable point nearest the room's centre, facing north, looking 30 degrees down."""
        pts = self.nav.points()
        if len(pts) == 0:
            from luminous_sim.errors import LuminousError

            raise LuminousError(f"scene in room {self.scene.room.name} has no reachable floor for the agent")
        c = np.array(self.scene.room.polygon().centroid.coords[0])
        x, y = pts[int(np.argmin(np.linalg.norm(pts - c, axis=1)))]
        return AgentPose(float(x), float(y), 0, 30)

    # ------------------------------------------------------------------ actions

    def step(self, action: str | dict[str, Any], **kwargs: Any) -> StepResult:
        """Run one low-level action (a name or an ALFRED api_action dict); never raises on bad input."""
        act = _action_dict(action, kwargs)
        name = act["action"]
        self._started = True
        if name not in AGENT_ACTIONS:
            self._kept = None  # an interaction, even a failed one, may change what a kept frame shows
        before = self._facts
        try:
            known = name in AGENT_ACTIONS or name in INTERACTION_ACTIONS
            why = argument_failure(act, (self.config.height, self.config.width)) if known else None
            if why is not None:
                result = StepResult.of(why, act)
            elif name in AGENT_ACTIONS:
                result = self._navigate(name, act)
                if result.success and self.interactions.held:
                    self.interactions.carry(self.interactions.held)
            elif name in INTERACTION_ACTIONS:
                result = self.interactions.run(name, act)
            else:
                result = StepResult.fail(FailureCode.UNKNOWN_ACTION, f"unknown action {shown(name)}; expected one of "
                                         f"{', '.join(AGENT_ACTIONS + INTERACTION_ACTIONS)}", act)
        except (KeyError, ValueError, TypeError) as exc:  # malformed arguments from an agent
            result = StepResult.fail(FailureCode.INVALID_ARGUMENT, f"invalid arguments for {name}: {shown(exc, 200)}",
                                     act)
        if result.success:
            self._facts = None  # not `invalidate_frame`: walking keeps a kept frame (see `keep_frame`)
        elif self._facts is not before:
            # A failed action leaves the world as it was, so the frame from before it is still the view;
            # one rendered during the action (a reach check) may show a half-done change: drop it.
            self._facts = before
        self.last = StepResult(result.success, result.error, act, result.code)
        return self.last

    def _navigate(self, name: str, act: dict[str, Any]) -> StepResult:
        pose = self.agent
        if name == "MoveAhead":
            if not self.nav.can_move(pose):
                return StepResult.fail(FailureCode.BLOCKED,
                                       "blocked: MoveAhead would leave the navigable floor or hit something", act)
            self.agent = pose.moved()
        elif name in ("RotateLeft", "RotateRight"):
            self.agent = pose.rotated(-1 if name == "RotateLeft" else 1)
        elif name in ("LookUp", "LookDown"):
            looked = pose.looked(-1 if name == "LookUp" else 1)
            if looked is None:
                return StepResult.fail(FailureCode.HORIZON_LIMIT,
                                       f"{name}: the horizon must stay within -30..60 degrees", act)
            self.agent = looked
        elif name in TELEPORT_ACTIONS:
            target = teleport_pose(act, pose, self.nav)
            if not isinstance(target, AgentPose):
                return StepResult.of(target, act)
            if target.grid_key() not in self.nav:
                return StepResult.fail(FailureCode.BLOCKED,
                                       f"{name} target ({target.x:g}, {target.y:g}) is not on the navigable grid", act)
            self.agent = target
        return StepResult.ok(act)

    # ------------------------------------------------------------------ sensing

    def invalidate_frame(self) -> None:
        """Forget the current frame and what it shows, and any kept one: the view may have changed (the next
        question renders)."""
        self._facts = None
        self._kept = None

    def frame_memo(self) -> KeptFrame:
        """The current frame (rendered now if need be), with the agent's pose and where what it holds is."""
        return KeptFrame(self.agent, self._held_poses(), self._frame_facts())

    def keep_frame(self, memo: KeptFrame) -> None:
        """Keep a frame rendered at another pose, to serve when the agent gets there by walking (after a
        search for a pose that sees an object, the agent walks to the pose it rendered). It is served only
        while nothing but navigation happened since (`invalidate_frame` and every other action drop it)
        and what the agent holds is exactly where it was then: the same scene from the same camera, so
        the same frame, pixel for pixel."""
        self._kept = memo

    def _held_poses(self) -> tuple[Any, ...]:
        held = self.interactions.held
        if held is None:
            return ()
        from luminous_sim.world.hand import family

        return tuple(self.client.getBasePositionAndOrientation(self.built.objects[o].body)
                     for o in family(self, self.interactions.state, held))

    def _compiled_renderer(self) -> CompiledRenderer | None:
        """The compiled rasteriser where the config asks for it (None: PyBullet's TinyRenderer draws)."""
        if self.config.rasteriser != "compiled":
            return None
        from luminous_sim.world.raster_scene import CompiledRenderer

        try:
            return CompiledRenderer(self.client, self.built.objects, self.eye_guard, self.config.cull)
        except UnsupportedGeometry as exc:
            warnings.warn(f"rasteriser='compiled' cannot draw this scene ({exc}); TinyRenderer draws it",
                          stacklevel=3)
            return None

    def _frame_facts(self) -> FrameFacts:
        kept = self._kept
        if self._facts is None and kept is not None and kept.pose == self.agent and kept.held == self._held_poses():
            self._facts, self._kept = kept.facts, None
        if self._facts is None:
            pose = self.agent
            eye = np.array(pose.eye())
            target = eye + np.array(pose.view_direction())
            c = self.config
            draw = partial(render, self.client, eye, target, width=c.width, height=c.height, fov=c.fov, near=0.05,
                           far=20.0, culler=self._culler, guard=self.eye_guard)
            try:
                frame = draw(compiled=self._compiled)
            except UnsupportedGeometry as exc:  # a body added since that the compiled rasteriser cannot draw
                warnings.warn(f"rasteriser='compiled' cannot draw this scene ({exc}); TinyRenderer draws it",
                              stacklevel=2)
                self._compiled = None
                frame = draw()
            self._facts = FrameFacts(frame)
        return self._facts

    def frame(self) -> Frame:
        """RGB, depth and raw segmentation from the agent's camera (rendered once per state)."""
        return self._frame_facts().frame

    def instance_ids(self, seg: np.ndarray | None = None) -> np.ndarray:
        """Per-pixel body ids (-1 for background), from PyBullet's object+link segmentation (of the current
        frame, read-only and computed once per frame, unless `seg` is given)."""
        return self._frame_facts().bodies() if seg is None else body_ids(seg)

    def body_to_object(self) -> dict[int, str]:
        return {loaded.body: oid for oid, loaded in self.built.objects.items()}

    def instance_masks(self) -> dict[str, np.ndarray]:
        """Boolean mask (read-only) of every object visible in the current frame, computed once per frame."""
        return dict(self._frame_facts().masks(self.body_to_object))

    def boxes(self) -> dict[str, list[int]]:
        """2D boxes [x_min, y_min, x_max, y_max] of every object in view, in ALFRED's convention."""
        return {oid: list(box) for oid, box in self._frame_facts().boxes(self.body_to_object).items()}

    def top_down(self):
        """A labelled top-down map image of the room as it is now, with the reachable grid (PIL image)."""
        return self._view.top_down(grid=True)

    def object_distance(self, object_id: str) -> float:
        """Distance from the camera to the object's nearest point (AABB), as AI2-THOR measures it."""
        body = self.built.objects[object_id].body
        lo, hi = body_aabb(self.client, body)
        eye = np.array(self.agent.eye())
        nearest = np.clip(eye, lo, hi)
        return float(np.linalg.norm(nearest - eye))

    def visible_objects(self) -> dict[str, int]:
        """Objects with at least `min_visible_pixels` pixels in view and within the visibility distance
        (computed once per frame)."""
        c = self.config
        return dict(self._frame_facts().visible(self.body_to_object, c.min_visible_pixels, c.visibility_distance,
                                                self.object_distance))

    def agent_metadata(self) -> dict[str, Any]:
        p = self.agent
        return {"position": {"x": p.x, "y": 0.9009995, "z": p.y},
                "rotation": {"x": 0.0, "y": float(p.rotation), "z": 0.0}, "cameraHorizon": float(p.horizon)}

    def metadata(self) -> dict[str, Any]:
        """AI2-THOR-style metadata: agent, inventory, objects, last action result."""
        from luminous_sim.world.metadata import object_metadata

        objects = self._frame_facts().objects(lambda: object_metadata(self, self.visible_objects()))
        held = self.interactions.held
        return {
            "agent": self.agent_metadata(),
            "inventoryObjects": [{"objectId": held, "objectType": self.interactions.type_of(held)}] if held else [],
            "objects": [dict(o) for o in objects],  # per-object dicts computed once per frame; nested values shared
            "lastAction": self.last.action.get("action", ""),
            "lastActionSuccess": self.last.success,
            "errorMessage": self.last.error,
        }
