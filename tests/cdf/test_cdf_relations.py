from __future__ import annotations

import pytest

from luminous_sim.cdf.relations import (
    ALIASES,
    RELATIONS,
    STRUCTURE_WEIGHT,
    canonical,
    default_weight,
    relation_info,
)

REQUIRED = (
    "on",
    "in",
    "beside",
    "near",
    "far",
    "against_wall",
    "in_corner",
    "in_centre",
    "away_from",
    "face",
    "in_front_of",
    "behind",
    "left_of",
    "right_of",
    "aligned_with",
    "under",
    "above",
)


def test_required_relations_are_there() -> None:
    assert set(REQUIRED) <= set(RELATIONS)


def test_inverse_of_inverse_is_itself() -> None:
    for info in RELATIONS.values():
        if info.inverse is not None:
            back = RELATIONS[info.inverse]
            assert back.inverse == info.name
            assert back.arity == info.arity == 2
            assert back.category == info.category


@pytest.mark.parametrize(
    ("name", "inverse"),
    [
        ("in_front_of", "behind"),
        ("left_of", "right_of"),
        ("under", "above"),
        ("beside", "beside"),
        ("near", "near"),
        ("far", "far"),
        ("aligned_with", "aligned_with"),
        ("face", None),
        ("on", None),
        ("in", None),
    ],
)
def test_inverse_table(name: str, inverse: str | None) -> None:
    assert RELATIONS[name].inverse == inverse
    assert RELATIONS[name].symmetric is (inverse == name)


@pytest.mark.parametrize(
    ("name", "arity", "category"),
    [
        ("on", 2, "support"),
        ("in", 2, "support"),
        ("against_wall", 1, "wall"),
        ("in_corner", 1, "wall"),
        ("in_centre", 1, "wall"),
        ("beside", 2, "spatial"),
        ("face", 2, "spatial"),
    ],
)
def test_arity_and_category(name: str, arity: int, category: str) -> None:
    assert (RELATIONS[name].arity, RELATIONS[name].category) == (arity, category)


def test_aliases() -> None:
    assert canonical("in_center") == "in_centre"
    assert canonical("faces") == "face"
    assert canonical("nonsense") is None
    assert all(v in RELATIONS for v in ALIASES.values())
    assert relation_info("in_center").name == "in_centre"
    with pytest.raises(ValueError, match="did you mean beside"):
        relation_info("besides")


def test_default_weights_follow_the_paper() -> None:
    assert default_weight("against_wall", None) == STRUCTURE_WEIGHT == 2.0
    assert default_weight("beside", "window") == 2.0
    assert default_weight("beside", "sofa") == 1.0
