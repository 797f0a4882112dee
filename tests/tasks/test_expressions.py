"""`goal_satisfied` on any expression: quantifiers, connectives, names, slices; `parents` semantics."""

from __future__ import annotations

import pytest

from luminous_sim.cdf import Atom, parse_expr
from luminous_sim.cdf.predicates import PREDICATES
from luminous_sim.states import Slice, apply
from luminous_sim.tasks import TaskError, conjunct_progress, goal_satisfied, parents
from luminous_sim.tasks.meanings import MEANINGS
from tests.tasks.helpers import KITCHEN, state_of

K = state_of(KITCHEN)
NAMES = {
    "apple": "Apple|1",
    "fridge": "Fridge|1",
    "counter": "CounterTop|1",
    "mug": "Mug|1",
    "plate": "Plate|1",
}


def sat(text: str, state=K, names=NAMES) -> bool:
    return goal_satisfied(parse_expr(text), state, names)


def test_every_cdf_predicate_has_an_evaluator():
    assert set(MEANINGS) == set(PREDICATES)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(inReceptacle apple counter)", True),
        ("(inReceptacle apple fridge)", False),
        ("(not (inReceptacle apple fridge))", True),
        ("(or (inReceptacle apple fridge) (inReceptacle mug counter))", True),
        ("(and (inReceptacle apple counter) (inReceptacle mug fridge))", False),
        ("(and)", True),
        ("(exists (?m - Mug) (inReceptacle ?m counter))", True),
        ("(exists (?m - Mug) (inReceptacle ?m fridge))", False),
        ("(forall (?m - Mug) (inReceptacle ?m counter))", False),
        (
            "(forall (?m - Mug) (or (inReceptacle ?m counter) (inReceptacle ?m DiningTable_1)))",
            True,
        ),
        ("(forall (?c - Cabinet) (not (isOpen ?c)))", True),
        ("(forall (?x - Egg) (isHot ?x))", True),  # vacuous: no eggs
        ("(exists (?x - Egg) (isHot ?x))", False),
        ("(exists (?a ?b - Mug) (and (not (= ?a ?b)) (inReceptacle ?a counter)))", True),
        ("(exists (?a ?b - Mug) (and (not (= ?a ?b)) (inReceptacle ?a fridge)))", False),
        ("(exists (?x) (holds ?x))", False),
        ("(exists (?r - DiningTable) (forall (?m - Plate) (inReceptacle ?m ?r)))", True),
        ("(= apple apple)", True),
        ("(= apple mug)", False),
    ],
)
def test_expressions(text, expected):
    names = NAMES | {"DiningTable_1": "DiningTable|1"}
    assert sat(text, names=names) is expected


def test_state_predicates():
    s = state_of(
        KITCHEN,
        {
            "Apple|1": {"temperature": "Hot"},
            "Potato|1": {"temperature": "Cold"},
            "Fridge|1": {"isOpen": True},
            "Mug|1": {"isDirty": True, "isFilledWithLiquid": True},
            "Microwave|1": {"isToggled": True},
        },
        held="Knife|1",
    )
    names = NAMES | {"potato": "Potato|1", "knife": "Knife|1", "mw": "Microwave|1", "mug2": "Mug|2"}
    for text, expected in [
        # warm or cold is not enough: isHot/isCool mean "heated/cooled by the agent", as ALFRED counts
        ("(isHot apple)", False),
        ("(isCool apple)", False),
        ("(isCool potato)", False),
        ("(isOpen fridge)", True),
        ("(isDirty mug)", True),
        ("(isClean mug)", False),
        ("(isClean mug2)", True),  # a dirtyable object that is not dirty is clean
        ("(isClean apple)", False),  # not dirtyable: clean only once washed
        ("(isFilled mug)", True),
        ("(isOn mw)", True),
        ("(isToggled mw)", True),
        ("(holds knife)", True),
        ("(holds apple)", False),
        ("(isSliced apple)", False),
    ]:
        assert goal_satisfied(parse_expr(text), s, names) is expected, text


