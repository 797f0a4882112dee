"""`WorldPool`: an environment's worlds, built once per scene and reused (`World.reset_to_start`) while
episodes stay in that scene: the agent's world, the expert's proof and its replanning shadows.

A world given back is kept only if it can be put back exactly as built (its physics was never touched:
the episode only looked around and walked, or its actions failed); then the next episode in the scene
plays exactly as in a new world. Any other world is closed, and the next one is built anew.
"""

from __future__ import annotations

from typing import Literal, cast

from luminous_sim.env.config import EnvConfig
from luminous_sim.episodes import WorldSource, set_initial
from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose, World, WorldConfig

MAX_IDLE = 2
"""Restored worlds kept for the current scene (the agent's and the expert's; each is a PyBullet client)."""


def world_config(config: EnvConfig) -> WorldConfig:
    """The simulator settings of an environment."""
    return WorldConfig(width=config.width, height=config.height, min_visible_pixels=config.visible_pixels,
                       rasteriser=cast(Literal["compiled", "tinyrenderer"], config.rasteriser))


__all__ = ["MAX_IDLE", "WorldPool", "WorldSource", "world_config"]


class WorldPool:
    """A `WorldSource`: worlds of one scene at their start, handed out again; `builds` and `reuses` count them."""

    def __init__(self, config: EnvConfig):
        self.config = config
        self._scene: Scene | None = None
        self._idle: list[World] = []
        self.builds = 0
        self.reuses = 0

    def get(self, scene: Scene, dirty: tuple[str, ...] = (), start: AgentPose | None = None) -> World:
        """A world of the scene at its start (a kept one, else a new one), set up: dirty objects, and the
        agent at `start` (else the world's default start)."""
        if not self._same(scene):
            self.clear()
            self._scene = scene
        if self._idle:
            world = self._idle.pop()
            self.reuses += 1
        else:
            world = World(scene, world_config(self.config))
            self.builds += 1
        return set_initial(world, dirty, start)

    @property
    def kept(self) -> int:
        """Worlds kept at their start, ready to hand out again."""
        return len(self._idle)

    def put(self, world: World) -> None:
        """Give a world back: kept at its start if it is of the current scene and can be restored, else closed."""
        if (world.client is not None and self._same(world.scene) and len(self._idle) < MAX_IDLE
                and world.reset_to_start()):
            self._idle.append(world)
        else:
            world.close()

    def clear(self) -> None:
        """Close every kept world."""
        for world in self._idle:
            world.close()
        self._idle = []
        self._scene = None

    def _same(self, scene: Scene) -> bool:
        return self._scene is not None and (scene is self._scene or scene == self._scene)
