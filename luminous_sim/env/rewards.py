"""ALFRED's reward configuration (spec/alfred.md section 5.2, A `models/config/rewards.json`), driven by the
task's named goal conditions rather than by the expert's subgoal sequence.

Dense (the default), per step:

* each goal condition that becomes met earns the `positive` reward of the action that meets it (the
  condition's stage: `PickupObjectAction` 2, `PutObjectAction` 2, `HeatObjectAction` 2, `ToggleObjectAction`
  1, ...; `GotoLocationAction` 4 for the navigation goal), per count for a condition of weight 2; a condition
  that stops being met costs the same amount back, so undoing and redoing earns nothing;
* reaching the goal earns `goal_reward` (+5);
* a failed action costs `failure` (-0.05, ALFRED's `failure` term);
* every step after the expert's length (0 when no expert plan is known) costs `step_penalty` (-0.01).

* while one of the expert's go-to subgoals is current, `goto_shaping` (0.2) x the path steps gained toward
  its location, and GotoLocationAction's +4 on coming within `goto_reach` (3) steps of it (ALFRED's
  navigation reward, `luminous_sim.env.goto_reward`; on with `EnvConfig.navigation_reward`, off in the
  `-v0` ids; it needs the expert's plan, so `verify_expert`).

ALFRED's per-step `success` bonus (+2 for any action that succeeds) is kept in the table but off
(`success_bonus` 0): spinning in place would farm it. Sparse: `goal_reward` on reaching the goal, else 0.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from types import MappingProxyType

from luminous_sim.errors import LuminousError

POSITIVE: Mapping[str, float] = MappingProxyType({
    "BaseAction": 1.0,
    "GotoLocationAction": 4.0,
    "PickupObjectAction": 2.0,
    "PutObjectAction": 2.0,
    "OpenObjectAction": 2.0,
    "CloseObjectAction": 1.0,
    "ToggleObjectAction": 1.0,
    "SliceObjectAction": 1.0,
    "CleanObjectAction": 2.0,
    "HeatObjectAction": 2.0,
    "CoolObjectAction": 2.0,
})
"""ALFRED's `positive` reward of each action section."""


@dataclass(frozen=True)
class RewardConfig:
    """The reward terms (ALFRED's values by default)."""

    goal_reward: float = 5.0
    failure: float = -0.05
    step_penalty: float = -0.01
    success_bonus: float = 0.0
    """ALFRED's `success` (+2 for every action that succeeds); off by default, see the module docstring."""
    goto_shaping: float = 0.2
    """ALFRED's reward per path step gained toward the current go-to location."""
    goto_reach: float = 3.0
    """ALFRED's `min_reach_distance`: a go-to is done within fewer path steps than this."""
    failed_stop: float = 0.0
    """Added when Stop ends a goal that counts only at Stop (ObjectNav) without reaching it. 0: the field scores
    a wrong Stop as a failed episode and nothing more; a training option (a negative value keeps a learner from
    stopping at once to end episodes that pay little)."""
    positive: Mapping[str, float] = field(default_factory=lambda: POSITIVE)
    sparse: bool = False

    @classmethod
    def of(cls, mode: str, overrides: Mapping[str, float]) -> RewardConfig:
        """The config of a reward mode with fields (or `positive` sections, by name) overridden.

        Raises:
            LuminousError: an override names no field and no section.
        """
        names = {f.name for f in fields(cls)} - {"positive", "sparse"}
        unknown = sorted(set(overrides) - names - set(POSITIVE))
        if unknown:
            raise LuminousError(f"env config reward: unknown term(s) {', '.join(unknown)}; expected some of "
                                f"{', '.join(sorted(names | set(POSITIVE)))}")
        positive = {**POSITIVE, **{k: float(v) for k, v in overrides.items() if k in POSITIVE}}
        terms = {k: float(v) for k, v in overrides.items() if k in names}
        return replace(cls(), positive=MappingProxyType(positive), sparse=mode == "sparse", **terms)

    def section(self, action: str) -> float:
        """The positive reward of the action that meets a condition (`PickupObject` -> PickupObjectAction)."""
        return self.positive.get(f"{action}Action", self.positive["BaseAction"])


def step_reward(cfg: RewardConfig, before: Mapping[str, int], after: Mapping[str, int], stages: Mapping[str, str],
                *, reached: bool, action_ok: bool, step: int, expert_length: int) -> float:
    """The reward of one step.

    Args:
        cfg: the reward terms.
        before: condition name -> count met before the step.
        after: condition name -> count met after it.
        stages: condition name -> the action that meets it (`PickupObject`, `GotoLocation`, ...).
        reached: the goal was reached by this step.
        action_ok: the step's action succeeded.
        step: the step's number, from 1.
        expert_length: the expert's number of steps (0 when unknown).
    """
    if cfg.sparse:
        return cfg.goal_reward if reached else 0.0
    r = sum((after[name] - before[name]) * cfg.section(stages[name]) for name in after)
    if reached:
        r += cfg.goal_reward
    r += cfg.success_bonus if action_ok else cfg.failure
    if step > expert_length:
        r += cfg.step_penalty
    return float(r)
