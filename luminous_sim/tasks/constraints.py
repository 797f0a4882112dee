"""ALFRED's type-level constraints on task parameters (A `gen/scripts/generate_trajectories.py`).

These need no scene: compatibility of the object, receptacle, movable receptacle and lamp types.
The scene-level ones (what is present, what already contains what) live in `sample.py`.
"""

from __future__ import annotations

from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import SLICED_PARENTS, task_info
from luminous_sim.vocab import ALL_TYPES, LAMPS, MOVABLE_RECEPTACLES, SLICED_TYPES, abilities, can_contain, vocab_data

PICKUP_TYPES: frozenset[str] = frozenset(vocab_data()["pickupable"]) - frozenset(SLICED_TYPES)
"""Object types ALFRED draws as `object_target` (its pickup candidates, slices folded to parents)."""
NEVER_PARENT: frozenset[str] = frozenset({"Toaster"})
PICK_TWO_EXCLUDED: frozenset[str] = frozenset(
    {"CoffeeMachine", "ToiletPaperHanger", "HandTowelHolder"}
)
"""Receptacles pick_two_obj_and_place may not use."""
DEVICES: dict[str, tuple[str, ...]] = {
    "pick_heat_then_place_in_recep": ("Microwave",),
    "pick_cool_then_place_in_recep": ("Fridge",),
    "pick_clean_then_place_in_recep": ("SinkBasin", "Faucet"),
}
"""Task type -> the types a scene needs to change the object's state (the first is the receptacle)."""
ABILITY: dict[str, str] = {
    "pick_heat_then_place_in_recep": "heatable",
    "pick_cool_then_place_in_recep": "coolable",
    "pick_clean_then_place_in_recep": "cleanable",
}
"""Task type -> the ability the object type needs."""


def _known(t: str) -> bool:
    return t in ALL_TYPES


def params_problems(task_type: str, params: PddlParams) -> list[str]:
    """What is wrong with a task's parameters, type by type (empty when ALFRED could draw them).

    Raises:
        TaskError: an unknown task type.
    """
    info = task_info(task_type)
    p = params
    out: list[str] = []
    slots = {
        "parent_target": p.parent_target,
        "toggle_target": p.toggle_target,
        "mrecep_target": p.mrecep_target,
    }
    for slot, value in slots.items():
        if slot in info.needs and not value:
            out.append(f"{task_type} needs a {slot}")
        elif slot not in info.needs and value:
            out.append(f"{task_type} takes no {slot} (got {value!r})")
        elif value and not _known(value):
            out.append(f"{slot} {value!r} is not an object type")
    if p.object_target not in PICKUP_TYPES:
        out.append(f"object_target {p.object_target!r} is not one of ALFRED's pickup types")
        return out
    if p.object_sliced and p.object_target not in SLICED_PARENTS:
        out.append(f"a sliced task needs one of {', '.join(SLICED_PARENTS)}, not {p.object_target}")
        return out
    if out:
        return out
    obj = p.object_type
    if task_type in ABILITY and not getattr(abilities(obj), ABILITY[task_type]):
        out.append(f"{obj} is not {ABILITY[task_type]}")
    if task_type in DEVICES and p.parent_target == DEVICES[task_type][0]:
        out.append(f"{task_type} may not use its device {p.parent_target} as the final receptacle")
    if task_type == "look_at_obj_in_light" and p.toggle_target not in LAMPS:
        out.append(f"toggle_target must be one of {', '.join(LAMPS)}, not {p.toggle_target}")
    if p.parent_target:
        out += _parent_problems(task_type, p, obj)
    return out


def _parent_problems(task_type: str, p: PddlParams, obj: str) -> list[str]:
    out = []
    parent = p.parent_target
    if not abilities(parent).receptacle:
        out.append(f"parent_target {parent} is not a receptacle")
    if parent in NEVER_PARENT:
        out.append(f"{parent} is never a final receptacle")
    if task_type == "pick_two_obj_and_place" and parent in PICK_TWO_EXCLUDED:
        out.append(f"pick_two_obj_and_place may not use {parent}")
    if task_type != "pick_and_place_with_movable_recep":
        if not can_contain(parent, obj):
            out.append(f"{parent} does not accept {obj}")
        return out
    m = p.mrecep_target
    if m not in MOVABLE_RECEPTACLES:
        out.append(f"mrecep_target must be one of {', '.join(MOVABLE_RECEPTACLES)}, not {m}")
        return out
    if p.object_target in MOVABLE_RECEPTACLES:
        out.append(f"the object {p.object_target} may not itself be a movable receptacle")
    if parent in MOVABLE_RECEPTACLES:
        out.append(f"the final receptacle {parent} may not be a movable receptacle")
    if not can_contain(m, obj):
        out.append(f"{m} does not accept {obj}")
    if not can_contain(parent, m):
        out.append(f"{parent} does not accept {m}")
    return out
