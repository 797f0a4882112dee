"""The oracle as a policy, an expert for imitation and DAgger.

It acts through the env's own action space: a discrete index whenever one means what the oracle means
(navigation, Stop, and an interaction whose target covers one of the k x k grid points), otherwise the
ALFRED dict form with the target's object id (`{"action": "PickupObject", "objectId": ...}`), which
`LuminousEnv.step` takes as well. Its plan comes from `planning.Oracle` for the env's current task and
state: proved at reset, followed at no cost while the agent takes its actions, recomputed from the
current state when the agent deviates (so it also labels states a learner reached on its own).
"""

from __future__ import annotations

from typing import Any

import gymnasium

from luminous_sim.env.alfred_env import LuminousEnv


class OraclePolicy:
    """The expert's next action for one env (a `LuminousEnv`, wrapped or not)."""

    def __init__(self, env: gymnasium.Env):
        inner = env.unwrapped
        if not isinstance(inner, LuminousEnv):
            raise TypeError(f"OraclePolicy needs a LuminousEnv, got {type(inner).__name__}")
        self.env = inner

    def __call__(self, observation: Any = None) -> int | dict[str, Any]:
        """The next action (the observation is not needed: the oracle knows the world)."""
        return self.env.expert_action()

    act = __call__

    def predict(self, observation: Any = None, state: Any = None, episode_start: Any = None,
                deterministic: bool = True) -> tuple[int | dict[str, Any], Any]:
        """stable-baselines3's policy signature: (action, state)."""
        return self.env.expert_action(), state
