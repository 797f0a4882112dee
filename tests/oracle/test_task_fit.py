"""Tasks the physical world can support, and whole oracle runs of goals whose plan order matters."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.planning.oracle import Oracle
from luminous_sim.planning.task_fit import draw_task, has_room, physically_feasible
from luminous_sim.tasks.errors import TaskSamplingError
from luminous_sim.tasks.evaluate import goal_conditions
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.types import goal_for
from tests.world.conftest import obj


def test_find_spot_is_a_dry_run(world, kitchen_scene):
    apple, micro = obj(kitchen_scene, "apple"), obj(kitchen_scene, "microwave")
    before = {k: world.built.pose_of(k)[0].tolist() for k in world.built.objects}
    rng_state = world.interactions.rng.bit_generator.state
    closed = world.interactions.find_spot(apple, micro, np.random.default_rng(0))
    assert isinstance(closed, str) and "no place" in closed  # the inside is behind the closed door
    x, y, z, _ = world.interactions.find_spot(apple, micro, np.random.default_rng(0), assume_open=True)
    lo, hi = world.client.getAABB(world.built.objects[micro].body, -1)
    assert lo[0] - 0.01 <= x <= hi[0] + 0.01 and lo[1] - 0.01 <= y <= hi[1] + 0.01 and lo[2] <= z <= hi[2]
    assert {k: world.built.pose_of(k)[0].tolist() for k in world.built.objects} == before
    assert world.interactions.rng.bit_generator.state == rng_state


def test_has_room_follows_the_real_sizes(world):
    assert has_room(world, "Apple", "Microwave")
    assert has_room(world, "AppleSliced", "Microwave")  # slices to come stand in by their whole
    assert not has_room(world, "Fridge", "Microwave")  # the type table is not asked: sizes are
    assert not physically_feasible(world, PddlParams("Fridge", "Microwave"))
    assert physically_feasible(world, PddlParams("Apple", "Fridge"))


def test_draw_task_leaves_out_unreachable_objects(world, kitchen_scene):
    rng = np.random.default_rng(0)
    apples = world.interactions.state.of_type("Apple")
    for _ in range(5):  # the mug and the plate can still be heated
        task = draw_task(kitchen_scene, world, "pick_heat_then_place_in_recep", rng, excluded=apples)
        assert task.params.object_target != "Apple"
    everything = [k for k, o in world.interactions.state.objects.items() if o.parent is None]
    with pytest.raises(TaskSamplingError):
        draw_task(kitchen_scene, world, "pick_heat_then_place_in_recep", rng, excluded=everything)


def test_sliced_heat_task_slices_first_and_heats_a_slice(world):
    """ALFRED's evaluator counts heated ids, and slices are new objects: heating the whole apple and
    slicing it afterwards leaves no heated slice, so the oracle must slice first."""
    params = PddlParams("Apple", "CounterTop", object_sliced=True)
    goal = goal_for(params, "pick_heat_then_place_in_recep")
    traj = Oracle(world, record_frames=False).run(goal)
    task = TaskInstance("pick_heat_then_place_in_recep", params, goal, 0)
    assert traj.success, traj.failures
    done, total = goal_conditions(task, world.interactions.state, set(world.visible_objects()))
    assert done == total
    actions = [h["planner_action"]["action"] for h in traj.high_pddl]
    assert actions.index("SliceObject") < actions.index("HeatObject")
    heated = world.interactions.state.heated
    assert any("AppleSliced" in h for h in heated)


def test_a_put_lands_where_the_agent_can_see_it(world, kitchen_scene):
    """Put into a sink basin from where the agent stands: the mug must stay in view (not behind the
    basin's near rim), so that it can be picked up again from the same pose."""
    from dataclasses import dataclass, field

    from luminous_sim.planning.trajectory import Trajectory

    @dataclass(frozen=True)
    class HL:
        action: str
        args: dict = field(default_factory=dict)

    mug = obj(kitchen_scene, "mug")
    basin = world.interactions.state.of_type("SinkBasin")[0]
    Oracle(world, record_frames=False)._execute(
        [HL("GotoLocation", {"objectId": mug}), HL("PickupObject", {"objectId": mug}),
         HL("GotoLocation", {"objectId": basin}), HL("PutObject", {"objectId": mug, "receptacleObjectId": basin})],
        Trajectory(init_action={}))
    assert world.interactions.state.objects[mug].parent == basin
    assert mug in world.visible_objects()
    assert world.step({"action": "PickupObject", "objectId": mug}).success
