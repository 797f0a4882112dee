"""Issue 17, items 2 and 3: every argument of a low-level action is checked. Hostile numbers (inf, nan, 1e308,
10**400, bools) and values ALFRED's discrete agent cannot honour (an off-grid teleport, a 0.5 m move, a
45 degree turn) are refused with INVALID_ARGUMENT and leave the world as it was; the arguments ALFRED's
own records carry are taken. One world for the module; each test starts from the same pose."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.errors import FailureCode
from luminous_sim.fileio import shown
from luminous_sim.world import World, WorldConfig, interaction_args
from luminous_sim.world.agent import AgentPose
from tests.world.conftest import obj
from tests.world.fuzz import snapshot
from tests.world.test_interactions import go_to

HOSTILE = [float("inf"), float("-inf"), float("nan"), 1e308, -1e308, 10**400, -(10**400), True, False, "1.25",
           None, [1.25], {"x": 1}, np.float64("inf"), np.float32("nan"), complex(1, 0)]
"""Values that are not usable numbers, or not numbers at all."""


@pytest.fixture(scope="module")
def kitchen(kitchen_scene):
    with World(kitchen_scene, WorldConfig(settle_steps=120)) as w:
        yield w


@pytest.fixture()
def world(kitchen):
    """The module's world with the agent back at its start pose."""
    r = kitchen.step(kitchen.default_start().to_alfred())
    assert r.success, r.error
    return kitchen


def refused(world: World, action: dict, code: FailureCode = FailureCode.INVALID_ARGUMENT) -> str:
    """Step an action that must fail with `code` and change nothing; its message."""
    before = snapshot(world)
    r = world.step(action)
    assert not r.success and r.code == code, (action, r)
    assert r.error and "\n" not in r.error, r.error
    assert snapshot(world) == before, f"{action} failed but changed the world"
    return r.error


def _elsewhere(world: World) -> AgentPose:
    """A reachable pose other than the start, one the agent can teleport to."""
    start = world.agent
    pts = world.nav.points()
    x, y = pts[int(np.argmax(np.hypot(pts[:, 0] - start.x, pts[:, 1] - start.y)))]
    return AgentPose(float(x), float(y), 90, 15)


# ---------------------------------------------------------------------------------------------- item 2


@pytest.mark.parametrize("key", ["x", "z", "y", "rotation", "horizon"])
@pytest.mark.parametrize("value", HOSTILE, ids=lambda v: shown(v, 20))
def test_teleport_refuses_hostile_numbers(world, key, value):
    action = {**_elsewhere(world).to_alfred(), key: value}
    refused(world, action)


def test_teleport_far_away_is_blocked_or_refused(world):
    refused(world, {"action": "TeleportFull", "x": 99.0, "z": 99.0}, FailureCode.BLOCKED)
    assert "no place in a room" in refused(world, {"action": "TeleportFull", "x": 1e5, "z": 1.0})


# ---------------------------------------------------------------------------------------------- item 3


def test_teleport_off_the_grid_names_the_nearest_grid_points(world):
    there = _elsewhere(world)
    message = refused(world, {**there.to_alfred(), "x": there.x + 0.1})
    assert f"({there.x:g}, {there.y:g})" in message and "off the 0.25 m grid" in message
    message = refused(world, {"action": "TeleportFull", "x": 3.6, "z": 1.3})
    assert "(3.5, 1.25)" in message


def test_teleport_takes_grid_points_up_to_float_noise_and_lands_exactly_on_them(world):
    there = _elsewhere(world)
    r = world.step({**there.to_alfred(), "x": there.x + 1e-9, "z": there.y - 1e-9})
    assert r.success, r.error
    assert world.agent == there and world.agent.grid_key() in world.nav


@pytest.mark.parametrize("rotation,horizon", [(45, 30), (90, 20), (90, 75), (90, -45), (90.5, 30)])
def test_teleport_refuses_poses_off_the_discrete_agent(world, rotation, horizon):
    refused(world, {**_elsewhere(world).to_alfred(), "rotation": rotation, "horizon": horizon})


