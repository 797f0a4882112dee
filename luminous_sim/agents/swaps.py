"""Counterfactual parents for training the instruction parser: an annotation's words with the parent's name
swapped for another receptacle's, and its label with it (entity substitution). ALFRED's train split never
asks for a bowl, pot or pan as the place to put something, so a parser learnt from it alone reads "put a hot
apple in the pot" as the movable-receptacle task; swapping names teaches it that the parent is where the
directive puts the object, whatever its name. Only ALFRED's own sentences are used. Torch-free."""

from __future__ import annotations

import random
from collections.abc import Sequence
from dataclasses import replace
from functools import cache

from luminous_sim.agents.annotations import Annotated
from luminous_sim.agents.mentions import mentions
from luminous_sim.language.names import spoken
from luminous_sim.language.speaker import tokenize
from luminous_sim.vocab import OBJECTS, SLICED_TYPES, abilities, can_contain

TOOLS: dict[str, frozenset[str]] = {
    "pick_clean_then_place_in_recep": frozenset({"Sink", "SinkBasin"}),
    "pick_heat_then_place_in_recep": frozenset({"Microwave"}),
    "pick_cool_then_place_in_recep": frozenset({"Fridge"}),
}
"""The receptacle a task type uses on the way (never its parent in a swap)."""


@cache
def receptacles() -> tuple[str, ...]:
    """Every receptacle type, sorted: the parents a swap may choose from."""
    return tuple(sorted(t for t in OBJECTS if abilities(t).receptacle))


def parent_choices(e: Annotated) -> tuple[str, ...]:
    """The receptacles that may hold what the annotation's task places (its movable receptacle, or its object,
    sliced where the task slices it), other than the task's own objects and tool."""
    sliced = f"{e.params['object_target']}Sliced"
    held = e.params["mrecep_target"] or (sliced if e.params["object_sliced"] and sliced in SLICED_TYPES
                                         else e.params["object_target"])
    own = {e.params["object_target"], e.params["mrecep_target"]} | TOOLS.get(e.task_type, frozenset())
    return tuple(r for r in receptacles() if r not in own and can_contain(r, held))


def swap_parent(words: Sequence[str], e: Annotated, rng: random.Random) -> tuple[list[str], Annotated] | None:
    """`words` (an input of annotation `e`) with every name of its parent replaced by a receptacle's named
    nowhere else in them, and the annotation relabelled; None where the parent is unnamed (or named by a word
    that may also mean another of its objects) or no receptacle is left."""
    parent = e.params["parent_target"]
    if not parent:
        return None
    found = mentions(words)
    others = {e.params[s] for s in ("object_target", "mrecep_target", "toggle_target")} - {""}
    hits = [m for m in found if parent in m.types and not m.types & others]
    named = {t for m in found for t in m.types}
    choices = [r for r in parent_choices(e) if r not in named]
    if not hits or not choices:
        return None
    new = rng.choice(choices)
    name = tokenize(spoken(new))
    out: list[str] = []
    at = 0
    for m in hits:
        out += [*words[at:m.start], *name]
        at = m.end
    out += words[at:]
    return out, replace(e, params={**e.params, "parent_target": new})
