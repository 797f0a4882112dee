"""S+/U+ splits: fixed structures, every entry legal for its task type, deterministic seeds."""

import json

import pytest

from luminous_sim.benchmark import split_layouts
from luminous_sim.rooms import scene_split
from luminous_sim.splits import PLUS_SPLITS, SplitError, oct21_document, plus_split
from luminous_sim.vocab import ROOM_TYPES


def _number(floor_plan: str) -> int:
    return int(floor_plan.removeprefix("FloorPlan"))


def test_s_plus_is_ten_seen_structures_per_room_type():
    structures = PLUS_SPLITS["S+"].structures
    assert len(structures) == len(set(structures)) == 40
    assert all(scene_split(_number(s)) == "seen" for s in structures)
    for hundred in (0, 2, 3, 4):
        assert sum(_number(s) // 100 == hundred for s in structures) == 10


def test_u_plus_is_valid_unseen_with_four_layouts():
    split = PLUS_SPLITS["U+"]
    assert split.structures == ("FloorPlan10", "FloorPlan219", "FloorPlan308", "FloorPlan424")
    assert split.layouts == 4
    assert all(scene_split(_number(s)) == "valid_unseen" for s in split.structures)
    layouts = split_layouts("U+")
    assert len({(lay.floor_plan, lay.layout) for lay in layouts}) == 16
    assert len({lay.layout_seed for lay in layouts}) == 16


def test_layouts_are_deterministic_and_splits_differ():
    assert split_layouts("S+") == split_layouts("S+") and len(split_layouts("S+")) == 40
    test_seeds = {lay.layout_seed for lay in split_layouts("U+test")}
    assert {lay.layout_seed for lay in split_layouts("U+")}.isdisjoint(test_seeds)
    for lay in split_layouts("S+"):
        assert lay.room_type in ROOM_TYPES


def test_bad_names_are_named():
    with pytest.raises(SplitError, match="unknown split 'S-'"):
        plus_split("S-")


def test_oct21_document_has_alfred_layout():
    doc = oct21_document({"S+": ["pick_and_place_simple-Apple-None-Fridge-8/trial_T1"]}, annotations=2)
    assert doc == {"S+": [{"repeat_idx": 0, "task": "pick_and_place_simple-Apple-None-Fridge-8/trial_T1"},
                          {"repeat_idx": 1, "task": "pick_and_place_simple-Apple-None-Fridge-8/trial_T1"}]}
    json.dumps(doc)
