"""Checks on instruction text that do not use the language layer's own name table (`language.names`), so
they can catch its mistakes: ALFRED type names glued into one word ("stoveburner", "dishsponge") or left in
CamelCase ("CounterTop"), and a landmark that is the target itself ("to the sink near the sink").

The glued forms come from ALFRED's type vocabulary (`luminous_sim.vocab.ALL_TYPES`): every type of two or
more CamelCase parts, lower-cased and joined, less the few that are English words written as one.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from functools import cache

ONE_WORD_IN_ENGLISH = frozenset({"armchair", "basketball"})
"""Types of two CamelCase parts that English writes as one word."""

GLUED_WITHOUT_CAPITALS = frozenset({"glassbottle"})
"""Types ALFRED spells as one capitalised word that are two English words ("Glassbottle")."""

_CAMEL_PARTS = re.compile(r"[A-Z]+(?![a-z])|[A-Z][a-z]+|[a-z]+")
_CAMEL_WORD = re.compile(r"\b[A-Za-z]*[a-z][A-Z][A-Za-z]*\b")
_LANDMARK = re.compile(r"\bthe ((?:[a-z]+ ){0,3}?[a-z]+) (?:by|next to|near|beside|close to) the \1\b",
                       re.IGNORECASE)


@cache
def glued_forms() -> frozenset[str]:
    """ALFRED's multi-word type names lower-cased and joined: "stoveburner", "dishsponge", "applesliced", ..."""
    from luminous_sim.vocab import ALL_TYPES

    forms = {t.lower() for t in ALL_TYPES if len(_CAMEL_PARTS.findall(t)) > 1}
    return frozenset((forms - ONE_WORD_IN_ENGLISH) | GLUED_WITHOUT_CAPITALS)


@cache
def _glued_pattern() -> re.Pattern[str]:
    alternatives = "|".join(sorted(glued_forms(), key=len, reverse=True))
    return re.compile(rf"\b(?:{alternatives})\b", re.IGNORECASE)


def glued_names(text: str) -> list[str]:
    """The glued or CamelCase type names in a text: "put a pan of dishsponge in stoveburner" -> ["dishsponge",
    "stoveburner"]."""
    found = [m.group(0) for m in _glued_pattern().finditer(text)]
    return found + [w for w in _CAMEL_WORD.findall(text) if w.lower() not in glued_forms()]


def self_landmarks(text: str) -> list[str]:
    """Places named by themselves: "to the sink near the sink" -> ["sink"]."""
    return [m.group(1) for m in _LANDMARK.finditer(text)]


def distinct_rate(annotations: Sequence[Sequence[str]]) -> tuple[int, int]:
    """Across one trajectory's annotations (each a list of sentences, aligned), the distinct sentences at each
    position and all sentences: (distinct, total)."""
    distinct = total = 0
    for position in zip(*annotations, strict=False):
        distinct += len(set(position))
        total += len(position)
    return distinct, total


def count_problems(texts: Iterable[str]) -> dict[str, int]:
    """Over texts: how many, how many with a glued name, how many with a self-landmark."""
    n = glued = selfish = 0
    for text in texts:
        n += 1
        glued += bool(glued_names(text))
        selfish += bool(self_landmarks(text))
    return {"texts": n, "glued": glued, "self_landmarks": selfish}
