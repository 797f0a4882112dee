"""The pure object state (`luminous_sim.states`) of a freshly built world (`states.scene_state` of its scene and
asset library)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.states import WorldState, scene_state

if TYPE_CHECKING:
    from luminous_sim.world.world import World


def initial_state(world: World) -> WorldState:
    """The pure state of a freshly built scene."""
    return scene_state(world.scene, world.catalog)
