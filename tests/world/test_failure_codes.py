"""Every failed World.step carries a FailureCode: one real failing action per code the world produces,
run in one kitchen as a single scenario (each failure leaves the world as it was), checked per code."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.errors import FailureCode
from luminous_sim.world import StepResult, World, WorldConfig
from tests.world.conftest import obj
from tests.world.test_interactions import go_to

WORLD_CODES = [
    FailureCode.UNKNOWN_ACTION, FailureCode.INVALID_ARGUMENT, FailureCode.NO_TARGET, FailureCode.UNKNOWN_OBJECT,
    FailureCode.BLOCKED, FailureCode.HORIZON_LIMIT, FailureCode.NOT_VISIBLE, FailureCode.OUT_OF_REACH,
    FailureCode.NOT_PICKUPABLE, FailureCode.NOT_OPENABLE, FailureCode.NOT_TOGGLEABLE, FailureCode.NOT_SLICEABLE,
    FailureCode.NOT_A_RECEPTACLE, FailureCode.HANDS_FULL, FailureCode.NOT_HOLDING, FailureCode.CLOSED,
    FailureCode.INCOMPATIBLE, FailureCode.ALREADY_DONE, FailureCode.MUST_BE_CLOSED, FailureCode.NEEDS_TOOL,
    FailureCode.NO_SPOT_IN_REACH, FailureCode.RECEPTACLE_FULL,
]


def _ok(world: World, action: dict) -> None:
    r = world.step(action)
    assert r.success, (action, r.error)


@pytest.fixture(scope="module")
def failures(kitchen_scene) -> dict[FailureCode, tuple[dict, StepResult]]:
    """The first failed result seen for each code, with the action that produced it."""
    from luminous_sim.world import placement

    got: dict[FailureCode, tuple[dict, StepResult]] = {}
    apple, fridge, micro, knife, mug, counter = (obj(kitchen_scene, n) for n in
                                                 ("apple", "fridge", "microwave", "knife", "mug", "counter"))
    with World(kitchen_scene, WorldConfig(settle_steps=120)) as world:

        def fail(action: dict) -> None:
            before = world.view().state
            r = world.step(action)
            assert not r.success and world.view().state == before, (action, r)
            got.setdefault(r.code, (action, r))

        fail({"action": "Jump"})
        fail({"action": "MoveAhead", "moveMagnitude": 0.5})
        fail({"action": "TeleportFull", "x": 99.0, "z": 99.0, "rotation": 0, "horizon": 30})
        fail({"action": "PickupObject"})
        fail({"action": "PickupObject", "objectId": "Nope|1|2|3"})
        fail({"action": "PutObject", "receptacleObjectId": counter})
        pts = world.nav.points()
        centre = (np.array(world.view().aabb(fridge)[0]) + world.view().aabb(fridge)[1])[:2] / 2
        far = pts[int(np.argmax(np.linalg.norm(pts - centre, axis=1)))]
        _ok(world, {"action": "TeleportFull", "x": float(far[0]), "z": float(far[1]), "rotation": 0, "horizon": 30})
        assert world.view().distance(fridge) > world.config.visibility_distance
        fail({"action": "OpenObject", "objectId": fridge})

        go_to(world, apple)
        at_apple = world.agent.to_alfred()
        fail({"action": "OpenObject", "objectId": apple})
        fail({"action": "ToggleObjectOn", "objectId": apple})
        fail({"action": "SliceObject", "objectId": apple})
        while world.step({"action": "LookUp"}).success:
            pass
        got.setdefault(world.last.code, ({"action": "LookUp"}, world.last))
        _ok(world, at_apple)
        _ok(world, {"action": "RotateLeft"})
        _ok(world, {"action": "RotateLeft"})
        assert world.view().distance(apple) <= world.config.visibility_distance
        fail({"action": "PickupObject", "objectId": apple})  # behind the agent: within reach, not in view

        go_to(world, fridge)
        fail({"action": "PickupObject", "objectId": fridge})
        fail({"action": "CloseObject", "objectId": fridge})
        go_to(world, mug)
        fail({"action": "SliceObject", "objectId": mug})
        go_to(world, knife)
        _ok(world, {"action": "PickupObject", "objectId": knife})
        go_to(world, apple)
        fail({"action": "PutObject", "objectId": knife, "receptacleObjectId": apple})
        fail({"action": "PickupObject", "objectId": apple})
        go_to(world, fridge)
        fail({"action": "PutObject", "objectId": knife, "receptacleObjectId": fridge})
        go_to(world, micro)
        _ok(world, {"action": "OpenObject", "objectId": micro})
        fail({"action": "ToggleObjectOn", "objectId": micro})
        fail({"action": "PutObject", "objectId": knife, "receptacleObjectId": micro})
        go_to(world, counter)
        with pytest.MonkeyPatch.context() as mp:  # no region of the counter within reach
            mp.setattr(placement, "region_spots", lambda *a, **k: [])
            fail({"action": "PutObject", "objectId": knife, "receptacleObjectId": counter})
        with pytest.MonkeyPatch.context() as mp:  # no free spot anywhere: not by draws, nor by a scan
            mp.setattr(placement, "sample_in_region", lambda *a, **k: None)
            mp.setattr(placement, "scan_region", lambda *a, **k: iter(()))
            fail({"action": "PutObject", "objectId": knife, "receptacleObjectId": counter})
    return got


@pytest.mark.parametrize("code", WORLD_CODES, ids=[c.value for c in WORLD_CODES])
def test_a_failing_action_reports_its_code(failures, code):
    assert code in failures, f"no action failed with {code}; seen: {sorted(failures)}"
    action, result = failures[code]
    assert result.error and result.failure is not None and result.failure.code == code, (action, result)


def test_a_step_result_cannot_fail_without_a_code():
    with pytest.raises(ValueError):
        StepResult(False, "broken", {})
    with pytest.raises(ValueError):
        StepResult(True, "", {}, FailureCode.BLOCKED)


def test_failure_codes_serialise_as_plain_strings():
    import json

    assert json.dumps({"code": FailureCode.RECEPTACLE_FULL}) == '{"code": "receptacle_full"}'
    assert FailureCode("receptacle_full") is FailureCode.RECEPTACLE_FULL
