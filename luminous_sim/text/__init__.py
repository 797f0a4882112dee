"""Luminous's trials as text games (layer L3): ALFWorld's names for a room's things, the PDDL problem
ALFWorld's own code reads (`initial_state.pddl`), and the native text game (`TextGame`) on our object states."""

from luminous_sim.text.alfworld_names import alfworld_id, demangled_names, mangle, names_of
from luminous_sim.text.alfworld_problem import (
    AlfworldProblem,
    ProblemError,
    alfworld_problem,
    fixed_holder,
    free_holders,
    goal,
    is_receptacle,
)
from luminous_sim.text.embodied import CarriedOut, carry_out, embodied_actions
from luminous_sim.text.expert import TextExpert
from luminous_sim.text.game import TextAction, TextGame, text_names

__all__ = [
    "AlfworldProblem",
    "CarriedOut",
    "ProblemError",
    "TextAction",
    "TextExpert",
    "TextGame",
    "alfworld_id",
    "alfworld_problem",
    "carry_out",
    "demangled_names",
    "embodied_actions",
    "fixed_holder",
    "free_holders",
    "goal",
    "is_receptacle",
    "mangle",
    "names_of",
    "text_names",
]
