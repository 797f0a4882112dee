"""Layer L1: Constrained Stochastic Scene Generation (and the uniform-random baseline).

A producer of scenes: nothing below layer L4 imports it (the environment generates scenes on the fly; `data/` builds
datasets and task-driven scenes).
The plain geometry it shares with the simulator and the planner lives in `luminous_sim.scene`.

Typical use::

    from luminous_sim.cssg import generate
    generated = generate(cdf, seed=0)   # generated.scene, generated.report
"""

from luminous_sim.cssg.baseline import empty_cdf, generate_uniform, sample_uniform
from luminous_sim.cssg.given import GivenScene, Placement, Repair, place_given
from luminous_sim.cssg.groups import GROUPS, GroupState, group_rates, house_rooms, room_groups
from luminous_sim.cssg.house import HouseGenerated, HouseReport, generate_house
from luminous_sim.cssg.measures import (
    ROBOT_RADIUS,
    CKLFigures,
    FloorMeasures,
    category_kl,
    ckl_figures,
    floor_measures,
    presence,
)
from luminous_sim.cssg.pipeline import ATTEMPTS, Generated, choose_room, generate, sample_layout, start_outside
from luminous_sim.cssg.reference import alfred_reference, reference_rooms
from luminous_sim.cssg.structure import structure_scene
from luminous_sim.cssg.validate import LayoutReport, RelationCheck, check_layout

__all__ = [
    "ATTEMPTS",
    "GROUPS",
    "ROBOT_RADIUS",
    "CKLFigures",
    "FloorMeasures",
    "Generated",
    "GivenScene",
    "GroupState",
    "HouseGenerated",
    "HouseReport",
    "LayoutReport",
    "Placement",
    "RelationCheck",
    "Repair",
    "alfred_reference",
    "category_kl",
    "check_layout",
    "choose_room",
    "ckl_figures",
    "empty_cdf",
    "floor_measures",
    "generate",
    "generate_house",
    "generate_uniform",
    "group_rates",
    "house_rooms",
    "place_given",
    "presence",
    "reference_rooms",
    "room_groups",
    "sample_layout",
    "sample_uniform",
    "start_outside",
    "structure_scene",
]
