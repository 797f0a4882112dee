"""Pure object states (AI2-THOR metadata) and the world state the rules read and the effects update.

Nothing here knows about physics: a `WorldState` is a value (frozen, hashable) that names every
object's state, what contains what (`parent`), what the agent holds, and ALFRED's bookkeeping sets.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import Any, Literal, get_args

from luminous_sim.errors import LuminousError
from luminous_sim.vocab import MOVABLE_RECEPTACLES, check_type

Temperature = Literal["RoomTemp", "Hot", "Cold"]
TEMPERATURES: tuple[str, ...] = get_args(Temperature)
BookkeepingKind = Literal["heated", "cooled", "cleaned"]
BOOKKEEPING_KINDS: tuple[str, ...] = get_args(BookkeepingKind)


class StateError(LuminousError, KeyError):
    """A state or effect that breaks the state layer's contract (unknown id, bad field, misuse)."""

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return str(self.args[0]) if self.args else ""


@dataclass(frozen=True)
class ObjectState:
    """One object's AI2-THOR-style state.

    Attributes:
        object_id: AI2-THOR style id, e.g. ``Apple|+00.46|+00.82|+02.27``.
        object_type: a vocabulary type (checked on construction).
        parent: the id of the receptacle the object is in/on, or None (on the floor, held, fixed).
    """

    object_id: str
    object_type: str
    isOpen: bool = False
    isToggled: bool = False
    isDirty: bool = False
    isSliced: bool = False
    temperature: Temperature = "RoomTemp"
    isCooked: bool = False
    isFilledWithLiquid: bool = False
    isPickedUp: bool = False
    parent: str | None = None

    def __post_init__(self) -> None:
        check_type(self.object_type, where=self.object_id)
        if self.temperature not in TEMPERATURES:
            raise StateError(
                f"{self.object_id}: temperature {self.temperature!r} "
                f"is not one of {', '.join(TEMPERATURES)}"
            )
        if self.parent == self.object_id:
            raise StateError(f"{self.object_id} cannot be its own parent")

    def __repr__(self) -> str:
        extra = "".join(
            f", {f.name}={getattr(self, f.name)!r}"
            for f in dataclasses.fields(self)
            if f.name not in ("object_id", "object_type") and getattr(self, f.name) != f.default
        )
        return f"ObjectState({self.object_id!r}, {self.object_type!r}{extra})"

    def replace(self, **changes: Any) -> ObjectState:
        """A copy with some fields changed (validated again)."""
        return dataclasses.replace(self, **changes)


STATE_FIELDS: tuple[str, ...] = tuple(
    f.name for f in dataclasses.fields(ObjectState) if f.name not in ("object_id", "object_type")
)
"""The ObjectState fields an effect may set."""


def _frozen_map(m: Mapping[str, Any]) -> Mapping[str, Any]:
    return MappingProxyType(dict(m))


