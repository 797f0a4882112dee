"""Objects named as people write them: words, articles, plurals and the receptacle's preposition."""

from __future__ import annotations

import pytest

from luminous_sim.language.names import (
    definite,
    indefinite,
    plural,
    pluralise,
    preposition,
    spoken,
    type_from_word,
    words_of,
)
from luminous_sim.vocab import ALL_TYPES


@pytest.mark.parametrize(("object_type", "name"), [
    ("DishSponge", "dish sponge"), ("StoveBurner", "stove burner"), ("DeskLamp", "desk lamp"),
    ("GarbageCan", "garbage can"), ("TVStand", "TV stand"), ("CounterTop", "counter"), ("SinkBasin", "sink"),
    ("BathtubBasin", "bathtub"), ("Television", "television"), ("CD", "CD"), ("Glassbottle", "glass bottle"),
    ("HandTowelHolder", "hand towel holder"), ("ArmChair", "armchair"), ("AppleSliced", "slice of apple"),
    ("Apple", "apple"), ("ToiletPaperHanger", "toilet paper hanger"), ("CoffeeMachine", "coffee machine"),
])
def test_names_are_words(object_type, name):
    assert spoken(object_type) == name


def test_every_type_has_a_name_of_lower_case_words_or_an_acronym():
    for t in ALL_TYPES:
        for word in spoken(t).split():
            assert word.islower() or word.isupper(), (t, spoken(t))


@pytest.mark.parametrize(("object_type", "a", "the"), [
    ("Apple", "an apple", "the apple"), ("Mug", "a mug", "the mug"), ("Egg", "an egg", "the egg"),
    ("AlarmClock", "an alarm clock", "the alarm clock"), ("ArmChair", "an armchair", "the armchair"),
    ("CD", "a CD", "the CD"), ("TVStand", "a TV stand", "the TV stand"), ("Bread", "a loaf of bread", "the bread"),
    ("AppleSliced", "a slice of apple", "the slice of apple"), ("Boots", "some boots", "the boots"),
    ("Ottoman", "an ottoman", "the ottoman"),
])
def test_articles(object_type, a, the):
    assert indefinite(object_type) == a
    assert definite(object_type) == the


def test_the_article_agrees_with_an_adjective():
    assert indefinite("Apple", "hot") == "a hot apple"
    assert indefinite("Mug", "empty") == "an empty mug"
    assert definite("Potato", "cold") == "the cold potato"


@pytest.mark.parametrize(("object_type", "many"), [
    ("Pencil", "pencils"), ("Knife", "knives"), ("ButterKnife", "butter knives"), ("Box", "boxes"),
    ("Glassbottle", "glass bottles"), ("Watch", "watches"), ("TissueBox", "tissue boxes"), ("CD", "CDs"),
    ("Potato", "potatoes"), ("Tomato", "tomatoes"), ("AppleSliced", "slices of apple"),
    ("Bread", "loaves of bread"), ("KeyChain", "key chains"), ("Boots", "boots"), ("Shelf", "shelves"),
    ("SoapBar", "bars of soap"), ("Candle", "candles"), ("DishSponge", "dish sponges"),
])
def test_plurals(object_type, many):
    assert plural(object_type) == many


def test_pluralise_works_on_the_head_noun():
    assert pluralise("slice of tomato") == "slices of tomato"
    assert pluralise("battery") == "batteries"
    assert pluralise("key") == "keys"


@pytest.mark.parametrize("receptacle", ["Fridge", "Drawer", "Cabinet", "Microwave", "SinkBasin", "Box", "Bowl",
                                        "Mug", "Pot", "GarbageCan", "BathtubBasin", "Safe", "LaundryHamper"])
def test_things_go_in(receptacle):
    assert preposition(receptacle) == "in"


@pytest.mark.parametrize("receptacle", ["CounterTop", "DiningTable", "Shelf", "Sofa", "Bed", "Desk", "Dresser",
                                        "StoveBurner", "TVStand", "Plate", "ArmChair", "Toilet", "SideTable"])
def test_things_go_on(receptacle):
    assert preposition(receptacle) == "on"


def test_alfreds_lower_cased_forms_map_back_to_types():
    assert type_from_word("countertop") == "CounterTop"
    assert type_from_word("stoveburner") == "StoveBurner"
    assert type_from_word("not a type") == "not a type"


def test_words_of_cover_every_form():
    assert {"knife", "knives", "a"} <= words_of("Knife")
    assert {"loaf", "loaves", "bread", "of"} <= words_of("Bread")
