"""S+/U+ splits: fixed structures, every entry legal for its task type, deterministic seeds."""

import json

import pytest

from luminous_sim.rooms import scene_split
from luminous_sim.splits import PLUS_SPLITS, SplitError, oct21_document, split_entries, split_entry
from luminous_sim.tasks import task_info
from luminous_sim.vocab import ALFRED_TASK_TYPES


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
    layouts = {(e.floor_plan, e.layout) for e in split_entries("U+", 700)}
    assert len(layouts) == 16


@pytest.mark.parametrize("name", sorted(PLUS_SPLITS))
def test_entries_cover_types_in_allowed_rooms(name):
    entries = split_entries(name, 140)
    assert [e.task_type for e in entries[:7]] == list(ALFRED_TASK_TYPES)
    for e in entries:
        assert e.room_type in task_info(e.task_type).rooms, e
        assert e.floor_plan in PLUS_SPLITS[name].structures
    assert len({e.task_seed for e in entries}) == len(entries)


def test_entries_are_deterministic_and_splits_differ():
    assert split_entry("S+", 123) == split_entry("S+", 123)
    assert split_entries("S+", 5, start=10) == [split_entry("S+", i) for i in range(10, 15)]
    a, b = split_entry("U+", 0), split_entry("U+test", 0)
    assert a.task_seed != b.task_seed and a.layout_seed != b.layout_seed
    # the same structure and layout share one layout seed whatever the task
    same = [e for e in split_entries("U+", 28) if e.floor_plan == "FloorPlan10" and e.layout == 0]
    assert len(same) > 1 and len({e.layout_seed for e in same}) == 1


def test_bad_names_and_indices_are_named():
    with pytest.raises(SplitError, match="unknown split 'S-'"):
        split_entry("S-", 0)
    with pytest.raises(SplitError, match="negative"):
        split_entry("U+", -1)


def test_oct21_document_has_alfred_layout():
    doc = oct21_document({"S+": ["pick_and_place_simple-Apple-None-Fridge-8/trial_T1"]}, annotations=2)
    assert doc == {"S+": [{"repeat_idx": 0, "task": "pick_and_place_simple-Apple-None-Fridge-8/trial_T1"},
                          {"repeat_idx": 1, "task": "pick_and_place_simple-Apple-None-Fridge-8/trial_T1"}]}
    json.dumps(doc)
