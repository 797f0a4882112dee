"""Effect values: what an allowed action changes.

The world applies each effect to the physics; `apply` applies them to the `WorldState`.

Pure-state effects (`SetState`, `Record`, `Slice`, `Attach`, `Release`) change the `WorldState`;
physical-only effects (`MoveJoint`, `ShowVisual`) leave it alone, since the `SetState` beside
them says the same thing in state terms.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal, get_args

from luminous_sim.states.model import BOOKKEEPING_KINDS, STATE_FIELDS, BookkeepingKind, StateError

Visual = Literal["on", "dirty"]
VISUALS: tuple[str, ...] = get_args(Visual)


@dataclass(frozen=True)
class SetState:
    """Set one ObjectState field (`isOpen`, `temperature`, `parent`, ...) of an object."""

    object_id: str
    field: str
    value: Any

    def __post_init__(self) -> None:
        if self.field not in STATE_FIELDS:
            raise StateError(
                f"SetState: {self.field!r} is not a state field; "
                f"expected one of {', '.join(STATE_FIELDS)}"
            )


@dataclass(frozen=True)
class Record:
    """Add an object to one of ALFRED's bookkeeping sets (heated, cooled, cleaned)."""

    kind: BookkeepingKind
    object_id: str

    def __post_init__(self) -> None:
        if self.kind not in BOOKKEEPING_KINDS:
            raise StateError(f"Record: {self.kind!r} is not one of {', '.join(BOOKKEEPING_KINDS)}")


@dataclass(frozen=True)
class Slice:
    """Replace an object by `count` slices of `sliced_type`.

    Slice ids are ``<object_id>|<sliced_type>_<k>`` with k from 1 (ALFRED's).

    The slices take the object's parent, temperature and cooked state, and are isSliced.
    """

    object_id: str
    sliced_type: str
    count: int = 1

    def __post_init__(self) -> None:
        if self.count < 1:
            raise StateError(
                f"Slice: {self.object_id} must break into at least one slice, not {self.count}"
            )


@dataclass(frozen=True)
class MoveJoint:
    """Drive an openable object's door/drawer/lid joints fully open or closed (physical only)."""

    object_id: str
    open: bool


@dataclass(frozen=True)
class ShowVisual:
    """Show or hide a state visual: "on" (a lit element, running water) or "dirty" (a stain).

    Physical only.
    """

    object_id: str
    state: Visual
    visible: bool

    def __post_init__(self) -> None:
        if self.state not in VISUALS:
            raise StateError(f"ShowVisual: {self.state!r} is not one of {', '.join(VISUALS)}")


@dataclass(frozen=True)
class Attach:
    """The object (with what it carries) goes into the agent's hand."""

    object_id: str
    holder: Literal["agent"] = "agent"


@dataclass(frozen=True)
class Release:
    """The held object leaves the hand and is placed in/on the receptacle."""

    object_id: str
    receptacle_id: str


Effect = SetState | Record | Slice | MoveJoint | ShowVisual | Attach | Release
"""Any effect value."""
