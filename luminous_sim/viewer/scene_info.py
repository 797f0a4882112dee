"""What the viewer's panel says about a scene, pure: each object's id, type, state and support, the rooms'
labels and where they go, the agent's reachable grid."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from shapely.geometry import Polygon

from luminous_sim.scene import Scene, scene_reachable_grid

HIDDEN_STATES = ("parentReceptacle", "receptacleObjectIds")
"""States the panel shows as the support line, not in the state line."""


@dataclass(frozen=True)
class ObjectInfo:
    """One object as the panel shows it."""

    object_id: str
    object_type: str
    state: str
    """`isOpen: yes, isDirty: no`, or "-" when the object has no state."""
    support: str
    """What it rests on or in (`CounterTop|...`, with the region), else `floor` or `wall`."""

    def markdown(self) -> str:
        """The panel's text for it."""
        return (f"**id** `{self.object_id}`  \n**type** {self.object_type}  \n**state** {self.state}  \n"
                f"**support** {self.support}")


def _state_text(states: dict[str, Any]) -> str:
    parts = []
    for key in sorted(states):
        if key in HIDDEN_STATES:
            continue
        value = states[key]
        parts.append(f"{key}: {'yes' if value is True else 'no' if value is False else value}")
    return ", ".join(parts) or "-"


def object_infos(scene: Scene, live_states: dict[str, dict[str, Any]] | None = None,
                 live_types: dict[str, str] | None = None) -> dict[str, ObjectInfo]:
    """The panel's facts for every object of `scene` (and every body of the built world in `live_states`,
    slices of a sliced thing included): scene.json's states, overlaid by the world's where given."""
    live_states = live_states or {}
    live_types = live_types or {}
    out: dict[str, ObjectInfo] = {}
    for o in scene.objects:
        states: dict[str, Any] = dict(o.states)
        states.update(live_states.get(o.id, {}))
        if o.parent is not None:
            support = f"`{o.parent}`" + (f" ({o.region})" if o.region else "")
        else:
            support = "floor" if o.position[2] < 0.05 or o.layer in ("furniture", "fixture") else "wall"
        out[o.id] = ObjectInfo(o.id, o.type, _state_text(states), support)
    for oid, states in live_states.items():
        if oid not in out:
            parent = states.get("parentReceptacle")
            out[oid] = ObjectInfo(oid, live_types.get(oid, oid.split("|")[0]), _state_text(states),
                                  f"`{parent}`" if parent else "-")
    return out


@dataclass(frozen=True)
class RoomLabel:
    """A room's name where it is drawn (the middle of its floor)."""

    text: str
    position: tuple[float, float]


def room_labels(scene: Scene) -> list[RoomLabel]:
    """One label per room of a house (its name and type), or the room's own for a single room."""
    shell = scene.room
    if shell.house is not None:
        rooms = [(f"{r.name} ({r.room_type})", r.polygon()) for r in shell.house.rooms]
    else:
        rooms = [(f"{shell.name} ({shell.room_type})", Polygon(shell.outline))]
    out = []
    for text, poly in rooms:
        p = poly.representative_point()
        out.append(RoomLabel(text, (float(p.x), float(p.y))))
    return out


def reachable_points(scene: Scene) -> np.ndarray:
    """The agent's reachable 0.25 m grid as (N, 2) floor points (the generator's and the simulator's rule)."""
    return np.asarray(scene_reachable_grid(scene), dtype=float).reshape(-1, 2)


def bounds(scene: Scene) -> tuple[tuple[float, float], tuple[float, float]]:
    """The floor's (min x, min y), (max x, max y)."""
    xs = [p[0] for p in scene.room.outline]
    ys = [p[1] for p in scene.room.outline]
    return (min(xs), min(ys)), (max(xs), max(ys))
