"""The shipped house examples: the two-bedroom flat loads, its task crosses three rooms, the oracle solves it."""

from __future__ import annotations

from pathlib import Path

from luminous_sim import cdf

EXAMPLES = Path(__file__).resolve().parents[2] / "cdf" / "examples" / "houses"
FLAT = EXAMPLES / "two_bedroom_flat.yaml"


def test_every_house_example_loads() -> None:
    paths = sorted(EXAMPLES.glob("*.yaml"))
    assert FLAT in paths
    for path in paths:
        assert cdf.load(path).scene.house is not None


def test_the_flat_is_two_bedrooms_and_its_task_crosses_three_rooms() -> None:
    from luminous_sim.cdf_episode import run_document

    doc = cdf.load(FLAT)
    assert doc.scene.house is not None
    types = sorted(r.type for r in doc.scene.house.rooms)
    assert types == ["Bathroom", "Bedroom", "Bedroom", "Kitchen", "LivingRoom"]
    ran = run_document(doc, str(FLAT), seed=0, record_frames=False)
    assert ran.result.success, ran.result.failure
    shell = ran.scene.room
    rooms = {name: shell.room_at(*ran.scene.object(oid).position[:2]) for name, oid in ran.task.names.items()
             if name in ("mug", "microwave", "coffee_table")}
    assert rooms == {"mug": "study", "microwave": "kitchen", "coffee_table": "living"}
    assert shell.house is not None and len(shell.house.room("living").outline) == 6  # the L room
    assert shell.room_at(*shell.wall(shell.doors[0].wall).point(shell.doors[0].offset + 0.5, 0.3)) == "living"
