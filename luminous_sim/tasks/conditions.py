"""A goal compiled into named conditions (ManiSkill's `evaluate()` pattern).

One `GoalConditions` answers everything asked of a goal: `success`, ALFRED's goal-condition counts
(`alfred_counts`), the per-condition `progress` a dense reward uses, and the `subgoals` in the order
the oracle pursues them. Every answer comes from the goal's own conjuncts, judged by the predicate
table (`tasks.meanings`).

Two readings of a goal:

* An ALFRED task (`alfred=True`, spec/alfred.md section 1.2) is judged as ALFRED's evaluator judges
  it. Its goal ``(exists (vars) (and conjuncts))`` gives one condition per conjunct, each met by
  *some* objects of its own (a target name matches objects by type, `Apple` also its slices, with
  the ability the evaluator asks of that argument), plus one joint condition per group of conjuncts
  that share a variable (the same object heated *and* in place). `isSliced` is counted on its own
  ("a slice exists"). Variables declared distinct (`(not (= ?o1 ?o2))`, same type) are twins: their
  conjuncts merge into one condition of weight 2 that scores the objects meeting it, up to 2 (pick_two
  counts two apples in the same fridge). A lamp counts only while the agent sees it. ALFRED's "every
  receptacle closed" conjunct is not checked by its evaluator, so it is left out.
* A custom (CDF) goal is judged by `goal_satisfied`'s meaning: one condition per top-level conjunct;
  an `exists` over a conjunction gives one condition per conjunct, all scored on the binding that
  meets the most of them; an empty goal is one met condition.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Collection, Iterator, Mapping
from dataclasses import dataclass

from luminous_sim.cdf.predicates import (
    And,
    Atom,
    Exists,
    Expr,
    Not,
    Or,
    Param,
    is_variable,
    to_sexpr,
)
from luminous_sim.states import WorldState
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.expressions import Evaluator
from luminous_sim.tasks.meanings import MEANINGS
from luminous_sim.tasks.model import TaskInstance
from luminous_sim.tasks.types import closed_receptacles_goal, task_info
from luminous_sim.vocab import SLICED_TYPES, abilities

__all__ = [
    "PLAN_ORDER",
    "Condition",
    "GoalConditions",
    "compile_goal",
    "conjunct_progress",
    "matching",
    "task_conditions",
]

PLAN_ORDER: tuple[str, ...] = (
    "SliceObject",
    "PickupObject",
    "OpenObject",
    "HeatObject",
    "CoolObject",
    "CleanObject",
    "ToggleObject",
    "PutObject",
    "CloseObject",
)
"""The order in which an expert plan meets conditions, by the action that meets each: slicing first
(it replaces the object), then the object in hand and changed, then placed (ALFRED's expert plans)."""

Visible = Collection[str] | None
_Scores = Callable[[WorldState, Visible], tuple[int, ...]]


@dataclass(frozen=True)
class Condition:
    """One named goal condition.

    Attributes:
        name: stable and readable: `isHot(Apple)`, `inReceptacle(Apple, Fridge)`, a joint condition
            `isHot(Apple) & inReceptacle(Apple, Fridge)`, twins `inReceptacle(Mug, Cabinet) x2`.
        expr: the condition on its own, as a goal expression (what a planner pursues to meet it).
        weight: how many of ALFRED's goal conditions it counts for (2 for twins).
        stage: its place in `PLAN_ORDER` (the last action needed to meet it).
    """

    name: str
    expr: Expr
    weight: int = 1
    stage: int = len(PLAN_ORDER)


@dataclass(frozen=True)
class _Group:
    """Conditions scored together (one call gives each its score, 0..weight)."""

    conditions: tuple[Condition, ...]
    scores: _Scores


class GoalConditions:
    """A goal compiled into named conditions: the one source of success, counts, progress and subgoals."""

    def __init__(self, groups: tuple[_Group, ...]):
        self._groups = groups
        self.conditions: tuple[Condition, ...] = tuple(c for g in groups for c in g.conditions)
        """The conditions, in the goal's order (joint conditions after their parts)."""

    def scores(self, state: WorldState, visible: Visible = None) -> dict[str, int]:
        """Condition name -> how many of its `weight` ALFRED counts as met.

        Args:
            state: the world state, with the heated/cooled/cleaned bookkeeping.
            visible: ids the agent sees now (a lamp must be seen); None skips the visibility check.
        """
        out: dict[str, int] = {}
        for g in self._groups:
            out.update(zip((c.name for c in g.conditions), g.scores(state, visible)))
        return out

    def alfred_counts(self, state: WorldState, visible: Visible = None) -> tuple[int, int]:
        """(met, total): ALFRED's `goal_conditions_met`."""
        return sum(self.scores(state, visible).values()), sum(c.weight for c in self.conditions)

    def success(self, state: WorldState, visible: Visible = None) -> bool:
        """ALFRED's `goal_satisfied`: every condition is fully met."""
        met, total = self.alfred_counts(state, visible)
        return met == total

    def progress(self, state: WorldState, visible: Visible = None) -> dict[str, bool | float]:
        """Condition name -> met (a bool), or the fraction met for a condition of weight over 1."""
        scores = self.scores(state, visible)
        return {
            c.name: bool(scores[c.name]) if c.weight == 1 else scores[c.name] / c.weight
            for c in self.conditions
        }

    def subgoals(self) -> tuple[Condition, ...]:
        """The conditions in the order the oracle pursues them (`PLAN_ORDER`, then the goal's order)."""
        return tuple(sorted(self.conditions, key=lambda c: c.stage))

    def __repr__(self) -> str:
        return f"GoalConditions({', '.join(c.name for c in self.conditions)})"


def compile_goal(
    goal: Expr, names: Mapping[str, str] | None = None, alfred: bool = False
) -> GoalConditions:
    """Compile a goal expression into named conditions.

    Args:
        goal: the goal.
        names: CDF object name -> object id, for a goal that names objects.
        alfred: judge it as ALFRED's evaluator does (the goal must be a goal-library goal, see the
            module docstring); otherwise as a custom goal.

    Raises:
        TaskError: `alfred` and the goal is not ``(exists (vars) (and atoms...))``.
    """
    groups = _alfred_groups(goal) if alfred else _custom_groups(goal, dict(names or {}))
    return GoalConditions(tuple(groups))


def task_conditions(task: TaskInstance) -> GoalConditions:
    """A task's goal conditions: ALFRED's reading for the seven types, the goal's own for a custom task.

    Raises:
        TaskError: an unknown task type.
    """
    if task.custom:
        return compile_goal(task.goal, task.names)
    task_info(task.task_type)
    return compile_goal(task.goal, alfred=True)


def conjunct_progress(
    expr: Expr, state: WorldState, names: Mapping[str, str] | None = None
) -> tuple[int, int]:
    """Goal-condition counts of a custom goal: (satisfied, total) over its top-level conjuncts.

    An `exists` over a conjunction counts each of its conjuncts, scored by the binding that
    satisfies the most of them; an empty goal counts as one satisfied condition.
    """
    return compile_goal(expr, names).alfred_counts(state)


def matching(state: WorldState, name: str, ability: str) -> list[str]:
    """Ids of objects that match a target name and have an ability (`receptacle`, `pickupable`, ...).

    ALFRED's evaluator matches by substring of the object id; we match by type: `Apple` matches
    apples and their slices, `AppleSliced` only slices (not its accidents: `Pot` matching `Potato`).
    """
    return _alfred_domain(state, name, (ability,))


def _alfred_domain(state: WorldState, name: str | None, needs: Collection[str]) -> list[str]:
    if not name:
        return []
    return [
        k
        for k, o in state.objects.items()
        if name in (o.object_type, SLICED_TYPES.get(o.object_type))
        and all(getattr(abilities(o.object_type), a) for a in needs)
    ]


# -- names and stages -------------------------------------------------------------------------


def _render(expr: Expr, types: Mapping[str, str | None]) -> str:
    """`pred(Type, name)` for an atom (a variable shown by its type), `not ...`, else the s-expression."""
    if isinstance(expr, Atom):
        args = ", ".join((types.get(a) or a) if is_variable(a) else a for a in expr.args)
        return f"{expr.pred}({args})"
    if isinstance(expr, Not) and isinstance(expr.arg, Atom):
        return "not " + _render(expr.arg, types)
    return to_sexpr(expr)


def _stage(expr: Expr, positive: bool = True) -> int:
    """The `PLAN_ORDER` index of the last action a condition needs (unknown actions last)."""
    if isinstance(expr, Atom):
        m = MEANINGS.get(expr.pred)
        act = None if m is None else m.achieved_by if positive else m.undone_by
        return PLAN_ORDER.index(act) if act in PLAN_ORDER else len(PLAN_ORDER)
    if isinstance(expr, Not):
        return _stage(expr.arg, not positive)
    if isinstance(expr, (And, Or)):
        return max((_stage(e, positive) for e in expr.args), default=len(PLAN_ORDER))
    return _stage(expr.body, positive)


def _condition(name: str, expr: Expr, weight: int = 1) -> Condition:
    return Condition(name, expr, weight, _stage(expr))


def _unique_names(conds: list[Condition], taken: set[str]) -> tuple[Condition, ...]:
    out = []
    for c in conds:
        name, n = c.name, 1
        while name in taken:
            n += 1
            name = f"{c.name} #{n}"
        taken.add(name)
        out.append(Condition(name, c.expr, c.weight, c.stage))
    return tuple(out)


def _conjuncts(expr: Expr) -> Iterator[Expr]:
    if isinstance(expr, And):
        for e in expr.args:
            yield from _conjuncts(e)
    else:
        yield expr


def _params(variables: Collection[str], types: Mapping[str, str | None]) -> tuple[Param, ...]:
    return tuple(Param(v, types[v]) for v in variables)


# -- ALFRED's reading -------------------------------------------------------------------------


@dataclass(frozen=True)
class _Counted:
    """An ALFRED condition: atoms met together by one binding of `variables`; `twin` is counted."""

    atoms: tuple[Atom, ...]
    variables: tuple[str, ...]
    twin: str | None = None
    weight: int = 1


def _alfred_groups(goal: Expr) -> list[_Group]:
    closed = set(_conjuncts(closed_receptacles_goal()))
    parts = [p for p in _conjuncts(goal) if p not in closed]
    if len(parts) != 1 or not isinstance(parts[0], Exists):
        raise TaskError(f"not an ALFRED goal-library goal (exists over atoms): {to_sexpr(goal)}")
    types: dict[str, str | None] = {p.var: p.type for p in parts[0].params}
    twins: dict[str, str] = {}
    atoms: dict[Atom, int] = {}  # conjunct, twins renamed to the first of them -> how many merged
    for e in _conjuncts(parts[0].body):
        if isinstance(e, Not) and isinstance(e.arg, Atom) and e.arg.pred == "=":
            a, b = e.arg.args
            if is_variable(a) and is_variable(b) and types.get(a) == types.get(b):
                twins[b] = twins.get(a, a)
                continue
        if not isinstance(e, Atom) or not all(is_variable(a) for a in e.args):
            raise TaskError(
                f"not an ALFRED goal-library goal (exists over atoms): {to_sexpr(goal)}"
            )
        canon = Atom(e.pred, tuple(twins.get(a, a) for a in e.args))
        atoms[canon] = atoms.get(canon, 0) + 1
    reps = set(twins.values())
    counted = []
    for atom, n in atoms.items():
        variables = tuple(dict.fromkeys(atom.args))
        twin = next((v for v in variables if v in reps), None) if n > 1 else None
        counted.append(_Counted((atom,), variables, twin, n))
    joined = [c.atoms[0] for c in counted if MEANINGS[c.atoms[0].pred].joint]
    for component in _linked(joined):
        if len(component) > 1:
            variables = tuple(dict.fromkeys(a for atom in component for a in atom.args))
            counted.append(_Counted(tuple(component), variables))
    needs: dict[str, set[str]] = {v: set() for v in types}
    for atom in atoms:
        for arg, need in zip(atom.args, MEANINGS[atom.pred].alfred_match):
            if need is not None:
                needs[arg].add(need)

    def scores(state: WorldState, visible: Visible) -> tuple[int, ...]:
        domains = {v: _alfred_domain(state, types[v], needs[v]) for v in types}
        return tuple(_alfred_score(c, state, visible, domains) for c in counted)

    conds = [
        _condition(
            " & ".join(_render(a, types) for a in c.atoms)
            + (f" x{c.weight}" if c.weight > 1 else ""),
            Exists(_params(c.variables, types), c.atoms[0] if len(c.atoms) == 1 else And(c.atoms)),
            c.weight,
        )
        for c in counted
    ]
    return [_Group(_unique_names(conds, set()), scores)]


def _linked(atoms: list[Atom]) -> list[list[Atom]]:
    """The atoms grouped by shared variables (connected components, in the goal's order)."""
    groups: list[list[Atom]] = []
    for atom in atoms:
        hit = [g for g in groups if any(set(atom.args) & set(a.args) for a in g)]
        merged = [a for g in hit for a in g] + [atom]
        groups = [g for g in groups if g not in hit] + [merged]
    return groups


def _alfred_score(
    c: _Counted, state: WorldState, visible: Visible, domains: Mapping[str, list[str]]
) -> int:
    def met(env: Mapping[str, str]) -> bool:
        for atom in c.atoms:
            m = MEANINGS[atom.pred]
            ids = tuple(env[a] for a in atom.args)
            if not m.alfred(state, ids):
                return False
            if visible is not None and any(
                state[i].object_type in m.seen and i not in visible for i in ids
            ):
                return False
        return True

    free = [v for v in c.variables if v != c.twin]
    best = 0
    for combo in itertools.product(*(domains[v] for v in free)):
        env = dict(zip(free, combo))
        if c.twin is None:
            if met(env):
                return 1
            continue
        n = sum(met({**env, c.twin: oid}) for oid in domains[c.twin])
        best = max(best, min(n, c.weight))
    return best


# -- a custom goal ----------------------------------------------------------------------------


def _custom_groups(goal: Expr, names: dict[str, str]) -> list[_Group]:
    parts = list(_conjuncts(goal))
    if not parts:
        return [_Group((_condition("true", goal),), lambda state, visible: (1,))]
    groups: list[_Group] = []
    taken: set[str] = set()
    for part in parts:
        if isinstance(part, Exists) and isinstance(part.body, And) and part.body.args:
            body = tuple(_conjuncts(part.body))
            types = {p.var: p.type for p in part.params}
            conds = [_condition(_render(e, types), Exists(part.params, e)) for e in body]
            groups.append(
                _Group(_unique_names(conds, taken), _best_binding(part.params, body, names))
            )
        else:
            groups.append(
                _Group(
                    _unique_names([_condition(_render(part, {}), part)], taken), _whole(part, names)
                )
            )
    return groups


def _best_binding(
    params: tuple[Param, ...], body: tuple[Expr, ...], names: dict[str, str]
) -> _Scores:
    def scores(state: WorldState, visible: Visible) -> tuple[int, ...]:
        ev = Evaluator(state, names)
        best = (0,) * len(body)
        for env in ev.bindings(params, {}):
            flags = tuple(int(ev.holds(e, env)) for e in body)
            if sum(flags) > sum(best):
                best = flags
                if sum(best) == len(body):
                    break
        return best

    return scores


def _whole(part: Expr, names: dict[str, str]) -> _Scores:
    return lambda state, visible: (int(Evaluator(state, names).holds(part, {})),)
