"""Goals that cannot hold: conflicting literals of one conjunction, over the same terms.

A conjunction is unsatisfiable when it holds a literal and its negation, two states that exclude
each other on one object (EXCLUSIVE_STATES), or one object in two receptacles of which neither can
hold the other, however deeply nested (`inReceptacle` is true of every ancestor receptacle).
Bodies of `exists` join the enclosing conjunction with fresh variables; `forall` bodies do too
when their range is known to be non-empty (else they hold vacuously). `or` and negated compound
expressions are not analysed, so every conflict reported is a real one.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cache
from itertools import combinations

from luminous_sim.cdf.affordances import can_support, is_receptacle
from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Param, is_variable, to_sexpr
from luminous_sim.vocab import ALL_TYPES

EXCLUSIVE_STATES: dict[frozenset[str], str] = {
    frozenset({"isHot", "isCool"}): "heating deletes isCool and cooling deletes isHot (ALFWorld's alfred.pddl)",
    frozenset({"isClean", "isDirty"}): "a clean object is not dirty",
}
"""Pairs of unary predicates that exclude each other on one object -> why."""

SYNONYMS: dict[str, str] = {"isOn": "isToggled"}
"""Predicates that mean the same (compared under the canonical name)."""


@dataclass(frozen=True)
class Conflict:
    """Two literals of one conjunction that cannot both hold, and why."""

    first: str
    second: str
    reason: str

    def message(self) -> str:
        return f"contradictory literals {self.first} and {self.second}: {self.reason}; expected a goal that can hold"


@dataclass(frozen=True)
class _Literal:
    atom: Atom  # with quantified variables renamed apart, synonyms replaced
    positive: bool
    shown: str  # as written


def find_conflicts(
    expr: Expr, type_of: Mapping[str, str], nonempty: Callable[[Param], bool]
) -> list[Conflict]:
    """Every conflicting pair of literals of `expr`'s top-level conjunction.

    Args:
        expr: A goal or initial-state expression.
        type_of: Object name -> type, for the declared objects.
        nonempty: Whether a `forall` parameter's range surely holds an object.
    """
    literals: list[_Literal] = []
    var_types: dict[str, str | None] = {}
    _collect(expr, {}, literals, var_types, nonempty)
    types = {**type_of, **{v: t for v, t in var_types.items() if t}}
    out: list[Conflict] = []
    for a, b in combinations(literals, 2):
        reason = _conflict(a, b, types)
        if reason:
            out.append(Conflict(a.shown, b.shown, reason))
    return out


def _collect(
    expr: Expr,
    env: dict[str, str],
    out: list[_Literal],
    var_types: dict[str, str | None],
    nonempty: Callable[[Param], bool],
) -> None:
    if isinstance(expr, And):
        for e in expr.args:
            _collect(e, env, out, var_types, nonempty)
    elif isinstance(expr, Atom):
        out.append(_literal(expr, env, True))
    elif isinstance(expr, Not) and isinstance(expr.arg, Atom):
        out.append(_literal(expr.arg, env, False))
    elif isinstance(expr, Not) and isinstance(expr.arg, Not):
        _collect(expr.arg.arg, env, out, var_types, nonempty)
    elif isinstance(expr, (Exists, ForAll)):
        if isinstance(expr, ForAll) and not all(nonempty(p) for p in expr.params):
            return
        inner = dict(env)
        for p in expr.params:
            fresh = f"{p.var}#{len(var_types)}"
            var_types[fresh] = p.type
            inner[p.var] = fresh
        _collect(expr.body, inner, out, var_types, nonempty)


def _literal(atom: Atom, env: dict[str, str], positive: bool) -> _Literal:
    canon = Atom(SYNONYMS.get(atom.pred, atom.pred), tuple(env.get(a, a) for a in atom.args))
    shown = to_sexpr(atom)
    return _Literal(canon, positive, shown if positive else f"(not {shown})")


def _conflict(a: _Literal, b: _Literal, types: Mapping[str, str]) -> str | None:
    if a.atom == b.atom and a.positive != b.positive:
        return "a literal and its negation"
    if not (a.positive and b.positive):
        return None
    if len(a.atom.args) == 1 and a.atom.args == b.atom.args:
        return EXCLUSIVE_STATES.get(frozenset({a.atom.pred, b.atom.pred}))
    if a.atom.pred == b.atom.pred == "inReceptacle" and a.atom.args[0] == b.atom.args[0]:
        return _two_places(a.atom.args[0], a.atom.args[1], b.atom.args[1], types)
    return None


def _two_places(obj: str, r1: str, r2: str, types: Mapping[str, str]) -> str | None:
    # Two distinct names are two objects; a variable may stand for either, so it never conflicts.
    if r1 == r2 or is_variable(r1) or is_variable(r2):
        return None
    t1, t2 = types.get(r1), types.get(r2)
    if t1 is None or t2 is None or _nests(t1, t2) or _nests(t2, t1):
        return None
    return (
        f"{obj!r} cannot be in both {r1!r} and {r2!r} (neither {_a(t1)} nor {_a(t2)} can hold the other, "
        "directly or nested)"
    )


def _a(word: str) -> str:
    return ("an " if word[:1].lower() in "aeiou" else "a ") + word


@cache
def _nests(outer: str, inner: str) -> bool:
    """Whether `inner` may lie on/in `outer`, directly or through a chain of receptacles."""
    seen, frontier = {outer}, [outer]
    while frontier:
        current = frontier.pop()
        for t in _RECEPTACLE_TYPES:
            if t not in seen and can_support(current, t):
                if t == inner:
                    return True
                seen.add(t)
                frontier.append(t)
    return False


_RECEPTACLE_TYPES: tuple[str, ...] = tuple(t for t in ALL_TYPES if is_receptacle(t))
