"""A small s-expression reader and writer for PDDL-like goals: `(and (isHot apple) (isOn lamp))`.

An s-expression is an atom (a string) or a list of s-expressions. `;` starts a comment to the end
of the line. The reader is iterative, so deep nesting cannot exhaust Python's stack.
"""

from __future__ import annotations

SExpr = str | list["SExpr"]

MAX_DEPTH = 64
"""Deepest nesting accepted (goals are shallow; this bounds the work on hostile input)."""


class SExprError(ValueError):
    """Malformed s-expression text; `pos` is the 0-based character offset of the problem."""

    def __init__(self, message: str, pos: int) -> None:
        super().__init__(f"{message} at character {pos + 1}")
        self.pos = pos


def tokenize(text: str) -> list[tuple[str, int]]:
    """Split text into `(`, `)` and atom tokens, each with its offset; comments are dropped."""
    tokens: list[tuple[str, int]] = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif c == ";":
            while i < n and text[i] != "\n":
                i += 1
        elif c in "()":
            tokens.append((c, i))
            i += 1
        else:
            start = i
            while i < n and not text[i].isspace() and text[i] not in "();":
                i += 1
            tokens.append((text[start:i], start))
    return tokens


def parse(text: str) -> SExpr:
    """Read exactly one s-expression.

    Raises:
        SExprError: Unbalanced parentheses, nesting deeper than MAX_DEPTH, no expression or
            more than one.
    """
    tokens = tokenize(text)
    if not tokens:
        raise SExprError("empty expression", 0)
    stack: list[tuple[list[SExpr], int]] = []
    result: SExpr | None = None
    for k, (tok, pos) in enumerate(tokens):
        if result is not None:
            raise SExprError(f"unexpected {tok!r} after the end of the expression", pos)
        if tok == "(":
            if len(stack) >= MAX_DEPTH:
                raise SExprError(f"nested deeper than {MAX_DEPTH} levels", pos)
            stack.append(([], pos))
        elif tok == ")":
            if not stack:
                raise SExprError("unmatched ')'", pos)
            done, _ = stack.pop()
            if stack:
                stack[-1][0].append(done)
            else:
                result = done
        elif stack:
            stack[-1][0].append(tok)
        elif k == 0 and len(tokens) == 1:
            result = tok
        else:
            raise SExprError(f"expected '(' but found {tok!r}", pos)
    if stack:
        raise SExprError("unclosed '('", stack[-1][1])
    assert result is not None
    return result


def to_text(expr: SExpr) -> str:
    """Write an s-expression on one line (`parse(to_text(e)) == e` for atoms without spaces)."""
    if isinstance(expr, str):
        return expr
    return "(" + " ".join(to_text(e) for e in expr) + ")"
