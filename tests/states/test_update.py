"""`apply`: each effect's pure update, and the errors for effects that do not fit the state."""

from __future__ import annotations

import pytest

from luminous_sim.scene.ids import type_of_id
from luminous_sim.states import (
    Attach,
    MoveJoint,
    Record,
    Release,
    SetState,
    ShowVisual,
    Slice,
    StateError,
    apply,
)
from luminous_sim.states.tables import DEFAULT_SLICE_COUNTS, SLICE_OF, slice_id
from luminous_sim.vocab import SLICED_TYPES, abilities
from tests.states.kitchen import diff, kitchen


def test_each_effect():
    s = kitchen()
    assert apply(s, []) == s
    assert apply(s, [MoveJoint("Fridge|1", True), ShowVisual("Faucet|1", "on", True)]) == s
    assert diff(s, apply(s, [SetState("Apple|1", "temperature", "Hot")])) == {"Apple|1": {"temperature": "Hot"}}
    assert apply(s, [Record("heated", "Apple|1"), Record("heated", "Apple|1")]).heated == {"Apple|1"}
    assert apply(s, [Attach("Apple|1")]).held == "Apple|1"
    h = kitchen(held="Mug|1")
    assert apply(h, [Release("Mug|1", "CounterTop|1")]).held is None
    assert apply(h, [Release("Apple|1", "CounterTop|1")]).held == "Mug|1"
    sl = apply(s, [Slice("Potato|1", "PotatoSliced", 2)])
    assert sl.of_type("PotatoSliced") == ["Potato|1|PotatoSliced_1", "Potato|1|PotatoSliced_2"]


@pytest.mark.parametrize(
    ("effect", "message"),
    [
        (SetState("Apple|9", "isOpen", True), "SetState: unknown object id 'Apple|9'"),
        (Record("cooled", "Apple|9"), "Record: unknown object id"),
        (Slice("Apple|9", "AppleSliced"), "Slice: unknown object id"),
        (Attach("Apple|9"), "Attach: unknown object id"),
        (MoveJoint("Apple|9", True), "MoveJoint: unknown object id"),
        (SetState("Apple|1", "temperature", "Warm"), "temperature 'Warm'"),
    ],
)
def test_bad_effects_raise(effect, message):
    with pytest.raises(StateError, match=message.replace("|", r"\|")):
        apply(kitchen(), [effect])


def test_effect_values_validate():
    with pytest.raises(StateError, match="not a state field"):
        SetState("Apple|1", "isHot", True)
    with pytest.raises(StateError, match="not one of heated"):
        Record("warmed", "Apple|1")  # type: ignore[arg-type]
    with pytest.raises(StateError, match="not one of on"):
        ShowVisual("Mug|1", "broken", True)  # type: ignore[arg-type]
    with pytest.raises(StateError, match="at least one slice"):
        Slice("Apple|1", "AppleSliced", 0)
    with pytest.raises(StateError, match="not an effect"):
        apply(kitchen(), ["PickupObject"])  # type: ignore[list-item]


def test_slicing_a_held_object_is_refused():
    with pytest.raises(StateError, match="is held"):
        apply(kitchen(held="Apple|1"), [Slice("Apple|1", "AppleSliced", 2)])


def test_slice_tables_agree_with_the_vocabulary_and_scene_ids():
    assert {SLICE_OF[p] for p in SLICE_OF} == set(SLICED_TYPES)
    assert set(DEFAULT_SLICE_COUNTS) == set(SLICE_OF)
    assert all(abilities(p).sliceable for p in SLICE_OF) and abilities("Egg").sliceable and "Egg" not in SLICE_OF
    for i in range(3):
        sid = slice_id("Apple|+00.46|+00.82|+02.27", "AppleSliced", i)
        assert sid == f"Apple|+00.46|+00.82|+02.27|AppleSliced_{i + 1}" and type_of_id(sid) == "AppleSliced"
