"""Fold effects into a new WorldState: the pure half of carrying out an action."""

from __future__ import annotations

from collections.abc import Iterable

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
from luminous_sim.states.model import BOOKKEEPING_KINDS, ObjectState, StateError, WorldState
from luminous_sim.states.tables import slice_id


def _need(objects: dict[str, ObjectState], object_id: str, effect: Effect) -> ObjectState:
    try:
        return objects[object_id]
    except KeyError:
        raise StateError(f"{type(effect).__name__}: unknown object id {object_id!r}") from None


def _slice(objects: dict[str, ObjectState], e: Slice) -> None:
    whole = objects.pop(e.object_id)
    for i in range(e.count):
        sid = slice_id(e.object_id, e.sliced_type, i)
        objects[sid] = ObjectState(
            sid,
            e.sliced_type,
            isSliced=True,
            temperature=whole.temperature,
            isCooked=whole.isCooked,
            parent=whole.parent,
        )
    for (
        k,
        o,
    ) in objects.items():  # nothing rests in a sliceable today; keep parents valid if it ever does
        if o.parent == e.object_id:
            objects[k] = o.replace(parent=whole.parent)


def apply(state: WorldState, effects: Iterable[Effect]) -> WorldState:
    """The state after the effects, applied in order.

    `SetState` sets a field, `Record` adds to a bookkeeping set, `Slice` replaces the object by its
    slices (bookkeeping sets keep the old id, as in ALFRED), `Attach`/`Release` set/clear `held`;
    `MoveJoint` and `ShowVisual` are physical only.

    Raises:
        StateError: an effect names an object that does not exist (or a bad value for a field).
    """
    objects = dict(state.objects)
    held = state.held
    books = {k: set(getattr(state, k)) for k in BOOKKEEPING_KINDS}
    for e in effects:
        if isinstance(e, SetState):
            objects[e.object_id] = _need(objects, e.object_id, e).replace(**{e.field: e.value})
        elif isinstance(e, Record):
            _need(objects, e.object_id, e)
            books[e.kind].add(e.object_id)
        elif isinstance(e, Slice):
            _need(objects, e.object_id, e)
            if held == e.object_id:
                raise StateError(f"Slice: {e.object_id} is held; put it down first")
            _slice(objects, e)
        elif isinstance(e, Attach):
            _need(objects, e.object_id, e)
            held = e.object_id
        elif isinstance(e, Release):
            _need(objects, e.object_id, e)
            if held == e.object_id:
                held = None
        elif isinstance(e, (MoveJoint, ShowVisual)):
            _need(objects, e.object_id, e)
        else:
            raise StateError(f"not an effect: {e!r}")
    return state.replace(objects=objects, held=held, **{k: frozenset(v) for k, v in books.items()})
