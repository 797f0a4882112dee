"""A house CDF's own task: goal, initial state and agent start anywhere in the house, solved by the oracle
across rooms (`luminous run --cdf house.yaml`)."""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest

from luminous_sim import cdf
from luminous_sim.cdf import CDFValidationError
from luminous_sim.cdf_episode import run_document
from luminous_sim.errors import CDFError

HOUSE: dict[str, Any] = {
    "cdf_version": 2,
    "name": "book_to_sofa",
    "scene": {
        "house": {
            "rooms": [
                {"name": "kitchen", "type": "Kitchen"},
                {"name": "living", "type": "LivingRoom", "objects": [{"name": "sofa", "type": "Sofa"}]},
                {"name": "bedroom", "type": "Bedroom",
                 "objects": [{"name": "bed", "type": "Bed"}, {"name": "book", "type": "Book"}],
                 "relations": [{"subject": "book", "relation": "on", "target": "bed"}]},
            ],
            "adjacency": [["kitchen", "living"], ["bedroom", "living"]],
        }
    },
    "task": {"goal": "(inReceptacle book sofa)"},
}


def _doc(**task: Any) -> cdf.ChallengeDefinition:
    doc = copy.deepcopy(HOUSE)
    doc["task"].update(task)
    return cdf.from_document(doc, "house.yaml")


def test_the_oracle_carries_an_object_from_one_room_to_another_from_a_start_in_a_third() -> None:
    from luminous_sim.cssg import generate_house

    scene = generate_house(_doc(), seed=0).scene
    assert scene.room.house is not None
    kitchen = scene.room.house.room("kitchen").polygon()
    x, y = (round(v * 4) / 4 for v in (kitchen.centroid.x, kitchen.centroid.y))
    doc = _doc(agent={"position": [x, y], "rotation": 90}, initial="(inReceptacle book bed)")
    ran = run_document(doc, "house.yaml", seed=0, record_frames=False)
    assert ran.scene.room.house is not None
    assert ran.result.success, ran.result.failure
    assert ran.result.goal_conditions == (1, 1)
    book, sofa = ran.task.names["book"], ran.task.names["sofa"]
    assert scene.room.room_at(*scene.object(book).position[:2]) == "bedroom"
    assert scene.room.room_at(*scene.object(sofa).position[:2]) == "living"


def test_luminous_run_solves_a_house_cdf(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from luminous_sim.cli.main import main

    path = tmp_path / "house.yaml"
    path.write_text(cdf.dumps(_doc()), encoding="utf-8")
    assert main(["run", "--cdf", str(path), "--seed", "0", "--out", str(tmp_path / "out")]) == 0
    assert "task done in house book_to_sofa" in capsys.readouterr().out
    assert (tmp_path / "out" / "top_down.png").exists()


def test_a_start_on_no_rooms_floor_is_refused_naming_the_rooms() -> None:
    with pytest.raises(CDFValidationError) as info:
        run_document(_doc(agent={"position": [-3.0, 1.0]}), "house.yaml", seed=0, record_frames=False)
    (issue,) = info.value.issues
    assert issue.path == "task.agent.position" and "on no room's floor" in issue.message
    assert "kitchen x " in issue.message and "in house coordinates" in issue.message


def test_a_start_outside_a_sized_house_is_refused_before_generation() -> None:
    doc = copy.deepcopy(HOUSE)
    doc["scene"]["house"]["size"] = {"width": 9, "depth": 7}
    doc["task"]["agent"] = {"position": [9.5, 1.0]}
    with pytest.raises(CDFValidationError, match=r"outside the house \(x 0..9, y 0..7 m"):
        run_document(cdf.from_document(doc), "house.yaml", seed=0, record_frames=False)


def test_a_house_takes_no_room_option() -> None:
    with pytest.raises(CDFError, match="expected no --room"):
        run_document(_doc(), "house.yaml", seed=0, room="FloorPlan1", record_frames=False)
