"""ALFRED's navigation reward (spec 5.2): 0.2 x path steps gained toward the expert's go-to location, +4 on
coming within 3 steps, by hand-made moves against `planning.NavGraph.distance`."""

from __future__ import annotations

import pickle

import gymnasium
import pytest

import luminous_sim  # noqa: F401  (registers the ids)
from luminous_sim.env.goto_reward import GotoTarget, goto_targets
from luminous_sim.errors import LuminousError
from luminous_sim.planning import NavGraph
from luminous_sim.world import AgentPose

ONLY_NAVIGATION = {"goal_reward": 0, "failure": 0, "step_penalty": 0, "PickupObjectAction": 0}
"""Every other reward term off, so that a step's reward is the navigation term alone."""
MOVES = ["RotateLeft", "MoveAhead", "MoveAhead", "RotateRight", "RotateRight", "MoveAhead", "LookDown",
         "MoveAhead", "RotateLeft", "MoveAhead"]


def test_the_expert_plan_is_cut_into_go_to_subgoals():
    start = AgentPose(1.0, 1.0, 0, 30)
    nav = [{"action": a} for a in ("MoveAhead", "RotateRight", "MoveAhead")]
    plan = (*nav, {"action": "OpenObject"}, {"action": "PickupObject"}, {"action": "MoveAhead"},
            {"action": "PutObject"}, {"action": "LookUp"})
    first = AgentPose(1.25, 1.25, 90, 30)
    assert goto_targets(start, plan) == [GotoTarget(first, ("OpenObject", "PickupObject")),
                                         GotoTarget(AgentPose(1.5, 1.25, 90, 30), ("PutObject",)),
                                         GotoTarget(AgentPose(1.5, 1.25, 90, 15), ())]
    assert goto_targets(start, ({"action": "PickupObject"},)) == [GotoTarget(start, ("PickupObject",), False)]
    with pytest.raises(LuminousError, match="TeleportFull"):
        goto_targets(start, ({"action": "TeleportFull", "x": 1, "z": 1},))


class Written:
    """ALFRED's Goto reward, written out from `NavGraph.distance`: shaping until the go-to is reached (with
    +4 on reaching), then nothing while its interaction is the subgoal."""

    def __init__(self, graph: NavGraph, target: AgentPose):
        self.graph, self.target, self.reached = graph, target, False

    def __call__(self, before: AgentPose, after: AgentPose) -> float:
        if self.reached:
            return 0.0
        d0, d1 = self.graph.distance(before, self.target), self.graph.distance(after, self.target)
        self.reached = d1 < 3
        return 0.2 * (d0 - d1) + (4.0 if self.reached else 0.0)


@pytest.mark.parametrize("seed", [2, 5])
def test_hand_made_moves_earn_the_formula_exactly(seed):
    env = gymnasium.make("Luminous-PickUp-64-v1", reward=ONLY_NAVIGATION).unwrapped
    env.reset(seed=seed)
    graph = NavGraph(env.world.nav)
    (target,) = env.shaper.goto.targets
    assert target.interactions == ("PickupObject",) and target.walked
    written = Written(graph, target.pose)
    for name in MOVES:  # wander: gains and losses
        before = env.world.agent
        assert env.step(env.actions.index(name))[1] == written(before, env.world.agent), name
    env.reset(seed=seed)  # the same episode again, along the expert's path this time
    written, rewards = Written(graph, target.pose), []
    for action in env.episode.expert.actions:
        before = env.world.agent
        _, reward, terminated, _, _ = env.step(env.action_for(action))
        rewards.append(reward)
        if action["action"] == "PickupObject":  # the go-to's interaction: no navigation term
            assert reward == 0.0 and terminated
        else:
            assert reward == written(before, env.world.agent), action
    assert sum(r >= 4.0 for r in rewards) == 1 and written.reached  # +4 paid once, on reaching
    env.close()


def test_the_v0_ids_keep_their_reward_and_a_pickled_env_keeps_the_subgoal_state():
    old = gymnasium.make("Luminous-PickUp-64-v0").unwrapped
    env = gymnasium.make("Luminous-PickUp-64-v1").unwrapped
    old.reset(seed=2), env.reset(seed=2)
    assert old.shaper.goto is None and not old.config.navigation_reward
    written = Written(NavGraph(env.world.nav), env.shaper.goto.targets[0].pose)
    for name in MOVES:  # the same steps: v1 earns v0's reward plus the navigation term
        before = env.world.agent
        r_old, r_new = old.step(old.actions.index(name))[1], env.step(env.actions.index(name))[1]
        assert r_new == pytest.approx(r_old + written(before, env.world.agent), abs=1e-12)
    copy = pickle.loads(pickle.dumps(env))
    assert (copy.shaper.goto.index, copy.shaper.goto.reached, copy.shaper.goto.distance) == \
        (env.shaper.goto.index, env.shaper.goto.reached, env.shaper.goto.distance)
    for action in env.episode.expert.actions[:6]:
        assert copy.step(copy.action_for(action))[1:] == env.step(env.action_for(action))[1:]
    old.close(), env.close(), copy.close()
