"""Goal and initial-state expressions: a typed AST over ALFRED's predicates, read from an
s-expression string or from a YAML/JSON structure, written back as an s-expression.

Grammar (s-expression form; keywords and predicate names are case-insensitive)::

    expr  := (and expr*) | (or expr+) | (not expr)
           | (exists (params) expr) | (forall (params) expr)
           | (PRED arg*)                      ; arity from PREDICATES
    params:= ?var ... [- Type] ...            ; PDDL typed list: `?a ?b - Mug ?r`
    arg   := name | ?var                      ; a declared object name or a bound variable

Structure form: a string (parsed as above); a list (a conjunction); or a one-key mapping:
`{and: [..]}`, `{or: [..]}`, `{not: expr}`, `{exists: {vars: {"?o": Apple}, body: expr}}`
(`forall` alike; `vars` may be a list of names), or `{PRED: [args]}` (`{PRED: arg}` if unary).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from luminous_sim.cdf import sexpr
from luminous_sim.errors import VocabularyError
from luminous_sim.vocab import check_type


@dataclass(frozen=True)
class PredicateInfo:
    """A predicate: its arity and the ability each argument's type needs (None: any object)."""

    name: str
    abilities: tuple[str | None, ...]
    description: str

    @property
    def arity(self) -> int:
        return len(self.abilities)


_PREDICATE_TABLE: tuple[PredicateInfo, ...] = (
    PredicateInfo("inReceptacle", (None, "receptacle"), "o is on/in receptacle r"),
    PredicateInfo(
        "inReceptacleObject", (None, "movable_receptacle"), "o is in movable receptacle m"
    ),
    PredicateInfo("isHot", ("heatable",), "o was heated"),
    PredicateInfo("isCool", ("coolable",), "o was cooled"),
    PredicateInfo("isClean", ("cleanable",), "o was cleaned"),
    PredicateInfo("isDirty", ("dirtyable",), "o is dirty"),
    PredicateInfo("isSliced", ("sliceable",), "o is sliced"),
    PredicateInfo("isOn", ("toggleable",), "o is switched on"),
    PredicateInfo("isToggled", ("toggleable",), "o is switched on (ALFRED's name)"),
    PredicateInfo("isOpen", ("openable",), "o is open"),
    PredicateInfo("isFilled", ("fillable",), "o holds a liquid"),
    PredicateInfo("holds", ("pickupable",), "the agent holds o"),
    PredicateInfo("=", (None, None), "the two arguments are the same object"),
)

PREDICATES: dict[str, PredicateInfo] = {p.name: p for p in _PREDICATE_TABLE}
"""Canonical predicate name -> metadata."""

PREDICATE_ALIASES: dict[str, str] = {"isCold": "isCool", "isToggledOn": "isToggled"}
_LOOKUP: dict[str, str] = {k.lower(): k for k in PREDICATES} | {
    k.lower(): v for k, v in PREDICATE_ALIASES.items()
}
KEYWORDS: tuple[str, ...] = ("and", "or", "not", "exists", "forall")

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_VAR = re.compile(r"\?[A-Za-z][A-Za-z0-9_]*")
MAX_DEPTH = 32


@dataclass(frozen=True)
class Atom:
    """`(pred arg ...)`: each argument is an object name or a `?variable`."""

    pred: str
    args: tuple[str, ...]


@dataclass(frozen=True)
class Not:
    arg: Expr


@dataclass(frozen=True)
class And:
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Or:
    args: tuple[Expr, ...]


@dataclass(frozen=True)
class Param:
    """A quantified variable (`?o`) with an optional object type."""

    var: str
    type: str | None = None


@dataclass(frozen=True)
class Exists:
    params: tuple[Param, ...]
    body: Expr


@dataclass(frozen=True)
class ForAll:
    params: tuple[Param, ...]
    body: Expr


Expr = Atom | Not | And | Or | Exists | ForAll
EXPR_TYPES = (Atom, Not, And, Or, Exists, ForAll)


class ExprError(ValueError):
    """A malformed expression; the message says where (sub-path or character) and what was "
    "expected."""


def is_variable(arg: str) -> bool:
    """Whether an argument is a `?variable`."""
    return arg.startswith("?")


def parse_expr(text: str) -> Expr:
    """Parse an s-expression string into an Expr.

    Raises:
        ExprError: Malformed text, unknown predicate, wrong arity, unbound variable, unknown type.
    """
    try:
        tree = sexpr.parse(text)
    except sexpr.SExprError as exc:
        raise ExprError(f"in {_clip(text)!r}: {exc}") from None
    return _from_sexpr(tree, frozenset(), "", 0)


def expr_from_data(data: Any) -> Expr:
    """Build an Expr from a string, list or one-key mapping (see the module docstring).

    Raises:
        ExprError: The structure is malformed; the message names the sub-path (`and[1].not`).
    """
    if isinstance(data, EXPR_TYPES):
        return parse_expr(to_sexpr(data))
    return _from_data(data, frozenset(), "", 0)


