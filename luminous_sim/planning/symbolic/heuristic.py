"""Goal distance: an estimate of the cost still to pay, and proof of infeasibility.

Each ground literal gets the cost of the few actions that would make it true (get the object in
hand, go, open, put, run the device), 0 exactly when it already holds; `and`/`forall` add,
`or`/`exists` take the least. The estimate is not admissible (shared steps are counted twice) but
it is informative, and it is infinite only when the literal can never hold from this state (no
microwave for `isHot`, a receptacle no chain of receptacles can fit, an undoable change), which lets
the search prune dead ends and lets `solve` refuse an impossible goal at once, saying why.

A variable of a sliced type (`?o - AppleSliced`) also ranges over the unsliced wholes it will come
from, at the cost of slicing them.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping

from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, ForAll, Not, Or, Param, is_variable
from luminous_sim.planning.symbolic.relevance import devices_of
from luminous_sim.planning.symbolic.semantics import (
    anchor,
    atom_true,
    constants,
    resolve,
    signature,
)
from luminous_sim.states import WorldState
from luminous_sim.states.tables import GATING_OPENABLE, SLICE_OF
from luminous_sim.tasks import MEANINGS
from luminous_sim.tasks.meanings import DEVICES, MACRO_ACTIONS
from luminous_sim.vocab import FILLABLE, SLICED_TYPES, SLICING_TOOLS, abilities, can_contain

INF = math.inf
MACRO = 5.0
_MACRO_OF = {action: pred for pred, action in MACRO_ACTIONS.items()}
"""Device macro -> the predicate it is named for (HeatObject -> isHot), from the predicate table."""
_CANNOT_MAKE = {
    "isDirty": "nothing makes {o} dirty",
    "=": "{o} and {r} are different objects",
}
"""Why a predicate no action makes true cannot be made true."""
_CANNOT_UNDO = {
    "isHot": "{o} was heated; that cannot be undone",
    "isCool": "{o} was cooled; that cannot be undone",
    "isClean": "nothing makes {o} dirty again",
    "isSliced": "{o} is sliced; that cannot be undone",
    "isFilled": "nothing empties {o}",
    "=": "two different objects are needed where there is only {o}",
}
"""Why a predicate no action makes false cannot be made false."""


def _mentions_sliced(expr: Expr, var: str) -> bool:
    if isinstance(expr, Atom):
        return expr.pred == "isSliced" and expr.args == (var,)
    if isinstance(expr, Not):
        return False
    if isinstance(expr, (And, Or)):
        return any(_mentions_sliced(e, var) for e in expr.args)
    return _mentions_sliced(expr.body, var)


class Estimator:
    """Goal-distance estimates for one goal (NNF) in states of one scene.

    Args:
        goal: the prepared goal (`semantics.prepare_goal`).
        names: goal constant -> object id.
        movable_types: movable receptacle types in the whole scene (for o -> movable -> r chains).
    """

    def __init__(self, goal: Expr, names: Mapping[str, str], movable_types: frozenset[str]):
        self.goal = goal
        self.names = dict(names)
        self.movable_types = movable_types
        self.reasons: list[str] = []
        self.named = frozenset(names.get(c, c) for c in constants(goal))

    def is_named(self, oid: str) -> bool:
        """Whether the goal names the object (or the whole it was sliced from)."""
        return oid in self.named or oid.rsplit("|", 1)[0] in self.named

    def __call__(self, state: WorldState, at: str | None) -> float:
        """The estimated cost from this state; infinite when the goal can no longer be reached."""
        self.reasons = []
        return _Node(self, state, at).cost(self.goal, {})


class _Node:
    """Per-state caches for one estimate."""

    def __init__(self, est: Estimator, state: WorldState, at: str | None):
        self.est = est
        self.s = state
        self.at = at
        self.held = state.held
        self._anchor: dict[str, str] = {}
        self._reach: dict[str, float] = {}
        self._devices: dict[str, tuple[str, ...]] | None = None
        self.stand_ins: frozenset[str] = frozenset()
        self._literal: dict[tuple[str, tuple[str, ...], bool], float] = {}

    # -- formula ------------------------------------------------------------------------------

    def cost(self, e: Expr, env: dict[str, str]) -> float:
        if isinstance(e, Atom):
            return min((self.literal(e.pred, g, True) for g in self._ground(e, env)), default=INF)
        if isinstance(e, Not):
            assert isinstance(e.arg, Atom), "the goal must be in negation normal form"
            return sum(self.literal(e.arg.pred, g, False) for g in self._ground(e.arg, env))
        if isinstance(e, And):
            if self._contradicts(e, env):
                return INF
            total = 0.0
            for a in e.args:
                total += self.cost(a, env)
                if total == INF:
                    break
            return total
        if isinstance(e, Or):
            return min((self.cost(a, env) for a in e.args), default=INF)
        if isinstance(e, Exists):
            best = INF
            for b, extra, stand_ins in self._bindings(e.params, env, proxies=True, body=e.body):
                saved = self.stand_ins
                self.stand_ins = saved | stand_ins
                best = min(best, extra + self.cost(e.body, b))
                self.stand_ins = saved
                if best == 0:
                    break
            if best == INF and not self.est.reasons:
                kinds = ", ".join(p.type or "object" for p in e.params)
                self.est.reasons.append(f"no binding of ({kinds}) can satisfy the goal")
            return best
        if isinstance(e, ForAll):
            total = 0.0
            for b, _, _ in self._bindings(e.params, env, proxies=False, body=e.body):
                total += self.cost(e.body, b)
                if total == INF:
                    break
            return total
        raise TypeError(f"not a goal expression: {e!r}")

    def _contradicts(self, e: And, env: dict[str, str]) -> bool:
        """Whether the conjunction asks for a ground atom and for its negation."""
        pos: set[tuple[str, tuple[str, ...]]] = set()
        neg: set[tuple[str, tuple[str, ...]]] = set()
        for a in e.args:
            if isinstance(a, Atom):
                atom, bucket = a, pos
            elif isinstance(a, Not):
                assert isinstance(a.arg, Atom), "the goal must be in negation normal form"
                atom, bucket = a.arg, neg
            else:
                continue
            ground = self._ground(atom, env)
            if len(ground) == 1:
                bucket.add((atom.pred, ground[0]))
        clash = pos & neg
        if clash:
            pred, ids = min(clash)
            self.est.reasons.append(f"the goal asks for ({pred} {' '.join(ids)}) and its negation")
        return bool(clash)

    def _ground(self, atom: Atom, env: Mapping[str, str]) -> list[tuple[str, ...]]:
        choices = [
            [env[a]] if is_variable(a) else resolve(a, self.s, self.est.names) for a in atom.args
        ]
        return list(itertools.product(*choices))

    def _domain(self, p: Param, proxies: bool) -> list[tuple[str, float]]:
        if p.type is None:
            return [(k, 0.0) for k in self.s.objects]
        out = [(k, 0.0) for k in self.s.of_type(p.type)]
        parent = SLICED_TYPES.get(p.type)
        if proxies and parent is not None:
            out += [(k, 1.0) for k in self.s.of_type(parent) if not self.s[k].isSliced]
        return out

    def _distinct(self, dom: list[tuple[str, float]], keep: int) -> list[tuple[str, float]]:
        """At most `keep` of each set of interchangeable objects (an `exists` needs no more)."""
        seen: dict[tuple, int] = {}
        out = []
        for oid, proxy in dom:
            if not self.est.is_named(oid):
                sig = (signature(self.s, oid), proxy)
                if seen.get(sig, 0) >= keep:
                    continue
                seen[sig] = seen.get(sig, 0) + 1
            out.append((oid, proxy))
        return out

    def _bindings(self, params: tuple[Param, ...], env: dict[str, str], proxies: bool, body: Expr):
        doms = [self._domain(p, proxies) for p in params]
        if proxies:  # an exists: interchangeable objects give the same cost
            doms = [self._distinct(d, len(params)) for d in doms]
        for combo in itertools.product(*doms):
            b = {**env, **{p.var: oid for p, (oid, _) in zip(params, combo)}}
            extra = 0.0
            stand_ins = frozenset(oid for oid, is_proxy in combo if is_proxy)
            for p, (oid, is_proxy) in zip(params, combo):
                if is_proxy and not _mentions_sliced(body, p.var):
                    extra += self.slice_cost(oid)
            yield b, extra, stand_ins

    # -- literals -----------------------------------------------------------------------------

    def literal(self, pred: str, ids: tuple[str, ...], positive: bool) -> float:
        if pred == "=" and not positive and ids[0] == ids[1] and ids[0] in self.stand_ins:
            return 0.0  # one whole stands for several slices to come
        key = (pred, ids, positive)
        c = self._literal.get(key)
        if c is None:
            c = self._literal[key] = self._literal_cost(pred, ids, positive)
        return c

    def _literal_cost(self, pred: str, ids: tuple[str, ...], positive: bool) -> float:
        if any(i not in self.s for i in ids):
            return INF if positive else 0.0
        true = atom_true(self.s, self.at, pred, ids)
        if true == positive:
            return 0.0
        c = self._positive(pred, ids) if positive else self._negative(pred, ids)
        return c

    def _fail(self, why: str) -> float:
        self.est.reasons.append(why)
        return INF

    def _positive(self, pred: str, ids: tuple[str, ...]) -> float:
        """Cost by the action the predicate table says makes the atom true."""
        o = ids[0]
        m = MEANINGS.get(pred)
        if m is None:
            return 1.0  # atLocation
        act = m.achieved_by
        if act == "PutObject":
            r = ids[1]
            if pred == "inReceptacleObject" and self.s[r].object_type not in self.est.movable_types:
                return self._fail(f"{r} is not a movable receptacle")
            return self.put_in(o, r)
        if act in _MACRO_OF:
            return self.device(o, _MACRO_OF[act], fill=pred == "isFilled")
        if act == "SliceObject":
            return self.slice_cost(o)
        if act == "ToggleObject":
            if not abilities(self.s[o].object_type).toggleable:
                return self._fail(f"{o} cannot be switched on")
            return self.goto(self.anchor(o)) + MACRO
        if act == "OpenObject":
            if not abilities(self.s[o].object_type).openable:
                return self._fail(f"{o} cannot be opened")
            return self.goto(self.anchor(o)) + 1
        if act == "PickupObject":
            return self.reach(o)
        return self._fail(_CANNOT_MAKE[pred].format(o=o, r=ids[-1]))

    def _negative(self, pred: str, ids: tuple[str, ...]) -> float:
        """Cost by the action the predicate table says makes the atom false."""
        o = ids[0]
        m = MEANINGS.get(pred)
        act = None if m is None else m.undone_by
        if m is None or act == "PutObject":
            return 1.0  # atLocation; holds: set it down
        if act == "PickupObject":  # take it out: pick up it or a movable receptacle holding it
            chain = [o, *self.s.ancestors(o)]
            movers = (
                [x for x in chain[: chain.index(ids[1])] if self.pickupable(x)]
                if ids[1] in chain
                else []
            )
            if not movers:
                return self._fail(f"nothing can take {o} out of {ids[1]}")
            return min(self.reach(x) for x in movers) + 2
        if act in _MACRO_OF:
            return self.device(o, _MACRO_OF[act])
        if act == "ToggleObject":
            return self.goto(self.anchor(o)) + MACRO
        if act == "CloseObject":
            return self.goto(self.anchor(o)) + 1
        return self._fail(_CANNOT_UNDO[pred].format(o=o))

    # -- action estimates ---------------------------------------------------------------------

    def anchor(self, o: str) -> str:
        a = self._anchor.get(o)
        if a is None:
            a = self._anchor[o] = anchor(self.s, o)
        return a

    def goto(self, place: str) -> float:
        return 0.0 if self.at == place else 1.0

    def pickupable(self, o: str) -> bool:
        return abilities(self.s[o].object_type).pickupable

    def closed_gates(self, o: str) -> int:
        return sum(
            1
            for a in self.s.ancestors(o)
            if self.s[a].object_type in GATING_OPENABLE and not self.s[a].isOpen
        )

    def reach(self, o: str) -> float:
        """Cost to have `o` in hand."""
        if self.held == o:
            return 0.0
        c = self._reach.get(o)
        if c is None:
            if not self.pickupable(o):
                c = self._fail(f"{o} ({self.s[o].object_type}) cannot be picked up")
            elif self.held is not None and self.held in self.s.ancestors(o):
                c = 3.0
            else:
                c = (
                    self.goto(self.anchor(o))
                    + self.closed_gates(o)
                    + 1
                    + (1 if self.held is not None else 0)
                )
            self._reach[o] = c
        return c

    def _place(self, o: str, r: str) -> float:
        """Cost to put `o`, once in hand, into `r`."""
        here = self.at if self.held == o else self.anchor(o)
        c = 0.0 if here == self.anchor(r) else 1.0
        robj = self.s[r]
        if robj.object_type in GATING_OPENABLE and not robj.isOpen:
            c += 1
        return c + self.closed_gates(r) + 1

    def _via_movable(self, otype: str, rtype: str) -> bool:
        return any(can_contain(m, otype) and can_contain(rtype, m) for m in self.est.movable_types)

    def put_in(self, o: str, r: str) -> float:
        """Cost to make `o` be in `r` (directly, by moving a movable receptacle holding it, or via one)."""
        otype, rtype = self.s[o].object_type, self.s[r].object_type
        best = INF
        if can_contain(rtype, otype) and self.pickupable(o):
            best = self.reach(o) + self._place(o, r)
        elif self.pickupable(o) and self._via_movable(otype, rtype):
            best = self.reach(o) + 6
        elif otype in SLICE_OF and not self.s[o].isSliced and can_contain(rtype, SLICE_OF[otype]):
            best = self.slice_cost(o) + 3  # only its slices fit (a Toaster takes BreadSliced)
        for m in self.s.ancestors(o):
            if m == r or not abilities(self.s[m].object_type).movable_receptacle:
                break
            if can_contain(rtype, self.s[m].object_type):
                best = min(best, self.reach(m) + self._place(m, r))
        if best == INF:
            return self._fail(f"{o} ({otype}) cannot be put in {r} ({rtype})")
        return best

    def devices(self) -> dict[str, tuple[str, ...]]:
        if self._devices is None:
            self._devices = devices_of(self.s)
        return self._devices

    def device(self, o: str, pred: str, fill: bool = False) -> float:
        """Cost to heat/cool/wash `o` with its device macro."""
        dtype, word = DEVICES[pred], pred.removeprefix("is").lower()
        otype = self.s[o].object_type
        if fill and otype not in FILLABLE:
            return self._fail(f"{o} ({otype}) cannot hold water")
        devs = self.devices()[pred]
        if not devs:
            what = "SinkBasin with a Faucet" if pred == "isClean" else dtype
            return self._fail(f"no {what} in the scene: cannot make {o} {word}")
        if pred == "isCool":
            fridge = next((a for a in self.s.ancestors(o) if a in devs), None)
            if fridge is not None:
                return self.goto(fridge) + (1.0 if self.s[fridge].isOpen else 2.0)
        fits = [d for d in devs if can_contain(self.s[d].object_type, otype)]
        if fits and self.pickupable(o):
            return self.reach(o) + min(self.goto(d) for d in fits) + MACRO
        if self.pickupable(o) and any(
            self._via_movable(otype, self.s[d].object_type) for d in devs
        ):
            return self.reach(o) + 3 + MACRO
        return self._fail(f"{o} ({otype}) cannot go in a {dtype}: cannot make it {word}")

    def slice_cost(self, o: str) -> float:
        """Cost to slice `o` (fetch a knife, go to `o`, slice)."""
        obj = self.s[o]
        if obj.isSliced:
            return 0.0
        if not abilities(obj.object_type).sliceable:
            return self._fail(f"{o} ({obj.object_type}) cannot be sliced")
        knives = [k for k, v in self.s.objects.items() if v.object_type in SLICING_TOOLS]
        if not knives:
            return self._fail(f"no Knife or ButterKnife in the scene: cannot slice {o}")
        held = self.s.get(self.held)
        knife = (
            0.0
            if held is not None and held.object_type in SLICING_TOOLS
            else min(self.reach(k) for k in knives)
        )
        return knife + (2.0 if self.held == o else 0.0) + 1.0 + MACRO
