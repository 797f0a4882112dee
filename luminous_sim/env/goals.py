"""Moved: `luminous_sim.episodes` (`Goal`, `TaskGoal`, `ExpertPlan`); this path warns and forwards until 0.3.0."""

from luminous_sim.lazy import moved_getattr

__getattr__ = moved_getattr(__name__, dict.fromkeys(("ExpertPlan", "Goal", "TaskGoal"), "luminous_sim.episodes"),
                            "0.3.0")
