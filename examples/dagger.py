"""A warm start for PPO: the policy network first imitates the oracle, with DAgger (Ross et al. 2011), then PPO
trains it on the env's reward (PIRLNav's recipe, Ramrakhya et al. 2023: imitation, then RL, the critic fitted
before the actor moves).

Round 1 follows the expert (`OraclePolicy`) and labels each step with its action; later rounds follow the
policy being trained (sampling its actions), taking the expert's action with probability `expert_share`, and
every step is labelled with the expert's action from where the policy got to (the oracle replans from any
state), so the clone learns to recover from its own mistakes. After each round the policy is fitted to all the
labels so far by cross-entropy. The labels are the oracle's, which knows the map: where the goal is not in view
a memoryless clone can only learn what the oracle does on average there.

Used by `train_ppo.py --bc-steps N`; the networks are the PPO model's own (`model.policy`), so PPO goes on from
what imitation learned.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import asdict, dataclass
from typing import Any

import gymnasium
import numpy as np


@dataclass(frozen=True)
class WarmStart:
    """How much imitation before PPO."""

    steps: int = 40_000
    """Labelled steps in all, over every round."""
    rounds: int = 4
    """Round 1 follows the expert; rounds 2.. follow the policy (DAgger)."""
    expert_share: float = 0.2
    """In rounds 2.., the share of steps that take the expert's action instead of the policy's."""
    epochs: int = 4
    """Passes over all the labels so far after each round."""
    learning_rate: float = 1e-3
    batch_size: int = 256


def expert_index(env: gymnasium.Env) -> Callable[[], int]:
    """The oracle's next action as an index of `env`'s action space (`ActionSubset` mapped back).

    Raises:
        ValueError: the oracle asks for an action the agent's space does not have.
    """
    from luminous_sim.env import ActionSubset, OraclePolicy

    oracle = OraclePolicy(env)
    wrapper: Any = env
    while not isinstance(wrapper, ActionSubset) and hasattr(wrapper, "env"):
        wrapper = wrapper.env
    back = {full: i for i, full in enumerate(wrapper.indices)} if isinstance(wrapper, ActionSubset) else None

    def index() -> int:
        action = oracle()
        if isinstance(action, dict) or (back is not None and action not in back):
            raise ValueError(f"the oracle's action {action!r} is not in the agent's action space")
        return int(action) if back is None else back[int(action)]

    return index


class Labels:
    """Observations (a dict of arrays per key) and the expert's action for each."""

    def __init__(self) -> None:
        self.obs: dict[str, list[np.ndarray]] = {}
        self.actions: list[int] = []

    def add(self, obs: dict[str, np.ndarray], action: int) -> None:
        for k, v in obs.items():
            self.obs.setdefault(k, []).append(np.asarray(v))
        self.actions.append(action)

    def __len__(self) -> int:
        return len(self.actions)

    def arrays(self) -> tuple[dict[str, np.ndarray], np.ndarray]:
        return {k: np.stack(v) for k, v in self.obs.items()}, np.asarray(self.actions, np.int64)


def collect(env: gymnasium.Env, act: Callable[[dict[str, Any]], int], expert: Callable[[], int], labels: Labels,
            steps: int, expert_share: float, rng: np.random.Generator, seed: int) -> dict[str, Any]:
    """`steps` labelled steps: the expert's action is the label, the step taken is the expert's with
    probability `expert_share` and `act(obs)` otherwise; the rollout's episodes and successes."""
    obs, _ = env.reset(seed=seed)
    episodes = successes = 0
    for _ in range(steps):
        label = expert()
        labels.add(obs, label)
        action = label if rng.random() < expert_share else act(obs)
        obs, _, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            episodes, successes = episodes + 1, successes + int(bool(info.get("success")))
            obs, _ = env.reset()
    return {"episodes": episodes, "successes": successes}


def fit(policy: Any, labels: Labels, epochs: int, learning_rate: float, batch_size: int,
        rng: np.random.Generator) -> dict[str, float]:
    """Cross-entropy of the policy's action distribution against the labels; the last epoch's loss and
    accuracy (the distribution's most likely action)."""
    import torch

    obs, actions = labels.arrays()
    target = torch.as_tensor(actions)
    optimizer = torch.optim.Adam(policy.parameters(), lr=learning_rate)
    policy.set_training_mode(True)
    loss_sum = correct = 0.0
    for _ in range(epochs):
        order = rng.permutation(len(actions))
        loss_sum = correct = 0.0
        for start in range(0, len(order), batch_size):
            batch = order[start:start + batch_size]
            tensors, _ = policy.obs_to_tensor({k: v[batch] for k, v in obs.items()})
            dist = policy.get_distribution(tensors)
            loss = -dist.log_prob(target[batch]).mean()
            optimizer.zero_grad()
            loss.backward()
            optimizer.step()
            loss_sum += loss.item() * len(batch)
            correct += float((dist.distribution.probs.argmax(1) == target[batch]).sum())
    policy.set_training_mode(False)
    return {"loss": round(loss_sum / len(actions), 4), "accuracy": round(correct / len(actions), 4)}


def warm_start(model: Any, env: gymnasium.Env, cfg: WarmStart, seed: int,
               cpu: Callable[[], float] = time.process_time) -> list[dict[str, Any]]:
    """Imitate the oracle with `model.policy` in `env` (an env as the policy sees it, made for training); a
    row per round (labelled steps so far, the round's rollout episodes and successes, loss, accuracy, CPU
    seconds)."""
    import torch

    if cfg.steps < cfg.rounds or cfg.rounds < 1 or not 0.0 <= cfg.expert_share <= 1.0:
        raise ValueError(f"warm start {asdict(cfg)}: expected steps >= rounds >= 1 and 0 <= expert_share <= 1")
    rng = np.random.default_rng(seed)
    expert = expert_index(env)
    labels = Labels()
    policy = model.policy

    def act(obs: dict[str, Any]) -> int:
        with torch.no_grad():
            return int(policy.predict(obs, deterministic=False)[0])

    rows = []
    per_round = cfg.steps // cfg.rounds
    for r in range(cfg.rounds):
        share = 1.0 if r == 0 else cfg.expert_share
        rollout = collect(env, act, expert, labels, per_round, share, rng, seed=seed + r)
        fitted = fit(policy, labels, cfg.epochs, cfg.learning_rate, cfg.batch_size, rng)
        rows.append({"round": r + 1, "labels": len(labels), "expert_share": share, **rollout, **fitted,
                     "cpu_seconds": round(cpu(), 1)})
    return rows


def critic_first(until: int) -> Any:
    """An SB3 callback that keeps the actor and the shared feature extractor frozen (no gradient) while the
    model's timesteps are below `until`, so only the critic learns (PIRLNav's critic warm-up)."""
    from stable_baselines3.common.callbacks import BaseCallback

    class CriticFirst(BaseCallback):
        def _frozen(self) -> list[Any]:
            p = self.model.policy
            return [p.features_extractor, p.pi_features_extractor, p.mlp_extractor.policy_net, p.action_net]

        def _set(self, trainable: bool) -> None:
            for module in self._frozen():
                for param in module.parameters():
                    param.requires_grad_(trainable)

        def _on_training_start(self) -> None:
            self._set(self.model.num_timesteps >= until)

        def _on_rollout_end(self) -> None:
            if self.model.num_timesteps >= until:
                self._set(True)

        def _on_step(self) -> bool:
            return True

    return CriticFirst()
