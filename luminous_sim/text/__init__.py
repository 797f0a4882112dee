"""Luminous's trials as text games (layer L3): ALFWorld's names for a room's things and the PDDL problem
ALFWorld's own code reads (`initial_state.pddl`)."""

from luminous_sim.text.alfworld_names import alfworld_id, demangled_names, mangle, names_of
from luminous_sim.text.alfworld_problem import (
    AlfworldProblem,
    ProblemError,
    alfworld_problem,
    fixed_holder,
    goal,
    is_receptacle,
)

__all__ = ["AlfworldProblem", "ProblemError", "alfworld_id", "alfworld_problem", "demangled_names", "fixed_holder",
           "goal", "is_receptacle", "mangle", "names_of"]
