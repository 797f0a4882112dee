"""Goals (and initial states) whose literals cannot hold together are refused at task.goal."""

from __future__ import annotations

import pytest

from luminous_sim.cdf import CDFValidationError, from_document
from tests.cdf.helpers import base

REFUSED = [
    ("(and (isHot apple) (isCool apple))", ["(isHot apple) and (isCool apple)", "heating deletes isCool"]),
    ("(and (isCold apple) (isHot apple))", ["(isCool apple) and (isHot apple)"]),
    ("(and (isClean plate) (isDirty plate))", ["(isClean plate) and (isDirty plate)"]),
    ("(and (isOpen fridge) (not (isOpen fridge)))", ["(isOpen fridge) and (not (isOpen fridge))", "its negation"]),
    ("(and (isOn toaster) (not (isToggled toaster)))", ["(isOn toaster) and (not (isToggled toaster))"]),
    ("(and (not (not (isHot apple))) (not (isHot apple)))", ["(isHot apple) and (not (isHot apple))"]),
    (
        "(and (inReceptacle apple fridge) (inReceptacle apple counter))",
        ["'apple' cannot be in both 'fridge' and 'counter'", "neither a Fridge nor a CounterTop"],
    ),
    ("(exists (?a - Apple) (and (isHot ?a) (isCool ?a)))", ["(isHot ?a) and (isCool ?a)"]),
    ("(and (isHot apple) (exists (?r) (isCool apple)))", ["(isHot apple) and (isCool apple)"]),
    ("(forall (?a - Apple) (and (isHot ?a) (isCool ?a)))", ["(isHot ?a) and (isCool ?a)"]),
]

ACCEPTED = [
    "(and (inReceptacle apple fridge) (isCool apple))",
    "(or (isHot apple) (isCool apple))",
    "(not (and (isHot apple) (isCool apple)))",
    # different objects, or variables that may name different objects
    "(and (isHot apple) (exists (?a - Apple) (isCool ?a)))",
    "(exists (?a ?b - Apple) (and (isHot ?a) (isCool ?b)))",
    "(and (inReceptacle apple fridge) (exists (?r - CounterTop) (inReceptacle apple ?r)))",
    # a bowl may stand on the counter with the apple in it: both are parents of the apple
    "(and (inReceptacle apple bowl) (inReceptacle apple counter))",
    # the same variable in two quantifiers is two variables
    "(and (exists (?a - Apple) (isHot ?a)) (exists (?a - Apple) (isCool ?a)))",
    # a forall over a type the scene does not declare holds vacuously
    "(forall (?p - Potato) (and (isHot ?p) (isCool ?p)))",
]


def _doc(goal: str) -> dict:
    doc = base()
    doc["scene"]["objects"] += [
        {"name": "bowl", "type": "Bowl"},
        {"name": "plate", "type": "Plate"},
        {"name": "toaster", "type": "Toaster"},
    ]
    doc["task"]["goal"] = goal
    return doc


@pytest.mark.parametrize(("goal", "fragments"), REFUSED, ids=[g for g, _ in REFUSED])
def test_contradictory_goal_is_refused(goal: str, fragments: list[str]) -> None:
    with pytest.raises(CDFValidationError) as info:
        from_document(_doc(goal), "kitchen.yaml")
    text = str(info.value)
    assert text.startswith("kitchen.yaml: task.goal: contradictory literals"), text
    for fragment in fragments:
        assert fragment in text, text


@pytest.mark.parametrize("goal", ACCEPTED)
def test_satisfiable_goal_is_accepted(goal: str) -> None:
    assert from_document(_doc(goal), "kitchen.yaml").task is not None


def test_contradictory_initial_state_is_refused() -> None:
    doc = _doc("(isCool apple)")
    doc["task"]["initial"] = "(and (isOpen fridge) (not (isOpen fridge)))"
    with pytest.raises(CDFValidationError, match=r"kitchen.yaml: task.initial: contradictory literals"):
        from_document(doc, "kitchen.yaml")

