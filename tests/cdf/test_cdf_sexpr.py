from __future__ import annotations

import contextlib

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from luminous_sim.cdf.sexpr import MAX_DEPTH, SExprError, parse, to_text, tokenize


@pytest.mark.parametrize(
    ("text", "tree"),
    [
        ("(a)", ["a"]),
        ("()", []),
        ("atom", "atom"),
        (
            "(and (inReceptacle apple fridge) (isCool apple))",
            ["and", ["inReceptacle", "apple", "fridge"], ["isCool", "apple"]],
        ),
        ("  (a\n  (b c) ; comment\n d)  ", ["a", ["b", "c"], "d"]),
        ("(exists (?x - Mug) (isHot ?x))", ["exists", ["?x", "-", "Mug"], ["isHot", "?x"]]),
        ("(= ?a ?b)", ["=", "?a", "?b"]),
    ],
)
def test_parse(text: str, tree: object) -> None:
    assert parse(text) == tree


@pytest.mark.parametrize(
    ("text", "message", "pos"),
    [
        ("", "empty expression", 0),
        ("   ; only a comment", "empty expression", 0),
        ("(a (b)", "unclosed '('", 0),
        ("(a))", "unexpected ')'", 3),
        (")", "unmatched ')'", 0),
        ("(a) (b)", "unexpected '('", 4),
        ("a b", "expected '('", 0),
    ],
)
def test_parse_errors(text: str, message: str, pos: int) -> None:
    with pytest.raises(SExprError) as info:
        parse(text)
    assert message in str(info.value)
    assert info.value.pos == pos
    assert f"at character {pos + 1}" in str(info.value)


def test_depth_limit_is_an_error_not_a_crash() -> None:
    parse("(" * MAX_DEPTH + ")" * MAX_DEPTH)
    with pytest.raises(SExprError, match="nested deeper"):
        parse("(" * 100_000 + ")" * 100_000)


def test_tokenize_offsets() -> None:
    assert tokenize("(ab c)") == [("(", 0), ("ab", 1), ("c", 4), (")", 5)]


_atoms = st.text(alphabet="abcXYZ?_-=019", min_size=1, max_size=5)
_trees = st.recursive(_atoms, lambda kids: st.lists(kids, max_size=4), max_leaves=20)


@settings(max_examples=200, deadline=None)
@given(_trees)
def test_write_then_read_round_trips(tree: object) -> None:
    assert parse(to_text(tree)) == tree  # type: ignore[arg-type]


@settings(max_examples=200, deadline=None)
@given(st.text(max_size=60))
def test_any_text_parses_or_raises_sexpr_error(text: str) -> None:
    with contextlib.suppress(SExprError):  # any other exception fails the test
        parse(text)
