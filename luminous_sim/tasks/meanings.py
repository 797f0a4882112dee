"""What each goal predicate means: the one table read by goal evaluation and by the symbolic planner.

For every predicate of `luminous_sim.cdf.PREDICATES` it holds the truth on a `WorldState` (what
`goal_satisfied` and the planner judge), ALFRED's evaluator's own reading where it differs
(spec/alfred.md section 1.2: it reads the agent's bookkeeping), how ALFRED counts it, its name in
`planning/domain/luminous_domain.pddl`, and the high-level actions that make it true or false (the
planner's heuristic and relevance filter dispatch on these).

Containment follows AI2-THOR's `parentReceptacles`: an object is in every receptacle of its chain
of ancestors up to and including the first one that is not a movable receptacle, so an apple on a
plate on the counter is in the plate and in the counter. The chain stops there because our scenes
nest fixtures (a microwave stands on a counter top, a basin belongs to a sink): an apple inside
the microwave is not on the counter.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from luminous_sim.states import WorldState
from luminous_sim.vocab import LAMPS, MOVABLE_RECEPTACLES, SLICED_TYPES, abilities

_MOVABLE = frozenset(MOVABLE_RECEPTACLES)

Check = Callable[[WorldState, tuple[str, ...]], bool]
"""A predicate's truth on a state, given the object ids of its arguments."""


def parents(state: WorldState, object_id: str) -> list[str]:
    """The receptacles an object counts as in, innermost first (AI2-THOR's `parentReceptacles`;
    `WorldState.parent_receptacles`)."""
    return state.parent_receptacles(object_id)


def in_receptacle(state: WorldState, object_id: str, receptacle_id: str) -> bool:
    """`inReceptacle(o, r)`: r is among o's parent receptacles."""
    return receptacle_id in parents(state, object_id)


def is_clean(state: WorldState, object_id: str) -> bool:
    """`isClean`: washed in a sink basin, or a dirtyable object that is not dirty."""
    o = state[object_id]
    return object_id in state.cleaned or (abilities(o.object_type).dirtyable and not o.isDirty)


@dataclass(frozen=True)
class PredicateMeaning:
    """One goal predicate.

    Attributes:
        name: the CDF predicate name.
        holds: its truth on a state (the goal's meaning, for success and for the planner).
        pddl: the domain predicate it stands for (`isOpen` is the domain's `opened`).
        achieved_by: the high-level action that makes it true (None: no action can).
        undone_by: the high-level action that makes it false (None: none can, once true).
        device: the device type whose macro (`achieved_by`) makes it true, for the three macros.
        evaluator: ALFRED's evaluator's reading when it differs from `holds`.
        joint: whether ALFRED also counts it jointly with the goal's other conjuncts on one binding
            (`isSliced` is counted on its own: "a slice exists").
        seen: object types ALFRED's evaluator counts only while the agent sees them (a lit lamp);
            the planner ends its plan beside them.
        alfred_match: the ability ALFRED's evaluator requires of each argument's candidates.
    """

    name: str
    holds: Check
    pddl: str
    achieved_by: str | None
    undone_by: str | None
    device: str | None = None
    evaluator: Check | None = None
    joint: bool = True
    seen: frozenset[str] = frozenset()
    alfred_match: tuple[str | None, ...] = ("pickupable",)

    def alfred(self, state: WorldState, ids: tuple[str, ...]) -> bool:
        """Whether ALFRED's evaluator counts the atom as met (without the visibility of `seen`)."""
        return (self.evaluator or self.holds)(state, ids)


def _toggled(name: str) -> PredicateMeaning:
    return PredicateMeaning(
        name,
        lambda s, a: s[a[0]].isToggled,
        "isToggled",
        "ToggleObject",
        "ToggleObject",
        seen=frozenset(LAMPS),
        alfred_match=("toggleable",),
    )


_TABLE: tuple[PredicateMeaning, ...] = (
    PredicateMeaning(
        "inReceptacle",
        lambda s, a: in_receptacle(s, a[0], a[1]),
        "inReceptacle",
        "PutObject",
        "PickupObject",
        alfred_match=("pickupable", "receptacle"),
    ),
    PredicateMeaning(
        "inReceptacleObject",
        lambda s, a: s[a[1]].object_type in _MOVABLE and in_receptacle(s, a[0], a[1]),
        "inReceptacleObject",
        "PutObject",
        "PickupObject",
        alfred_match=("pickupable", "pickupable"),
    ),
    # ALFRED's bookkeeping, as its evaluator counts: heated/cooled by the agent, so the slices of a
    # heated apple (new objects) are not "hot" however warm they are.
    PredicateMeaning(
        "isHot", lambda s, a: a[0] in s.heated, "isHot", "HeatObject", None, device="Microwave"
    ),
    PredicateMeaning(
        "isCool", lambda s, a: a[0] in s.cooled, "isCool", "CoolObject", None, device="Fridge"
    ),
    PredicateMeaning(
        "isClean",
        lambda s, a: is_clean(s, a[0]),
        "isClean",
        "CleanObject",
        None,
        device="SinkBasin",
        evaluator=lambda s, a: a[0] in s.cleaned,  # washed by the agent, not merely not dirty
    ),
    PredicateMeaning("isDirty", lambda s, a: s[a[0]].isDirty, "isDirty", None, "CleanObject"),
    PredicateMeaning(
        "isSliced",
        lambda s, a: s[a[0]].isSliced,
        "isSliced",
        "SliceObject",
        None,
        evaluator=lambda s, a: s[a[0]].object_type in SLICED_TYPES,  # "a slice exists"
        joint=False,
    ),
    _toggled("isOn"),
    _toggled("isToggled"),
    PredicateMeaning("isOpen", lambda s, a: s[a[0]].isOpen, "opened", "OpenObject", "CloseObject"),
    # filled under the faucet, as washing is
    PredicateMeaning(
        "isFilled", lambda s, a: s[a[0]].isFilledWithLiquid, "isFilled", "CleanObject", None
    ),
    PredicateMeaning("holds", lambda s, a: s.held == a[0], "holds", "PickupObject", "PutObject"),
    PredicateMeaning("=", lambda s, a: a[0] == a[1], "=", None, None, alfred_match=(None, None)),
)

MEANINGS: dict[str, PredicateMeaning] = {m.name: m for m in _TABLE}
"""Goal predicate name -> its meaning (every predicate of `luminous_sim.cdf.PREDICATES`)."""

MACRO_ACTIONS: dict[str, str] = {
    m.name: m.achieved_by for m in _TABLE if m.device is not None and m.achieved_by is not None
}
"""Predicate -> the device macro that makes it true (isHot: HeatObject), in table order."""
DEVICES: dict[str, str] = {m.name: m.device for m in _TABLE if m.device is not None}
"""Predicate -> the type of the device its macro runs (isHot: Microwave, isClean: SinkBasin)."""
MACRO_PREDICATES: tuple[str, ...] = tuple(MACRO_ACTIONS)
"""The predicates a device macro makes true (isHot, isCool, isClean), in table order."""

WASHING: frozenset[str] = frozenset(
    m.name for m in _TABLE if "CleanObject" in (m.achieved_by, m.undone_by)
)
"""The predicates a sink basin under a running faucet changes (isClean, isDirty, isFilled)."""