def to_sexpr(expr: Expr) -> str:
    """Write an Expr as an s-expression string (`parse_expr(to_sexpr(e)) == e`)."""
    return sexpr.to_text(_to_tree(expr))


def atoms(
    expr: Expr, scope: Mapping[str, str | None] | None = None
) -> Iterator[tuple[Atom, dict[str, str | None]]]:
    """Every atom of an expression with the variables in scope there (variable -> type or None)."""
    env = dict(scope or {})
    if isinstance(expr, Atom):
        yield expr, env
    elif isinstance(expr, Not):
        yield from atoms(expr.arg, env)
    elif isinstance(expr, (And, Or)):
        for e in expr.args:
            yield from atoms(e, env)
    else:
        inner = env | {p.var: p.type for p in expr.params}
        yield from atoms(expr.body, inner)


def is_ground_conjunction(expr: Expr) -> bool:
    """Whether `expr` is an atom, a negated atom, or an `and` of those, with no variables (an "
    "init state)."""
    if isinstance(expr, And):
        return all(is_ground_conjunction(e) for e in expr.args)
    if isinstance(expr, Not):
        expr = expr.arg
    return isinstance(expr, Atom) and not any(is_variable(a) for a in expr.args)


# -- internals --------------------------------------------------------------------------------


def _clip(text: str, n: int = 60) -> str:
    return text if len(text) <= n else text[: n - 3] + "..."


def _where(path: str) -> str:
    return f"at {path}: " if path else ""


def _to_tree(expr: Expr) -> sexpr.SExpr:
    if isinstance(expr, Atom):
        return [expr.pred, *expr.args]
    if isinstance(expr, Not):
        return ["not", _to_tree(expr.arg)]
    if isinstance(expr, (And, Or)):
        return ["and" if isinstance(expr, And) else "or", *(_to_tree(e) for e in expr.args)]
    params: list[sexpr.SExpr] = []
    for p in expr.params:
        params += [p.var, "-", p.type] if p.type else [p.var]
    return ["exists" if isinstance(expr, Exists) else "forall", params, _to_tree(expr.body)]


def _predicate(name: str, path: str) -> PredicateInfo:
    canon = _LOOKUP.get(name.lower())
    if canon is None:
        hint = difflib.get_close_matches(name, list(PREDICATES) + list(PREDICATE_ALIASES), n=3)
        extra = f"; did you mean {', '.join(hint)}?" if hint else ""
        raise ExprError(
            f"{_where(path)}unknown predicate {name!r}{extra} "
            f"(expected and, or, not, exists, forall or one of {', '.join(PREDICATES)})"
        )
    return PREDICATES[canon]


def _atom(name: str, args: list[Any], bound: frozenset[str], path: str) -> Atom:
    info = _predicate(name, path)
    if len(args) != info.arity:
        raise ExprError(
            f"{_where(path)}{info.name} takes {info.arity} argument(s), got {len(args)}"
        )
    out = []
    for i, a in enumerate(args):
        if not isinstance(a, str):
            raise ExprError(
                f"{_where(path)}argument {i + 1} of {info.name} must be a name, got {a!r}"
            )
        if _VAR.fullmatch(a):
            if a not in bound:
                raise ExprError(
                    f"{_where(path)}variable {a} is not bound by an enclosing exists/forall"
                )
        elif not _NAME.fullmatch(a):
            raise ExprError(
                f"{_where(path)}argument {a!r} of {info.name} is neither an object name "
                "(letters, digits, _) nor a ?variable"
            )
        out.append(a)
    return Atom(info.name, tuple(out))


def _check_type(t: str, path: str) -> str:
    try:
        return check_type(t)
    except VocabularyError as exc:
        raise ExprError(f"{_where(path)}{exc}") from None


def _params(items: list[Any], path: str) -> tuple[Param, ...]:
    params: list[Param] = []
    pending: list[str] = []
    i = 0
    while i < len(items):
        tok = items[i]
        if tok == "-":
            if not pending or i + 1 >= len(items) or not isinstance(items[i + 1], str):
                raise ExprError(f"{_where(path)}'-' must follow variables and precede a type name")
            t = _check_type(items[i + 1], path)
            params += [Param(v, t) for v in pending]
            pending = []
            i += 2
            continue
        if not isinstance(tok, str) or not _VAR.fullmatch(tok):
            raise ExprError(
                f"{_where(path)}expected a ?variable in the parameter list, got {tok!r}"
            )
        pending.append(tok)
        i += 1
    params += [Param(v) for v in pending]
    return _unique(params, path)


def _unique(params: list[Param], path: str) -> tuple[Param, ...]:
    if not params:
        raise ExprError(f"{_where(path)}a quantifier needs at least one ?variable")
    names = [p.var for p in params]
    dup = sorted({n for n in names if names.count(n) > 1})
    if dup:
        raise ExprError(f"{_where(path)}variable {dup[0]} is declared twice")
    return tuple(params)


