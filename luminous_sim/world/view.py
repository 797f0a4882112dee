"""`WorldView`: the read-only face of a World for planning, tasks, language and environments.

It answers what is where and in which state, what the agent sees and could see, where it can stand,
and whether a put would fit (a dry run on its own random stream). Nothing it offers changes the world:
every change goes through `World.step` (and scene set-up before the first step, `World.set_up_dirty`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

import numpy as np

from luminous_sim.errors import Failure
from luminous_sim.scene.model import Scene
from luminous_sim.states.model import WorldState
from luminous_sim.world.agent import AgentPose
from luminous_sim.world.camera import Frame
from luminous_sim.world.client import body_aabb
from luminous_sim.world.config import WorldConfig
from luminous_sim.world.navigation import NavGrid
from luminous_sim.world.placement import Spot

if TYPE_CHECKING:
    from PIL import Image

    from luminous_sim.world.world import World

@runtime_checkable
class WorldView(Protocol):
    """Read-only access to a World (poses, containment, states, visibility, reachable poses, dry-run puts)."""

    @property
    def scene(self) -> Scene:
        """The scene the world was built from (initial poses and states, the room)."""
        ...

    @property
    def config(self) -> WorldConfig:
        """Sensor and agent settings."""
        ...

    @property
    def state(self) -> WorldState:
        """The pure object state now: every object's states, containment, what is held."""
        ...

    @property
    def held(self) -> str | None:
        """The held object's id, if any."""
        ...

    @property
    def agent(self) -> AgentPose:
        """The agent's pose now."""
        ...

    @property
    def nav(self) -> NavGrid:
        """The grid points the agent can stand on."""
        ...

    def body_ids(self) -> frozenset[str]:
        """Ids of the objects that have a body now (a sliced object's slices, not the whole)."""
        ...

    def pose(self, object_id: str) -> tuple[np.ndarray, float]:
        """Base-link position (x, y, z) and yaw of an object now."""
        ...

    def aabb(self, object_id: str) -> tuple[np.ndarray, np.ndarray]:
        """World-axis bounding box (lo, hi) of an object now."""
        ...

    def main_colour(self, object_id: str) -> tuple[float, float, float] | None:
        """The RGB (0..1) of the object's main material slot, if it has one."""
        ...

    def distance(self, object_id: str) -> float:
        """Metres from the camera to the object's nearest point, as AI2-THOR measures it."""
        ...

    def frame(self) -> Frame:
        """RGB, depth and segmentation from the agent's camera now."""
        ...

    def instance_masks(self) -> dict[str, np.ndarray]:
        """Boolean mask of every object in the current frame."""
        ...

    def visible_objects(self) -> dict[str, int]:
        """Objects visible now (enough pixels, within the visibility distance), with their pixel counts."""
        ...

    def open_container_in_view(self, object_id: str) -> str | None:
        """The open container in view and reach that the object can be taken from, if any."""
        ...

    def unseeable(self) -> set[str]:
        """Objects to interact with that no sight line from any reachable pose meets."""
        ...

    def interaction_pose(self, object_id: str,
                         prefer: Callable[[AgentPose], bool] | None = None) -> AgentPose | None:
        """A reachable pose that sees the object within reach (with `prefer`, one passing it if any)."""
        ...

    def free_spot(self, object_id: str, receptacle: str, rng: np.random.Generator, *, assume_open: bool = False,
                  eye: tuple[float, float, float] | None = None,
                  also: tuple[tuple[str, Spot], ...] = ()) -> Spot | Failure:
        """A dry-run put: a free, stable pose for the object in the receptacle, or the failure a put
        would meet (`RECEPTACLE_FULL`, `NO_SPOT_IN_REACH`)."""
        ...

    def metadata(self) -> dict[str, Any]:
        """AI2-THOR-style metadata: agent, inventory, objects, last action result."""
        ...

    def top_down(self, path: np.ndarray | None = None, grid: bool = False) -> Image.Image:
        """A labelled top-down picture of the room now, with an agent `path` and the reachable `grid`."""
        ...


class LiveView:
    """The `WorldView` of a live World: every answer is read from the world when asked."""

    def __init__(self, world: World):
        self._world = world

    @property
    def scene(self) -> Scene:
        return self._world.scene

    @property
    def config(self) -> WorldConfig:
        return self._world.config

    @property
    def state(self) -> WorldState:
        return self._world.interactions.state

    @property
    def held(self) -> str | None:
        return self._world.interactions.held

    @property
    def agent(self) -> AgentPose:
        return self._world.agent

    @property
    def nav(self) -> NavGrid:
        return self._world.nav

    def body_ids(self) -> frozenset[str]:
        return frozenset(self._world.built.objects)

    def pose(self, object_id: str) -> tuple[np.ndarray, float]:
        return self._world.built.pose_of(object_id)

    def aabb(self, object_id: str) -> tuple[np.ndarray, np.ndarray]:
        return body_aabb(self._world.client, self._world.built.objects[object_id].body)

    def main_colour(self, object_id: str) -> tuple[float, float, float] | None:
        from luminous_sim.world.asset_loader import main_slot

        loaded = self._world.built.objects[object_id]
        slot = main_slot(loaded.entry)
        colour = next((c for (link, _), c in loaded.colors.items()
                       for v in loaded.entry.visuals if v["slot"] == slot and v["link"] == link), None)
        return None if colour is None else (colour[0], colour[1], colour[2])

    def distance(self, object_id: str) -> float:
        return self._world.object_distance(object_id)

    def frame(self) -> Frame:
        return self._world.frame()

    def instance_masks(self) -> dict[str, np.ndarray]:
        return self._world.instance_masks()

    def visible_objects(self) -> dict[str, int]:
        return self._world.visible_objects()

    def open_container_in_view(self, object_id: str) -> str | None:
        from luminous_sim.world.reach import open_container_in_view

        return open_container_in_view(self._world, self.state, object_id)

    def unseeable(self) -> set[str]:
        from luminous_sim.world.sightlines import world_unseen

        return world_unseen(self._world, self.state)

    def interaction_pose(self, object_id: str,
                         prefer: Callable[[AgentPose], bool] | None = None) -> AgentPose | None:
        """A reachable pose that sees the object within reach (see `poses.find_interaction_pose`). The
        agent is tried at candidate poses and put back, with what it holds, exactly where it was."""
        from luminous_sim.world.poses import find_interaction_pose

        return find_interaction_pose(self._world, object_id, prefer=prefer)

    def free_spot(self, object_id: str, receptacle: str, rng: np.random.Generator, *, assume_open: bool = False,
                  eye: tuple[float, float, float] | None = None,
                  also: tuple[tuple[str, Spot], ...] = ()) -> Spot | Failure:
        """A dry-run put (see `placement.find_spot`): nothing moves and the world's own random stream is
        left alone. Without `eye`, within reach and clear view of some place the agent can stand; with
        it, what a real put from there would find."""
        from luminous_sim.world.placement import find_spot

        return find_spot(self._world, self.state, object_id, receptacle, rng, dry_run=True, assume_open=assume_open,
                         eye=eye, also=also)

    def metadata(self) -> dict[str, Any]:
        return self._world.metadata()

    def top_down(self, path: np.ndarray | None = None, grid: bool = False) -> Image.Image:
        from luminous_sim.world.views import top_down

        w = self._world
        return top_down(w.built, grid=w.nav.points() if grid else None, path=path)
