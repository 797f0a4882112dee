"""Counterfactual parents for the parser's training: the parent's name swapped for a receptacle that may hold
what the task places, named nowhere else, and the label swapped with it; ALFRED's own words otherwise kept."""

from __future__ import annotations

import random

from luminous_sim.agents.annotations import Annotated
from luminous_sim.agents.mentions import mentions
from luminous_sim.agents.swaps import TOOLS, parent_choices, swap_parent
from luminous_sim.language.speaker import tokenize
from luminous_sim.vocab import can_contain

HEAT = Annotated("Put a heated mug down on a table.", ("Heat the mug in the microwave.",),
                 "pick_heat_then_place_in_recep",
                 {"object_target": "Mug", "parent_target": "SideTable", "mrecep_target": "", "toggle_target": "",
                  "object_sliced": False}, "pick_heat_then_place_in_recep-Mug-None-SideTable-1")


def test_a_swap_renames_every_mention_of_the_parent_and_relabels_it():
    words = tokenize("put the mug on the table , then leave the table")
    seen = set()
    for seed in range(40):
        out = swap_parent(words, HEAT, random.Random(seed))
        assert out is not None
        new_words, relabelled = out
        new = relabelled.params["parent_target"]
        seen.add(new)
        assert new != "SideTable" and can_contain(new, "Mug") and new not in TOOLS[HEAT.task_type]
        assert "table" not in new_words and new_words[:3] == ["put", "the", "mug"]
        assert sum(new in m.types for m in mentions(new_words)) == 2  # both names, each now the new parent
        assert {k: v for k, v in relabelled.params.items() if k != "parent_target"} == \
            {k: v for k, v in HEAT.params.items() if k != "parent_target"}
    assert len(seen) > 3  # a draw, not one fixed answer
    assert swap_parent(words, HEAT, random.Random(3)) == swap_parent(words, HEAT, random.Random(3))


def test_no_swap_where_the_parent_is_unnamed_or_the_task_has_none():
    assert swap_parent(tokenize("heat a mug and put it down"), HEAT, random.Random(0)) is None
    look = Annotated("look at a book by the lamp", (), "look_at_obj_in_light",
                     {"object_target": "Book", "parent_target": "", "mrecep_target": "", "toggle_target": "DeskLamp",
                      "object_sliced": False}, "t")
    assert swap_parent(tokenize(look.directive), look, random.Random(0)) is None


def test_the_choices_hold_what_is_placed_and_never_a_name_already_in_the_input():
    sliced = Annotated("put a slice of apple in the fridge", (), "pick_and_place_simple",
                       {"object_target": "Apple", "parent_target": "Fridge", "mrecep_target": "",
                        "toggle_target": "", "object_sliced": True}, "t")
    assert all(can_contain(r, "AppleSliced") for r in parent_choices(sliced))
    words = tokenize("put the mug from the bowl on the table")
    for seed in range(30):
        out = swap_parent(words, HEAT, random.Random(seed))
        assert out is not None and out[1].params["parent_target"] != "Bowl"
