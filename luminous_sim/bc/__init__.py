"""Layer L5: behaviour cloning from oracle demonstrations, a language-conditioned agent anyone can retrain on
a CPU (torch, the `learn` extra; importing this package does not import torch).

Oracle demonstrations of picking up a named object in the layouts of S+ (`collect_demos`; or of the split's own
ALFRED episodes, family `alfred`, `FAMILIES`) train a small policy (`BCPolicy`: a CNN over the 64 px view, the
instruction's tokens, the objects in view and the last action) by cross-entropy over the env's discrete actions
(`train_bc`); `BCAgent` plays it through the evaluation's agent interface, on held-out S+ entries and on U+
(`evaluate_pickup`, `luminous eval`).

Typical use::

    from luminous_sim.bc import collect_demos, train_bc, evaluate_pickup
    collect_demos(Path("out/bc/demos"), "S+", range(28, 228))
    train_bc(Path("out/bc/demos"), Path("out/bc/bc.pt"), seed=0)
    # LUMINOUS_BC_CHECKPOINT=out/bc/bc.pt
    outcomes = evaluate_pickup("luminous_sim.bc:bc_agent", "U+", list(range(28)))
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.bc.agent import CHECKPOINT_VAR, BCAgent, bc_agent, bc_agent_sampling
    from luminous_sim.bc.demos import TOKENS, Demo, collect_demos, demos_env, load_demos
    from luminous_sim.bc.family import (
        ALFRED_ENV,
        FAMILIES,
        PICKUP_ENV,
        evaluate_pickup,
        family_env,
        pickup_env,
        play_pickup,
    )
    from luminous_sim.bc.model import BCPolicy
    from luminous_sim.bc.train import TrainResult, load_checkpoint, train_bc

_WHERE = {
    "CHECKPOINT_VAR": "agent", "BCAgent": "agent", "bc_agent": "agent", "bc_agent_sampling": "agent",
    "TOKENS": "demos", "Demo": "demos", "collect_demos": "demos", "demos_env": "demos", "load_demos": "demos",
    "ALFRED_ENV": "family", "FAMILIES": "family", "family_env": "family", "PICKUP_ENV": "family",
    "evaluate_pickup": "family", "pickup_env": "family", "play_pickup": "family",
    "BCPolicy": "model",
    "TrainResult": "train", "load_checkpoint": "train", "train_bc": "train",
}

__all__ = [
    "ALFRED_ENV",
    "CHECKPOINT_VAR",
    "FAMILIES",
    "PICKUP_ENV",
    "TOKENS",
    "BCAgent",
    "BCPolicy",
    "Demo",
    "TrainResult",
    "bc_agent",
    "bc_agent_sampling",
    "collect_demos",
    "demos_env",
    "evaluate_pickup",
    "family_env",
    "load_checkpoint",
    "load_demos",
    "pickup_env",
    "play_pickup",
    "train_bc",
]

__getattr__ = lazy_getattr(__name__, _WHERE)
