"""Worked examples of a user's agent: `luminous eval --policy luminous_sim.eval.examples:wanderer` and
`luminous eval --policy luminous_sim.eval.examples:step_reader`.

`step_reader` reads what ALFRED's agents read: the goal directive (`instruction`) and the step-by-step
instructions (`info["high_descs"]` at reset, the `high_descs` observation every step). It works through the
steps in order: a step that names an action (pick up, put, open, close, turn on or off, slice; heat, cool
and clean are a put into the device, a toggle and a pick up) is tried on the lower middle of its view for a
few turns; any other step (go to, walk, turn) is a short walk. A successful interaction moves it to the next
step; it stops when the steps run out. No perception: it shows the interface, not a strong agent.

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


STEP_VERBS: tuple[tuple[tuple[str, ...], str], ...] = (
    (("pick up", "take", "grab", "get the", "remove"), "PickupObject"),
    (("put", "place", "set", "drop", "heat", "cool", "chill", "rinse", "wash", "clean"), "PutObject"),
    (("open",), "OpenObject"),
    (("close", "shut"), "CloseObject"),
    (("turn on", "switch on", "light"), "ToggleObjectOn"),
    (("turn off", "switch off"), "ToggleObjectOff"),
    (("slice", "cut"), "SliceObject"),
)
"""The action a step instruction asks for, by the words it starts a clause with (the first match wins)."""
WALK = 6
"""Steps of walking for a navigation step."""
TRIES = 8
"""Steps spent on an interaction step (turning between tries) before moving on."""


def step_action(step: str) -> str:
    """The interaction a step instruction names, or "" for a navigation step."""
    text = f" {step.lower()}"
    for words, action in STEP_VERBS:
        if any(f" {w}" in text for w in words):
            return action
    return ""


class StepReader:
    """Follows the step-by-step instructions in order; see the module docstring."""

    def __init__(self, context: AgentContext):
        self.actions = context.actions
        height, width = context.config.height, context.config.width
        rows, cols = np.ogrid[:height, :width]
        ahead = (rows - 0.65 * height) ** 2 + (cols - 0.5 * width) ** 2 <= (0.15 * min(height, width)) ** 2
        self.ahead_rle = mask_to_rle(ahead)
        self.steps: list[str] = []
        self.goal, self.k, self.spent, self.last = "", 0, 0, ""

    def reset(self, instruction: str, info: dict[str, Any]) -> None:
        self.goal = instruction                          # the goal directive
        self.steps = list(info.get("high_descs") or [])  # the step-by-step instructions
        self.k, self.spent, self.last = 0, 0, ""

    def act(self, observation: dict[str, Any], info: dict[str, Any]) -> int | dict[str, Any]:
        ok = info.get("failure_code") is None
        if self.last and self.last not in ("MoveAhead", "RotateLeft", "RotateRight") and ok:
            self.k, self.spent = self.k + 1, 0          # the step's interaction worked: next step
        if self.k >= len(self.steps):
            self.last = "Stop"
            return {"action": "Stop"}
        action = step_action(self.steps[self.k])
        self.spent += 1
        if not action:                                   # navigation: walk ahead, turn when blocked
            if self.spent > WALK:
                self.k, self.spent = self.k + 1, 0
            blocked = self.last == "MoveAhead" and not ok
            self.last = "RotateRight" if blocked else "MoveAhead"
            return self.actions.index(self.last)
        if self.spent > TRIES:                           # give up on this step
            self.k, self.spent = self.k + 1, 0
        if self.spent % 2 == 0:                          # turn between tries
            self.last = "RotateLeft"
            return self.actions.index(self.last)
        self.last = action
        return {"action": action, "mask": self.ahead_rle}


def step_reader(context: AgentContext) -> StepReader:
    """The factory `luminous eval --policy luminous_sim.eval.examples:step_reader` calls."""
    return StepReader(context)
