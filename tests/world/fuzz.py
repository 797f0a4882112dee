"""Random-action fuzzing of a World (used by the robustness tests and the `slow` sweep)."""

from __future__ import annotations

import numpy as np

from luminous_sim.world.masks import mask_to_rle

NAV = ["MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown"]
INTERACT = ["PickupObject", "PutObject", "OpenObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff",
            "SliceObject"]


def random_action(world, rng: np.random.Generator) -> dict:
    """Mostly sensible actions on visible things, some on anything, some garbage."""
    r = rng.random()
    if r < 0.45:
        return {"action": NAV[int(rng.integers(len(NAV)))]}
    if r < 0.5:
        pts = world.nav.points()
        x, y = pts[int(rng.integers(len(pts)))] + rng.normal(0, 0.1, 2) * (rng.random() < 0.2)
        return {"action": "TeleportFull", "x": float(x), "z": float(y), "rotation": int(rng.integers(4)) * 90,
                "horizon": int(rng.integers(-2, 5)) * 15}
    name = INTERACT[int(rng.integers(len(INTERACT)))]
    if r < 0.85:
        visible = sorted(world.instance_masks())
        ids = visible or sorted(world.built.objects)
        target = ids[int(rng.integers(len(ids)))]
        if rng.random() < 0.3:  # by mask, as a learned agent would
            return {"action": name, "mask": mask_to_rle(world.instance_masks().get(target, np.zeros((300, 300))))}
        key = "receptacleObjectId" if name == "PutObject" else "objectId"
        return {"action": name, key: target}
    if r < 0.95:
        ids = sorted(world.built.objects)
        key = "receptacleObjectId" if name == "PutObject" else "objectId"
        return {"action": name, key: ids[int(rng.integers(len(ids)))]}
    garbage = [{"action": name}, {"action": name, "objectId": "Nope|1|2|3"}, {"action": "Jump"}, {"action": None},
               {"action": name, "mask": [[-5, 3]]}, {"action": name, "point": [999, -1]},
               {"action": "MoveAhead", "moveMagnitude": "far"}, {"action": "TeleportFull", "x": "a"}]
    return garbage[int(rng.integers(len(garbage)))]


RESULT_KEYS = ("lastAction", "lastActionSuccess", "errorMessage")
"""Metadata that reports the last action rather than the world."""


def snapshot(world) -> dict:
    """Everything an action could change: the agent's pose, what is held, the pure state, the metadata,
    and every body's pose, joint positions and colours, read from PyBullet."""
    c = world.client
    bodies = {}
    for oid, loaded in sorted(world.built.objects.items()):
        b = loaded.body
        joints = tuple(c.getJointState(b, j)[0] for j in range(c.getNumJoints(b)))
        colours = tuple((v[1], v[7]) for v in c.getVisualShapeData(b))  # (link, rgba)
        bodies[oid] = (c.getBasePositionAndOrientation(b), joints, colours)
    view = world.view()
    metadata = {k: v for k, v in view.metadata().items() if k not in RESULT_KEYS}
    return {"agent": view.agent, "held": view.held, "state": view.state, "metadata": metadata, "bodies": bodies}


def check_world(world) -> list[str]:
    """Problems: non-finite poses, objects outside the room or under the floor."""
    minx, miny, maxx, maxy = world.scene.room.bounds
    problems = []
    for oid, loaded in world.built.objects.items():
        pos, orn = world.client.getBasePositionAndOrientation(loaded.body)
        if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(orn))):
            problems.append(f"{oid} has a non-finite pose")
        elif not (minx - 0.3 <= pos[0] <= maxx + 0.3 and miny - 0.3 <= pos[1] <= maxy + 0.3 and -0.2 < pos[2] < 3.0):
            problems.append(f"{oid} left the room: {np.round(pos, 3).tolist()}")
    return problems


def fuzz(world, steps: int, seed: int) -> dict:
    rng = np.random.default_rng(seed)
    ok = 0
    codes: dict = {}
    for i in range(steps):
        result = world.step(random_action(world, rng))
        ok += result.success
        assert isinstance(result.error, str) and (result.success or result.error)
        assert result.success == (result.code is None), f"step {i}: a failure without a code: {result}"
        if result.code is not None:
            codes[result.code] = codes.get(result.code, 0) + 1
        if i % 50 == 0 or i == steps - 1:
            problems = check_world(world)
            assert not problems, f"step {i}: {problems}"
    return {"steps": steps, "succeeded": ok, "codes": codes}
