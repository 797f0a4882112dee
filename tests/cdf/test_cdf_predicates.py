from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from luminous_sim.cdf.predicates import (
    PREDICATES,
    And,
    Atom,
    Exists,
    ExprError,
    ForAll,
    Not,
    Or,
    Param,
    atoms,
    expr_from_data,
    is_ground_conjunction,
    parse_expr,
    to_sexpr,
)

A = Atom


@pytest.mark.parametrize(
    ("text", "expr"),
    [
        ("(isHot apple)", A("isHot", ("apple",))),
        (
            "(and (inReceptacle apple fridge) (isCool apple))",
            And((A("inReceptacle", ("apple", "fridge")), A("isCool", ("apple",)))),
        ),
        (
            "(or (isOn lamp) (not (isOpen box)))",
            Or((A("isOn", ("lamp",)), Not(A("isOpen", ("box",))))),
        ),
        ("(AND (ISHOT a))", And((A("isHot", ("a",)),))),
        ("(isCold apple)", A("isCool", ("apple",))),
        ("(and)", And(())),
        ("(holds book)", A("holds", ("book",))),
        ("(inReceptacleObject apple bowl)", A("inReceptacleObject", ("apple", "bowl"))),
        (
            "(exists (?a ?b - Mug ?r) (and (inReceptacle ?a ?r) (not (= ?a ?b))))",
            Exists(
                (Param("?a", "Mug"), Param("?b", "Mug"), Param("?r")),
                And((A("inReceptacle", ("?a", "?r")), Not(A("=", ("?a", "?b"))))),
            ),
        ),
        (
            "(forall (?c - Cabinet) (not (isOpen ?c)))",
            ForAll((Param("?c", "Cabinet"),), Not(A("isOpen", ("?c",)))),
        ),
    ],
)
def test_parse_expr(text: str, expr: Any) -> None:
    assert parse_expr(text) == expr
    assert parse_expr(to_sexpr(expr)) == expr


@pytest.mark.parametrize(
    ("data", "expr"),
    [
        ({"isHot": "apple"}, A("isHot", ("apple",))),
        ({"isHot": ["apple"]}, A("isHot", ("apple",))),
        ([{"isCool": "a"}, {"isOpen": "f"}], And((A("isCool", ("a",)), A("isOpen", ("f",))))),
        (
            {"and": [{"inReceptacle": ["a", "f"]}, "(isCool a)"]},
            And((A("inReceptacle", ("a", "f")), A("isCool", ("a",)))),
        ),
        ({"not": {"isOpen": "f"}}, Not(A("isOpen", ("f",)))),
        ({"or": [{"isOn": "l"}]}, Or((A("isOn", ("l",)),))),
        (
            {"exists": {"vars": {"?m": "Mug"}, "body": {"isHot": "?m"}}},
            Exists((Param("?m", "Mug"),), A("isHot", ("?m",))),
        ),
        (
            {"forall": {"vars": ["?x"], "body": "(not (isOpen ?x))"}},
            ForAll((Param("?x"),), Not(A("isOpen", ("?x",)))),
        ),
    ],
)
def test_expr_from_data(data: Any, expr: Any) -> None:
    assert expr_from_data(data) == expr


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("(isHott apple)", "unknown predicate 'isHott'; did you mean isHot?"),
        ("(isHot a b)", "isHot takes 1 argument(s), got 2"),
        ("(inReceptacle a)", "inReceptacle takes 2 argument(s), got 1"),
        ("(isHot ?x)", "variable ?x is not bound"),
        ("(exists (?x - Mugg) (isHot ?x))", "unknown object type 'Mugg'; did you mean Mug?"),
        ("(exists (?x ?x) (isHot ?x))", "variable ?x is declared twice"),
        ("(exists (x) (isHot x))", "expected a ?variable"),
        ("(exists () (isHot a))", "at least one ?variable"),
        ("(exists (?x -) (isHot ?x))", "'-' must follow variables"),
        ("(exists (?x) (isHot ?x) extra)", "expected (exists (?var - Type ...) expr)"),
        ("(not)", "'not' takes exactly one operand, got 0"),
        ("(or)", "'or' needs at least one operand"),
        ("(isHot (a))", "arguments of isHot must be names"),
        ("(isHot a.b)", "neither an object name"),
        ("isHot", "expected '(keyword-or-predicate ...)'"),
        ("(and (isHot a)", "unclosed '('"),
        ({"and": "x"}, "at and: expected a list of expressions"),
        ({"a": 1, "b": 2}, "exactly one key"),
        (5, "exactly one key"),
        (None, "exactly one key"),
        ({1: "a"}, "expected a keyword or predicate name as key"),
        ({"isHot": [1]}, "argument 1 of isHot must be a name"),
        ({"exists": {"vars": ["x"], "body": "(isHot x)"}}, "at exists.vars: expected a ?variable"),
        ({"exists": {"vars": 3, "body": "(isHot x)"}}, "expected a mapping ?var -> Type"),
        ({"exists": {"body": "(isHot x)"}}, "keys 'vars' and 'body'"),
        ([{"not": {"isHott": "a"}}], "at [0].not.isHott: unknown predicate"),
    ],
)
def test_expression_errors(source: Any, message: str) -> None:
    with pytest.raises(ExprError) as info:
        parse_expr(source) if isinstance(source, str) else expr_from_data(source)
    assert message in str(info.value)


def test_nesting_limit() -> None:
    deep: Any = {"isHot": "a"}
    for _ in range(100):
        deep = {"not": deep}
    with pytest.raises(ExprError, match="nested deeper"):
        expr_from_data(deep)


def test_atoms_carry_scope() -> None:
    e = parse_expr("(and (isHot a) (exists (?m - Mug) (inReceptacle ?m t)))")
    got = [(atom.pred, scope) for atom, scope in atoms(e)]
    assert got == [("isHot", {}), ("inReceptacle", {"?m": "Mug"})]


@pytest.mark.parametrize(
    ("text", "ground"),
    [
        ("(isOpen f)", True),
        ("(and (isOpen f) (not (isOn l)))", True),
        ("(or (isOpen f))", False),
        ("(exists (?x) (isOpen ?x))", False),
        ("(not (and (isOpen f)))", False),
    ],
)
def test_is_ground_conjunction(text: str, ground: bool) -> None:
    assert is_ground_conjunction(parse_expr(text)) is ground


def test_predicate_table_covers_alfred_goals() -> None:
    for name in (
        "inReceptacle",
        "inReceptacleObject",
        "isHot",
        "isCool",
        "isClean",
        "isSliced",
        "isOn",
        "isOpen",
        "holds",
        "isToggled",
    ):
        assert name in PREDICATES
    assert PREDICATES["inReceptacle"].arity == 2


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet="()? -abisHotnOpedrxyzCl;\n", max_size=50))
def test_random_goal_strings_parse_or_raise_expr_error(text: str) -> None:
    try:
        e = parse_expr(text)
    except ExprError:
        return
    assert parse_expr(to_sexpr(e)) == e
