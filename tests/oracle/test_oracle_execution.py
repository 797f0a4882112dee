"""The oracle's execution layer: navigation, ALFRED expansions, verification and ALFRED-format records,
driven here by hand-written high-level plans (the symbolic planner has its own tests)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pytest

from luminous_sim.errors import FailureCode
from luminous_sim.language import Describer
from luminous_sim.language.instructions import _segments
from luminous_sim.planning import ExecutionError, NavGraph, Oracle, Trajectory, goto_actions, look_steps
from luminous_sim.planning.alfred_actions import type_name
from luminous_sim.world import AgentPose, rle_to_mask
from tests.world.conftest import obj


@dataclass(frozen=True)
class HL:
    action: str
    args: dict = field(default_factory=dict)


def test_navigation_graph_shortest_paths(world):
    graph = NavGraph(world.nav)
    start = world.agent
    pts = world.nav.points()
    far = pts[int(np.argmax(np.linalg.norm(pts - [start.x, start.y], axis=1)))]
    goal = AgentPose(float(far[0]), float(far[1]), 180, 30)
    path = graph.path(start, goal)
    assert path and set(path) <= {"MoveAhead", "RotateLeft", "RotateRight"}
    for a in goto_actions(graph, start, goal):
        assert world.step(a).success, a
    assert world.agent.grid_key() == goal.grid_key() and world.agent.rotation == 180 and world.agent.horizon == 30
    manhattan = abs(round((far[0] - start.x) / 0.25)) + abs(round((far[1] - start.y) / 0.25))
    assert path.count("MoveAhead") >= manhattan
    assert look_steps(30, 45) == ["LookDown"] and look_steps(45, 0) == ["LookUp"] * 3


def test_pick_and_place_in_fridge_with_alfred_records(world, kitchen_scene):
    apple, fridge = obj(kitchen_scene, "apple"), obj(kitchen_scene, "fridge")
    oracle = Oracle(world)
    traj = Trajectory(init_action=world.agent.to_alfred())
    plan = [HL("GotoLocation", {"objectId": apple}), HL("PickupObject", {"objectId": apple}),
            HL("GotoLocation", {"objectId": fridge}),
            HL("PutObject", {"objectId": apple, "receptacleObjectId": fridge})]
    oracle._execute(plan, traj)
    state = world.view().state
    assert state.objects[apple].parent == fridge and not state.objects[fridge].isOpen
    assert apple in state.cooled  # closing the fridge after the put cools what is inside, as in ALFRED
    names = [a["discrete_action"]["action"] for a in traj.low_actions]
    assert names[-3:] == ["OpenObject", "PutObject", "CloseObject"] and "PickupObject" in names
    assert [h["planner_action"]["action"] for h in traj.high_pddl] == [p.action for p in plan]
    assert traj.high_pddl[0]["planner_action"]["location"].startswith("loc|")
    assert traj.high_pddl[0]["discrete_action"]["args"] == ["apple"]
    assert traj.high_pddl[3]["discrete_action"]["args"] == ["apple", "fridge"]
    put = traj.low_actions[-2]
    assert put["api_action"] == {"action": "PutObject", "objectId": apple, "receptacleObjectId": fridge,
                                 "forceAction": True, "placeStationary": True}
    args = put["discrete_action"]["args"]
    mask = rle_to_mask(args["mask"])
    assert mask.sum() >= 10 and len(args["bbox"]) == 4 and mask[args["point"][1], args["point"][0]]
    assert all(a["high_idx"] in (0, 1, 2, 3) for a in traj.low_actions)
    assert [a["high_idx"] for a in traj.low_actions] == sorted(a["high_idx"] for a in traj.low_actions)
    assert len(traj.frames) == len(traj.low_actions) and traj.frames[0].shape == (300, 300, 3)
    text = Describer(world.view(), np.random.default_rng(1)).describe(traj, "put an apple in the fridge")
    assert len(text.high_descs) == 4 and "fridge" in text.high_descs[2] and "apple" in text.high_descs[1]


def test_heat_expansion_runs_alfreds_sequence(world, kitchen_scene):
    mug, micro = obj(kitchen_scene, "mug"), obj(kitchen_scene, "microwave")
    traj = Trajectory(init_action=world.agent.to_alfred())
    Oracle(world)._execute([HL("GotoLocation", {"objectId": mug}), HL("PickupObject", {"objectId": mug}),
                            HL("GotoLocation", {"objectId": micro}),
                            HL("HeatObject", {"objectId": mug, "receptacleObjectId": micro})], traj)
    heat = [a["discrete_action"]["action"] for a in traj.low_actions
            if a["high_idx"] == 3 and not a["discrete_action"]["action"].endswith(("_15", "_25", "_90"))]
    assert heat == ["OpenObject", "PutObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff", "OpenObject",
                    "PickupObject", "CloseObject"]
    assert mug in world.view().state.heated and world.view().held == mug


def test_a_failing_step_raises_for_replanning(world, kitchen_scene):
    apple = obj(kitchen_scene, "apple")
    with pytest.raises(ExecutionError, match="OpenObject failed|not openable") as failed:
        Oracle(world)._execute([HL("GotoLocation", {"objectId": apple}), HL("OpenObject", {"objectId": apple})],
                               Trajectory(init_action={}))
    assert failed.value.code == FailureCode.NOT_OPENABLE


def test_navigation_sentences_and_names():
    assert _segments(["RotateLeft_90", "MoveAhead_25", "MoveAhead_25", "RotateRight_90", "RotateRight_90"]) == \
        [("left", 1), ("walk", 2), ("around", 1)]
    assert type_name("Apple|+01.00|+00.90|+02.00|AppleSliced_3") == "applesliced"
    assert type_name("Sink|+00.27|+00.00|+02.35") == "sink"