def test_teleport_turns_like_thor(world):
    there = _elsewhere(world)
    for rotation, expected in [(-90, 270), (450, 90), (90.0, 90), (10**30 * 360, 0)]:
        r = world.step({**there.to_alfred(), "rotation": rotation})
        assert r.success and world.agent.rotation == expected, (rotation, r.error)
    start = world.agent
    r = world.step({"action": "Teleport", "x": start.x, "z": start.y, "rotateOnTeleport": False})
    assert r.success and world.agent == start  # no rotation asked: the heading is kept
    refused(world, {"action": "Teleport", "x": start.x, "z": start.y, "rotation": 90, "rotateOnTeleport": False})
    refused(world, {"action": "Teleport", "x": start.x, "y": start.y})  # THOR's y is up: z is needed


@pytest.mark.parametrize("magnitude", [0.5, 0.0, -0.25, 0.2501, float("nan"), float("inf"), 1e308, 10**400,
                                       True, "0.25", None], ids=lambda v: shown(v, 20))
def test_move_ahead_refuses_any_magnitude_but_the_grid_step(world, magnitude):
    message = refused(world, {"action": "MoveAhead", "moveMagnitude": magnitude})
    assert "0.25" in message


@pytest.mark.parametrize("action,degrees", [("RotateLeft", 45), ("RotateRight", 180), ("RotateLeft", -90),
                                            ("RotateLeft", float("nan")), ("LookUp", 30), ("LookDown", 90),
                                            ("LookDown", True), ("RotateRight", "90")])
def test_turns_and_looks_refuse_other_angles(world, action, degrees):
    refused(world, {"action": action, "degrees": degrees})


@pytest.mark.parametrize("action,degrees,change", [("RotateLeft", 90, (-90, 0)), ("RotateRight", 90.0, (90, 0)),
                                                   ("LookDown", 15, (0, 15)), ("LookUp", 15.0, (0, -15))])
def test_turns_and_looks_take_their_own_step(world, action, degrees, change):
    before = world.agent
    r = world.step({"action": action, "degrees": degrees})
    assert r.success, r.error
    assert ((world.agent.rotation - before.rotation) % 360, world.agent.horizon - before.horizon) == (
        change[0] % 360, change[1])


@pytest.mark.parametrize("action", [
    {"action": "MoveAhead", "speed": 2},
    {"action": "RotateLeft", "moveMagnitude": 0.25},
    {"action": "LookUp", "x": 1.0},
    {"action": "Pass", "degrees": 90},
    {"action": "TeleportFull", "x": 0.0, "z": 0.0, "standing": True},
    {"action": "PickupObject", "objectId": "Apple|1", "bbox": [1, 2, 3, 4]},
    {"action": "PickupObject", "objectId": "Apple|1", "receptacleObjectId": "Fridge|1"},
    {"action": "CloseObject", "objectId": "Fridge|1", "moveMagnitude": 1.0},
    {"action": "MoveAhead", 3: 4},
])
def test_keys_an_action_does_not_take_are_refused(world, action):
    message = refused(world, action)
    assert "takes no" in message


def test_forcing_flags_must_be_bools(world):
    refused(world, {"action": "MoveAhead", "forceAction": "yes"})
    refused(world, {"action": "PutObject", "receptacleObjectId": "Fridge|1", "placeStationary": 1})
    refused(world, {"action": "PutObject", "receptacleObjectId": "Fridge|1", "placeStationary": False})
    refused(world, {"action": "OpenObject", "objectId": "Fridge|1", "moveMagnitude": 0.5})


