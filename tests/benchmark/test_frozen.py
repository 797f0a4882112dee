"""The frozen splits: the paper's sizes, the shipped manifests, one definition of an episode."""

from __future__ import annotations

from dataclasses import replace

import pytest

from luminous_sim.benchmark import (
    FROZEN,
    PAPER_COUNTS,
    benchmark_entries,
    benchmark_entry,
    benchmark_size,
    episode_key,
    frozen_header,
    type_counts,
)
from luminous_sim.benchmark.counts import allocate
from luminous_sim.episodes import SplitVersionError, entry_spec
from luminous_sim.splits import SplitError
from luminous_sim.vocab import ALFRED_TASK_TYPES
from luminous_sim.world import AgentPose


def test_the_paper_counts_are_table_1_of_the_evaluation_section():
    assert sum(PAPER_COUNTS["S+"]) == 1405 and sum(PAPER_COUNTS["U+"]) == 435
    assert type_counts("U+")["look_at_obj_in_light"] == 178 and type_counts("S+")["pick_two_obj_and_place"] == 167


@pytest.mark.parametrize("split", FROZEN)
def test_a_frozen_split_holds_the_paper_count_of_each_type(split):
    header = frozen_header(split)
    counts = {t: 0 for t in ALFRED_TASK_TYPES}
    for e in benchmark_entries(split):
        counts[e.task_type] += 1
    assert counts == header["counts"] == type_counts(split)
    assert benchmark_size(split) == sum(PAPER_COUNTS[split])
    for t, stats in header["stats"].items():
        assert stats["built"] == stats["asked"], (t, stats)
        assert set(stats["rejected"]) == {"layout", "no_task", "duplicate", "oracle"}


@pytest.mark.parametrize("split", FROZEN)
def test_no_episode_is_frozen_twice_and_repeats_come_only_when_a_layout_is_out_of_tasks(split):
    entries = benchmark_entries(split)
    assert len({e.episode_key for e in entries}) == len(entries)
    assert [e.index for e in entries] == list(range(len(entries)))
    by_layout: dict[tuple[str, str, int], list] = {}
    for e in entries:
        by_layout.setdefault((e.task_type, e.floor_plan, e.layout), []).append(e)
    for group in by_layout.values():
        tasks = [repr(sorted(e.pddl_params.items())) for e in group]
        first_repeat = next((k for k, e in enumerate(group) if e.repeat), len(group))
        assert len(set(tasks[:first_repeat])) == first_repeat, "distinct tasks come before any repeat"
        assert all(e.repeat for e in group[first_repeat:])
        assert all(t in tasks[:first_repeat] for t in tasks[first_repeat:])


def test_the_first_entries_cover_every_type_in_turn():
    assert [e.task_type for e in benchmark_entries("U+", 7)] == list(ALFRED_TASK_TYPES)
    assert [e.task_type for e in benchmark_entries("S+", 14)] == list(ALFRED_TASK_TYPES) * 2


def test_an_index_outside_a_split_is_named():
    with pytest.raises(SplitError, match=r"episode index 435 is outside 0\.\.434"):
        benchmark_entry("U+", 435)
    with pytest.raises(SplitError, match="unknown split"):
        benchmark_entry("V+", 0)


@pytest.mark.parametrize("split,index", [("U+", 0), ("U+", 3), ("S+", 5)])
def test_an_entry_made_here_is_the_frozen_one(split, index):
    entry = benchmark_entry(split, index)
    made = entry_spec(entry)
    assert made.key == entry.episode_key
    assert made.task.params.to_json() == entry.pddl_params and made.start == entry.start
    assert made.task.task_type == entry.task_type
    again = entry_spec(entry)
    assert again.key == made.key and again.task.instruction == made.task.instruction


def test_a_checkout_that_makes_another_episode_refuses_to_play_it():
    entry = benchmark_entry("U+", 0)
    with pytest.raises(SplitVersionError, match="the start differs.*new version"):
        entry_spec(replace(entry, start=replace(entry.start, rotation=(entry.start.rotation + 90) % 360),
                              episode_key="0" * 20))
    with pytest.raises(SplitVersionError, match="scene or the initial state differs"):
        entry_spec(replace(entry, episode_key="0" * 20))


