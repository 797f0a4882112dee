"""Layer L4: the Gymnasium environments (`gymnasium.make("Luminous-ALFRED-v1")` and friends).

Ids are declared as data in the repository's `envs/*.toml` and registered when `luminous_sim` is imported,
by string entry point, so that importing the package loads neither the simulator nor pybullet. Public
names below are loaded on first use for the same reason.

Typical use::

    import gymnasium, luminous_sim
    env = gymnasium.make("Luminous-PickUp-64-v1")
    obs, info = env.reset(seed=0)
    obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.env.actions import ActionTable
    from luminous_sim.env.alfred_env import LuminousEnv, ResetNeeded
    from luminous_sim.env.config import EnvConfig
    from luminous_sim.env.expert import Expert
    from luminous_sim.env.grouped_vector import GroupedVectorEnv, VectorWorkerError
    from luminous_sim.env.kinds import TASK_KINDS, TaskKind
    from luminous_sim.env.oracle_policy import OraclePolicy
    from luminous_sim.env.registration import EnvEntry, eval_seeds, load_entries, register_envs
    from luminous_sim.env.reset_options import RESET_OPTIONS, ResetOptions, reset_options
    from luminous_sim.env.rewards import RewardConfig
    from luminous_sim.env.vector import StepInfo, make_vector_env
    from luminous_sim.env.wrappers import (
        ActionFeedback,
        ActionSubset,
        FailureLimitEnds,
        InstructionTokens,
        NewPlaceBonus,
        SceneRepeat,
    )
    from luminous_sim.episodes import UNAVAILABLE_CAUSES, EpisodeUnavailable

_WHERE = {
    "ActionTable": "actions",
    "LuminousEnv": "alfred_env", "ResetNeeded": "alfred_env",
    "EnvConfig": "config",
    "EpisodeUnavailable": "luminous_sim.episodes", "UNAVAILABLE_CAUSES": "luminous_sim.episodes",
    "Expert": "expert",
    "TaskKind": "kinds", "TASK_KINDS": "kinds",
    "OraclePolicy": "oracle_policy",
    "EnvEntry": "registration", "load_entries": "registration", "register_envs": "registration",
    "RESET_OPTIONS": "reset_options", "ResetOptions": "reset_options", "reset_options": "reset_options",
    "eval_seeds": "registration",
    "RewardConfig": "rewards",
    "InstructionTokens": "wrappers", "ActionFeedback": "wrappers", "ActionSubset": "wrappers",
    "FailureLimitEnds": "wrappers", "NewPlaceBonus": "wrappers",
    "SceneRepeat": "wrappers",
    "StepInfo": "vector", "make_vector_env": "vector",
    "GroupedVectorEnv": "grouped_vector", "VectorWorkerError": "grouped_vector",
}

__all__ = [
    "RESET_OPTIONS",
    "TASK_KINDS",
    "UNAVAILABLE_CAUSES",
    "ActionFeedback",
    "ActionSubset",
    "ActionTable",
    "EnvConfig",
    "EnvEntry",
    "EpisodeUnavailable",
    "Expert",
    "FailureLimitEnds",
    "GroupedVectorEnv",
    "InstructionTokens",
    "LuminousEnv",
    "NewPlaceBonus",
    "OraclePolicy",
    "ResetNeeded",
    "ResetOptions",
    "RewardConfig",
    "SceneRepeat",
    "StepInfo",
    "TaskKind",
    "VectorWorkerError",
    "eval_seeds",
    "load_entries",
    "make_vector_env",
    "register_envs",
    "reset_options",
]


__getattr__ = lazy_getattr(__name__, _WHERE)
