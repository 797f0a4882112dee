"""Small hand-built shells shared by the room tests."""

from __future__ import annotations

import pytest

from luminous_sim.rooms.shell import (
    CounterRun,
    Door,
    FixturePlan,
    FixtureSlot,
    RoomShell,
    Window,
    make_shell,
)


def rect_shell(**extra) -> RoomShell:
    """A 4 m x 3 m kitchen-like room with one door, one window and a counter with a sink."""
    fields = {
        "name": "test_rect",
        "room_type": "Bedroom",
        "shape": "rect",
        "outline": [(0, 0), (4, 0), (4, 3), (0, 3)],
        "wall_height": 2.5,
        "wall_thickness": 0.1,
        "doors": (
            Door(id="Door_0", wall="w0", offset=1.0, width=0.9, height=2.05, swing_clearance=1.0),
        ),
        "windows": (
            Window(id="Window_0", wall="w2", offset=1.5, width=1.2, sill_height=0.9, height=1.2),
        ),
    }
    fields.update(extra)
    return make_shell(**fields)


@pytest.fixture
def rect() -> RoomShell:
    return rect_shell()


@pytest.fixture
def kitchen_rect() -> RoomShell:
    plan = FixturePlan(
        layout="I",
        counters=(CounterRun(id="CounterTop_0", wall="w1", start=0.2, end=2.8),),
        slots=(
            FixtureSlot(
                id="Sink_0",
                type="Sink",
                wall="w1",
                offset=0.5,
                width=0.8,
                depth=0.6,
                height=0.9,
                counter="CounterTop_0",
            ),
        ),
    )
    return rect_shell(room_type="Kitchen", fixtures=plan)


@pytest.fixture
def l_shell() -> RoomShell:
    return make_shell(
        name="test_L",
        room_type="LivingRoom",
        shape="L",
        outline=[(0, 0), (5, 0), (5, 2), (3, 2), (3, 4), (0, 4)],
        wall_height=2.6,
        wall_thickness=0.15,
        doors=(
            Door(id="Door_0", wall="w5", offset=1.0, width=0.9, height=2.0, swing_clearance=1.0),
        ),
    )
