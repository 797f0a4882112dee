"""A worked example of a user's agent: `luminous eval --policy luminous_sim.eval.examples:wanderer`.

`wanderer` is a factory (the `MODULE:CALLABLE` an evaluation calls once per worker); the `Wanderer` it
returns is a tiny heuristic, not a learner: it walks ahead until blocked and turns, and every few steps
tries to pick up whatever is in the lower middle of its view (or, holding something, to put it there), in
ALFRED's full action form, an interaction mask as run-length encoding, as ALFRED's models (MOCA, ET, HiTUT)
emit it. It stops after a budget of steps. It reads only its observation and the last action's failure.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from luminous_sim.eval.policies import AgentContext
from luminous_sim.world import mask_to_rle

BUDGET = 40
"""Steps before the wanderer stops (ALFRED's limit is 1000; it would only wander on)."""
TRY_EVERY = 5
"""An interaction every this many steps."""


class Wanderer:
    """Walk, turn when blocked, try to pick up or put down what lies ahead; see the module docstring."""

    def __init__(self, context: AgentContext, budget: int = BUDGET):
        self.actions = context.actions
        self.budget = budget
        height, width = context.config.height, context.config.width
        rows, cols = np.ogrid[:height, :width]
        ahead = (rows - 0.7 * height) ** 2 + (cols - 0.5 * width) ** 2 <= (0.12 * min(height, width)) ** 2
        self.ahead_rle = mask_to_rle(ahead)
        self.rng = np.random.default_rng(0)
        self.steps, self.holding, self.last = 0, False, ""

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.rng = np.random.default_rng(info["episode_seed"])
        self.steps, self.holding, self.last = 0, False, ""

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> int | dict[str, Any]:
        ok = info.get("failure_code") is None
        if ok and self.last in ("PickupObject", "PutObject"):
            self.holding = self.last == "PickupObject"
        blocked = self.last == "MoveAhead" and not ok
        self.steps += 1
        if self.steps > self.budget:
            self.last = "Stop"
            return {"action": "Stop"}
        if self.steps % TRY_EVERY == 0:
            self.last = "PutObject" if self.holding else "PickupObject"
            return {"action": self.last, "mask": self.ahead_rle}
        self.last = str(self.rng.choice(["RotateLeft", "RotateRight"])) if blocked else "MoveAhead"
        return self.actions.index(self.last)


def wanderer(context: AgentContext) -> Wanderer:
    """The factory `luminous eval --policy luminous_sim.eval.examples:wanderer` calls."""
    return Wanderer(context)
