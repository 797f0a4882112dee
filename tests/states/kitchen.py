"""The state-rule tests' kitchen (tests/kitchen.py's, with two more objects) and a state diff."""

from __future__ import annotations

from typing import Any

from luminous_sim.states import WorldState
from tests import kitchen as shared

LAYOUT = shared.with_(
    shared.KITCHEN, Egg_1=("Egg", "CounterTop|1"), ButterKnife_1=("ButterKnife", "CounterTop|1")
)
"""The shared kitchen with an egg and a butter knife on the counter (the fridge stays empty)."""


def kitchen(
    changes: dict[str, dict[str, Any]] | None = None, held: str | None = None, **kwargs: Any
) -> WorldState:
    """The kitchen, all closed and off, with per-object field changes and a held object."""
    return shared.kitchen(changes, held, layout=LAYOUT, **kwargs)


def diff(before: WorldState, after: WorldState) -> dict[str, dict[str, Any]]:
    """Changed fields per object id; a removed object maps to {"removed": True}, an added one to
    {"added": its type}."""
    out: dict[str, dict[str, Any]] = {}
    for oid, a in after.objects.items():
        b = before.get(oid)
        if b is None:
            out[oid] = {"added": a.object_type}
            continue
        changed = {k: v for k, v in vars(a).items() if getattr(b, k) != v}
        if changed:
            out[oid] = changed
    for oid in before.objects:
        if oid not in after:
            out[oid] = {"removed": True}
    return out
