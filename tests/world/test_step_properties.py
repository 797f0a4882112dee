"""Issue 17, beyond the list: a property over `World.step`. Any JSON-like action (hostile numbers, wrong types,
unknown ids, malformed masks and points, unknown keys) gives a `StepResult` and never raises; a failed one
carries a code and leaves the world as it was: the agent, what is held, every object's state, pose, joints
and colours, and the metadata (`fuzz.snapshot`). The random stream of puts is not part of that: a put that
finds no room has drawn from it, as a real put in AI2-THOR draws from Unity's.

Actions start from the fuzzer's sensible ones (`fuzz.random_action`: mostly navigation and interactions with
things in view) and have keys added or replaced by hostile values. The fast variant tries few actions in one
world built once for the module; the slow one many.
"""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.vocab import AGENT_ACTIONS, INTERACTION_ACTIONS
from luminous_sim.world import StepResult, World, WorldConfig
from luminous_sim.world.arguments import ACCEPTED
from tests.world.fuzz import random_action, snapshot

KEYS = sorted(set().union(*ACCEPTED.values())) + ["bbox", "speed", "standing", "", "ACTION"]

NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([float("nan"), float("inf"), -float("inf"), 1e308, -1e308, 5e-324, 0.25, 90, 15, 1.0, 3.6, -0.0]),
    st.integers(min_value=-(10**400), max_value=10**400),
    st.sampled_from([10**400, -(10**400), 2**63, -(2**63) - 1, 0, 1, -1, 300, 90_000]),
    st.booleans(),
)
JSON_LIKE = st.recursive(
    st.one_of(st.none(), NUMBERS, st.text(max_size=8), st.sampled_from(["Nope|1|2|3", "Apple|1", "", "MoveAhead"])),
    lambda inner: st.one_of(st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=4), inner, max_size=3)),
    max_leaves=8,
)
MASKS = st.one_of(
    st.lists(st.lists(NUMBERS, min_size=0, max_size=3), max_size=4),
    st.lists(st.tuples(st.integers(-5, 90_005), st.integers(-5, 90_005)), max_size=5),
    st.sampled_from([[[0, 90_000]], [[89_999, 1]], [[0, 0]], [], [[45_150, 10]]]),
)
POINTS = st.one_of(st.lists(NUMBERS, max_size=3), st.tuples(st.integers(-5, 305), st.integers(-5, 305)))


@st.composite
def hostile_action(draw, world: World) -> dict | str | object:
    """A sensible action from the fuzzer, then some of its keys added or replaced by hostile values."""
    seed = draw(st.integers(0, 2**32 - 1))
    action: dict = random_action(world, np.random.default_rng(seed))
    kind = draw(st.integers(0, 9))
    if kind <= 3:  # as the fuzzer made it, so that the world moves on: things get held, opened, sliced
        return action
    if kind == 9:  # not an action dict at all
        return draw(st.one_of(JSON_LIKE, st.sampled_from(list(AGENT_ACTIONS + INTERACTION_ACTIONS))))
    if kind == 8:
        action["action"] = draw(st.one_of(JSON_LIKE, st.sampled_from(list(AGENT_ACTIONS + INTERACTION_ACTIONS))))
    ids = sorted(world.built.objects)
    for _ in range(draw(st.integers(0 if kind == 8 else 1, 3))):
        key = draw(st.sampled_from(KEYS))
        if key == "mask":
            value = draw(MASKS)
        elif key == "point":
            value = draw(POINTS)
        elif key.endswith("Id"):
            value = draw(st.one_of(st.sampled_from(ids), JSON_LIKE))
        elif key in ("x", "y", "z"):
            grid = [float(v) for v in world.nav.points()[:, 0 if key == "x" else 1]]
            value = draw(st.one_of(NUMBERS, JSON_LIKE, st.sampled_from(grid)))
        else:
            value = draw(st.one_of(NUMBERS, JSON_LIKE))
        action[key] = value
    return action


def check_step(world: World, action, seen: Counter) -> StepResult:
    before = snapshot(world)
    result = world.step(action)
    assert isinstance(result, StepResult)
    seen[result.code or "success"] += 1
    assert result.success == (result.code is None) and isinstance(result.error, str)
    if not result.success:
        assert result.error and "\n" not in result.error and len(result.error) < 600, result.error
        after = snapshot(world)
        changed = [k for k in before if before[k] != after[k]]
        assert not changed, f"{action!r:.300} failed ({result.code}: {result.error}) but changed {changed}"
    return result


@pytest.fixture(scope="module")
def kitchen(kitchen_scene):
    with World(kitchen_scene, WorldConfig(settle_steps=120)) as w:
        yield w


def _check_many(world: World, max_examples: int, derandomize: bool) -> Counter:
    """Run the property; how often each outcome came (a code, or "success")."""
    seen: Counter = Counter()

    @settings(max_examples=max_examples, deadline=None, database=None, derandomize=derandomize,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
    @given(data=st.data())
    def run(data: st.DataObject) -> None:
        check_step(world, data.draw(hostile_action(world), label="action"), seen)

    run()
    print(dict(seen))
    return seen


def test_any_action_gives_a_result_and_a_failure_changes_nothing(kitchen):
    seen = _check_many(kitchen, max_examples=200, derandomize=True)
    assert seen["success"] >= 20 and len(seen) >= 6, seen  # the property met successes and failures of many kinds


@pytest.mark.slow
def test_any_action_gives_a_result_and_a_failure_changes_nothing_long(kitchen):
    seen = _check_many(kitchen, max_examples=2000, derandomize=False)
    assert seen["success"] >= 50 and len(seen) >= 8, seen
