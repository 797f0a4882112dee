"""Named groups of object types and action names, read once from `data/` (layer L0).

Every package takes these from here instead of keeping its own copy. ALFRED's groups come from
`data/alfred_vocab.json` (spec/alfred.md sections 1-3); the placement layers from
`data/object_layers.json`. Ordered groups are tuples (their order shows in messages and choices);
pure membership groups are frozensets.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from functools import cache
from importlib import resources
from types import MappingProxyType
from typing import Any

from luminous_sim.vocab.alfred import vocab_data


@cache
def object_layers_data() -> dict[str, Any]:
    """The raw placement-layer document (read once)."""
    text = resources.files("luminous_sim.vocab").joinpath("data/object_layers.json").read_text()
    return json.loads(text)


_D = vocab_data()
_ACTIONS = _D["actions"]
_LAYERS = object_layers_data()

# Object groups.

FILLABLE: frozenset[str] = frozenset(_D["fillable_thor"])
"""Vessels that fill with water under a running faucet (AI2-THOR's canFillWithLiquid types)."""

LAMPS: tuple[str, ...] = tuple(_D["toggleable"])
"""ALFRED's toggleable types, DeskLamp and FloorLamp: the toggle_target candidates of
look_at_obj_in_light, whose lit state a task checks from beside them."""

MOVABLE_RECEPTACLES: tuple[str, ...] = tuple(_D["movable_receptacles"])
"""ALFRED's MOVABLE_RECEPTACLES (the mrecep_target candidates)."""

SLICING_TOOLS: tuple[str, ...] = tuple(_D["slicing_tools"])
"""What the agent must hold to slice (ALFRED: any type whose name contains "Knife"); the first is the
one a task asks for when it needs a knife."""

BASINS: tuple[str, ...] = tuple(_D["basins"])
"""The basin parts of sinks and bathtubs (AI2-THOR ids `Sink|x|y|z|SinkBasin`)."""

PILING_RECEPTACLES: frozenset[str] = frozenset(MOVABLE_RECEPTACLES + BASINS)
"""Receptacles where things may pile up or rest across the rim when they do not fit side by side:
ALFRED's movable receptacles and the basins (not ALFRED's movable receptacles themselves)."""

HANGERS: frozenset[str] = frozenset(_D["hangers"])
"""Receptacles that things hang on (a bar, a ring, a spindle) rather than stand in."""

# Action names.

NAVIGATION_ACTIONS: tuple[str, ...] = tuple(_ACTIONS["navigation"])
"""ALFRED's five low-level navigation actions (spec section 2.2)."""

DISCRETE_NAVIGATION: Mapping[str, str] = MappingProxyType(
    dict(zip(NAVIGATION_ACTIONS, _ACTIONS["navigation_discrete"], strict=True))
)
"""Navigation action -> the name ALFRED records in `discrete_action` (`MoveAhead` -> `MoveAhead_25`)."""

INTERACTION_ACTIONS: tuple[str, ...] = tuple(_ACTIONS["interaction"])
"""ALFRED's seven low-level interaction actions (spec section 2.2)."""

HIGH_LEVEL_ACTIONS: tuple[str, ...] = tuple(_ACTIONS["high_level"])
"""ALFRED's high-level planner actions (its `End` is not listed)."""

ALFRED_TASK_TYPES: tuple[str, ...] = tuple(_D["task_types"])
"""ALFRED's seven task types, in its order."""

ALFRED_TASK_ROOMS: Mapping[str, frozenset[str]] = MappingProxyType(
    {t: frozenset(_D["task_rooms"][t]) for t in ALFRED_TASK_TYPES}
)
"""ALFRED task type -> the room types its generator places it in (spec/alfred.md, section 1)."""

NOOP_ACTION: str = _ACTIONS["noop"]
"""The action that does nothing (ALFRED's `End` records it as its discrete action)."""

TELEPORT_ACTIONS: tuple[str, ...] = tuple(_ACTIONS["teleport_thor"])
"""AI2-THOR's teleports: put the agent at a pose directly."""

STATE_NEUTRAL_ACTIONS: tuple[str, ...] = NAVIGATION_ACTIONS + (NOOP_ACTION,)
"""Low-level actions that change no object state: the state rules allow them and give no effect."""

AGENT_ACTIONS: tuple[str, ...] = NAVIGATION_ACTIONS + TELEPORT_ACTIONS + (_ACTIONS["pass_thor"], NOOP_ACTION)
"""Every simulator action that moves the agent or waits, touching no object (navigation, AI2-THOR's
teleports and Pass, and the no-op)."""

# Placement layers (two classifications with different jobs; see data/object_layers.json).

STRUCTURE_TYPES: frozenset[str] = frozenset(_LAYERS["cdf_layers"]["structure"])
"""Types that belong to the room itself (the CDF's structure layer)."""

DECORATION_TYPES: frozenset[str] = frozenset(_LAYERS["cdf_layers"]["decoration"])
"""Types placed last, on walls or windows (the CDF's decoration layer)."""

FIXTURE_TYPES: frozenset[str] = frozenset(_LAYERS["generation_layers"]["fixture"])
"""Types CSSG takes from a room's fixture plan (counters, sinks, fridge, toilet, tub, shower)."""

FURNITURE_TYPES: frozenset[str] = frozenset(_LAYERS["generation_layers"]["furniture"])
"""Types CSSG stands on the floor as furniture."""

WALL_TYPES: frozenset[str] = frozenset(_LAYERS["generation_layers"]["wall"])
"""Types CSSG can hang on a wall."""
