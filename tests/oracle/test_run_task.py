"""A given task (issue 14): solved without redraws, from its start pose and initial state, by the oracle or
by following a script; the first cause of a failure is kept beside the later ones."""

from __future__ import annotations

import json

import pytest

from luminous_sim.cdf import AgentPoseSpec, parse_expr
from luminous_sim.cdf.schema import HighLevelStep, LowLevelStep
from luminous_sim.episode import run_task
from luminous_sim.errors import FailureCode, PlanningError
from luminous_sim.planning import LowLevelAction, script_from_cdf
from luminous_sim.planning.symbolic import HighLevelAction
from luminous_sim.tasks import PddlParams, TaskError, TaskInstance, goal_for, state_from_scene
from tests.world.conftest import obj


def _names(scene) -> dict[str, str]:
    return {n: obj(scene, n) for n in ("apple", "fridge", "counter", "microwave", "mug")}


def _custom(scene, goal: str) -> TaskInstance:
    return TaskInstance("custom", PddlParams(""), parse_expr(goal), 0, custom=True, names=_names(scene))


def test_a_given_task_is_solved_as_given(kitchen_scene):
    params = PddlParams("Apple", "Fridge")
    task = TaskInstance("pick_and_place_simple", params, goal_for(params, "pick_and_place_simple"), 0)
    result = run_task(kitchen_scene, task, seed=0, record_frames=False)
    assert result.success and result.goal_conditions == (1, 1) and result.failure == "" and not result.failures


def test_a_given_task_the_oracle_cannot_do_is_not_redrawn(kitchen_scene):
    """run_episode would redraw on GOAL_UNREACHABLE; a given task stands, with its cause."""
    params = PddlParams("Apple", "Toilet")
    task = TaskInstance("pick_and_place_simple", params, goal_for(params, "pick_and_place_simple"), 0)
    result = run_task(kitchen_scene, task, seed=0, record_frames=False)
    assert not result.success and "Toilet" in result.goal
    assert result.failure_code == FailureCode.GOAL_UNREACHABLE and "cannot be reached" in result.failure


def test_the_first_cause_is_kept_when_a_replan_fails_differently(kitchen_scene, tmp_path):
    """The apple lies beyond every pose's reach: no pose sees it (first), then the replan, without it,
    finds the goal unreachable (last). The first cause is the one that says what happened."""
    apple = obj(kitchen_scene, "apple")
    far = [o.model_copy(update={"position": (40.0, 40.0, 0.9), "parent": None}) if o.id == apple else o
           for o in kitchen_scene.objects]
    scene = kitchen_scene.model_copy(update={"objects": far})
    result = run_task(scene, _custom(scene, "(inReceptacle apple fridge)"), seed=0, out_dir=tmp_path,
                      record_frames=False)
    assert not result.success and len(result.failures) >= 2
    assert result.failure_code == FailureCode.NO_POSE and apple in result.failure
    assert result.failures[0].message == result.failure and result.failures[-1].code != FailureCode.NO_POSE
    record = json.loads((tmp_path / "trajectory.json").read_text())
    assert record["failure"] == result.failure and record["failure_code"] == "no_pose"
    assert [f["code"] for f in record["failures"]] == [str(f.code) for f in result.failures]


def test_the_start_pose_and_the_initial_state_are_applied(kitchen_scene):
    fridge = obj(kitchen_scene, "fridge")
    start = AgentPoseSpec(position=(1.1, 1.1), rotation=180, horizon=0)
    result, record = run_task(kitchen_scene, _custom(kitchen_scene, "(isOpen fridge)"), seed=0, start=start,
                              initial=parse_expr("(and (isOpen fridge) (not (isOpen microwave)))"),
                              record_frames=False, return_record=True)
    assert record.start_state.objects[fridge].isOpen and not state_from_scene(kitchen_scene).objects[fridge].isOpen
    init = record.trajectory.init_action
    assert (init["rotation"], init["horizon"]) == (180, 0)
    assert (init["x"], init["z"]) != (1.1, 1.1) and "nearest reachable point" in result.notes[0]
    assert result.success and result.low_actions == 0  # the goal held from the start


def test_an_initial_state_the_scene_does_not_meet_is_refused(kitchen_scene):
    with pytest.raises(TaskError, match=r"task.initial: \(inReceptacle apple fridge\) does not hold"):
        run_task(kitchen_scene, _custom(kitchen_scene, "(isCool apple)"), seed=0,
                 initial=parse_expr("(inReceptacle apple fridge)"), record_frames=False)


def test_a_high_level_script_is_followed(kitchen_scene):
    steps = [("GotoLocation", "apple"), ("PickupObject", "apple"), ("GotoLocation", "fridge")]
    script = [HighLevelStep(action=a, object=o) for a, o in steps]
    script.append(HighLevelStep(action="PutObject", receptacle="fridge"))
    result, record = run_task(kitchen_scene, _custom(kitchen_scene, "(and (inReceptacle apple fridge) (isCool apple))"),
                              seed=0, script=script, record_frames=False, return_record=True)
    high = [h["planner_action"]["action"] for h in record.trajectory.high_pddl]
    assert high == ["GotoLocation", "PickupObject", "GotoLocation", "PutObject", "End"]
    low = [a["api_action"]["action"] for a in record.trajectory.low_actions if a["high_idx"] == 3]
    assert low == ["OpenObject", "PutObject", "CloseObject"]  # ALFRED's expansion of a put into a fridge
    assert result.success and result.goal_conditions == (2, 2)


def test_a_low_level_script_runs_as_written_and_stops_at_its_first_failure(kitchen_scene):
    script = [LowLevelStep(action="RotateLeft"), LowLevelStep(action="RotateLeft"),
              LowLevelStep(action="PutObject", objectId="apple", receptacleObjectId="fridge")]
    result, record = run_task(kitchen_scene, _custom(kitchen_scene, "(inReceptacle apple fridge)"), seed=0,
                              script=script, record_frames=False, return_record=True)
    traj = record.trajectory
    assert [a["api_action"]["action"] for a in traj.low_actions] == ["RotateLeft", "RotateLeft"]
    assert {a["high_idx"] for a in traj.low_actions} == {0}  # one walk, one GotoLocation subgoal
    assert traj.high_pddl[0]["planner_action"]["action"] == "GotoLocation"
    assert not result.success and result.failure_code is not None and len(result.failures) == 1


def test_script_from_cdf_names_objects_holds_and_devices(kitchen_scene):
    names, state = _names(kitchen_scene), state_from_scene(kitchen_scene)
    script = script_from_cdf([HighLevelStep(action="PickupObject", object="apple"),
                              HighLevelStep(action="GotoLocation", object="microwave"),
                              HighLevelStep(action="HeatObject", object="apple"),
                              HighLevelStep(action="NoOp"),
                              LowLevelStep(action="MoveAhead"),
                              LowLevelStep(action="PutObject", receptacleObjectId="counter")], names, state)
    apple, microwave = names["apple"], names["microwave"]
    assert script[2] == HighLevelAction("HeatObject", {"objectId": apple, "receptacleObjectId": microwave})
    assert script[3] == LowLevelAction("MoveAhead")
    assert script[4].args["objectId"] == apple and len(script) == 5
    with pytest.raises(PlanningError, match=r"execution\[0\] \(PutObject\): puts into .* holds nothing"):
        script_from_cdf([HighLevelStep(action="PutObject", receptacle="fridge")], names, state)
    with pytest.raises(PlanningError, match=r"execution\[0\] \(PickupObject\)\.object: 'pear'"):
        script_from_cdf([HighLevelStep(action="PickupObject", object="pear")], names, state)
