"""What a goal means to the planner: the task layer's predicates, plus where the agent stands.

Atoms are judged by the predicate table `luminous_sim.tasks.MEANINGS`, the one definition of the
goal predicates (the success check and ALFRED's counts use the same), so a plan that reaches the
planner's goal satisfies `goal_satisfied`. Quantified variables range over objects of exactly their type (all
objects when untyped); a name stands for its object, or for its slices once it was sliced.

The planner adds one predicate of ALFRED's PDDL, `atLocation(x)`: the agent stands at x's
interaction location (`anchor`). `prepare_goal` uses it for what must be seen (a predicate's
`seen` types in the table: lamps): a positive `isToggled`/`isOn` of a DeskLamp or FloorLamp also
asks the agent to end beside the lamp, as ALFRED's look_at_obj_in_light goal does (the evaluator
checks that the lamp is lit and visible).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Mapping

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Or, Param, is_variable
from luminous_sim.errors import PlanningError
from luminous_sim.states import WorldState
from luminous_sim.tasks import MEANINGS
from luminous_sim.vocab import abilities

AT_LOCATION = "atLocation"
"""The planner's extra predicate: the agent is at the argument's interaction location."""


def anchor(state: WorldState, object_id: str) -> str:
    """Where the agent stands to interact with an object: its innermost fixed container.

    The object itself if it cannot be picked up (a fridge, a lamp), else the first ancestor that
    cannot (the counter under a plate under an apple); an object resting on nothing is its own place.
    """
    chain = [object_id, *state.ancestors(object_id)]
    for oid in chain:
        obj = state.objects.get(oid)
        if obj is not None and not abilities(obj.object_type).pickupable:
            return oid
    return chain[-1]


def signature(state: WorldState, object_id: str) -> tuple:
    """What makes objects interchangeable: type, every state field, container and contents, bookkeeping."""
    obj = state[object_id]
    contents = tuple(sorted(state[c].object_type for c in state.contents(object_id)))
    books = tuple(object_id in getattr(state, k) for k in ("heated", "cooled", "cleaned"))
    return (
        obj.object_type,
        obj.parent,
        obj.isOpen,
        obj.isToggled,
        obj.isDirty,
        obj.isSliced,
        obj.temperature,
        obj.isCooked,
        obj.isFilledWithLiquid,
        obj.isPickedUp,
        contents,
        books,
    )


def resolve(name: str, state: WorldState, names: Mapping[str, str]) -> list[str]:
    """The ids a goal constant stands for: its object, or the slices of an object that was sliced.

    Raises:
        PlanningError: the name is neither mapped, an object id, nor a sliced object's id.
    """
    oid = names.get(name, name)
    if oid in state:
        return [oid]
    slices = [k for k in state.objects if k.startswith(oid + "|")]
    if not slices and name not in names:
        known = ", ".join(sorted(names)) or "none"
        raise PlanningError(
            f"goal names {name!r}, which is neither a mapped name ({known}) nor an object id"
        )
    return slices


def domain(param: Param, state: WorldState) -> list[str]:
    """The objects a quantified variable ranges over (exact type; all objects when untyped)."""
    return list(state.objects) if param.type is None else state.of_type(param.type)


def bindings(
    params: tuple[Param, ...], state: WorldState, env: Mapping[str, str]
) -> Iterator[dict[str, str]]:
    """Every assignment of the variables to objects, extending `env`."""
    for combo in itertools.product(*(domain(p, state) for p in params)):
        yield {**env, **{p.var: oid for p, oid in zip(params, combo)}}


def atom_true(state: WorldState, at: str | None, pred: str, ids: tuple[str, ...]) -> bool:
    """Whether a ground atom holds (the task layer's predicates, plus `atLocation`)."""
    if pred == AT_LOCATION:
        return ids[0] in state and at == anchor(state, ids[0])
    return MEANINGS[pred].holds(state, ids)


def ground_choices(
    atom: Atom, env: Mapping[str, str], state: WorldState, names: Mapping[str, str]
) -> list[tuple[str, ...]]:
    """The ground argument tuples an atom stands for (more than one when it names a sliced object)."""
    choices = [[env[a]] if is_variable(a) else resolve(a, state, names) for a in atom.args]
    return list(itertools.product(*choices))


def holds(
    expr: Expr,
    state: WorldState,
    at: str | None,
    names: Mapping[str, str],
    env: Mapping[str, str] | None = None,
) -> bool:
    """Whether a goal (with the planner's `atLocation`) holds in a state with the agent at `at`."""
    env = env or {}
    if isinstance(expr, Atom):
        return any(
            atom_true(state, at, expr.pred, g) for g in ground_choices(expr, env, state, names)
        )
    if isinstance(expr, Not):
        return not holds(expr.arg, state, at, names, env)
    if isinstance(expr, And):
        return all(holds(e, state, at, names, env) for e in expr.args)
    if isinstance(expr, Or):
        return any(holds(e, state, at, names, env) for e in expr.args)
    if isinstance(expr, Exists):
        return any(holds(expr.body, state, at, names, b) for b in bindings(expr.params, state, env))
    if isinstance(expr, ForAll):
        return all(holds(expr.body, state, at, names, b) for b in bindings(expr.params, state, env))
    raise PlanningError(f"not a goal expression: {expr!r}")


def nnf(expr: Expr, negate: bool = False) -> Expr:
    """Negation normal form: `not` only directly above atoms."""
    if isinstance(expr, Atom):
        return Not(expr) if negate else expr
    if isinstance(expr, Not):
        return nnf(expr.arg, not negate)
    if isinstance(expr, (And, Or)):
        args = tuple(nnf(e, negate) for e in expr.args)
        return (Or(args) if isinstance(expr, And) else And(args)) if negate else type(expr)(args)
    if isinstance(expr, (Exists, ForAll)):
        body = nnf(expr.body, negate)
        existential = isinstance(expr, Exists) != negate
        return Exists(expr.params, body) if existential else ForAll(expr.params, body)
    raise PlanningError(f"not a goal expression: {expr!r}")


def _seen_typed(
    arg: str,
    seen: frozenset[str],
    types: Mapping[str, str | None],
    state: WorldState,
    names: Mapping[str, str],
) -> bool:
    if is_variable(arg):
        return types.get(arg) in seen
    oid = names.get(arg, arg)
    return oid in state and state[oid].object_type in seen


def prepare_goal(expr: Expr, state: WorldState, names: Mapping[str, str]) -> Expr:
    """The goal the search pursues: NNF, with "end beside it" after each atom about what must be seen."""

    def walk(e: Expr, types: dict[str, str | None]) -> Expr:
        if isinstance(e, Atom):
            m = MEANINGS.get(e.pred)
            if m is not None and m.seen and _seen_typed(e.args[0], m.seen, types, state, names):
                return And((e, Atom(AT_LOCATION, e.args)))
            return e
        if isinstance(e, Not):
            return e
        if isinstance(e, (And, Or)):
            return type(e)(tuple(walk(a, types) for a in e.args))
        inner = {**types, **{p.var: p.type for p in e.params}}
        return type(e)(e.params, walk(e.body, inner))

    return walk(nnf(expr), {})


def constants(expr: Expr) -> set[str]:
    """The object names (not variables) an expression mentions."""
    if isinstance(expr, Atom):
        return {a for a in expr.args if not is_variable(a)}
    if isinstance(expr, Not):
        return constants(expr.arg)
    if isinstance(expr, (And, Or)):
        return set().union(*(constants(e) for e in expr.args)) if expr.args else set()
    return constants(expr.body)