def test_slices_of_a_heated_apple_are_not_heated():
    """ALFRED's evaluator counts heated ids; slices are new objects, so the expert slices first."""
    s = K.replace(heated=frozenset({"Apple|1"}))
    s = apply(s, [Slice("Apple|1", "AppleSliced", 2)])
    assert sat("(isSliced s)", s, {"s": "Apple|1|AppleSliced_1"})
    assert not sat("(isHot s)", s, {"s": "Apple|1|AppleSliced_1"})
    assert sat("(isHot s)", s.replace(heated=frozenset({"Apple|1|AppleSliced_1"})), {"s": "Apple|1|AppleSliced_1"})


def test_bookkeeping_sets_make_hot_cool_clean():
    s = K.replace(heated={"Apple|1"}, cooled={"Potato|1"}, cleaned={"Apple|1"})
    names = NAMES | {"potato": "Potato|1"}
    assert sat("(and (isHot apple) (isClean apple) (isCool potato))", s, names)


def test_parents_go_through_movable_receptacles_only():
    s = state_of(
        KITCHEN,
        {
            "Plate|1": {"parent": "Fridge|1"},
            "Apple|1": {"parent": "Plate|1"},
            "Mug|1": {"parent": "Microwave|1"},
        },
    )
    assert parents(s, "Apple|1") == ["Plate|1", "Fridge|1"]
    assert parents(s, "Mug|1") == ["Microwave|1"]  # the microwave stands on the counter
    assert parents(s, "Microwave|1") == ["CounterTop|1"]
    assert parents(s, "Fridge|1") == []
    assert sat("(and (inReceptacle apple fridge) (inReceptacleObject apple plate))", s)
    assert not sat("(inReceptacleObject apple fridge)", s)  # a fridge is not a movable receptacle
    assert not sat("(inReceptacle mug counter)", s)


def test_a_sliced_name_stands_for_its_slices():
    s = apply(K, [Slice("Apple|1", "AppleSliced", 2)])
    s = s.with_object("Apple|1|AppleSliced_2", parent="Fridge|1")
    assert sat("(isSliced apple)", s)
    assert sat("(inReceptacle apple fridge)", s)
    assert not sat("(forall (?s - AppleSliced) (inReceptacle ?s fridge))", s)
    assert sat("(exists (?s - AppleSliced) (and (isSliced ?s) (inReceptacle ?s fridge)))", s)


def test_names_map_to_ids_and_ids_work_directly():
    goal = Atom("inReceptacle", ("Apple|1", "CounterTop|1"))
    assert goal_satisfied(goal, K)
    with pytest.raises(TaskError, match="'banana'.*apple"):
        sat("(holds banana)")


def test_a_mapped_object_that_is_gone_makes_its_atoms_false():
    assert not sat("(holds ghost)", names=NAMES | {"ghost": "Ghost|1"})


def test_conjunct_progress_counts_conjuncts_and_the_best_binding():
    goal = parse_expr(
        "(and (exists (?o - Apple ?r - Fridge) (and (isCool ?o) (inReceptacle ?o ?r)))"
        " (forall (?c - Cabinet) (not (isOpen ?c))) (inReceptacle mug counter))"
    )
    assert conjunct_progress(goal, K, NAMES) == (2, 4)
    s = K.with_object("Apple|1", parent="Fridge|1")
    assert conjunct_progress(goal, s, NAMES) == (3, 4)
    s = s.replace(cooled={"Apple|1"}).with_object("Cabinet|1", isOpen=True)
    assert conjunct_progress(goal, s, NAMES) == (3, 4)
    assert conjunct_progress(goal, s.with_object("Cabinet|1", isOpen=False), NAMES) == (4, 4)
    assert conjunct_progress(parse_expr("(and)"), K) == (1, 1)