@dataclass(frozen=True)
class WorldState:
    """Every object's state plus what the agent holds and ALFRED's bookkeeping sets.

    Attributes:
        objects: object id -> ObjectState (keys must equal the objects' ids).
        held: the id of the object in the agent's hand, or None.
        heated: ids that were inside a microwave (or on a burner) when it was switched on.
        cooled: ids that were inside a fridge when its door was closed.
        cleaned: ids that were in a sink basin when its faucet was switched on.
        controls: StoveKnob id -> the StoveBurner id it switches (decided by the world).
        faucet_basin: Faucet id -> the SinkBasin/BathtubBasin id it serves (decided by the world).
        slice_counts: sliceable object id -> how many slices its asset breaks into; objects not
            listed use `tables.DEFAULT_SLICE_COUNTS`.
    """

    objects: Mapping[str, ObjectState]
    held: str | None = None
    heated: frozenset[str] = frozenset()
    cooled: frozenset[str] = frozenset()
    cleaned: frozenset[str] = frozenset()
    controls: Mapping[str, str] = field(default_factory=dict)
    faucet_basin: Mapping[str, str] = field(default_factory=dict)
    slice_counts: Mapping[str, int] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name in ("objects", "controls", "faucet_basin", "slice_counts"):
            object.__setattr__(self, name, _frozen_map(getattr(self, name)))
        for name in BOOKKEEPING_KINDS:
            object.__setattr__(self, name, frozenset(getattr(self, name)))
        for key, obj in self.objects.items():
            if key != obj.object_id:
                raise StateError(f"objects[{key!r}] holds the state of {obj.object_id!r}")
        if self.held is not None and self.held not in self.objects:
            raise StateError(f"held object {self.held!r} is not in the world")

    def __hash__(self) -> int:
        return hash(
            (
                frozenset(self.objects.items()),
                self.held,
                self.heated,
                self.cooled,
                self.cleaned,
                frozenset(self.controls.items()),
                frozenset(self.faucet_basin.items()),
                frozenset(self.slice_counts.items()),
            )
        )

    def __repr__(self) -> str:
        parts = [f"[{', '.join(map(repr, self.objects.values()))}]"]
        for name in ("held", *BOOKKEEPING_KINDS, "controls", "faucet_basin", "slice_counts"):
            value = getattr(self, name)
            if value:
                value = dict(value) if isinstance(value, Mapping) else value
                parts.append(f"{name}={sorted(value) if isinstance(value, frozenset) else value!r}")
        return f"WorldState.of({', '.join(parts)})"

    @classmethod
    def of(cls, objects: Iterable[ObjectState], **kwargs: Any) -> WorldState:
        """Build a state from a list of objects (ids taken from the objects)."""
        return cls({o.object_id: o for o in objects}, **kwargs)

    def get(self, object_id: str | None) -> ObjectState | None:
        """The object's state, or None when there is no such object (like `dict.get`)."""
        return self.objects.get(object_id) if object_id is not None else None

    def __getitem__(self, object_id: str) -> ObjectState:
        try:
            return self.objects[object_id]
        except KeyError:
            raise StateError(f"unknown object id {object_id!r}") from None

    def __contains__(self, object_id: object) -> bool:
        return object_id in self.objects

    def of_type(self, object_type: str) -> list[str]:
        """Ids of the objects of exactly this type, in insertion order."""
        return [k for k, o in self.objects.items() if o.object_type == object_type]

    @cached_property
    def _children(self) -> dict[str, list[str]]:
        out: dict[str, list[str]] = {}
        for k, o in self.objects.items():
            if o.parent is not None:
                out.setdefault(o.parent, []).append(k)
        return out

    def contents(self, receptacle_id: str, recursive: bool = False) -> list[str]:
        """Objects whose parent is the receptacle; `recursive` adds what those hold, depth first.

        An apple on a plate in the fridge is in `contents(fridge, recursive=True)` but not in
        `contents(fridge)`.
        """
        direct = list(self._children.get(receptacle_id, ()))
        if not recursive:
            return direct
        out: list[str] = []
        seen = {receptacle_id}
        stack = direct[::-1]
        while stack:
            oid = stack.pop()
            if oid in seen:
                continue
            seen.add(oid)
            out.append(oid)
            stack.extend(self._children.get(oid, ())[::-1])
        return out

    def ancestors(self, object_id: str) -> list[str]:
        """The receptacles holding the object, innermost first (stops at a missing id, a cycle)."""
        out: list[str] = []
        obj = self.objects.get(object_id)
        while (
            obj is not None
            and obj.parent is not None
            and obj.parent not in out
            and obj.parent != object_id
        ):
            out.append(obj.parent)
            obj = self.objects.get(obj.parent)
        return out

    def parent_receptacles(self, object_id: str) -> list[str]:
        """The receptacles an object counts as in, innermost first (AI2-THOR's `parentReceptacles`): its
        ancestors, cut after the first that is not a movable receptacle (an apple in a bowl in a fridge is in
        the bowl and the fridge, as the fridge's receptacle volume holds both)."""
        out: list[str] = []
        for anc in self.ancestors(object_id):
            out.append(anc)
            if self.objects[anc].object_type not in MOVABLE_RECEPTACLES:
                break
        return out

    def without(self, excluded: set[str] | frozenset[str]) -> WorldState:
        """The state with some objects (and everything resting on or in them) left out; the held
        object is never left out."""
        if not excluded:
            return self
        gone = {k for k in self.objects if k != self.held and (
            k in excluded or any(a in excluded for a in self.ancestors(k)))}
        return self.replace(objects={k: v for k, v in self.objects.items() if k not in gone})

    def replace(self, **changes: Any) -> WorldState:
        """A copy with some fields changed."""
        return dataclasses.replace(self, **changes)

    def with_object(self, object_id: str, **changes: Any) -> WorldState:
        """A copy in which one object's fields are changed."""
        objects = dict(self.objects)
        objects[object_id] = self[object_id].replace(**changes)
        return self.replace(objects=objects)

    def problems(self) -> list[str]:
        """Broken invariants, as messages (empty when the state is consistent).

        Checked: the held object exists, is marked picked up and has no parent; no other object is
        marked picked up; every parent exists; no object is its own ancestor.
        """
        out: list[str] = []
        if self.held is not None:
            h = self.objects.get(self.held)
            if h is None:
                out.append(f"held object {self.held} does not exist")
            elif h.parent is not None or not h.isPickedUp:
                out.append(f"held object {self.held} must have isPickedUp and no parent")
        for k, o in self.objects.items():
            if o.isPickedUp and k != self.held:
                out.append(f"{k} is marked picked up but not held")
            if o.parent is not None and o.parent not in self.objects:
                out.append(f"{k} has a parent {o.parent} that does not exist")
        for k in self.objects:
            seen = {k}
            p = self.objects[k].parent
            while p is not None and p in self.objects:
                if p in seen:
                    out.append(f"{k}: its chain of receptacles loops back at {p}")
                    break
                seen.add(p)
                p = self.objects[p].parent
        return out
