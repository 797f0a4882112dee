"""What an object type can do or hold, for CDF validation: ALFRED's tables plus a few extras.

`vocab.can_contain` lists only pickupable objects. Appliances and lamps stand on furniture too
("a coffee machine on the counter top", paper section on CSSG): `STANDS_ON` adds those placements.
"""

from __future__ import annotations

from luminous_sim.errors import VocabularyError
from luminous_sim.vocab import FILLABLE, abilities, can_contain, receptacle_objects

_TABLES = frozenset(
    {"CounterTop", "DiningTable", "CoffeeTable", "SideTable", "Desk", "Dresser", "Shelf"}
)

STANDS_ON: dict[str, frozenset[str]] = {
    "CoffeeMachine": frozenset({"CounterTop", "DiningTable", "SideTable", "Shelf"}),
    "Toaster": frozenset({"CounterTop", "DiningTable", "SideTable", "Shelf"}),
    "Microwave": frozenset({"CounterTop", "DiningTable", "Shelf"}),
    "DeskLamp": _TABLES,
    "Lamp": _TABLES,
    "Television": frozenset({"TVStand", "Dresser", "Shelf", "SideTable", "Desk", "CounterTop"}),
    "HousePlant": _TABLES,
    "TeddyBear": frozenset({"Bed", "Sofa", "ArmChair", "Shelf", "Dresser"}),
    "PaperTowelRoll": frozenset({"CounterTop", "DiningTable", "Shelf"}),
}
"""Object type -> receptacle types it may stand on, beyond ALFRED's compatibility table."""

def has_ability(object_type: str, ability: str) -> bool:
    """Whether a known object type has an ability (a field of `vocab.Abilities`, or "fillable"); False when
    unknown."""
    try:
        if ability == "fillable":
            return object_type in FILLABLE
        return bool(getattr(abilities(object_type), ability))
    except VocabularyError:
        return False


def is_receptacle(object_type: str) -> bool:
    """Whether objects may be put on or in `object_type`."""
    return has_ability(object_type, "receptacle")


def can_support(receptacle_type: str, object_type: str) -> bool:
    """Whether `object_type` may be on/in `receptacle_type` (ALFRED's table or STANDS_ON)."""
    if not is_receptacle(receptacle_type):
        return False
    try:
        if can_contain(receptacle_type, object_type):
            return True
    except VocabularyError:
        return False
    return receptacle_type in STANDS_ON.get(object_type, frozenset())


def accepted_by(receptacle_type: str) -> list[str]:
    """Sorted object types `receptacle_type` accepts (for error messages)."""
    try:
        allowed = set(receptacle_objects(receptacle_type))
    except VocabularyError:
        return []
    allowed |= {t for t, on in STANDS_ON.items() if receptacle_type in on}
    return sorted(allowed)
