"""Instructions read as people would write them, by a check of its own: no ALFRED type name glued into one
word ("stoveburner") or left in CamelCase, and no landmark that names the target ("the sink near the sink").

The check is built here from ALFRED's type vocabulary, not from the language layer's name table
(`language.names`), so it can catch that table's mistakes.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from luminous_sim.language import lint
from luminous_sim.tasks import TEMPLATES, PddlParams, TaskInstance, goal_for, task_description
from luminous_sim.tasks.templates import fill_template
from luminous_sim.vocab import ALFRED_TASK_TYPES, ALL_TYPES, LAMPS, MOVABLE_RECEPTACLES, SLICED_TYPES, abilities

_PARTS = re.compile(r"[A-Z]+(?![a-z])|[A-Z][a-z]+")
GLUED = ({t.lower() for t in ALL_TYPES if len(_PARTS.findall(t)) > 1} - {"armchair", "basketball"}) | {"glassbottle"}
"""ALFRED's multi-word type names lower-cased and joined, less two that English writes as one word."""
_GLUED = re.compile(r"\b(?:" + "|".join(sorted(GLUED, key=len, reverse=True)) + r")\b", re.IGNORECASE)
_CAMEL = re.compile(r"\b[A-Za-z]*[a-z][A-Z][A-Za-z]*\b")
_SELF = re.compile(r"\bthe ((?:[a-z]+ ){0,3}?[a-z]+) (?:by|next to|near|beside) the \1\b", re.IGNORECASE)


def problems(text: str) -> list[str]:
    return ([f"glued {m}" for m in _GLUED.findall(text)] + [f"CamelCase {m}" for m in _CAMEL.findall(text)]
            + [f"self-landmark {m}" for m in _SELF.findall(text)])


def test_the_check_finds_what_the_issue_found():
    assert problems("put a pan of dishsponge in stoveburner") == ["glued dishsponge", "glued stoveburner"]
    assert problems("look at cellphone under the floorlamp") == ["glued cellphone", "glued floorlamp"]
    assert problems("Turn right to the sink near the sink.") == ["self-landmark sink"]
    assert problems("Put the mug on the CounterTop.") == ["glued CounterTop", "CamelCase CounterTop"]
    assert problems("Put the basketball on the armchair near the stove burner.") == []


def test_the_library_check_agrees():
    for text in ("put a pan of dishsponge in stoveburner", "to the sink near the sink", "put a mug in the sink",
                 "look at cellphone under the floorlamp", "Put the mug on the CounterTop."):
        assert bool(lint.glued_names(text) or lint.self_landmarks(text)) == bool(problems(text)), text
    assert lint.glued_forms() == GLUED


def _sample_tasks() -> list[TaskInstance]:
    """Every goal key's templates over every pickupable object, with receptacles, lamps and movable
    receptacles in turn (the templates do not check that a combination is feasible)."""
    objects = sorted(t for t in ALL_TYPES if abilities(t).pickupable and t not in SLICED_TYPES)
    receptacles = sorted(t for t in ALL_TYPES if abilities(t).receptacle)
    sliceable = sorted(set(SLICED_TYPES.values()))
    tasks = []
    for i, obj in enumerate(objects + sliceable):
        sliced = obj in sliceable and i >= len(objects)
        for task_type in ALFRED_TASK_TYPES:
            params = PddlParams(obj, "" if task_type == "look_at_obj_in_light" else receptacles[i % len(receptacles)],
                                LAMPS[i % len(LAMPS)] if task_type == "look_at_obj_in_light" else "",
                                MOVABLE_RECEPTACLES[i % len(MOVABLE_RECEPTACLES)]
                                if task_type == "pick_and_place_with_movable_recep" else "", sliced)
            tasks.append(TaskInstance(task_type, params, goal_for(params, task_type), 0))
    return tasks


def test_goal_directives_of_every_template_read_as_words():
    bad = {}
    for task in _sample_tasks():
        for template in TEMPLATES[task.goal_key]:
            text = fill_template(template, task)
            if problems(text) or "  " in text:
                bad[text] = problems(text)
    assert not bad, list(bad.items())[:10]


def test_goal_directives_use_plurals_for_two_and_prepositions():
    t = TaskInstance("pick_two_obj_and_place", PddlParams("Knife", "Drawer"),
                     goal_for(PddlParams("Knife", "Drawer"), "pick_two_obj_and_place"), 0)
    assert {task_description(t, np.random.default_rng(s)) for s in range(20)} == {
        "put two knives in the drawer", "find two knives and put them in the drawer"}


def test_directives_for_alfreds_designs(shared_alfred):
    bad = []
    for path in sorted((shared_alfred / "valid_seen").glob("*/*/traj_data.json")):
        data = json.loads(path.read_text())
        params = PddlParams.from_json(data["pddl_params"])
        task = TaskInstance(data["task_type"], params, goal_for(params, data["task_type"]), 0)
        for template in TEMPLATES[task.goal_key]:
            text = fill_template(template, task)
            bad += [(text, p) for p in problems(text)]
    assert not bad, bad[:10]


@pytest.fixture(scope="module")
def annotations(uplus_build):
    """The three annotations of each trial of a U+ build of one episode of every task type (no frames)."""
    return [json.loads(p.read_text())["turk_annotations"]["anns"] for p in sorted(uplus_build.rglob("traj_data.json"))]


def test_a_builds_instructions_have_no_glued_names_and_no_self_landmarks(annotations):
    texts = [t for anns in annotations for a in anns for t in [a["task_desc"], *a["high_descs"]]]
    assert len(texts) > 100
    bad = [(t, problems(t)) for t in texts if problems(t)]
    assert not bad, bad[:10]