def _from_sexpr(tree: sexpr.SExpr, bound: frozenset[str], path: str, depth: int) -> Expr:
    if depth > MAX_DEPTH:
        raise ExprError(f"{_where(path)}expression nested deeper than {MAX_DEPTH} levels")
    if isinstance(tree, str) or not tree or not isinstance(tree[0], str):
        raise ExprError(
            f"{_where(path)}expected '(keyword-or-predicate ...)', got {sexpr.to_text(tree)!r}"
        )
    head, rest = tree[0], tree[1:]
    key = head.lower()
    sub = f"{path}.{key}" if path else key
    if key in ("and", "or"):
        args = tuple(_from_sexpr(e, bound, f"{sub}[{i}]", depth + 1) for i, e in enumerate(rest))
        if key == "or" and not args:
            raise ExprError(f"{_where(path)}'or' needs at least one operand")
        return And(args) if key == "and" else Or(args)
    if key == "not":
        if len(rest) != 1:
            raise ExprError(f"{_where(path)}'not' takes exactly one operand, got {len(rest)}")
        return Not(_from_sexpr(rest[0], bound, sub, depth + 1))
    if key in ("exists", "forall"):
        if len(rest) != 2 or isinstance(rest[0], str):
            raise ExprError(f"{_where(path)}expected ({key} (?var - Type ...) expr)")
        params = _params(rest[0], sub)
        body = _from_sexpr(rest[1], bound | {p.var for p in params}, sub, depth + 1)
        return Exists(params, body) if key == "exists" else ForAll(params, body)
    for a in rest:
        if not isinstance(a, str):
            raise ExprError(
                f"{_where(path)}arguments of {head} must be names, got {sexpr.to_text(a)!r}"
            )
    return _atom(head, list(rest), bound, path)


def _from_data(data: Any, bound: frozenset[str], path: str, depth: int) -> Expr:
    if depth > MAX_DEPTH:
        raise ExprError(f"{_where(path)}expression nested deeper than {MAX_DEPTH} levels")
    if isinstance(data, str):
        try:
            tree = sexpr.parse(data)
        except sexpr.SExprError as exc:
            raise ExprError(f"{_where(path)}in {_clip(data)!r}: {exc}") from None
        return _from_sexpr(tree, bound, path, depth)
    if isinstance(data, list):
        return And(
            tuple(_from_data(e, bound, f"{path}[{i}]", depth + 1) for i, e in enumerate(data))
        )
    if not isinstance(data, dict) or len(data) != 1:
        raise ExprError(
            f"{_where(path)}expected an s-expression string, a list, or a mapping with exactly "
            "one key "
            f"(and, or, not, exists, forall or a predicate), got {_clip(repr(data))}"
        )
    ((head, value),) = data.items()
    if not isinstance(head, str):
        raise ExprError(f"{_where(path)}expected a keyword or predicate name as key, got {head!r}")
    key = head.lower()
    sub = f"{path}.{head}" if path else head
    if key in ("and", "or"):
        if not isinstance(value, list):
            raise ExprError(f"{_where(sub)}expected a list of expressions")
        args = tuple(_from_data(e, bound, f"{sub}[{i}]", depth + 1) for i, e in enumerate(value))
        if key == "or" and not args:
            raise ExprError(f"{_where(sub)}'or' needs at least one operand")
        return And(args) if key == "and" else Or(args)
    if key == "not":
        return Not(_from_data(value, bound, sub, depth + 1))
    if key in ("exists", "forall"):
        params, body = _quantifier_data(value, sub)
        inner = _from_data(body, bound | {p.var for p in params}, f"{sub}.body", depth + 1)
        return Exists(params, inner) if key == "exists" else ForAll(params, inner)
    terms = value if isinstance(value, list) else [value]
    return _atom(head, terms, bound, sub)


def _quantifier_data(value: Any, path: str) -> tuple[tuple[Param, ...], Any]:
    if not isinstance(value, dict) or set(value) != {"vars", "body"}:
        raise ExprError(f"{_where(path)}expected a mapping with keys 'vars' and 'body'")
    raw = value["vars"]
    if isinstance(raw, dict):
        items = list(raw.items())
    elif isinstance(raw, list):
        items = [(v, None) for v in raw]
    else:
        raise ExprError(f"{_where(path)}.vars: expected a mapping ?var -> Type or a list of ?vars")
    params = []
    for var, t in items:
        if not isinstance(var, str) or not _VAR.fullmatch(var):
            raise ExprError(f"{_where(path + '.vars')}expected a ?variable, got {var!r}")
        if t is not None and not isinstance(t, str):
            raise ExprError(f"{_where(path + '.vars')}type of {var} must be a type name, got {t!r}")
        params.append(Param(var, _check_type(t, path + ".vars") if t else None))
    return _unique(params, path), value["body"]
