"""A fixed word vocabulary for instructions, built from the project's template language: ALFRED's goal
templates (`tasks.templates`), the env's task kinds' own (`env.kinds`), the verb table and colour words
(`language.verbs`), and every object type both as ALFRED's templates write it ("spraybottle") and as
the language layer speaks it ("spray bottle"). It depends on code only, so it is the same for everyone.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from functools import cache

from luminous_sim.env.kinds import kind_templates
from luminous_sim.language.names import spoken, words_of
from luminous_sim.language.verbs import COLOUR_NAMES, PREPOSITION, VERBS
from luminous_sim.tasks import TEMPLATES
from luminous_sim.tasks.templates import directive_words
from luminous_sim.vocab import ALL_TYPES

PAD, UNK = "<pad>", "<unk>"
_WORD = re.compile(r"[a-z0-9]+")


def words(text: str) -> list[str]:
    """Lower-cased words of a text (letters and digits; everything else separates)."""
    return _WORD.findall(text.lower())


def _template_words(templates: Iterable[str]) -> set[str]:
    return {w for t in templates for w in words(re.sub(r"\{\w+\}", " ", t))}


@cache
def vocabulary() -> tuple[str, ...]:
    """`<pad>` (id 0), `<unk>` (id 1), then the words, sorted."""
    found = _template_words(t for options in TEMPLATES.values() for t in options) | directive_words()
    found |= _template_words(kind_templates())
    found |= {w for verbs in VERBS.values() for v in verbs for w in words(v)}
    found |= set(COLOUR_NAMES) | set(PREPOSITION) | {"on", "a", "the", "then", "and"}
    for t in ALL_TYPES:
        found.add(t.lower())
        found |= set(words(spoken(t))) | words_of(t)
    return (PAD, UNK, *sorted(found))


def encode(text: str, length: int) -> list[int]:
    """Token ids of a text, cut or padded (with `<pad>`) to `length`; unknown words are `<unk>`."""
    index = _index()
    ids = [index.get(w, 1) for w in words(text)][:length]
    return ids + [0] * (length - len(ids))


@cache
def _index() -> dict[str, int]:
    return {w: i for i, w in enumerate(vocabulary())}
