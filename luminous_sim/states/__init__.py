"""Layer L1: ALFRED's object-state rules, pure (no physics).

`rules.check(action, state, target, receptacle)` says whether an interaction is allowed;
`rules.effects(...)` lists what it changes (values from `effects`, which the world applies to
the physics);
`apply(state, effects)` gives the new `WorldState`; `step` does all three.
"""

from luminous_sim.states import effects, rules
from luminous_sim.states.effects import (
    Attach,
    Effect,
    MoveJoint,
    Record,
    Release,
    SetState,
    ShowVisual,
    Slice,
)
from luminous_sim.states.model import STATE_FIELDS, ObjectState, StateError, Temperature, WorldState
from luminous_sim.states.rules import check, enclosing_closed, step
from luminous_sim.states.scene_state import scene_state
from luminous_sim.states.update import apply

__all__ = [
    "STATE_FIELDS",
    "Attach",
    "Effect",
    "MoveJoint",
    "ObjectState",
    "Record",
    "Release",
    "SetState",
    "ShowVisual",
    "Slice",
    "StateError",
    "Temperature",
    "WorldState",
    "apply",
    "check",
    "effects",
    "enclosing_closed",
    "rules",
    "scene_state",
    "step",
]
