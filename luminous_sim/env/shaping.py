"""`RewardShaper`: one episode's progress and reward: the goal's condition scores after each step, whether the
goal was reached, and the step's reward (ALFRED's terms, `rewards.step_reward`, plus with `navigation` the
navigation term of the expert's go-to subgoals, `goto_reward.GotoReward`)."""

from __future__ import annotations

from luminous_sim.env.actions import STOP_NAMES
from luminous_sim.env.goto_reward import GotoReward, goto_targets
from luminous_sim.env.rewards import RewardConfig, step_reward
from luminous_sim.episodes import ExpertPlan, Goal
from luminous_sim.world import World


def goal_scores(goal: Goal, world: World) -> dict[str, int]:
    """The goal's conditions met in the world now (condition name -> counts)."""
    return goal.scores(world.view(), set(world.visible_objects()))


class RewardShaper:
    """The scores and reward of the episode started last (`start`).

    Args:
        config: the reward terms.
        navigation: add ALFRED's navigation term (dense rewards, with the expert's plan known).
    """

    def __init__(self, config: RewardConfig, navigation: bool):
        self.config, self.navigation = config, navigation
        self.goal: Goal | None = None
        self.scores: dict[str, int] = {}
        """Condition name -> counts met after the last step."""
        self.reached = False
        """Whether the goal has been met at some step of the episode."""
        self.goto: GotoReward | None = None
        """ALFRED's navigation reward of the episode (dense rewards with the expert's plan known), else None."""
        self._expert_length = 0
        self._stopped = False

    def start(self, goal: Goal, world: World, expert: ExpertPlan | None) -> None:
        """A new episode in `world`, at its start."""
        self.goal, self.reached, self._stopped = goal, False, False
        self._expert_length = len(expert.actions) if expert is not None else 0
        self.scores = goal_scores(goal, world)
        self.goto = None
        c = self.config
        if not c.sparse and self.navigation and expert is not None:
            from luminous_sim.planning import NavGraph

            agent = world.agent
            self.goto = GotoReward(NavGraph(world.nav), goto_targets(agent, expert.actions), agent,
                                   shaping=c.goto_shaping, reach=c.goto_reach, bonus=c.section("GotoLocation"))

    @property
    def success(self) -> bool:
        """Whether every goal condition is met after the last step (and, for a goal that counts only at Stop,
        the last step was Stop)."""
        return (self.goal is not None and self.scores == self.goal.weights()
                and (self._stopped or not self.goal.stop_to_succeed))

    def step(self, world: World, action: str | None, ok: bool, step: int) -> float:
        """The reward of step number `step` (from 1), which left `world` as it is after `action` (its name; None
        when nothing was sent) succeeded or not."""
        assert self.goal is not None, "start an episode first"
        self._stopped = action in STOP_NAMES
        before, self.scores = self.scores, goal_scores(self.goal, world)
        success = self.success
        reached = success and not self.reached
        self.reached = self.reached or success
        reward = step_reward(self.config, before, self.scores, self.goal.stages(), reached=reached, action_ok=ok,
                             step=step, expert_length=self._expert_length)
        if self.goto is not None:
            reward += self.goto.step(world.agent, action, ok)
        if self._stopped and self.goal.stop_to_succeed and not success:
            reward += self.config.failed_stop
        return reward

    def replayed(self, world: World, action: str, ok: bool) -> None:
        """Follow a step replayed without its reward (restoring an episode): only the go-to state moves."""
        if self.goto is not None:
            self.goto.step(world.agent, action, ok)

    def resume(self, world: World, reached: bool) -> None:
        """After a replay: the scores of the world as it is now, and whether the goal had been reached."""
        assert self.goal is not None, "start an episode first"
        self.scores, self.reached = goal_scores(self.goal, world), reached
