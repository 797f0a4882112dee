"""The agent's reach, measured from the eye as ALFRED measures it."""

from __future__ import annotations

import pytest

from luminous_sim.scene.reach import REACH, horizontal_reach
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT


def test_low_things_must_be_nearer_than_tall_ones():
    """ALFRED measures reach from the eye: a garbage can's top is far below it, a fridge's is not."""
    assert horizontal_reach(0.0, 2.0) == pytest.approx(REACH)
    assert horizontal_reach(1.8, 2.0) == pytest.approx((REACH**2 - (1.8 - CAMERA_HEIGHT) ** 2) ** 0.5)
    can = horizontal_reach(0.0, 0.3)
    assert can == pytest.approx((REACH**2 - (CAMERA_HEIGHT - 0.3) ** 2) ** 0.5) and can < 0.8
    assert horizontal_reach(0.0, 0.0, reach=1.0) == 0.0
