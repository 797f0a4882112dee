"""Layer L3: instructions for trajectories: templates (default) and a learned speaker (`language.speaker`)."""

from luminous_sim.language.instructions import Describer, Instructions

__all__ = ["Describer", "Instructions"]
