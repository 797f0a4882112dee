"""`BCAgent`: a trained `BCPolicy` behind the evaluation's agent interface (docs/evaluation.md).

`luminous eval --policy luminous_sim.bc:bc_agent` with the checkpoint named by the `LUMINOUS_BC_CHECKPOINT`
environment variable. The env must be the one the policy was trained in (image size, object-slot targets,
number of slots); the factory says which env options to pass when it is not. Each step `bc_agent` takes the
policy's most probable action; `bc_agent_sampling` samples from its distribution with a generator seeded
by the episode's seed (repeatable too). In benchmarks/bench_bc.py the two were within one success of each
other on 28 episodes a split.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np
import torch

from luminous_sim.bc.model import BCPolicy
from luminous_sim.bc.train import load_checkpoint
from luminous_sim.env.vocabulary import encode
from luminous_sim.errors import LuminousError
from luminous_sim.eval import AgentContext

CHECKPOINT_VAR = "LUMINOUS_BC_CHECKPOINT"
"""The environment variable `bc_agent` reads the checkpoint's path from."""


class BCAgent:
    """Plays a `BCPolicy`; see the module docstring."""

    def __init__(self, model: BCPolicy, meta: dict[str, Any], context: AgentContext, greedy: bool = True):
        config, trained = context.config, meta["env"]
        wanted = {k: trained[k] for k in ("width", "height", "targets", "object_slots")}
        have = {k: getattr(config, k) for k in wanted}
        if have != wanted:
            options = " ".join(f"--env {k}={v}" for k, v in wanted.items())
            if wanted["targets"] == "objects":  # object slots are privileged
                options = f"--track privileged {options}"
            raise LuminousError(f"the behaviour-cloning policy was trained in an env with {wanted}, this one has "
                                f"{have}; evaluate it with {options}")
        self.model, self.meta, self.greedy = model, meta, greedy
        self.n = model.shape.actions
        self.generator = torch.Generator().manual_seed(0)
        self.tokens = torch.zeros(1, int(meta["tokens"]), dtype=torch.int64)
        self.previous = self.n

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.tokens = torch.tensor([encode(instruction, int(self.meta["tokens"]))], dtype=torch.int64)
        self.generator = torch.Generator().manual_seed(int(info.get("episode_seed", 0)))
        self.previous = self.n

    @torch.no_grad()
    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> int:
        logits = self.model(torch.from_numpy(np.ascontiguousarray(observation["rgb"]))[None], self.tokens,
                            torch.from_numpy(np.asarray(observation["objects"], np.int64))[None],
                            torch.tensor([self.previous]), torch.tensor([info.get("failure_code") is not None]))[0]
        if self.greedy:
            action = int(logits.argmax())
        else:
            action = int(torch.multinomial(torch.softmax(logits, 0), 1, generator=self.generator))
        self.previous = action
        return action


def _checkpoint() -> Path:
    path = os.environ.get(CHECKPOINT_VAR)
    if not path:
        raise LuminousError(f"set {CHECKPOINT_VAR} to the checkpoint of `luminous bc train`")
    return Path(path)


def bc_agent(context: AgentContext) -> BCAgent:
    """The factory of `--policy luminous_sim.bc:bc_agent` (checkpoint from `LUMINOUS_BC_CHECKPOINT`, greedy)."""
    model, meta = load_checkpoint(_checkpoint())
    return BCAgent(model, meta, context)


def bc_agent_sampling(context: AgentContext) -> BCAgent:
    """As `bc_agent`, sampling each action from the policy's distribution (seeded per episode)."""
    model, meta = load_checkpoint(_checkpoint())
    return BCAgent(model, meta, context, greedy=False)
