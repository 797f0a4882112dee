"""ALFRED's scene-level constraints as stages that enumerate feasible task parameters.

Each stage maps a partial candidate to its feasible extensions (object, slicing, state-change
ability, movable receptacle, receptacle or lamp); `candidates` runs them in order and reports the
first stage that leaves nothing, with the reason (A `gen/scripts/generate_trajectories.py`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import replace

from luminous_sim.states import WorldState
from luminous_sim.states.tables import DEFAULT_SLICE_COUNTS
from luminous_sim.tasks.constraints import (
    ABILITY,
    DEVICES,
    NEVER_PARENT,
    PICKUP_TYPES,
    params_problems,
)
from luminous_sim.tasks.expressions import parents
from luminous_sim.tasks.model import PddlParams
from luminous_sim.tasks.types import SLICED_PARENTS, task_info
from luminous_sim.vocab import LAMPS, MOVABLE_RECEPTACLES, SLICED_TYPES, SLICING_TOOLS, abilities, can_contain


class Holdings:
    """What a state holds, by type."""

    def __init__(self, state: WorldState):
        self.state = state
        self.count: dict[str, int] = {}
        for o in state.objects.values():
            self.count[o.object_type] = self.count.get(o.object_type, 0) + 1

    def has(self, object_type: str) -> bool:
        return self.count.get(object_type, 0) > 0

    def present(self, types: Iterable[str]) -> list[str]:
        return sorted(t for t in set(types) if self.has(t))

    def pieces(self, parent: str) -> int:
        """Slices there are or could be of a sliceable type (existing ones plus whole ones cut)."""
        whole = [k for k in self.state.of_type(parent) if not self.state[k].isSliced]
        made = sum(
            self.state.slice_counts.get(k, DEFAULT_SLICE_COUNTS.get(parent, 1)) for k in whole
        )
        return self.count.get(parent + "Sliced", 0) + made

    def holds_type(self, receptacle_type: str, object_type: str) -> bool:
        """Whether an object of the type (or a slice of it) is already in a `receptacle_type`."""
        s = self.state
        return any(
            object_type in (o.object_type, SLICED_TYPES.get(o.object_type))
            and any(s[r].object_type == receptacle_type for r in parents(s, k))
            for k, o in s.objects.items()
        )


_Expand = Callable[[Holdings, PddlParams], list[PddlParams]]


def _stages(task_type: str, sliced: bool | None) -> list[tuple[_Expand, str]]:
    """(expand, why-empty) per stage; each maps a partial candidate to its feasible extensions."""

    def objects(h: Holdings, p: PddlParams) -> list[PddlParams]:
        banned = MOVABLE_RECEPTACLES if task_type == "pick_and_place_with_movable_recep" else ()
        return [replace(p, object_target=t) for t in h.present(PICKUP_TYPES) if t not in banned]

    def slicing(h: Holdings, p: PddlParams) -> list[PddlParams]:
        can = (
            task_info(task_type).sliced
            and p.object_target in SLICED_PARENTS
            and bool(h.present(SLICING_TOOLS))
        )
        options = {
            None: [False, True] if can else [False],
            False: [False],
            True: [True] if can else [],
        }[sliced]
        return [replace(p, object_sliced=s) for s in options]

    no_slice = (
        f"{task_type} is never sliced in ALFRED"
        if sliced and not task_info(task_type).sliced
        else f"a sliced {task_type} needs one of {', '.join(SLICED_PARENTS)} and a "
        f"{' or '.join(SLICING_TOOLS)} in the scene"
    )
    stages: list[tuple[_Expand, str]] = [
        (
            objects,
            "the scene holds no object type ALFRED picks up"
            + (
                " other than a movable receptacle"
                if task_type == "pick_and_place_with_movable_recep"
                else ""
            ),
        ),
        (slicing, no_slice),
    ]
    if task_type in DEVICES:
        device, ability = DEVICES[task_type][0], ABILITY[task_type]
        stages += [
            (
                lambda h, p: [p] if getattr(abilities(p.object_type), ability) else [],
                f"no object in the scene is {ability}",
            ),
            (
                lambda h, p: [] if h.holds_type(device, p.object_target) else [p],
                f"every {ability} object type present already has an instance inside the {device}",
            ),
        ]
    if task_type == "pick_two_obj_and_place":
        stages.append(
            (
                lambda h, p: (
                    [p]
                    if (
                        h.pieces(p.object_target)
                        if p.object_sliced
                        else h.count.get(p.object_target, 0)
                    )
                    >= 2
                    else []
                ),
                "pick_two_obj_and_place needs two instances of one object type",
            )
        )
    if task_type == "pick_and_place_with_movable_recep":
        stages.append(
            (
                lambda h, p: [
                    replace(p, mrecep_target=m)
                    for m in h.present(MOVABLE_RECEPTACLES)
                    if can_contain(m, p.object_type)
                ],
                f"no movable receptacle ({', '.join(MOVABLE_RECEPTACLES)}) in the scene accepts an object present",
            )
        )
    if task_type == "look_at_obj_in_light":
        stages.append(
            (
                lambda h, p: [replace(p, toggle_target=t) for t in h.present(LAMPS)],
                f"the scene has no {' or '.join(LAMPS)}",
            )
        )
        return stages

    def receptacles(h: Holdings, p: PddlParams) -> list[PddlParams]:
        out = []
        for r in h.present(t for t in h.count if abilities(t).receptacle and t not in NEVER_PARENT):
            q = replace(p, parent_target=r)
            if params_problems(task_type, q):
                continue
            if task_type == "pick_two_obj_and_place" and h.holds_type(r, q.object_type):
                continue
            if q.mrecep_target and h.holds_type(r, q.mrecep_target):
                continue
            out.append(q)
        return out

    why = "no receptacle in the scene may take the object (ALFRED's receptacle table and exclusions"
    if task_type == "pick_two_obj_and_place":
        why += "; pick_two: not CoffeeMachine/ToiletPaperHanger/HandTowelHolder, none already holding the type"
    if task_type == "pick_and_place_with_movable_recep":
        why += "; it must accept the movable receptacle and not already hold one of its type"
    stages.append((receptacles, why + ")"))
    return stages


def candidates(
    state: WorldState, task_type: str, sliced: bool | None
) -> tuple[list[PddlParams], str]:
    """Every parameter set the stages allow, and (when there is none) why.

    Returns:
        (candidates, "") or ([], the reason the first empty stage gives).
    """
    h = Holdings(state)
    missing = [d for d in DEVICES.get(task_type, ()) if not h.has(d)]
    if missing:
        return [], f"the scene has no {' and no '.join(missing)}"
    cands = [PddlParams(object_target="")]
    for expand, why in _stages(task_type, sliced):
        cands = [q for p in cands for q in expand(h, p)]
        if not cands:
            return [], why
    return cands, ""
