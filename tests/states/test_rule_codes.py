"""`rules.failure`: every rule that refuses an action says why with a `FailureCode`, and its message is
exactly what `rules.check` reports."""

from __future__ import annotations

import pytest

from luminous_sim.errors import FailureCode
from luminous_sim.states import rules
from tests.states.kitchen import kitchen
from tests.states.test_rules import IN_CLOSED_FRIDGE, ROWS

# (code, changes, held, action, target, receptacle): one refused action per code the rules produce
CODES = [
    (FailureCode.UNKNOWN_ACTION, {}, None, "Jump", "Apple|1", None),
    (FailureCode.UNKNOWN_ACTION, {}, "Apple|1", "HeatObject", "Apple|1", "Microwave|1"),
    (FailureCode.NO_TARGET, {}, None, "PickupObject", None, None),
    (FailureCode.NO_TARGET, {}, "Apple|1", "PutObject", "Apple|1", None),
    (FailureCode.UNKNOWN_OBJECT, {}, None, "PickupObject", "Apple|9", None),
    (FailureCode.NOT_PICKUPABLE, {}, None, "PickupObject", "Fridge|1", None),
    (FailureCode.NOT_OPENABLE, {}, None, "OpenObject", "Apple|1", None),
    (FailureCode.NOT_TOGGLEABLE, {}, None, "ToggleObjectOn", "Apple|1", None),
    (FailureCode.NOT_SLICEABLE, {}, "Knife|1", "SliceObject", "Fridge|1", None),
    (FailureCode.NOT_A_RECEPTACLE, {}, "Mug|1", "PutObject", "Mug|1", "Apple|1"),
    (FailureCode.HANDS_FULL, {}, "Mug|1", "PickupObject", "Apple|1", None),
    (FailureCode.NOT_HOLDING, {}, None, "PutObject", "Apple|1", "CounterTop|1"),
    (FailureCode.CLOSED, {}, "Apple|1", "PutObject", "Apple|1", "Fridge|1"),
    (FailureCode.SHUT_IN, IN_CLOSED_FRIDGE, None, "PickupObject", "Apple|1", None),
    (FailureCode.INCOMPATIBLE, {"Microwave|1": {"isOpen": True}}, "Knife|1", "PutObject", "Knife|1", "Microwave|1"),
    (FailureCode.INCOMPATIBLE, {}, "Plate|1", "PutObject", "Plate|1", "Plate|1"),
    (FailureCode.ALREADY_DONE, {}, None, "CloseObject", "Fridge|1", None),
    (FailureCode.MUST_BE_CLOSED, {"Microwave|1": {"isOpen": True}}, None, "ToggleObjectOn", "Microwave|1", None),
    (FailureCode.NEEDS_TOOL, {}, None, "SliceObject", "Apple|1", None),
]


@pytest.mark.parametrize("code, changes, held, action, target, receptacle", CODES,
                         ids=[f"{c[0].value}-{c[3]}" for c in CODES])
def test_each_rule_failure_has_its_code(code, changes, held, action, target, receptacle):
    state = kitchen(changes, held=held)
    got = rules.failure(action, state, target, receptacle)
    assert got is not None and got.code == code, got
    assert got.message == rules.check(action, state, target, receptacle)


@pytest.mark.parametrize("row", ROWS, ids=[r[0] for r in ROWS])
def test_every_refusal_of_the_rule_table_has_a_code(row):
    _, changes, held, action, target, receptacle, expected = row
    got = rules.failure(action, kitchen(changes, held=held), target, receptacle)
    if expected is None:
        assert got is None
    else:
        assert isinstance(got.code, FailureCode) and expected in got.message
