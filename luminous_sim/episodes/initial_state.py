"""ALFRED's set-up of a world for an episode, the only copy: `alfred_set_up` says which objects start dirty
(for cleaning, every dirtyable object that can be picked up, as ALFRED's `dirty_and_empty` initialisation
does) and makes them so; `prepare` puts a world in a spec's initial state (those objects dirty, the agent at
its start). Where worlds come from is a `WorldSource` (the env's pool, or `FreshWorlds`)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

from luminous_sim.scene import Scene
from luminous_sim.world import AgentPose, World, WorldConfig

if TYPE_CHECKING:
    from luminous_sim.episodes.spec import EpisodeSpec


class WorldSource(Protocol):
    """Where worlds come from, set up for an episode, and go back to when done."""

    def get(self, scene: Scene, dirty: tuple[str, ...] = (), start: AgentPose | None = None) -> World:
        """A world of the scene at its start, prepared: `dirty` made dirty and the agent at `start` (if given)."""
        ...

    def put(self, world: World) -> None:
        """Give a world back (the source keeps or closes it)."""
        ...


def set_initial(world: World, dirty: Sequence[str] = (), start: AgentPose | None = None) -> World:
    """Make `dirty` dirty and put the agent at `start` (unchanged where none is given); the world."""
    if dirty:
        world.set_up_dirty(dirty)
    if start is not None:
        world.set_start(start)
    return world


def prepare(world: World, spec: EpisodeSpec) -> World:
    """Put a world of the spec's scene, as built, in the spec's initial state; the world."""
    return set_initial(world, spec.dirty, spec.start)


def alfred_set_up(world: World, task_type: str) -> tuple[str, ...]:
    """ALFRED's set-up of `world` for a task of the type: the objects it made dirty (none but for cleaning)."""
    from luminous_sim.tasks import alfred_dirty

    dirty = alfred_dirty(world.view().state, task_type)
    set_initial(world, dirty)
    return dirty


class FreshWorlds:
    """A `WorldSource` that builds a new world for every `get` and closes it on `put` (at `config`'s camera,
    ALFRED's by default)."""

    def __init__(self, config: WorldConfig | None = None):
        self.config = config

    def get(self, scene: Scene, dirty: tuple[str, ...] = (), start: AgentPose | None = None) -> World:
        return set_initial(World(scene, self.config), dirty, start)

    def put(self, world: World) -> None:
        world.close()
