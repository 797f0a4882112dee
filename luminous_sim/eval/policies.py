"""Policies an evaluation runs: the oracle, a uniformly random one, or a user's agent named `MODULE:CALLABLE`.

The agent interface (see docs/evaluation.md for a worked example)::

    def make_agent(context: AgentContext) -> Agent        # the MODULE:CALLABLE, once per worker, in a child

    class Agent:
        def reset(self, instruction: str, info: dict) -> None: ...      # before each episode
        def act(self, observation: dict, info: dict) -> int | dict: ...  # each step

`act` returns an index into `context.action_space` (a `Discrete`; `context.actions` names each index), or
the full ALFRED form as a dict (`{"action": "PickupObject", "mask": rle}`, `"point": [x, y]` or, for
research, `"objectId": id`; `{"action": "Stop"}` or `"<<stop>>"` ends the episode). `info` is the env's:
`failure_code` and `error` say why the last action failed; the reset `info` also carries `episode_seed`,
a seed for the agent's own randomness in this episode (so results do not depend on how episodes are shared
among workers). An agent that reads `success`, `goal_conditions` or `subgoal` from `info`, or looks into
the env, is not playing ALFRED's game. A user's agent runs in a child process with time and memory limits
(`luminous_sim.eval.sandbox`); the built-ins run in the evaluation's process.
"""

from __future__ import annotations

import importlib
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from gymnasium import spaces

from luminous_sim.env import ActionTable, EnvConfig, LuminousEnv, OraclePolicy
from luminous_sim.errors import LuminousError

if TYPE_CHECKING:
    from luminous_sim.eval.sandbox import AgentLimits

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


@dataclass(frozen=True)
class TextAgentContext:
    """What a text agent's process is told (`luminous eval --mode text`): the split and the step limit. The
    callable a text policy names is the agent's `act(observation, admissible) -> command` itself."""

    split: str
    max_steps: int


class _TextAgent:
    """A text agent's callable behind the agent interface (in the child process)."""

    def __init__(self, spec: str, act: Callable[[str, list[str]], str]):
        self.spec, self._act = spec, act

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        return None

    def act(self, observation: Any, info: dict[str, Any]) -> str:
        command = self._act(observation, list(info["admissible_commands"]))
        if not isinstance(command, str):
            raise PolicyError(f"policy {self.spec!r}: a text agent returns a command (a str), got "
                              f"{type(command).__name__}")
        return command


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
    check_spec(spec)
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


def check_spec(spec: str) -> str:
    """The spec if it is a built-in's name or of the form MODULE:CALLABLE (nothing is imported); else PolicyError."""
    if spec not in BUILT_IN and not _SPEC.match(spec):
        raise PolicyError(f"policy {spec!r}: expected {' or '.join(BUILT_IN)}, or MODULE:CALLABLE "
                          "(a dotted module path, a colon, a callable's name)")
    return spec


def check_policy(spec: str, limits: AgentLimits | None = None) -> str:
    """The spec if it names a usable policy (a built-in, or a callable that imports); else PolicyError. A
    user's module is imported in a child process (`sandbox.probe`, with `limits`), never in this one.

    Raises:
        PolicyError: a malformed spec, a module that does not import, a name that is not a callable.
        AgentCrashed: importing the module ended its process (`sys.exit`, a signal, the memory limit).
    """
    check_spec(spec)
    if spec not in BUILT_IN:
        from luminous_sim.eval.sandbox import probe

        probe(spec, limits)
    return spec


def make_agent(spec: str, env: LuminousEnv, limits: AgentLimits | None = None, *,
               in_process: bool = False) -> Agent:
    """The agent of a policy spec for one env: a built-in in this process; a user's agent (`MODULE:CALLABLE`)
    in a child process with `limits` (`sandbox.AgentProcess`), or with `in_process` here (trusted code only:
    it can then stall or end the evaluation).

    Raises:
        PolicyError: a bad spec, or a factory that raised or whose result has no `reset` and `act`.
        AgentCrashed: the agent's process ended while starting (`sandbox.AgentCrashed`).
    """
    if spec == "oracle":
        return OracleAgent(env)
    if spec == "random":
        return RandomAgent(env.actions.n)  # the size of env.action_space, a Discrete
    context = AgentContext(env.action_space, env.observation_space, env.actions, env.config)
    if in_process:
        return build_agent(spec, resolve_factory(spec), context)
    from luminous_sim.eval.sandbox import AgentProcess

    check_spec(spec)
    return AgentProcess(spec, context, limits)


def build_agent(spec: str, factory: Callable[[AgentContext], Agent], context: AgentContext | TextAgentContext
                ) -> Agent:
    """`factory(context)`, checked to be an agent (in the process that runs it); for a text agent
    (`TextAgentContext`), the callable itself behind the agent interface.

    Raises:
        PolicyError: the factory raised, or returned something without `reset` and `act`.
    """
    if isinstance(context, TextAgentContext):
        return _TextAgent(spec, factory)  # type: ignore[arg-type,return-value]
    try:
        agent = factory(context)
    except Exception as exc:
        raise PolicyError(f"policy {spec!r}: the factory raised {type(exc).__name__}: {exc}") from exc
    missing = [m for m in ("reset", "act") if not callable(getattr(agent, m, None))]
    if missing:
        raise PolicyError(f"policy {spec!r}: the factory returned a {type(agent).__name__}, which has no "
                          f"{' or '.join(missing)} method")
    return agent
