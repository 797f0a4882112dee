"""ALFRED's high-level plan of each task type as the agent's subgoals: an interaction and what it acts on, made
from a parsed task (its type and `pddl_params`), as the expert's plans are (ALFRED's `gen/planner`: open what
is closed before a put, close the microwave or fridge before it heats or cools)."""

from __future__ import annotations

from dataclasses import dataclass

from luminous_sim.vocab import SLICING_TOOLS, abilities

SINK = "SinkBasin"
FAUCET = "Faucet"
MICROWAVE = "Microwave"
FRIDGE = "Fridge"
KNIFE_PLACES = ("CounterTop", "DiningTable", "SideTable", "Shelf", "Sink", "SinkBasin", "Cart")
"""Where the agent puts a knife down after slicing (surfaces any kitchen has; the first it has seen)."""


@dataclass(frozen=True)
class Subgoal:
    """One interaction: `action` (ALFRED's name) on an instance of one of `types`.

    `role` names the instance for later subgoals: "object" (the task's object, followed through the episode),
    "other" (an instance of the object's type other than the first: the second of pick_two), "mrecep",
    "" for any instance."""

    action: str
    types: tuple[str, ...]
    role: str = ""


def _put(receptacle: str, role: str = "") -> list[Subgoal]:
    opens = abilities(receptacle).openable if receptacle else False
    put = Subgoal("PutObject", (receptacle,), role)
    return [Subgoal("OpenObject", (receptacle,), role), put] if opens else [put]


def subgoals(task_type: str, params: dict[str, object]) -> list[Subgoal]:
    """The subgoals of a task (its type and ALFRED's five `pddl_params`)."""
    obj = str(params.get("object_target") or "")
    parent = str(params.get("parent_target") or "")
    mrecep = str(params.get("mrecep_target") or "")
    toggle = str(params.get("toggle_target") or "")
    sliced = bool(params.get("object_sliced"))
    held = f"{obj}Sliced" if sliced else obj
    plan: list[Subgoal] = []
    if sliced:
        plan += [Subgoal("PickupObject", SLICING_TOOLS), Subgoal("SliceObject", (obj,)),
                 Subgoal("PutObject", KNIFE_PLACES)]
    plan.append(Subgoal("PickupObject", (held,), "object"))
    if task_type == "look_at_obj_in_light":
        return plan + [Subgoal("ToggleObjectOn", (toggle,))]
    if task_type == "pick_clean_then_place_in_recep":
        plan += [Subgoal("PutObject", (SINK,)), Subgoal("ToggleObjectOn", (FAUCET,)),
                 Subgoal("ToggleObjectOff", (FAUCET,)), Subgoal("PickupObject", (held,), "object")]
    elif task_type == "pick_heat_then_place_in_recep":
        plan += [Subgoal("OpenObject", (MICROWAVE,)), Subgoal("PutObject", (MICROWAVE,)),
                 Subgoal("CloseObject", (MICROWAVE,)), Subgoal("ToggleObjectOn", (MICROWAVE,)),
                 Subgoal("ToggleObjectOff", (MICROWAVE,)), Subgoal("OpenObject", (MICROWAVE,)),
                 Subgoal("PickupObject", (held,), "object"), Subgoal("CloseObject", (MICROWAVE,))]
    elif task_type == "pick_cool_then_place_in_recep":
        plan += [Subgoal("OpenObject", (FRIDGE,)), Subgoal("PutObject", (FRIDGE,)), Subgoal("CloseObject", (FRIDGE,)),
                 Subgoal("OpenObject", (FRIDGE,)), Subgoal("PickupObject", (held,), "object"),
                 Subgoal("CloseObject", (FRIDGE,))]
    elif task_type == "pick_and_place_with_movable_recep":
        plan += [Subgoal("PutObject", (mrecep,), "mrecep"), Subgoal("PickupObject", (mrecep,), "mrecep")]
        return plan + _put(parent, "parent")
    plan += _put(parent, "parent")
    if task_type == "pick_two_obj_and_place":
        plan += [Subgoal("PickupObject", (held,), "other")] + _put(parent, "parent")
    return plan
