"""The instruction parser: ALFRED's annotations read with their labels, a directive parsed into a task type and
arguments ALFRED's task definitions allow, training that writes the same bytes for the same data and seed, the
shipped checkpoint, bad files named, and `luminous agents parse`."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("torch")

from luminous_sim.agents import (
    SLOTS,
    AnnotationError,
    InstructionParser,
    ParserError,
    TrainSettings,
    accuracy,
    default_parser,
    read_annotations,
    train_parser,
)
from luminous_sim.agents.annotations import allowed, held_apart
from luminous_sim.vocab import ALFRED_TASK_TYPES
from tests.conftest import REPO

SAMPLE_TRAJECTORIES = 60
"""Trajectories of valid_seen a test trains on (a small fixed sample: seconds on one thread)."""


@pytest.fixture(scope="module")
def sample(shared_alfred, tmp_path_factory) -> Path:
    """The first trajectories of valid_seen, copied (links would do, but a copy is what a user has)."""
    import shutil

    out = tmp_path_factory.mktemp("alfred") / "sample"
    files = sorted((shared_alfred / "valid_seen").rglob("traj_data.json"))[:SAMPLE_TRAJECTORIES]
    for f in files:
        dest = out / f.relative_to(shared_alfred / "valid_seen")
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy(f, dest)
    return out


@pytest.fixture(scope="module")
def trained(sample, tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("parser") / "a.pt"
    train_parser(sample, TrainSettings(epochs=2)).save(path)
    return path


def test_training_with_swapped_parents_may_answer_any_receptacle_as_the_parent(trained):
    from luminous_sim.agents.swaps import receptacles

    assert set(receptacles()) <= set(InstructionParser.load(trained).answers["parent_target"])


def test_every_annotation_is_read_with_its_task(shared_alfred):
    examples = read_annotations(shared_alfred / "valid_seen")
    assert len(examples) == 820 and {e.task_type for e in examples} == set(ALFRED_TASK_TYPES)
    assert all(set(e.params) == set(SLOTS) and e.directive for e in examples)
    assert all(allowed(e.task_type, s, e.params[s]) for e in examples for s in SLOTS)  # the rules hold in ALFRED
    kept, apart = held_apart(examples, 0.2, 0)
    assert {e.task for e in kept}.isdisjoint({e.task for e in apart}) and 0 < len(apart) < len(examples) / 2


def test_training_twice_with_one_seed_writes_the_same_bytes(sample, trained, tmp_path):
    again = tmp_path / "b.pt"
    train_parser(sample, TrainSettings(epochs=2)).save(again)
    assert again.read_bytes() == trained.read_bytes()
    other = tmp_path / "c.pt"
    train_parser(sample, TrainSettings(epochs=2, seed=1)).save(other)
    assert other.read_bytes() != trained.read_bytes()


def test_a_trained_parser_reads_back_and_answers_within_alfreds_task_definitions(sample, trained):
    parser = InstructionParser.load(trained)
    assert parser.record["settings"]["epochs"] == 2 and len(parser.record["epochs"]) == 2
    examples = read_annotations(sample)
    for task in parser.parse_many([(e.directive, e.steps) for e in examples]):
        assert task.task_type in ALFRED_TASK_TYPES
        assert all(allowed(task.task_type, s, task.pddl_params[s]) for s in SLOTS)
    assert accuracy(parser, examples, True)["task_type"] > 0.5  # it learnt something from its own data


def test_the_shipped_parser_reads_clear_directives():
    parser = default_parser()
    got = parser.parse("Put a clean apple in the fridge.")
    assert got.task_type == "pick_clean_then_place_in_recep"
    assert got.pddl_params["object_target"] == "Apple" and got.pddl_params["parent_target"] == "Fridge"
    lamp = parser.parse("Examine the alarm clock under the light of the desk lamp.")
    assert lamp.task_type == "look_at_obj_in_light" and lamp.pddl_params["toggle_target"] == "DeskLamp"
    assert lamp.pddl_params["parent_target"] == ""


@pytest.mark.parametrize(("directive", "task_type", "parent"), [
    ("put a hot apple in the pot", "pick_heat_then_place_in_recep", "Pot"),
    ("cool an egg and put it in the bowl", "pick_cool_then_place_in_recep", "Bowl"),
    ("put a pencil in the bowl", "pick_and_place_simple", "Bowl"),
])
def test_the_shipped_parser_reads_a_pot_or_bowl_as_the_parent_not_a_movable_receptacle(directive, task_type, parent):
    """ALFRED's train split never puts anything in a bowl, pot or pan; U+ does. The swapped parents of training
    (`agents/swaps.py`) are what teach this."""
    got = default_parser().parse(directive)
    assert (got.task_type, got.pddl_params["parent_target"], got.pddl_params["mrecep_target"]) == \
        (task_type, parent, "")


def test_the_shipped_parser_scores_on_valid_seen_as_docs_say(shared_alfred):
    """Negative control for the shipped file: a parser that answered at random would score near 0 here."""
    scores = accuracy(default_parser(), read_annotations(shared_alfred / "valid_seen"), True)
    assert scores["task_type"] > 0.9 and scores["slots"] > 0.7


def test_bad_files_are_named(tmp_path):
    with pytest.raises(ParserError, match="no such parser checkpoint"):
        InstructionParser.load(tmp_path / "none.pt")
    junk = tmp_path / "junk.pt"
    junk.write_bytes(b"not a checkpoint")
    with pytest.raises(ParserError, match="junk.pt: not a readable parser checkpoint"):
        InstructionParser.load(junk)
    import torch

    hollow = tmp_path / "hollow.pt"
    torch.save({"format": "luminous-instruction-parser/1", "vocab": ["<pad>"]}, hollow)
    with pytest.raises(ParserError, match="hollow.pt: a parser checkpoint with a missing or damaged part"):
        InstructionParser.load(hollow)
    with pytest.raises(AnnotationError, match="holds no traj_data.json"):
        read_annotations(tmp_path)
    trial = tmp_path / "t" / "trial" / "traj_data.json"
    trial.parent.mkdir(parents=True)
    trial.write_text(json.dumps({"task_type": "pick_and_place_simple", "pddl_params": {"object_target": 3}}))
    with pytest.raises(AnnotationError, match=r"traj_data.json: field 'pddl_params.object_target': expected a str"):
        read_annotations(tmp_path / "t")


def test_luminous_agents_parse_prints_one_json_line_per_directive(tmp_path):
    directives = tmp_path / "d.txt"
    directives.write_text("Put a clean apple in the fridge.\nPut two pencils in the drawer.\n")
    done = subprocess.run([sys.executable, "-m", "luminous_sim.cli.main", "agents", "parse", str(directives)],
                          capture_output=True, text=True, cwd=REPO, timeout=300)
    assert done.returncode == 0, done.stderr
    lines = [json.loads(x) for x in done.stdout.splitlines()]
    assert len(lines) == 2 and lines[1]["task_type"] == "pick_two_obj_and_place"
    assert set(lines[0]) == {"task_type", "pddl_params"} and set(lines[0]["pddl_params"]) == set(SLOTS)
    bad = subprocess.run([sys.executable, "-m", "luminous_sim.cli.main", "agents", "parse", str(tmp_path / "no")],
                         capture_output=True, text=True, cwd=REPO, timeout=300)
    assert bad.returncode != 0 and "no" in bad.stderr and "Traceback" not in bad.stderr


def test_names_are_found_longest_first_with_every_type_they_may_mean():
    from luminous_sim.agents.mentions import mentions
    from luminous_sim.language.speaker import tokenize

    found = mentions(tokenize("Put the butter knife and two knives by the sink, on the table."))
    assert [(m.start, m.end, sorted(m.types)) for m in found] == [
        (2, 4, ["ButterKnife"]), (6, 7, ["Knife"]), (9, 10, ["Sink", "SinkBasin"]),
        (13, 14, ["CoffeeTable", "DiningTable", "SideTable"])]


def test_the_pointer_fills_a_slot_with_a_named_type_the_classifier_never_learnt(sample):
    """Trained without swapped parents, on a sample with no bowl as a parent; pointed at, "the bowl" still fills
    the slot, and the pointer's "none of them" leaves the classifier's answer."""
    import numpy as np

    from luminous_sim.agents.mentions import mentions
    from luminous_sim.agents.parser import POINTER_SLOTS
    from luminous_sim.language.speaker import tokenize

    parser = train_parser(sample, TrainSettings(epochs=1, swap=0.0))
    assert parser.net.shape.pointers == len(POINTER_SLOTS) and "Bowl" not in parser.answers["parent_target"]
    found = mentions(tokenize("heat a tomato and put it in the bowl"))
    assert [sorted(m.types) for m in found] == [["Tomato"], ["Bowl"]]
    probs = [np.full(len(parser.answers[h]), 1.0 / len(parser.answers[h])) for h in ("task_type", *SLOTS)]
    parent = POINTER_SLOTS.index("parent_target")
    to_bowl = np.zeros((1 + len(found), len(POINTER_SLOTS)))
    to_bowl[0, :], to_bowl[0, parent], to_bowl[2, parent] = 1.0, 0.1, 0.9
    scores = parser.slot_scores(probs, to_bowl, found)["parent_target"]
    assert max(scores, key=lambda v: scores[v]) == "Bowl"
    nowhere = np.zeros_like(to_bowl)
    nowhere[0, :] = 1.0
    unpointed = parser.slot_scores(probs, nowhere, found)["parent_target"]
    other = next(v for v in parser.answers["parent_target"] if v)
    assert unpointed.get("Bowl", -np.inf) < -20 < unpointed[other]
