"""Tasks the physical world can support, and whole oracle runs of goals whose plan order matters."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.planning import Oracle, draw_task, has_room, physically_feasible
from luminous_sim.tasks.errors import TaskSamplingError
from luminous_sim.tasks.evaluate import goal_conditions
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.types import goal_for
from tests.world.conftest import obj


def test_free_spot_is_a_dry_run(world, kitchen_scene):
    apple, micro = obj(kitchen_scene, "apple"), obj(kitchen_scene, "microwave")
    view = world.view()
    before = {k: world.built.pose_of(k)[0].tolist() for k in world.built.objects}
    rng_state = world.interactions.rng.bit_generator.state
    closed = view.free_spot(apple, micro, np.random.default_rng(0))
    assert isinstance(closed, Failure) and "no place" in closed.message  # the inside is behind the closed door
    assert closed.code == FailureCode.NO_SPOT_IN_REACH
    x, y, z, _ = view.free_spot(apple, micro, np.random.default_rng(0), assume_open=True)
    lo, hi = view.aabb(micro)
    assert lo[0] - 0.01 <= x <= hi[0] + 0.01 and lo[1] - 0.01 <= y <= hi[1] + 0.01 and lo[2] <= z <= hi[2]
    assert {k: world.built.pose_of(k)[0].tolist() for k in world.built.objects} == before
    assert world.interactions.rng.bit_generator.state == rng_state


def test_has_room_follows_the_real_sizes(world):
    view = world.view()
    assert has_room(view, "Apple", "Microwave")
    assert has_room(view, "AppleSliced", "Microwave")  # slices to come stand in by their whole
    assert not has_room(view, "Fridge", "Microwave")  # the type table is not asked: sizes are
    assert not physically_feasible(view, PddlParams("Fridge", "Microwave"))
    assert physically_feasible(view, PddlParams("Apple", "Fridge"))


def test_draw_task_leaves_out_unreachable_objects(world, kitchen_scene):
    rng = np.random.default_rng(0)
    view = world.view()
    apples = view.state.of_type("Apple")
    for _ in range(5):  # the mug and the plate can still be heated
        task = draw_task(kitchen_scene, view, "pick_heat_then_place_in_recep", rng, excluded=apples)
        assert task.params.object_target != "Apple"
    everything = [k for k, o in view.state.objects.items() if o.parent is None]
    with pytest.raises(TaskSamplingError):
        draw_task(kitchen_scene, view, "pick_heat_then_place_in_recep", rng, excluded=everything)


def test_sliced_heat_task_slices_first_and_heats_a_slice(world):
    """ALFRED's evaluator counts heated ids, and slices are new objects: heating the whole apple and
    slicing it afterwards leaves no heated slice, so the oracle must slice first."""
    params = PddlParams("Apple", "CounterTop", object_sliced=True)
    goal = goal_for(params, "pick_heat_then_place_in_recep")
    traj = Oracle(world, record_frames=False).run(goal)
    task = TaskInstance("pick_heat_then_place_in_recep", params, goal, 0)
    assert traj.success, traj.failures
    done, total = goal_conditions(task, world.view().state, set(world.visible_objects()))
    assert done == total
    actions = [h["planner_action"]["action"] for h in traj.high_pddl]
    assert actions.index("SliceObject") < actions.index("HeatObject")
    heated = world.view().state.heated
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
    basin = world.view().state.of_type("SinkBasin")[0]
    Oracle(world, record_frames=False)._execute(
        [HL("GotoLocation", {"objectId": mug}), HL("PickupObject", {"objectId": mug}),
         HL("GotoLocation", {"objectId": basin}), HL("PutObject", {"objectId": mug, "receptacleObjectId": basin})],
        Trajectory(init_action={}))
    assert world.view().state.objects[mug].parent == basin
    assert mug in world.visible_objects()
    assert world.step({"action": "PickupObject", "objectId": mug}).success


def test_a_put_lands_within_reach_of_the_eye(world, kitchen_scene):
    """A real put from where the agent stands, and a dry run from a given eye, land within reach of that
    eye; from an eye far from everything there is no spot at all."""
    apple, counter = obj(kitchen_scene, "apple"), obj(kitchen_scene, "counter")
    reach = world.config.visibility_distance
    pts = world.nav.points()
    view = world.view()
    lo, hi = view.aabb(counter)
    centre = (np.array(lo[:2]) + np.array(hi[:2])) / 2
    near = pts[np.argmin(np.linalg.norm(pts - centre, axis=1))]
    eye = (float(near[0]), float(near[1]), 1.576)
    for seed in range(5):
        got = view.free_spot(apple, counter, np.random.default_rng(seed), eye=eye)
        assert not isinstance(got, Failure), got
        assert np.linalg.norm(np.array(got[:3]) - np.array(eye)) <= reach + 0.1
    far = (float(centre[0]) + 20.0, float(centre[1]), 1.576)
    assert isinstance(view.free_spot(apple, counter, np.random.default_rng(0), eye=far), Failure)


def test_doors_the_agent_cannot_open_are_never_counted_open():
    """A side table's drawer is a gated region of a type ALFRED cannot open: a dry run that counts doors
    as open still leaves it out."""
    from luminous_sim import cdf
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.cssg import generate
    from luminous_sim.scene import region_spots
    from luminous_sim.world import World
    from luminous_sim.world.placement import _host_now

    doc = cdf.load(Path(__file__).resolve().parents[2] / "cdf" / "examples" / "bedroom_reading_desk.yaml")
    catalog = default_catalog()

    def drawer_table(scene) -> bool:
        return any(o.type == "SideTable" and any(r.get("requires_open") for r in catalog.for_object(o).regions)
                   for o in scene.objects)

    # the first layout with a drawer side table (which seed holds one changes with the generator)
    scene = next(s for s in (generate(doc, seed=k).scene for k in range(10)) if drawer_table(s))
    with World(scene) as w:
        view = w.view()
        tables = [o for o in view.state.of_type("SideTable")
                  if any(r.get("requires_open") for r in w.built.objects[o].entry.regions)]
        assert tables, "the example bedroom should hold a side table with a drawer"
        cd = next(iter(view.state.of_type("CD") or view.state.of_type("CellPhone") or view.state.of_type("Book")))
        for table in tables:
            host = _host_now(w, view.state, table)
            drawers = [s for s in region_spots(host, w.built.objects[table].entry) if s.gated]
            for seed in range(10):
                got = view.free_spot(cd, table, np.random.default_rng(seed), assume_open=True)
                if isinstance(got, Failure):
                    continue
                assert not any(abs(got[2] - (s.floor_z + 0.002 - w.built.objects[cd].entry.bbox_min[2])) < 1e-6
                               for s in drawers)


def test_a_dry_run_can_pretend_a_first_object_is_already_put(world, kitchen_scene):
    from luminous_sim.planning.task_fit import has_room_for_two
    from luminous_sim.scene import footprint

    apple, mug, counter = obj(kitchen_scene, "apple"), obj(kitchen_scene, "mug"), obj(kitchen_scene, "counter")
    view = world.view()
    for seed in range(5):
        first = view.free_spot(apple, counter, np.random.default_rng(seed))
        second = view.free_spot(mug, counter, np.random.default_rng(seed), also=((apple, first),))
        assert not isinstance(first, Failure) and not isinstance(second, Failure)
        a = footprint(world.built.objects[apple].entry, first[0], first[1], first[3])
        m = footprint(world.built.objects[mug].entry, second[0], second[1], second[3])
        assert not a.intersects(m)
    # one microwave, one fridge: "two of a kind" needs two objects of that kind to begin with
    assert len(view.state.of_type("Fridge")) == 1 and not has_room_for_two(view, "Fridge", "CounterTop")


def test_two_slices_to_be_cut_fit_where_their_whole_does(world, kitchen_scene):
    from luminous_sim.planning.task_fit import has_room, has_room_for_two

    view = world.view()
    state = view.state
    assert len(state.of_type("Apple")) == 1 and not state.of_type("AppleSliced")
    # one apple, no slices yet: a pick_two of slices is as placeable as the apple itself
    assert has_room_for_two(view, "AppleSliced", "CounterTop") == has_room(view, "Apple", "CounterTop") is True
    assert not has_room_for_two(view, "Apple", "CounterTop")  # but two whole apples there are not


def test_a_redraw_puts_nothing_where_a_put_found_no_room(world, kitchen_scene):
    """A put that found a receptacle full rules it out of later draws (ALFRED's generator drops such
    tasks), but not the other receptacles of its type."""
    view = world.view()
    state = view.state
    micro = state.of_type("Microwave")
    assert len(micro) == 1 and has_room(view, "Apple", "Microwave")
    assert not has_room(view, "Apple", "Microwave", full=micro)
    assert not physically_feasible(view, PddlParams("Apple", "Microwave"), full=micro)
    rng = np.random.default_rng(0)
    for _ in range(8):
        task = draw_task(kitchen_scene, view, "pick_heat_then_place_in_recep", rng, full=micro)
        assert task.params.parent_target != "Microwave"
    counters = state.of_type("CounterTop")
    if len(counters) > 1:
        assert has_room(view, "Apple", "CounterTop", full=counters[:1])


@pytest.mark.parametrize("code, error, reported", [
    (FailureCode.RECEPTACLE_FULL, "{} is full: no free, stable spot for {}", True),  # no room at all: redraw
    (FailureCode.NO_SPOT_IN_REACH, "{} has no place to put things within reach", False),  # out of reach: kept
])
def test_the_oracle_reports_only_receptacles_with_no_room_at_all(world, kitchen_scene, monkeypatch, code, error,
                                                                 reported):
    """The receptacles the episode's redraw leaves out (episode.run_episode passes them to draw_task): the
    oracle tells them by the put's failure code."""
    from luminous_sim.world import placement

    micro = world.view().state.of_type("Microwave")[0]
    real = placement.find_spot

    def no_room_in_the_microwave(w, state, oid, receptacle, *args, **kwargs):
        if receptacle == micro:
            return Failure(code, error.format(receptacle, oid))
        return real(w, state, oid, receptacle, *args, **kwargs)

    monkeypatch.setattr(placement, "find_spot", no_room_in_the_microwave)
    traj = Oracle(world, record_frames=False).run(goal_for(PddlParams("Apple", "Microwave"), "pick_and_place_simple"))
    assert not traj.success and traj.full == ([micro] if reported else [])
    assert any(f"PutObject failed: {error.format(micro, '')}"[:40] in f for f in traj.failures)
    assert code in traj.failure_codes and len(traj.failure_codes) == len(traj.failures)
