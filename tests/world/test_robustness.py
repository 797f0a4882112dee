"""Agents make mistakes: random and malformed actions never raise, never produce NaN, and never throw
objects out of the room. Replaying the same actions reproduces the same states and frames."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.world.world import World, WorldConfig
from tests.world.fuzz import fuzz, random_action


def _world(room_type: str, seed: int) -> World:
    return World(generate(empty_cdf(room_type), seed=seed).scene, WorldConfig(settle_steps=120))


@pytest.mark.parametrize("room_type,seed", [("Kitchen", 0), ("LivingRoom", 1)])
def test_random_actions_sample(room_type, seed):
    with _world(room_type, seed) as w:
        stats = fuzz(w, steps=400, seed=seed)
    assert stats["succeeded"] > 50
    assert len(stats["codes"]) >= 4, stats["codes"]  # every failure had a code (fuzz checks), of many kinds


@pytest.mark.slow
@pytest.mark.parametrize("room_type,seed", [("Kitchen", 10), ("LivingRoom", 11), ("Bedroom", 12), ("Bathroom", 13)])
def test_random_actions_10000_steps(room_type, seed):
    """10,000 random actions in all: 2,500 in each of four scenes."""
    with _world(room_type, seed) as w:
        fuzz(w, steps=2_500, seed=seed)


def test_replaying_actions_reproduces_states_and_frames(kitchen_scene):
    rng = np.random.default_rng(5)
    recorded = []
    with World(kitchen_scene, WorldConfig(settle_steps=120)) as w:
        for _ in range(120):
            a = random_action(w, rng)
            recorded.append(a)
            w.step(a)
        first_state, first_frame = w.view().state, w.frame().rgb.copy()
        first_md = w.metadata()
    with World(kitchen_scene, WorldConfig(settle_steps=120)) as w:
        for a in recorded:
            w.step(a)
        assert w.view().state == first_state
        assert np.array_equal(w.frame().rgb, first_frame)
        assert w.metadata() == first_md
