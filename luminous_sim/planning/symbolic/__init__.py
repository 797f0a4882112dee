"""The oracle's symbolic planner (evidence and API filled in below)."""

from luminous_sim.planning.symbolic.actions import ACTIONS, COSTS, HighLevelAction, Plan
from luminous_sim.planning.symbolic.macros import apply_action, expand_macro, replay
from luminous_sim.planning.symbolic.solver import BACKENDS, solve

__all__ = ["ACTIONS", "BACKENDS", "COSTS", "HighLevelAction", "Plan", "apply_action", "expand_macro", "replay", "solve"]
