"""Any goal expression evaluated on a pure `WorldState` (and/or/not, exists/forall, named objects).

Containment follows AI2-THOR's `parentReceptacles`: an object is in every receptacle of its chain
of ancestors up to and including the first one that is not a movable receptacle, so an apple on a
plate on the counter is in the plate and in the counter. The chain stops there because our scenes
nest fixtures (a microwave stands on a counter top, a basin belongs to a sink): an apple inside
the microwave is not on the counter.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterator, Mapping

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Or, Param, is_variable
from luminous_sim.states import WorldState
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.types import MOVABLE_RECEPTACLES
from luminous_sim.vocab import abilities

_MOVABLE = frozenset(MOVABLE_RECEPTACLES)


def parents(state: WorldState, object_id: str) -> list[str]:
    """The receptacles an object counts as in, innermost first (AI2-THOR's `parentReceptacles`).

    The chain of ancestors, cut after the first one that is not a movable receptacle.
    """
    out: list[str] = []
    for anc in state.ancestors(object_id):
        out.append(anc)
        if state[anc].object_type not in _MOVABLE:
            break
    return out


def in_receptacle(state: WorldState, object_id: str, receptacle_id: str) -> bool:
    """`inReceptacle(o, r)`: r is among o's parent receptacles."""
    return receptacle_id in parents(state, object_id)


def is_clean(state: WorldState, object_id: str) -> bool:
    """`isClean`: washed in a sink basin, or a dirtyable object that is not dirty."""
    o = state[object_id]
    return object_id in state.cleaned or (abilities(o.object_type).dirtyable and not o.isDirty)


_Pred = Callable[[WorldState, tuple[str, ...]], bool]
PREDICATE_FUNCTIONS: dict[str, _Pred] = {
    "inReceptacle": lambda s, a: in_receptacle(s, a[0], a[1]),
    "inReceptacleObject": lambda s, a: (
        s[a[1]].object_type in _MOVABLE and in_receptacle(s, a[0], a[1])
    ),
    # ALFRED's bookkeeping, as its evaluator counts: heated/cooled by the agent, so the slices of a
    # heated apple (new objects) are not "hot" however warm they are.
    "isHot": lambda s, a: a[0] in s.heated,
    "isCool": lambda s, a: a[0] in s.cooled,
    "isClean": lambda s, a: is_clean(s, a[0]),
    "isDirty": lambda s, a: s[a[0]].isDirty,
    "isSliced": lambda s, a: s[a[0]].isSliced,
    "isOn": lambda s, a: s[a[0]].isToggled,
    "isToggled": lambda s, a: s[a[0]].isToggled,
    "isOpen": lambda s, a: s[a[0]].isOpen,
    "isFilled": lambda s, a: s[a[0]].isFilledWithLiquid,
    "holds": lambda s, a: s.held == a[0],
    "=": lambda s, a: a[0] == a[1],
}
"""Predicate name -> its truth on a state, given object ids (the CDF's PREDICATES, all of them)."""


class _Evaluator:
    def __init__(self, state: WorldState, names: Mapping[str, str] | None):
        self.state = state
        self.names = dict(names or {})

    def objects(self, name: str) -> list[str]:
        """The ids a name stands for: its object, or the slices of an object that was sliced."""
        oid = self.names.get(name, name)
        if oid in self.state:
            return [oid]
        slices = [k for k in self.state.objects if k.startswith(oid + "|")]
        if not slices and name not in self.names:
            known = ", ".join(sorted(self.names)) or "none"
            raise TaskError(
                f"goal names {name!r}, which is neither a mapped name ({known}) nor an object id"
            )
        return slices

    def domain(self, param: Param) -> list[str]:
        if param.type is None:
            return list(self.state.objects)
        return self.state.of_type(param.type)

    def bindings(self, params: tuple[Param, ...], env: dict[str, str]) -> Iterator[dict[str, str]]:
        for combo in itertools.product(*(self.domain(p) for p in params)):
            yield env | {p.var: oid for p, oid in zip(params, combo)}

    def atom(self, atom: Atom, env: dict[str, str]) -> bool:
        fn = PREDICATE_FUNCTIONS[atom.pred]
        choices = [[env[a]] if is_variable(a) else self.objects(a) for a in atom.args]
        return any(fn(self.state, combo) for combo in itertools.product(*choices))

    def holds(self, expr: Expr, env: dict[str, str]) -> bool:
        if isinstance(expr, Atom):
            return self.atom(expr, env)
        if isinstance(expr, Not):
            return not self.holds(expr.arg, env)
        if isinstance(expr, And):
            return all(self.holds(e, env) for e in expr.args)
        if isinstance(expr, Or):
            return any(self.holds(e, env) for e in expr.args)
        if isinstance(expr, Exists):
            return any(self.holds(expr.body, b) for b in self.bindings(expr.params, env))
        if isinstance(expr, ForAll):
            return all(self.holds(expr.body, b) for b in self.bindings(expr.params, env))
        raise TaskError(f"not a goal expression: {expr!r}")

    def progress(self, expr: Expr) -> tuple[int, int]:
        """Satisfied and total conjuncts; an `exists` over a conjunction scores its best binding."""
        done = total = 0
        for part in _conjuncts(expr):
            if isinstance(part, Exists) and isinstance(part.body, And) and part.body.args:
                body = list(_conjuncts(part.body))
                best = 0
                for b in self.bindings(part.params, {}):
                    best = max(best, sum(self.holds(e, b) for e in body))
                    if best == len(body):
                        break
                done, total = done + best, total + len(body)
            else:
                done, total = done + self.holds(part, {}), total + 1
        return (done, total) if total else (1, 1)


def _conjuncts(expr: Expr) -> Iterator[Expr]:
    if isinstance(expr, And):
        for e in expr.args:
            yield from _conjuncts(e)
    else:
        yield expr


def goal_satisfied(expr: Expr, state: WorldState, names: Mapping[str, str] | None = None) -> bool:
    """Whether a goal expression holds in a state.

    Args:
        expr: any goal (atoms, and/or/not, exists/forall with typed or untyped variables).
        state: the world state.
        names: CDF object name -> object id; a name not listed is taken as an object id. A name
            whose object was sliced stands for its slices (an atom holds if it holds for one).

    Raises:
        TaskError: the goal names something that is neither a mapped name nor an object id.
    """
    return _Evaluator(state, names).holds(expr, {})


def conjunct_progress(
    expr: Expr, state: WorldState, names: Mapping[str, str] | None = None
) -> tuple[int, int]:
    """Goal-condition counts of a custom goal: (satisfied, total) over its top-level conjuncts.

    An `exists` over a conjunction counts each of its conjuncts, scored by the binding that
    satisfies the most of them; an empty goal counts as one satisfied condition.
    """
    return _Evaluator(state, names).progress(expr)