def test_the_key_hashes_content_not_names():
    entry = benchmark_entry("U+", 0)
    made = entry_spec(entry)
    params = made.task.params.to_json()
    key = episode_key(made.scene, made.task.task_type, params, made.start, made.dirty)
    assert key == made.key
    assert episode_key(made.scene, made.task.task_type, params, replace(made.start, x=made.start.x + 0.25),
                       made.dirty) != key
    assert episode_key(made.scene, made.task.task_type, {**params, "parent_target": "Sink"}, made.start,
                       made.dirty) != key
    assert episode_key(made.scene, made.task.task_type, params, made.start, ("Mug|1",)) != key
    moved = made.scene.model_copy(update={"seed": made.scene.seed + 1})
    assert episode_key(moved, made.task.task_type, params, made.start, made.dirty) != key
    doc_key = episode_key(__import__("json").loads(made.scene.to_json()), made.task.task_type, params,
                          AgentPose(made.start.x, made.start.y, made.start.rotation, made.start.horizon), made.dirty)
    assert doc_key == key


@pytest.mark.parametrize("capacities,count,want", [
    ([3, 3, 3], 6, [2, 2, 2]),
    ([1, 5, 0], 4, [1, 3, 0]),
    ([1, 1, 0], 5, [3, 2, 0]),
    ([0, 2], 0, [0, 0]),
])
def test_allocation_fills_distinct_tasks_before_repeats(capacities, count, want):
    assert allocate(capacities, count) == want


def test_allocation_refuses_a_type_no_layout_holds():
    with pytest.raises(ValueError, match="no layout"):
        allocate([0, 0], 3)


def test_the_shipped_manifests_have_the_digests_in_code():
    import hashlib

    from luminous_sim.benchmark.frozen import MANIFEST_SHA256, manifest_path

    for split in FROZEN:
        assert hashlib.sha256(manifest_path(split).read_bytes()).hexdigest() == MANIFEST_SHA256[split]


@pytest.mark.parametrize("edit", [
    lambda lines: [lines[0], lines[1].replace('"episode_key": "', '"episode_key": "0'), *lines[2:]],  # a changed key
    lambda lines: lines[:-3],  # truncated
    lambda lines: [lines[0], lines[2], lines[1], *lines[3:]],  # renumbered
    lambda lines: [lines[0], "garbage", *lines[2:]],
])
def test_a_changed_manifest_is_refused_with_a_message(tmp_path, monkeypatch, edit):
    from luminous_sim.benchmark import frozen

    lines = frozen.manifest_path("U+").read_text().splitlines()
    changed = tmp_path / "U+.jsonl"
    changed.write_text("\n".join(edit(lines)) + "\n")
    monkeypatch.setattr(frozen, "manifest_path", lambda split, folder=None: changed)
    frozen._manifest.cache_clear()
    try:
        with pytest.raises(SplitError, match=r"the frozen manifest of U\+ was changed .* reinstall luminous-sim"):
            benchmark_entry("U+", 0)
    finally:
        frozen._manifest.cache_clear()


def test_the_canonical_build_is_keyed_by_split_version_and_manifest_not_package_version(tmp_path, monkeypatch):
    from luminous_sim.benchmark import SPLIT_VERSION, canonical_build_dir
    from luminous_sim.benchmark.frozen import MANIFEST_SHA256

    monkeypatch.setenv("LUMINOUS_CACHE", str(tmp_path))
    for split in FROZEN:
        assert canonical_build_dir(split) == tmp_path / f"benchmark-v{SPLIT_VERSION}" / \
            f"{split}-{MANIFEST_SHA256[split][:16]}"
    assert canonical_build_dir("S+") != canonical_build_dir("U+")
    with pytest.raises(SplitError, match="not frozen"):
        canonical_build_dir("U+test")
