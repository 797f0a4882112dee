"""Which objects and actions the search considers (a relevance filter over the scene).

Kept: what the goal names or quantifies over (the wholes a sliced type comes from, too), the tools
and devices its predicates need (knives for isSliced, microwaves for isHot, fridges for isCool,
sink basins with their faucets for isClean/isDirty/isFilled), movable receptacles that connect an
object to a receptacle that cannot hold it directly, the held object, and every container of
those. Put destinations are the goal's receptacles plus the fixed receptacles the kept objects
stand on (somewhere to set a knife down). `full=True` keeps everything: the solver's fallback when
the filtered search finds nothing.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from luminous_sim.cdf.predicates import (
    PREDICATES,
    And,
    Atom,
    Exists,
    Expr,
    ForAll,
    Not,
    Or,
    is_variable,
)
from luminous_sim.planning.symbolic.semantics import AT_LOCATION, constants, resolve
from luminous_sim.states import WorldState
from luminous_sim.states.tables import GATING_OPENABLE
from luminous_sim.tasks import MEANINGS
from luminous_sim.tasks.meanings import DEVICES, MACRO_PREDICATES, WASHING
from luminous_sim.vocab import FILLABLE, SLICED_TYPES, SLICING_TOOLS, abilities, can_contain

DEVICE_TYPES: dict[str, str] = {p: t for p, t in DEVICES.items() if p not in WASHING}
"""Predicate -> the device type whose macro makes it true (isHot: Microwave), washing apart."""
RECEPTACLE_PREDICATES = frozenset(p for p, m in MEANINGS.items() if m.achieved_by == "PutObject")


@dataclass(frozen=True)
class Relevance:
    """What the search may touch.

    Attributes:
        objects: ids kept in the search state (closed under containers).
        destinations: receptacles PutObject may target.
        openers: objects OpenObject may target.
        toggles: objects ToggleObject may target.
        devices: predicate (isHot/isCool/isClean) -> ids of the devices for its macro.
        named: ids the goal names (never merged by symmetry).
        full: whether nothing was filtered out.
    """

    objects: frozenset[str]
    destinations: frozenset[str]
    openers: frozenset[str]
    toggles: frozenset[str]
    devices: Mapping[str, tuple[str, ...]]
    named: frozenset[str]
    full: bool = False

    def restrict(self, state: WorldState) -> WorldState:
        """The state with only the kept objects (the rest of its fields unchanged)."""
        if self.full:
            return state
        return state.replace(objects={k: v for k, v in state.objects.items() if k in self.objects})


def _has_ability(object_type: str, ability: str | None) -> bool:
    if ability is None:
        return True
    if ability == "fillable":
        return object_type in FILLABLE
    return bool(getattr(abilities(object_type), ability, False))


def _typed(state: WorldState, object_type: str) -> list[str]:
    """Objects of a type, plus the unsliced wholes a sliced type will come from."""
    out = state.of_type(object_type)
    parent = SLICED_TYPES.get(object_type)
    if parent is not None:
        out += [k for k in state.of_type(parent) if not state[k].isSliced]
    return out


def _walk(expr: Expr, types: dict[str, str | None], positive: bool):
    if isinstance(expr, Atom):
        yield expr, types, positive
    elif isinstance(expr, Not):
        yield from _walk(expr.arg, types, not positive)
    elif isinstance(expr, (And, Or)):
        for e in expr.args:
            yield from _walk(e, types, positive)
    elif isinstance(expr, (Exists, ForAll)):
        yield from _walk(expr.body, {**types, **{p.var: p.type for p in expr.params}}, positive)


def basins_with_faucets(state: WorldState) -> list[str]:
    """Sink/bathtub basins that some faucet in the state serves."""
    return sorted({b for f, b in state.faucet_basin.items() if f in state and b in state})


def devices_of(state: WorldState) -> dict[str, tuple[str, ...]]:
    """Macro devices in a state: isHot -> microwaves, isCool -> fridges, isClean -> basins with a faucet."""
    return {
        p: tuple(basins_with_faucets(state))
        if p in WASHING
        else tuple(state.of_type(DEVICE_TYPES[p]))
        for p in MACRO_PREDICATES
    }


def relevance(
    state: WorldState, goal: Expr, names: Mapping[str, str], full: bool = False
) -> Relevance:
    """The relevance filter for a goal (NNF, see `semantics.prepare_goal`) in a state."""
    devices = devices_of(state)
    receptacles = [k for k, o in state.objects.items() if abilities(o.object_type).receptacle]
    if full:
        everything = frozenset(state.objects)
        every_opener = frozenset(
            k for k, o in state.objects.items() if abilities(o.object_type).openable
        )
        every_lamp = frozenset(
            k for k, o in state.objects.items() if o.object_type in ("DeskLamp", "FloorLamp")
        )
        named = _named(state, goal, names)
        return Relevance(
            everything,
            frozenset(receptacles),
            every_opener,
            every_lamp | _toggle_targets(state, goal, names),
            devices,
            named,
            full=True,
        )

    keep: set[str] = set()
    dests: set[str] = set()
    openers: set[str] = set()
    toggles: set[str] = set()
    used_devices: dict[str, tuple[str, ...]] = {k: () for k in devices}
    pairs: list[tuple[list[str], list[str]]] = []
    for atom, types, positive in _walk(goal, {}, True):
        cands = _candidates(atom, types, state, names)
        for c in cands:
            keep.update(c)
        pred = atom.pred
        if pred in RECEPTACLE_PREDICATES:
            dests.update(cands[1])
            pairs.append((cands[0], cands[1]))
        if pred in DEVICE_TYPES:
            used_devices[pred] = devices[pred]
        if pred in WASHING:
            wash = next(p for p in MACRO_PREDICATES if p in WASHING)  # isClean
            used_devices[wash] = devices[wash]
            keep.update(
                f for f, b in state.faucet_basin.items() if b in devices[wash] and f in state
            )
        if pred == "isSliced" or any(
            types.get(a) in SLICED_TYPES for a in atom.args if is_variable(a)
        ):
            keep.update(k for k, o in state.objects.items() if o.object_type in SLICING_TOOLS)
        if pred in ("isToggled", "isOn"):
            toggles.update(cands[0])
        if pred == "isOpen" and positive:
            openers.update(cands[0])
    for ids in used_devices.values():
        keep.update(ids)
        dests.update(ids)
    links = _connecting_movables(state, pairs)
    keep |= links
    dests |= links
    if state.held is not None:
        keep.add(state.held)
    keep |= dests
    keep |= {a for k in list(keep) for a in state.ancestors(k)}
    dests |= _parking(state, keep, receptacles)
    keep |= dests
    keep |= {a for k in list(keep) for a in state.ancestors(k)}
    for k in keep:
        obj = state[k]
        if obj.object_type in GATING_OPENABLE and (
            k in dests or any(k in state.ancestors(x) for x in keep)
        ):
            openers.add(k)
    openers.update(
        d for ids in used_devices.values() for d in ids if abilities(state[d].object_type).openable
    )
    return Relevance(
        frozenset(keep),
        frozenset(dests),
        frozenset(openers),
        frozenset(toggles),
        used_devices,
        _named(state, goal, names),
    )


def _candidates(
    atom: Atom, types: Mapping[str, str | None], state: WorldState, names: Mapping[str, str]
) -> list[list[str]]:
    info = PREDICATES.get(atom.pred)
    out = []
    for i, a in enumerate(atom.args):
        if not is_variable(a):
            out.append(resolve(a, state, names))
        elif (a_type := types.get(a)) is not None:
            out.append(_typed(state, a_type))
        else:
            need = info.abilities[i] if info is not None and atom.pred != AT_LOCATION else None
            out.append([k for k, o in state.objects.items() if _has_ability(o.object_type, need)])
    return out


def _connecting_movables(state: WorldState, pairs: list[tuple[list[str], list[str]]]) -> set[str]:
    """Movable receptacles m with o -> m -> r where r cannot hold o directly."""
    movables = [k for k, o in state.objects.items() if abilities(o.object_type).movable_receptacle]
    out: set[str] = set()
    for objs, recs in pairs:
        otypes = {state[o].object_type for o in objs}
        rtypes = {state[r].object_type for r in recs}
        for ot in otypes:
            for rt in rtypes:
                if can_contain(rt, ot):
                    continue
                out.update(
                    m
                    for m in movables
                    if can_contain(state[m].object_type, ot)
                    and can_contain(rt, state[m].object_type)
                )
    return out


def _parking(state: WorldState, keep: set[str], receptacles: list[str]) -> set[str]:
    """Fixed receptacles to set kept objects down on: where they stand now, else the first that fits."""
    out: set[str] = set()
    fixed = [r for r in receptacles if not abilities(state[r].object_type).pickupable]
    for k in sorted(keep):
        obj = state[k]
        if not abilities(obj.object_type).pickupable:
            continue
        parent = obj.parent
        if parent is not None and abilities(state[parent].object_type).receptacle:
            out.add(parent)
    for k in sorted(keep):
        obj = state[k]
        if not abilities(obj.object_type).pickupable:
            continue
        open_spots = [r for r in out if state[r].object_type not in GATING_OPENABLE]
        if any(can_contain(state[r].object_type, obj.object_type) for r in open_spots):
            continue
        spot = next(
            (
                r
                for r in fixed
                if state[r].object_type not in GATING_OPENABLE
                and can_contain(state[r].object_type, obj.object_type)
            ),
            None,
        )
        if spot is not None:
            out.add(spot)
    return out


def _named(state: WorldState, goal: Expr, names: Mapping[str, str]) -> frozenset[str]:
    out: set[str] = set()
    for c in constants(goal):
        out.update(resolve(c, state, names))
    return frozenset(out)


def _toggle_targets(state: WorldState, goal: Expr, names: Mapping[str, str]) -> frozenset[str]:
    out: set[str] = set()
    for atom, types, _ in _walk(goal, {}, True):
        if atom.pred in ("isToggled", "isOn"):
            out.update(_candidates(atom, types, state, names)[0])
    return frozenset(out)