@pytest.mark.parametrize("args", [
    {"objectId": 5}, {"objectId": ""}, {"objectId": ["Apple|1"]}, {"objectId": True},
    {"point": [True, 3]}, {"point": "ab"}, {"point": [1, 2, 3]}, {"point": [1.5, 2]},
    {"point": {"x": 1}}, {"point": np.zeros((2, 2), dtype=int)},
    {"mask": [[0, 1.5]]}, {"mask": [[-1, 3]]}, {"mask": [[89_999, 2]]}, {"mask": [[0, True]]}, {"mask": "0 5"},
    {"mask": [[0, 1, 2]]}, {"mask": [0, 1]}, {"mask": {"0": 5}}, {"mask": [[10**400, 1]]},
    {"mask": [[0, float("nan")]]},
    {"mask": np.ones((10, 10), dtype=bool)}, {"mask": np.ones((300, 300), dtype=float)},
    {"objectId": "Apple|1", "point": [150, 150]}, {"mask": [[0, 5]], "point": [150, 150]},
    {"coordinateObjectId": 3}, {"coordinateObjectId": "Apple|1"}, {"coordinateObjectId": ["Apple", [1, 2]]},
    {"coordinateReceptacleObjectId": ["Fridge", [1, 1, 2, 2, float("inf"), 3]]}, {"cleanObjectId": 7},
])
def test_malformed_targets_are_refused(world, args):
    refused(world, {"action": "PickupObject", **args})


def test_points_outside_the_frame_hit_nothing(world):
    for point in ([999, -1], [300, 0], [10**400, 1]):
        refused(world, {"action": "PickupObject", "point": point}, FailureCode.NO_TARGET)


def test_alfreds_own_records_are_taken(world, kitchen_scene):
    """The api_action dicts ALFRED records (spec 2.2), with every key they carry, succeed."""
    for api in [{"action": "MoveAhead", "forceAction": True, "moveMagnitude": 0.25},
                {"action": "RotateLeft", "forceAction": True}, {"action": "RotateRight", "forceAction": True},
                {"action": "LookDown", "forceAction": True}, {"action": "LookUp", "forceAction": True},
                {"action": "Pass"}, {"action": "NoOp"}]:
        if api["action"] == "MoveAhead" and not world.nav.can_move(world.agent):
            world.step("RotateRight")
        r = world.step(api)
        assert r.success, (api, r.error)
    start = world.default_start()
    init = {"action": "TeleportFull", "horizon": 30, "rotateOnTeleport": True, "rotation": 180, "x": start.x,
            "y": 0.9011651, "z": start.y}
    assert world.step(init).success and world.agent == AgentPose(start.x, start.y, 180, 30)
    micro, apple = obj(kitchen_scene, "microwave"), obj(kitchen_scene, "apple")
    go_to(world, micro)
    r = world.step({"action": "OpenObject", "objectId": micro, "moveMagnitude": 1.0})
    assert r.success, r.error
    r = world.step({"action": "CloseObject", "objectId": micro, "forceAction": True})
    assert r.success, r.error
    where = ["Microwave", [-4, -4, 7, 7, 4, 4]]
    r = world.step({"action": "ToggleObjectOn", "objectId": micro, "coordinateReceptacleObjectId": where,
                    "forceVisible": True})
    assert r.success, r.error
    assert world.step({"action": "ToggleObjectOff", "objectId": micro}).success
    go_to(world, apple)
    mask = interaction_args(world.instance_masks()[apple])["mask"]
    r = world.step({"action": "PickupObject", "mask": mask, "objectId": None})
    assert r.success and world.view().held == apple, r.error
    counter = obj(kitchen_scene, "counter")
    go_to(world, counter)
    r = world.step({"action": "PutObject", "objectId": apple, "receptacleObjectId": counter, "forceAction": True,
                    "placeStationary": True})
    assert r.success, r.error


def test_every_accepted_key_is_documented():
    from pathlib import Path

    from luminous_sim.world.arguments import ACCEPTED

    doc = (Path(__file__).resolve().parents[2] / "docs" / "failure_codes.md").read_text()
    table = doc[doc.index("## Action arguments"):]
    missing = sorted({k for keys in ACCEPTED.values() for k in keys if f"`{k}`" not in table})
    assert not missing, f"keys World.step takes that docs/failure_codes.md does not list: {missing}"
