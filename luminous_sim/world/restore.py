"""Putting a World back to the state it was built in, without building it again, exactly.

Why not PyBullet's `saveState`/`restoreState`: it brings back poses, velocities and joint positions, but not
the simulator's hidden state (the broadphase tree and its fattened boxes, the order of collision objects
and their proxy ids, the contact cache), and that state steers the physics that follows. Measured on a
generated kitchen: after restoring, the next put settles other objects up to 1e-6 m differently from a
world never restored, whenever the history before the restore moved a body or a link (picking up, opening,
or even a planner swinging a door to see where it would sweep). An environment whose outcome depends on
its history breaks `reset(seed=...)` determinism, so a world is restored only when its physics was never
touched: every client call that can change the simulation (anything but queries, ray tests, rendering
and visual colours) marks the world as touched (`WatchedClient`). What an untouched world can still have
changed is kept outside the simulator or is visual only: the agent's pose, the pure object state (with
what `set_up_dirty` made dirty), the put stream, the last action, and the colours of state visuals (on,
dirty, open); those the snapshot puts back as the builder left them.
"""

from __future__ import annotations

import copy
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.states.model import WorldState
from luminous_sim.world.agent import AgentPose
from luminous_sim.world.asset_loader import default_alpha, set_visual_alpha, show_state

if TYPE_CHECKING:
    from luminous_sim.world.world import World

HARMLESS_PREFIXES = ("get", "compute", "ray", "invert", "multiply", "calculate", "is")
"""Client calls that only read (queries, transforms, ray tests, rendering)."""
HARMLESS = frozenset({"changeVisualShape", "disconnect", "configureDebugVisualizer"})
"""Calls that change nothing the physics sees (colours are put back by `restore`)."""


class WatchedClient:
    """A PyBullet client that notes whether anything that steers the physics was called (`touched`)."""

    def __init__(self, client: Any):
        self._client = client
        self.touched = False

    def __getattr__(self, name: str) -> Any:
        attr = getattr(self._client, name)
        if name in HARMLESS or name.startswith(HARMLESS_PREFIXES) or not callable(attr):
            return attr
        return self._noting(attr)

    def _noting(self, call: Callable[..., Any]) -> Callable[..., Any]:
        def noted(*args: Any, **kwargs: Any) -> Any:
            self.touched = True
            return call(*args, **kwargs)
        return noted


@dataclass(frozen=True)
class StartSnapshot:
    """What an untouched world can have changed, as built."""

    pure: WorldState
    rng: np.random.Generator
    agent: AgentPose


def take_snapshot(world: World) -> StartSnapshot:
    """The world as it is now (right after building, before set-up and actions), to come back to."""
    return StartSnapshot(world.interactions.state, copy.deepcopy(world.interactions.rng), world.agent)


def restore(world: World, snap: StartSnapshot) -> None:
    """Put an untouched world back to the snapshot: state visuals as the builder left them (`load_asset`'s
    defaults, then `_apply_states`), the pure state, the put stream and the agent's pose."""
    c = world.client
    for obj in world.scene.objects:
        loaded = world.built.objects[obj.id]
        for vis in loaded.entry.visuals:
            if vis["state"] is not None:
                set_visual_alpha(c, loaded, vis["link"], vis["index"], default_alpha(vis["state"]))
        if obj.states.get("isToggled"):
            show_state(c, loaded, "on", True)
        if obj.states.get("isDirty"):
            show_state(c, loaded, "dirty", True)
    world.interactions.state = snap.pure
    world.interactions.rng = copy.deepcopy(snap.rng)
    world.agent = snap.agent
