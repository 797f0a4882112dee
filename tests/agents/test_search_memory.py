"""What the modular agent remembers to search and act again: a receptacle's sites (a long counter is looked at
site by site), a receptacle's shape before it was opened (restored when closed, so its swung door does not
mislead the approach), and where it put the task's object (to look there again, as in a fridge it cooled in)."""

from __future__ import annotations

import numpy as np

from luminous_sim.agents.modular_agent import ModularAgent, type_index
from luminous_sim.agents.own_pose import OwnPose
from luminous_sim.agents.semantic_map import SITE, Instance, _add_sites


def test_sites_are_the_squares_an_instance_was_seen_in_with_their_mean_points():
    counter = Instance(7, type_index("CounterTop"))
    _add_sites(counter, np.array([[0.2, 0.1, 0.9], [0.4, 0.3, 0.9], [1.5, 0.2, 0.9]]))
    _add_sites(counter, np.array([[2.6, 0.5, 0.9]]))
    assert sorted(counter.sites) == [(0, 0), (1, 0), (2, 0)] and SITE == 1.0
    assert np.allclose(counter.site_point((0, 0)), [0.3, 0.2, 0.9])
    _add_sites(counter, np.array([[0.9, 0.9, 1.0]]))  # a later frame adds to a site, never replaces it
    assert np.allclose(counter.site_point((0, 0)), [1.5 / 3, 1.3 / 3, 2.8 / 3])


def _agent_after(agent: ModularAgent, action: str, body: int, failure: str = "") -> None:
    agent.ep.last, agent.ep.target = {"action": action, "mask": np.ones((2, 2), bool)}, body
    agent._feedback({"failure_code": failure})


def test_a_closed_receptacle_gets_back_the_points_it_was_seen_at_before_it_opened():
    agent = ModularAgent(64, 64, settings=None)
    agent.reset("", {"episode_seed": 0})
    closed = np.array([[1.0, 2.0, 0.9], [1.1, 2.0, 0.9]])
    fridge = agent.ep.map.instances[3] = Instance(3, type_index("Fridge"), closed.copy())
    _agent_after(agent, "OpenObject", 3)
    assert 3 in agent.ep.opened
    fridge.points = np.concatenate([np.array([[0.2, 1.2, 1.0]]), fridge.points])  # the door, seen swung open
    _agent_after(agent, "CloseObject", 3, failure="blocked")  # a failed close changes nothing
    assert len(fridge.points) == 3
    _agent_after(agent, "CloseObject", 3)
    assert np.array_equal(fridge.points, closed) and 3 not in agent.ep.opened


def test_it_remembers_where_it_put_what_it_held_and_goes_back_to_look():
    agent = ModularAgent(64, 64)
    agent.task = {}
    from luminous_sim.agents.subgoals import subgoals

    agent.ep.plan = subgoals("pick_cool_then_place_in_recep", {"object_target": "Egg", "parent_target": "SideTable"})
    agent.ep.index, agent.ep.held, agent.ep.roles = 2, 9, {"object": 9}
    agent.ep.pose = OwnPose(node=(0, 0), heading=0, horizon=15)
    agent.ep.map.visited.update({(0, 0), (0, 1), (0, 2)})
    agent.ep.map.instances[3] = Instance(3, type_index("Fridge"), np.array([[0.0, 1.0, 0.9]]))
    _agent_after(agent, "PutObject", 3)
    assert agent.ep.held is None and agent.ep.put_at[9] == OwnPose(node=(0, 0), heading=0, horizon=15)
    agent.ep.pose = OwnPose(node=(0, 2), heading=2, horizon=30)
    pickup = agent.ep.plan[5]
    assert pickup.action == "PickupObject" and pickup.role == "object"
    first = agent._back_to_put(pickup)
    assert first is not None and agent.ep.queue[-1] == "LookUp"  # the way back, then the horizon it put from
    agent.ep.queue.clear()
    agent.ep.pose = OwnPose(node=(0, 0), heading=0, horizon=15)
    assert agent._back_to_put(pickup) is None and 9 not in agent.ep.put_at  # there, and it is still unseen
