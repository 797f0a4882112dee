"""Word tokenisation of instructions: lower-case words, punctuation kept as separate tokens."""

from __future__ import annotations

import re

_TOKEN = re.compile(r"[a-z0-9]+(?:'[a-z]+)*|[^\sa-z0-9]")
_NO_SPACE_BEFORE = {".", ",", "!", "?", ";", ":", ")", "'s", "'"}


def tokenize(text: str) -> list[str]:
    """Split an instruction into lower-case word and punctuation tokens.

    Args:
        text: Any instruction, e.g. ``"Turn around,walk to the table."``.

    Returns:
        The tokens, e.g. ``["turn", "around", ",", "walk", "to", "the", "table", "."]``.
    """
    return _TOKEN.findall(text.lower())


def detokenize(tokens: list[str]) -> str:
    """Join tokens into a sentence: no space before punctuation, first letter upper-case.

    Args:
        tokens: Word and punctuation tokens as produced by :func:`tokenize`.

    Returns:
        A readable sentence, e.g. ``"Turn around, walk to the table."``.
    """
    out = ""
    for tok in tokens:
        if out and tok not in _NO_SPACE_BEFORE and not out.endswith("("):
            out += " "
        out += tok
    return out[:1].upper() + out[1:]
