"""Where an instruction names object types: spans of its words ("dish sponge", "knives", "countertop") and the
types each may mean, the parser's candidates to point at (a copy mechanism, so that a receptacle ALFRED's
train split never uses as a parent can still be read where it is named). Torch-free."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache


@dataclass(frozen=True)
class Mention:
    """Words `start:end` of an input name the object `types` (more than one for "sink" or "table")."""

    start: int
    end: int
    types: frozenset[str]


LONGEST_NAME = 4
"""Words in the longest name looked for ("toilet paper hanger" is 3)."""


@cache
def _names() -> dict[tuple[str, ...], frozenset[str]]:
    """Each name as words -> the types it may mean: spoken names, their plurals, ALFRED's own forms
    ("countertop"), and a head word that several types share ("table": dining, coffee and side tables)."""
    from luminous_sim.language.names import plural, spoken
    from luminous_sim.language.speaker import tokenize
    from luminous_sim.vocab import OBJECTS

    by_name: dict[tuple[str, ...], set[str]] = {}
    for t in OBJECTS:
        for name in (spoken(t), plural(t), t):
            by_name.setdefault(tuple(tokenize(name)), set()).add(t)
    heads: dict[str, set[str]] = {}
    for t in OBJECTS:
        words = tuple(tokenize(spoken(t)))
        if len(words) > 1 and words[-1:] not in by_name:
            heads.setdefault(words[-1], set()).add(t)
    for head, types in heads.items():
        if len(types) > 1:  # a head only one type has ("paper") is too often something else
            by_name.setdefault((head,), set()).update(types)
            by_name.setdefault((head + "s",), set()).update(types)
    return {name: frozenset(types) for name, types in by_name.items() if 0 < len(name) <= LONGEST_NAME}


def mentions(words: Sequence[str]) -> list[Mention]:
    """The names in a list of lower-case words, left to right, the longest name at each place ("butter knife"
    is not also a knife)."""
    names = _names()
    found: list[Mention] = []
    i = 0
    while i < len(words):
        for n in range(min(LONGEST_NAME, len(words) - i), 0, -1):
            types = names.get(tuple(words[i:i + n]))
            if types:
                found.append(Mention(i, i + n, types))
                i += n
                break
        else:
            i += 1
    return found
