"""ALFWorld's names for a room's things: the PDDL identifier of each object (AI2-THOR's id mangled as ALFRED's
planner mangles it: `|` -> `_bar_`, `-` -> `_minus_`, ...) and the name a text game shows for it ("apple 1",
"sinkbasin 2"), numbered as ALFWorld's `Demangler(shuffle=False)` numbers the entities of a game, so that
a command means the same object in ALFWorld's text env and in ours.

A basin keeps ALFRED's id shape (`Sink|x|y|z|SinkBasin`): ALFWorld names an id that contains "basin" by
the part before its first `|` plus "basin", so only that shape reads "sinkbasin"."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Mapping

from luminous_sim.vocab import BASINS

ESCAPES: tuple[tuple[str, str], ...] = (("-", "_minus_"), ("|", "_bar_"), ("+", "_plus_"), (".", "_dot_"),
                                        (",", "_comma_"))
"""ALFRED's identifier escapes, in the order its planner applies them."""


def mangle(text: str) -> str:
    """An AI2-THOR id (or a `loc|x|z|r|h` location) as a PDDL identifier, escaped as ALFRED escapes it."""
    for raw, escaped in ESCAPES:
        text = text.replace(raw, escaped)
    return text


def alfworld_id(object_id: str, object_type: str) -> str:
    """The AI2-THOR-style id ALFWorld would see for one of our objects: our id, except that a basin
    (`SinkBasin|x|y|z`) takes ALFRED's shape (`Sink|x|y|z|SinkBasin`)."""
    if object_type in BASINS and object_id.startswith(object_type + "|"):
        return object_type.removesuffix("Basin") + object_id[len(object_type):] + "|" + object_type
    return object_id


def demangled_names(entities: Iterable[str]) -> dict[str, str]:
    """The text name of each PDDL entity of a game, as ALFWorld's `Demangler(shuffle=False)` gives it.

    Entities are compared lower-cased, as TextWorld reads PDDL. Those without `_bar_` (types, the agent) keep
    their identifier as name; the others are named by the part before the first `_bar_` (plus "basin" when
    the identifier holds "basin"), each name's instances numbered from 1 in the reverse of the identifiers'
    sorted order (ALFWorld hands out the numbers last-first)."""
    ids = sorted({e.lower() for e in entities})
    stems = {i: _stem(i) for i in ids}
    numbers: dict[str, list[int]] = {name: list(range(1, n + 1))
                                     for name, n in Counter(s for s in stems.values() if s is not None).items()}
    out = {}
    for i in ids:
        stem = stems[i]
        out[i] = _unescape(i) if stem is None else f"{stem} {numbers[stem].pop()}"
    return out


def _stem(identifier: str) -> str | None:
    head, bar, _ = identifier.partition("_bar_")
    if not bar:
        return None
    return head + "basin" if "basin" in identifier else head


def _unescape(text: str) -> str:
    for raw, escaped in (("|", "_bar_"), ("-", "_minus_"), ("+", "_plus_"), (".", "_dot_"), (",", "_comma_")):
        text = text.replace(escaped, raw)
    return text


def names_of(ids: Mapping[str, str]) -> dict[str, str]:
    """Each of our object ids (mapped to its PDDL identifier in `ids`) to its ALFWorld text name; the
    numbering counts every entity given, so pass the game's whole set (locations included)."""
    named = demangled_names(ids.values())
    return {oid: named[pddl.lower()] for oid, pddl in ids.items()}
