"""`AgentPose.after`: a recorded trajectory's poses replayed action by action (the demo's path, the viewer)."""

from __future__ import annotations

from luminous_sim.world.agent import AgentPose


def test_after_follows_each_navigation_action_and_leaves_the_rest():
    p = AgentPose(1.0, 2.0, 0, 30)
    assert p.after("MoveAhead") == AgentPose(1.0, 2.25, 0, 30)
    assert p.after("RotateRight") == AgentPose(1.0, 2.0, 90, 30)
    assert p.after("RotateLeft") == AgentPose(1.0, 2.0, 270, 30)
    assert p.after("LookDown") == AgentPose(1.0, 2.0, 0, 45)
    assert p.after("LookUp") == AgentPose(1.0, 2.0, 0, 15)
    assert AgentPose(0, 0, 0, 60).after("LookDown") == AgentPose(0, 0, 0, 60)  # past the limit: unchanged
    assert p.after("PickupObject") == p
    assert p.after("RotateRight").after("MoveAhead") == AgentPose(1.25, 2.0, 90, 30)
