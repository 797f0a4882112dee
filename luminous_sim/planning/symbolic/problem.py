"""PDDL problems over `luminous_domain.pddl` from a `WorldState` and a goal expression.

Identifiers follow ALFRED's escaping (spec 6.1: `-` -> `_minus_`, `|` -> `_bar_`, `+` -> `_plus_`,
`.` -> `_dot_`, `,` -> `_comma_`). Fixed receptacles are `receptacle`s, everything else an
`item`, each with its ALFRED type as an `rtype`/`otype` constant (`FridgeType`, `AppleType`);
`canContain`/`canContainObject` facts come from ALFRED's compatibility table. There is one
location per interaction place (`loc_` + the escaped id of the fixed container, see
`semantics.anchor`), plus `loc_start` when the agent stands nowhere yet. Like ALFRED's problems,
only the relevant objects are listed (`relevance`), and the goal is translated with the planner's
semantics (typed variables range over their exact type; a named sliceable object also stands for
its slices).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from importlib import resources

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, Not, Or, is_variable
from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic.relevance import Relevance, relevance
from luminous_sim.planning.symbolic.semantics import (
    AT_LOCATION,
    anchor,
    atom_true,
    prepare_goal,
    resolve,
)
from luminous_sim.states import WorldState
from luminous_sim.states.tables import (
    DEFAULT_SLICE_COUNTS,
    GATING_OPENABLE,
    SLICE_OF,
    slice_id,
)
from luminous_sim.tasks import MEANINGS
from luminous_sim.tasks.meanings import MACRO_PREDICATES, parents
from luminous_sim.vocab import FILLABLE, abilities, can_contain

ESCAPES: tuple[tuple[str, str], ...] = (
    ("-", "_minus_"),
    ("|", "_bar_"),
    ("+", "_plus_"),
    (".", "_dot_"),
    (",", "_comma_"),
)
"""ALFRED's identifier escapes (A gen/game_states/planned_game_state.py)."""

DOMAIN_CONSTANTS = frozenset(
    {
        "MicrowaveType",
        "FridgeType",
        "SinkBasinType",
        "BathtubBasinType",
        "KnifeType",
        "ButterKnifeType",
    }
)
AGENT = "agent0"
START = "loc_start"


def domain_text() -> str:
    """The text of `luminous_sim/planning/domain/luminous_domain.pddl`."""
    return (
        resources.files("luminous_sim.planning").joinpath("domain/luminous_domain.pddl").read_text()
    )


def pddl_name(object_id: str) -> str:
    """An object id as a PDDL name, escaped as ALFRED does (`Apple|+00.46` -> `Apple_bar__plus_00_dot_46`)."""
    out = object_id
    for raw, esc in ESCAPES:
        out = out.replace(raw, esc)
    return out if out[:1].isalpha() else "o_" + out


def location_name(place: str) -> str:
    """The PDDL location of an interaction place (an object id)."""
    return "loc_" + pddl_name(place)


def is_fixed_receptacle(object_type: str) -> bool:
    """Whether a type is a PDDL `receptacle` (a receptacle that cannot be picked up)."""
    ab = abilities(object_type)
    return ab.receptacle and not ab.pickupable


@dataclass
class PddlProblem:
    """A problem's text and the maps back from PDDL names (lower-cased) to ids."""

    text: str
    objects: dict[str, str] = field(default_factory=dict)
    locations: dict[str, str] = field(default_factory=dict)


def to_pddl_problem(
    state: WorldState,
    goal: Expr,
    name: str = "luminous",
    names: Mapping[str, str] | None = None,
    at: str | None = None,
) -> str:
    """A PDDL problem for `luminous_domain.pddl`.

    Args:
        state: the world state (objects, containment, states, held object).
        goal: any goal expression (translated with the planner's semantics, see the module docstring).
        name: the problem's name.
        names: goal constant -> object id.
        at: the place (object id) the agent stands at, if any.

    Returns:
        The problem text.
    """
    names = dict(names or {})
    prepared = prepare_goal(goal, state, names)
    return build_problem(state, prepared, names, at, relevance(state, prepared, names), name).text


def build_problem(
    state: WorldState,
    prepared: Expr,
    names: Mapping[str, str],
    at: str | None,
    rel: Relevance,
    name: str = "luminous",
) -> PddlProblem:
    """The problem for a prepared goal (`semantics.prepare_goal`) over the relevant objects."""
    return _Builder(state, prepared, dict(names), at, rel).build(name)


