"""Policies an evaluation runs: the oracle, a uniformly random one, or a user's agent named `MODULE:CALLABLE`.

The agent interface (see docs/evaluation.md for a worked example)::

    def make_agent(context: AgentContext) -> Agent        # the MODULE:CALLABLE, called once per worker

    class Agent:
        def reset(self, instruction: str, info: dict) -> None: ...      # before each episode
        def act(self, observation: dict, info: dict) -> int | dict: ...  # each step

`act` returns an index into `context.action_space` (a `Discrete`; `context.actions` names each index), or
the full ALFRED form as a dict (`{"action": "PickupObject", "mask": rle}`, `"point": [x, y]` or, for
research, `"objectId": id`; `{"action": "Stop"}` or `"<<stop>>"` ends the episode). `info` is the env's:
`failure_code` and `error` say why the last action failed; the reset `info` also carries `episode_seed`,
a seed for the agent's own randomness in this episode (so results do not depend on how episodes are shared
among workers). An agent that reads `success`, `goal_conditions` or `subgoal` from `info`, or looks into
the env, is not playing ALFRED's game.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from gymnasium import spaces

from luminous_sim.env import ActionTable, EnvConfig, LuminousEnv, OraclePolicy
from luminous_sim.errors import LuminousError

BUILT_IN: tuple[str, ...] = ("oracle", "random")
_SPEC = re.compile(r"^[A-Za-z_][\w]*(\.[A-Za-z_][\w]*)*:[A-Za-z_][\w]*(\.[A-Za-z_][\w]*)*$")


class PolicyError(LuminousError):
    """A policy spec that names no usable agent, or an agent that breaks the interface."""


@dataclass(frozen=True)
class AgentContext:
    """What a user's agent factory is given: the env's spaces, its action table and configuration."""

    action_space: spaces.Space
    observation_space: spaces.Space
    actions: ActionTable
    config: EnvConfig


class Agent(Protocol):
    """An agent an evaluation runs (see the module docstring)."""

    def reset(self, instruction: str, info: dict[str, Any]) -> None: ...

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> Any: ...


class OracleAgent:
    """The oracle (`env.OraclePolicy`): the expert's next action in the env's own action form."""

    def __init__(self, env: LuminousEnv):
        self.policy = OraclePolicy(env)

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        """Nothing to reset: the oracle replans from the env's state at every step."""

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> Any:
        return self.policy(observation)


class ReplayAgent:
    """The oracle of a built dataset: a trial's recorded low-level actions, sent through the agent interface as
    a model sends them (ALFRED's dict form: the action's name and, for an interaction, its recorded mask), then
    Stop. Its success rate measures how faithfully a trial replays from its files, not a filter."""

    def __init__(self) -> None:
        self.actions: tuple[dict[str, Any], ...] = ()
        self.cursor = 0

    def load(self, actions: tuple[dict[str, Any], ...]) -> None:
        """The actions to replay in the next episode."""
        self.actions, self.cursor = actions, 0

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.cursor = 0

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> Any:
        if self.cursor >= len(self.actions):
            return {"action": "Stop"}
        self.cursor += 1
        return dict(self.actions[self.cursor - 1])


class RandomAgent:
    """An action drawn uniformly from the discrete space each step, seeded per episode."""

    def __init__(self, n: int):
        self.n = n
        self.rng = np.random.default_rng(0)

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.rng = np.random.default_rng(info["episode_seed"])

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> int:
        return int(self.rng.integers(self.n))


def resolve_factory(spec: str) -> Callable[[AgentContext], Agent]:
    """The callable a `MODULE:CALLABLE` spec names.

    Raises:
        PolicyError: the spec is malformed, the module cannot be imported, or the name is not a callable.
    """
    if not _SPEC.match(spec):
        raise PolicyError(f"policy {spec!r}: expected {' or '.join(BUILT_IN)}, or MODULE:CALLABLE "
                          "(a dotted module path, a colon, a callable's name)")
    module_name, _, attr = spec.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise PolicyError(f"policy {spec!r}: cannot import module {module_name!r} ({exc})") from None
    target: Any = module
    for part in attr.split("."):
        if not hasattr(target, part):
            raise PolicyError(f"policy {spec!r}: module {module_name!r} has no {attr!r}")
        target = getattr(target, part)
    if not callable(target):
        raise PolicyError(f"policy {spec!r}: {attr!r} is a {type(target).__name__}, not a callable")
    return target


def check_policy(spec: str) -> str:
    """The spec if it names a usable policy (a built-in, or a callable that imports); else PolicyError."""
    if spec not in BUILT_IN:
        resolve_factory(spec)
    return spec


def make_agent(spec: str, env: LuminousEnv) -> Agent:
    """The agent of a policy spec for one env.

    Raises:
        PolicyError: a bad spec, or a factory whose result has no `reset` and `act`.
    """
    if spec == "oracle":
        return OracleAgent(env)
    if spec == "random":
        return RandomAgent(env.actions.n)  # the size of env.action_space, a Discrete
    factory = resolve_factory(spec)
    try:
        agent = factory(AgentContext(env.action_space, env.observation_space, env.actions, env.config))
    except Exception as exc:
        raise PolicyError(f"policy {spec!r}: the factory raised {type(exc).__name__}: {exc}") from exc
    missing = [m for m in ("reset", "act") if not callable(getattr(agent, m, None))]
    if missing:
        raise PolicyError(f"policy {spec!r}: the factory returned a {type(agent).__name__}, which has no "
                          f"{' or '.join(missing)} method")
    return agent
