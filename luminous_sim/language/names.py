"""How objects are named in instructions, as people write them: words, not type names ("dish sponge",
"stove burner", "TV stand"), with articles ("a mug", "an apple", "some bread"), plurals ("two knives",
"two slices of apple") and the preposition a receptacle takes ("on the counter", "in the fridge").

Names come from the type's CamelCase parts, lower-cased, except for the irregular ones in `SPECIAL`.
"""

from __future__ import annotations

import re
from functools import cache

SPECIAL: dict[str, str] = {
    "TVStand": "TV stand", "CD": "CD", "CounterTop": "counter", "SinkBasin": "sink", "BathtubBasin": "bathtub",
    "GarbageCan": "garbage can", "Glassbottle": "glass bottle", "ArmChair": "armchair", "BasketBall": "basketball",
    "Television": "television", "Footstool": "footstool", "Newspaper": "newspaper", "Laptop": "laptop",
    "ToiletPaper": "toilet paper", "PaperTowelRoll": "paper towel roll", "SoapBar": "bar of soap",
    "HousePlant": "house plant", "KeyChain": "key chain", "CellPhone": "cell phone",
}
"""Types whose name is not their CamelCase parts lower-cased."""

PLURALS: dict[str, str] = {
    "knife": "knives", "butter knife": "butter knives", "bar of soap": "bars of soap", "shelf": "shelves",
    "loaf of bread": "loaves of bread", "head of lettuce": "heads of lettuce", "toilet paper": "rolls of toilet paper",
    "boots": "pairs of boots", "blinds": "blinds", "curtains": "curtains", "CD": "CDs", "TV stand": "TV stands",
}
"""Plurals that are not the name plus "s" or "es"."""

MASS: dict[str, str] = {"Bread": "loaf of bread", "Lettuce": "head of lettuce", "ToiletPaper": "roll of toilet paper"}
"""Types whose name is a mass noun ("the bread"), with the unit one of them is counted in ("a loaf of bread")."""

PLURAL_ONLY = frozenset({"Boots", "Blinds", "Curtains"})
"""Types named by a plural ("the boots", "some boots")."""

IN: frozenset[str] = frozenset({
    "Fridge", "Microwave", "Cabinet", "Drawer", "Box", "Safe", "Sink", "SinkBasin", "Bathtub", "BathtubBasin",
    "GarbageCan", "LaundryHamper", "Mug", "Cup", "Bowl", "Pot", "Pan", "CoffeeMachine", "Toaster", "Kettle",
    "Vase",
})
"""Receptacles things go *in*; everything else they go *on* ("on the counter", "on the shelf")."""

_VOWEL_SOUND = re.compile(r"^(?:[aeio]|u(?!s[aeiou]|ni|ten)|hour|[FHLMNRSX][A-Z]*\b)")
_PARTS = re.compile(r"[A-Z]+(?![a-z])|[A-Z][a-z]*|[a-z]+|\d+")


@cache
def spoken(object_type: str) -> str:
    """The object's name: `CoffeeMachine` -> "coffee machine"; `AppleSliced` -> "slice of apple"."""
    if object_type.endswith("Sliced"):
        return f"slice of {spoken(object_type[:-6])}"
    if object_type in SPECIAL:
        return SPECIAL[object_type]
    words = _PARTS.findall(object_type)
    return " ".join(w if w.isupper() and len(w) > 1 else w.lower() for w in words)


def _counted(object_type: str) -> str:
    """The name one of the objects is counted by ("loaf of bread", "mug")."""
    return MASS.get(object_type, spoken(object_type))


def pluralise(noun: str) -> str:
    """A noun phrase's plural, on its head noun: "mug" -> "mugs", "box" -> "boxes", "slice of apple" ->
    "slices of apple", "butter knife" -> "butter knives"."""
    if noun in PLURALS:
        return PLURALS[noun]
    head, sep, rest = noun.partition(" of ")
    if sep:
        return f"{pluralise(head)} of {rest}"
    *first, last = noun.split(" ")
    if last in PLURALS:
        word = PLURALS[last]
    elif re.search(r"(s|x|z|ch|sh)$", last):
        word = last + "es"
    elif re.search(r"[^aeiou]y$", last):
        word = last[:-1] + "ies"
    elif re.search(r"[^aeiou]o$", last) and last in ("potato", "tomato"):
        word = last + "es"
    else:
        word = last + "s"
    return " ".join([*first, word])


def plural(object_type: str) -> str:
    """The plural name: `Pencil` -> "pencils", `Knife` -> "knives", `AppleSliced` -> "slices of apple"."""
    if object_type in PLURAL_ONLY:
        return spoken(object_type)
    return pluralise(_counted(object_type))


def indefinite_article(phrase: str) -> str:
    """ "a" or "an" for a phrase, by how its first word sounds ("an apple", "a CD", "an umbrella", "a usb")."""
    return "an" if _VOWEL_SOUND.match(phrase) else "a"


def indefinite(object_type: str, adjective: str = "") -> str:
    """ "a mug", "an apple", "a clean slice of apple", "a loaf of bread", "some boots"; with an adjective
    before the name ("a hot potato")."""
    name = _counted(object_type)
    phrase = f"{adjective} {name}" if adjective else name
    if object_type in PLURAL_ONLY:
        return f"some {phrase}"
    return f"{indefinite_article(phrase)} {phrase}"


def definite(object_type: str, adjective: str = "") -> str:
    """ "the mug", "the bread", "the hot slice of apple"."""
    name = spoken(object_type)
    return f"the {adjective} {name}" if adjective else f"the {name}"


def preposition(receptacle_type: str) -> str:
    """ "in" (fridge, drawer, cabinet, microwave, sink, box, bowl, mug, pot, garbage can, ...) or "on"."""
    return "in" if receptacle_type in IN else "on"


def words_of(object_type: str) -> set[str]:
    """Every word an object's names use (singular, plural, counted), lower-cased."""
    text = " ".join((spoken(object_type), plural(object_type), indefinite(object_type)))
    return set(re.findall(r"[a-z0-9]+", text.lower()))


@cache
def type_from_word(word: str) -> str:
    """A type from its lower-cased ALFRED form ("countertop" -> "CounterTop"); the word when unknown."""
    from luminous_sim.vocab import ALL_TYPES

    by_lower = {t.lower(): t for t in ALL_TYPES}
    return by_lower.get(word.lower(), word)
