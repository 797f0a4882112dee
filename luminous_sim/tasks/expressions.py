"""Any goal expression evaluated on a pure `WorldState` (and/or/not, exists/forall, named objects).

Atoms are judged by the predicate table (`tasks.meanings`); containment follows AI2-THOR's
`parentReceptacles` (see `meanings.parents`).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Or, Param, is_variable
from luminous_sim.states import WorldState
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.meanings import MEANINGS, in_receptacle, is_clean, parents

__all__ = ["Evaluator", "goal_satisfied", "in_receptacle", "is_clean", "parents"]


class Evaluator:
    """Truth of goal expressions on one state, with named objects (see `goal_satisfied`)."""

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
        fn = MEANINGS[atom.pred].holds
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
    return Evaluator(state, names).holds(expr, {})
