"""The CDF's relation vocabulary, as data: arity, inverse, symmetry, category and default weight.

A binary relation `r(subject, target)` places `subject` relative to `target`. Where `inverse`
is set, `r(a, b)` holds exactly when `inverse(b, a)` does, so CSSG may rewrite one into the
other to place the earlier object first (paper, appendix on CSSG: "a desk is in front of a
chair" is resolved so that the desk is the anchor). Directions (left/right, in front/behind)
are read in one fixed frame, which makes those pairs exact inverses. `face` has no inverse:
"chair faces desk" says nothing about the desk.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from typing import Literal

from luminous_sim.vocab.agent_body import AGENT_RADIUS

Category = Literal["support", "spatial", "wall"]


@dataclass(frozen=True)
class RelationInfo:
    """Metadata of one relation.

    Attributes:
        name: Canonical name as written in a CDF.
        arity: 1 for unary relations (subject only), 2 for binary ones (subject and target).
        category: "support" (on/in a receptacle), "spatial" (between two things) or "wall"
            (a unary relation to the room structure).
        inverse: The relation `r'` with `r(a, b) <=> r'(b, a)`; equal to `name` for a symmetric
            relation; None where no relation of the vocabulary is the inverse.
        description: One line for humans and the JSON Schema.
    """

    name: str
    arity: int
    category: Category
    inverse: str | None
    description: str

    @property
    def symmetric(self) -> bool:
        """Whether `r(a, b) <=> r(b, a)`."""
        return self.inverse == self.name

    @property
    def invertible(self) -> bool:
        """Whether subject and target may be swapped (with the relation replaced by its inverse)."""
        return self.inverse is not None


_TABLE: tuple[RelationInfo, ...] = (
    RelationInfo("on", 2, "support", None, "rests on top of the target receptacle"),
    RelationInfo("in", 2, "support", None, "is inside the target receptacle"),
    RelationInfo("beside", 2, "spatial", "beside", "stands at the target's left or right side, too close for the "
                 f"agent to walk between (a gap under {2 * AGENT_RADIUS:g} m)"),
    RelationInfo("near", 2, "spatial", "near", "is within a short distance of the target"),
    RelationInfo("far", 2, "spatial", "far", "is at a long distance from the target"),
    RelationInfo("away_from", 2, "spatial", "away_from", "keeps clear of the target"),
    RelationInfo("face", 2, "spatial", None, "is turned towards the target"),
    RelationInfo("in_front_of", 2, "spatial", "behind", "is in front of the target"),
    RelationInfo("behind", 2, "spatial", "in_front_of", "is behind the target"),
    RelationInfo("left_of", 2, "spatial", "right_of", "is to the left of the target"),
    RelationInfo("right_of", 2, "spatial", "left_of", "is to the right of the target"),
    RelationInfo("aligned_with", 2, "spatial", "aligned_with", "is aligned with the target"),
    RelationInfo("under", 2, "spatial", "above", "is below the target"),
    RelationInfo("above", 2, "spatial", "under", "is above the target (a painting above a sofa)"),
    RelationInfo("against_wall", 1, "wall", None, "stands with its back against a wall"),
    RelationInfo("in_corner", 1, "wall", None, "stands in a corner of the room"),
    RelationInfo("in_centre", 1, "wall", None, "stands in the middle of the room"),
)

RELATIONS: dict[str, RelationInfo] = {r.name: r for r in _TABLE}
"""Canonical relation name -> metadata."""

ALIASES: dict[str, str] = {
    "in_center": "in_centre",
    "faces": "face",
    "next_to": "beside",
    "below": "under",
    "away": "away_from",
}
"""Accepted spellings that are rewritten to a canonical name on load."""

STRUCTURE_ELEMENTS: tuple[str, ...] = ("wall", "window", "door")
"""Room elements a binary relation may target without declaring them ("bed beside window")."""

EXCLUSIVE_UNARY: tuple[frozenset[str], ...] = (
    frozenset({"in_corner", "in_centre"}),
    frozenset({"against_wall", "in_centre"}),
)
"""Unary relations that cannot hold together for one object."""

EXCLUSIVE_BINARY: tuple[frozenset[str], ...] = (
    frozenset({"near", "far"}),
    frozenset({"beside", "far"}),
)
"""Binary relations that cannot hold together for one pair (in either direction)."""

ORDER_AXES: tuple[tuple[str, str], ...] = (
    ("left_of", "right_of"),
    ("in_front_of", "behind"),
    ("under", "above"),
)
"""Relation pairs that order objects along one axis: a cycle along an axis is a contradiction."""

STRUCTURE_WEIGHT = 2.0
"""Default weight of a relation to the room structure (paper appendix: furniture vs room)."""
OBJECT_WEIGHT = 1.0
"""Default weight of a relation between two objects (paper: furniture vs furniture)."""


def canonical(name: str) -> str | None:
    """The canonical spelling of a relation name or alias, or None when it is unknown."""
    if name in RELATIONS:
        return name
    return ALIASES.get(name)


def relation_info(name: str) -> RelationInfo:
    """Metadata of a relation given by canonical name or alias.

    Raises:
        ValueError: The name is not a relation; the message lists close matches.
    """
    canon = canonical(name)
    if canon is None:
        raise ValueError(unknown_relation_message(name))
    return RELATIONS[canon]


def unknown_relation_message(name: object) -> str:
    """A message for an unknown relation name, naming close matches and the accepted names."""
    known = list(RELATIONS) + list(ALIASES)
    hint = difflib.get_close_matches(str(name), known, n=3) if isinstance(name, str) else []
    extra = f"; did you mean {', '.join(hint)}?" if hint else ""
    return f"unknown relation {name!r}{extra} (expected one of {', '.join(RELATIONS)})"


def default_weight(relation: str, target: str | None) -> float:
    """The weight CSSG gives a relation whose CDF entry sets none.

    Args:
        relation: Canonical relation name.
        target: The target name, or None for a unary relation.
    """
    info = RELATIONS[relation]
    if info.category == "wall" or target in STRUCTURE_ELEMENTS:
        return STRUCTURE_WEIGHT
    return OBJECT_WEIGHT