class _Builder:
    def __init__(
        self, state: WorldState, goal: Expr, names: dict[str, str], at: str | None, rel: Relevance
    ):
        self.s = state
        self.goal = goal
        self.names = names
        self.at = at
        self.ids = sorted(k for k in state.objects if k in rel.objects or rel.full)
        self.slices: dict[str, list[str]] = {}
        for k in self.ids:
            kind = state[k].object_type
            if abilities(kind).sliceable and not state[k].isSliced and kind in SLICE_OF:
                n = state.slice_counts.get(k, DEFAULT_SLICE_COUNTS.get(kind, 1))
                self.slices[k] = [slice_id(k, SLICE_OF[kind], i) for i in range(n)]
        self.pddl: dict[str, str] = {}
        for k in self.ids + [x for xs in self.slices.values() for x in xs]:
            self.pddl[k] = pddl_name(k)
        lowered: dict[str, str] = {}
        for k, v in self.pddl.items():
            if v.lower() in lowered:
                raise PlanningError(
                    f"objects {lowered[v.lower()]} and {k} have the same PDDL name {v}"
                )
            lowered[v.lower()] = k
        self.fresh = 0

    def type_of(self, oid: str) -> str:
        if oid in self.s:
            return self.s[oid].object_type
        return next(SLICE_OF[self.s[w].object_type] for w, xs in self.slices.items() if oid in xs)

    def kind(self, oid: str) -> str:
        return "receptacle" if is_fixed_receptacle(self.type_of(oid)) else "item"

    def build(self, name: str) -> PddlProblem:
        all_ids = list(self.pddl)
        places = sorted({anchor(self.s, k) for k in self.ids})
        locs = {location_name(p): p for p in places}
        goal_types = _param_types(self.goal)
        rtypes = sorted(
            {self.type_of(k) for k in all_ids if self.kind(k) == "receptacle"}
            | {t for t in goal_types if is_fixed_receptacle(t)}
        )
        otypes = sorted(
            {self.type_of(k) for k in all_ids if self.kind(k) == "item"}
            | {t for t in goal_types if not is_fixed_receptacle(t)}
        )
        objects = [f"{AGENT} - agent", *(f"{loc} - location" for loc in locs)]
        if self.at is None:
            objects.append(f"{START} - location")
        objects += [f"{t}Type - rtype" for t in rtypes if f"{t}Type" not in DOMAIN_CONSTANTS]
        objects += [f"{t}Type - otype" for t in otypes if f"{t}Type" not in DOMAIN_CONSTANTS]
        objects += [f"{self.pddl[k]} - {self.kind(k)}" for k in all_ids]
        init = [
            f"(atLocation {AGENT} {location_name(anchor(self.s, self.at)) if self.at else START})",
            "(= (total-cost) 0)",
        ]
        init += [
            f"(canContain {r}Type {o}Type)" for r in rtypes for o in otypes if can_contain(r, o)
        ]
        init += [
            f"(canContainObject {m}Type {o}Type)"
            for m in otypes
            if abilities(m).movable_receptacle
            for o in otypes
            if can_contain(m, o)
        ]
        for k in self.ids:
            init += self.facts(k)
        for whole, xs in self.slices.items():
            for x in xs:
                sliced = self.type_of(x)
                init += [
                    f"(objectType {self.pddl[x]} {sliced}Type)",
                    f"(sliceOf {self.pddl[x]} {self.pddl[whole]})",
                    f"(removed {self.pddl[x]})",
                    f"(pickupable {self.pddl[x]})",
                ]
        goal = self.expr(self.goal, {})
        text = "\n".join(
            [
                f"(define (problem {name})",
                "  (:domain luminous)",
                "  (:objects",
                *(f"    {o}" for o in objects),
                "  )",
                "  (:init",
                *(f"    {f}" for f in init),
                "  )",
                f"  (:goal {goal})",
                "  (:metric minimize (total-cost))",
                ")",
                "",
            ]
        )
        return PddlProblem(
            text,
            {v.lower(): k for k, v in self.pddl.items()},
            {k.lower(): v for k, v in locs.items()},
        )

    def facts(self, k: str) -> list[str]:
        s, n = self.s, self.pddl[k]
        o = s[k]
        ab = abilities(o.object_type)
        loc = location_name(anchor(s, k))
        out = []
        if self.kind(k) == "receptacle":
            out += [
                f"(receptacleType {n} {o.object_type}Type)",
                f"(receptacleAtLocation {n} {loc})",
            ]
        else:
            out.append(f"(objectType {n} {o.object_type}Type)")
            if s.held == k:
                out += [f"(holds {AGENT} {n})", f"(holdsAny {AGENT})"]
            else:
                out.append(f"(objectAtLocation {n} {loc})")
        for p in parents(s, k):
            pred = "inReceptacle" if is_fixed_receptacle(s[p].object_type) else "inReceptacleObject"
            if p in self.pddl:
                out.append(f"({pred} {n} {self.pddl[p]})")
        flags = {
            "pickupable": ab.pickupable,
            "openable": ab.openable,
            "gating": o.object_type in GATING_OPENABLE,
            "opened": o.isOpen,
            "toggleable": ab.toggleable,
            "isToggled": o.isToggled,
            "sliceable": ab.sliceable,
            "isSliced": o.isSliced,
            "fillable": o.object_type in FILLABLE,
            "isFilled": o.isFilledWithLiquid,
            "isDirty": o.isDirty,
            "isReceptacleObject": ab.movable_receptacle and ab.receptacle,
        }
        out += [f"({f} {n})" for f, v in flags.items() if v]
        for pred in MACRO_PREDICATES:  # the bookkeeping the macros keep
            if atom_true(s, None, pred, (k,)):
                out.append(f"({pred} {n})")
        out += [
            f"(faucetFor {n} {self.pddl[b]})"
            for f, b in s.faucet_basin.items()
            if f == k and b in self.pddl
        ]
        return out

    # -- goal ---------------------------------------------------------------------------------

    def expr(self, e: Expr, env: dict[str, str | None]) -> str:
        if isinstance(e, Atom):
            return self.atom(e, env)
        if isinstance(e, Not):
            return f"(not {self.expr(e.arg, env)})"
        if isinstance(e, (And, Or)):
            if not e.args:
                return "(and)" if isinstance(e, And) else "(or)"
            word = "and" if isinstance(e, And) else "or"
            return f"({word} {' '.join(self.expr(a, env) for a in e.args)})"
        inner = {**env, **{p.var: p.type for p in e.params}}
        decls = " ".join(f"{p.var} - {self.var_kind(p.type)}" for p in e.params)
        guards = [self.guard(p.var, p.type) for p in e.params]
        body = self.expr(e.body, inner)
        guard = guards[0] if len(guards) == 1 else f"(and {' '.join(guards)})"
        if isinstance(e, Exists):
            return f"(exists ({decls}) (and {guard} {body}))"
        return f"(forall ({decls}) (imply {guard} {body}))"

    @staticmethod
    def var_kind(kind: str | None) -> str:
        if kind is None:
            return "thing"
        return "receptacle" if is_fixed_receptacle(kind) else "item"

    def guard(self, var: str, kind: str | None) -> str:
        if kind is None:
            return f"(not (removed {var}))"
        if is_fixed_receptacle(kind):
            return f"(receptacleType {var} {kind}Type)"
        return f"(and (objectType {var} {kind}Type) (not (removed {var})))"

    def atom(self, a: Atom, env: dict[str, str | None]) -> str:
        options: list[list[str]] = []
        for arg in a.args:
            if is_variable(arg):
                options.append([arg])
                continue
            ids = resolve(arg, self.s, self.names)
            ids = [i for i in ids if i in self.pddl]
            for i in list(ids):
                ids += self.slices.get(i, [])
            if not ids:
                return "(or)"
            options.append(ids)
        alts = []
        for combo in _product(options):
            alts.append(self.ground(a.pred, combo, a.args, env))
        return alts[0] if len(alts) == 1 else f"(or {' '.join(alts)})"

    def ground(
        self, pred: str, combo: tuple[str, ...], raw: tuple[str, ...], env: dict[str, str | None]
    ) -> str:
        args = [c if is_variable(c) else self.pddl[c] for c in combo]
        if pred in ("inReceptacle", "inReceptacleObject"):
            second = combo[1]
            if is_variable(second):
                kind = env.get(second)
                movable = None if kind is None else not is_fixed_receptacle(kind)
            else:
                movable = not is_fixed_receptacle(self.type_of(second))
            if pred == "inReceptacleObject" or movable:
                return f"(inReceptacleObject {args[0]} {args[1]})"
            if movable is None:
                return f"(or (inReceptacle {args[0]} {args[1]}) (inReceptacleObject {args[0]} {args[1]}))"
            return f"(inReceptacle {args[0]} {args[1]})"
        if pred == "holds":
            return f"(holds {AGENT} {args[0]})"
        if pred == AT_LOCATION:
            self.fresh += 1
            lv = f"?l{self.fresh}"
            return (
                f"(exists ({lv} - location) (and (atLocation {AGENT} {lv}) "
                f"(or (objectAtLocation {args[0]} {lv}) (receptacleAtLocation {args[0]} {lv}))))"
            )
        return f"({MEANINGS[pred].pddl} {' '.join(args)})"


def _param_types(e: Expr) -> set[str]:
    """The types the goal's quantified variables are declared with."""
    if isinstance(e, Atom):
        return set()
    if isinstance(e, Not):
        return _param_types(e.arg)
    if isinstance(e, (And, Or)):
        return set().union(*(_param_types(a) for a in e.args)) if e.args else set()
    return {p.type for p in e.params if p.type} | _param_types(e.body)


def _product(options: list[list[str]]) -> list[tuple[str, ...]]:
    out: list[tuple[str, ...]] = [()]
    for opts in options:
        out = [(*t, o) for t in out for o in opts]
    return out
