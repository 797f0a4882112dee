"""The PDDL problem ALFWorld reads beside each trial (`initial_state.pddl`), in ALFWorld's own domain
(`alfred.pddl`, domain `alfred`): every object and receptacle of the room at the trial's start under ALFWorld's
names (`alfworld_names`), one location per receptacle (the pose from which the agent sees and reaches it, as
ALFRED's `loc|x|z|rotation|horizon`) and the agent's start, what is in what, what opens, what is open, the
abilities ALFWorld's actions ask for, `canContain` from ALFRED's compatibility table, and the task's goal in
the form of ALFWorld's goal library (ALFRED's, without its "every receptacle closed" conjunct).

Movable receptacles (a bowl, a pot) are objects with `isReceptacleObject`; what sits in one is also
`inReceptacle` the fixed receptacle under it (what ALFWorld's text shows on a shelf includes what is in
the bowl on it) and `inReceptacleObject` the bowl. Two departures, each where ALFWorld's domain could not
otherwise state the trial:
- a task whose receptacle is of a movable type ("put a potato in a pot", which ALFRED never samples and
  our splits do) has the pots as `receptacle`s at the place of what they stand on, so that ALFWorld's
  `PutObject` can reach them;
- a thing that can be taken or switched on but stands on no receptacle (a floor lamp, a ball on the
  floor) is on the receptacle nearest it that does not close (a lamp is not in a safe), as AI2-THOR's
  `parentReceptacles` puts it (ALFWorld's `PickupObject` and `ToggleObject` need one)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from luminous_sim.errors import LuminousError
from luminous_sim.states import WorldState
from luminous_sim.states.tables import GATING_OPENABLE
from luminous_sim.text.alfworld_names import alfworld_id, mangle
from luminous_sim.vocab import abilities, can_contain

AGENT = "agent1"
DOMAIN = "alfred"
TASK_TYPES = ("pick_and_place_simple", "look_at_obj_in_light", "pick_clean_then_place_in_recep",
              "pick_heat_then_place_in_recep", "pick_cool_then_place_in_recep", "pick_two_obj_and_place",
              "pick_and_place_with_movable_recep")


class ProblemError(LuminousError):
    """The trial cannot be written as an ALFWorld problem (an unknown task type, a receptacle without a
    place, a goal naming a type with no entity)."""


@dataclass(frozen=True)
class AlfworldProblem:
    """A problem's text and each of our object ids' PDDL identifier in it."""

    text: str
    ids: Mapping[str, str]
    locations: tuple[str, ...]


def is_receptacle(object_type: str) -> bool:
    """A PDDL `receptacle` of ALFWorld's domain: a receptacle that is not picked up."""
    ab = abilities(object_type)
    return ab.receptacle and not ab.pickupable


def fixed_holder(state: WorldState, object_id: str) -> str | None:
    """The fixed receptacle the object is in or on (through a bowl or pot it sits in), or None."""
    for a in state.ancestors(object_id):
        if is_receptacle(state[a].object_type):
            return a
    return None


def alfworld_problem(state: WorldState, places: Mapping[str, str], start: str, task_type: str,
                     params: Mapping[str, Any], name: str) -> AlfworldProblem:
    """The problem of a trial from its starting state.

    Args:
        places: each fixed receptacle's location (`loc|x|z|rotation|horizon`); one missing is an error.
        start: the agent's starting location (`loc|...`).
        params: `traj_data.json`'s `pddl_params`.
        name: the problem's name (ALFWorld's are `plan_trial_...`).

    Raises:
        ProblemError: an unknown task type, or a fixed receptacle without a place.
    """
    if task_type not in TASK_TYPES:
        raise ProblemError(f"task type {task_type!r} is none of ALFRED's seven ({', '.join(TASK_TYPES)})")
    ids = {oid: mangle(alfworld_id(oid, o.object_type)) for oid, o in sorted(state.objects.items())}
    fixed = sorted(oid for oid, o in state.objects.items() if is_receptacle(o.object_type))
    missing = [r for r in fixed if r not in places]
    if missing:
        raise ProblemError(f"receptacles without a place to stand: {', '.join(missing)}")
    holders = {oid: fixed_holder(state, oid) for oid in state.objects}
    raised = {oid for oid, o in state.objects.items()
              if o.object_type == params.get("parent_target") and abilities(o.object_type).movable_receptacle
              and task_type != "pick_and_place_with_movable_recep" and holders[oid] is not None}
    receptacles = sorted([*fixed, *raised])
    objects = sorted(oid for oid in state.objects if oid not in receptacles)
    loc = {r: mangle(places[r]) for r in fixed}
    loc.update({r: loc[holders[r]] for r in raised if holders[r] is not None})
    for oid in raised:  # what is in a raised pot is in the pot
        for inner in state.contents(oid, recursive=True):
            holders[inner] = oid
    for oid, h in free_holders(state).items():
        if holders[oid] is None:
            holders[oid] = h
    locations = tuple(sorted({*loc.values(), mangle(start)}))
    rtypes = sorted({state[r].object_type for r in receptacles})
    otypes = sorted({state[o].object_type for o in objects})
    init = [f"(atLocation {AGENT} {mangle(start)})"]
    init += [f"(canContain {rt}Type {ot}Type)" for rt in rtypes for ot in otypes if can_contain(rt, ot)]
    for r in receptacles:
        s = state[r]
        init += [f"(receptacleType {ids[r]} {s.object_type}Type)", f"(receptacleAtLocation {ids[r]} {loc[r]})"]
        if s.object_type in GATING_OPENABLE:
            init.append(f"(openable {ids[r]})")
            if s.isOpen:
                init.append(f"(opened {ids[r]})")
    for o in objects:
        init += _object_facts(state, o, ids, loc, holders.get(o))
    if state.held is not None:
        init += [f"(holds {AGENT} {ids[state.held]})", f"(holdsAny {AGENT})"]
    declared = ([f"{AGENT} - agent"] + [f"{ids[o]} - object" for o in objects]
                + [f"{ids[r]} - receptacle" for r in receptacles] + [f"{lo} - location" for lo in locations]
                + [f"{t}Type - otype" for t in otypes] + [f"{t}Type - rtype" for t in rtypes])
    text = "\n".join([
        f"(define (problem {name})", f"  (:domain {DOMAIN})", "  (:objects",
        *(f"    {d}" for d in declared), "  )", "  (:init", *(f"    {f}" for f in init), "  )",
        f"  (:goal {goal(task_type, params)})", ")", ""])
    return AlfworldProblem(text, ids, locations)


def free_holders(state: WorldState) -> dict[str, str]:
    """Things that can be taken or switched on but stand on no receptacle (a floor lamp, a ball on the floor),
    each with the receptacle nearest it that does not close (any receptacle, in a room of closing ones)."""
    fixed = sorted(oid for oid, o in state.objects.items() if is_receptacle(o.object_type))
    open_tops = [r for r in fixed if state[r].object_type not in GATING_OPENABLE] or fixed
    out = {}
    for oid, o in sorted(state.objects.items()):
        ab = abilities(o.object_type)
        if (open_tops and not is_receptacle(o.object_type) and (ab.pickupable or ab.toggleable)
                and state.held != oid and fixed_holder(state, oid) is None and o.parent is None):
            out[oid] = _nearest(oid, open_tops)
    return out


def _nearest(object_id: str, receptacles: list[str]) -> str:
    """The receptacle whose position (in its AI2-THOR-style id) is nearest the object's, across the floor."""
    x, z = _floor_xy(object_id)
    return min(receptacles, key=lambda r: (math.hypot(_floor_xy(r)[0] - x, _floor_xy(r)[1] - z), r))


def _floor_xy(object_id: str) -> tuple[float, float]:
    parts = object_id.split("|")
    try:
        return float(parts[1]), float(parts[3])
    except (IndexError, ValueError) as exc:
        raise ProblemError(f"{object_id}: not an AI2-THOR-style id (Type|x|y|z)") from exc


def _object_facts(state: WorldState, o: str, ids: Mapping[str, str], loc: Mapping[str, str],
                  holder: str | None) -> list[str]:
    s, p = state[o], ids[o]
    ab = abilities(s.object_type)
    facts = [f"(objectType {p} {s.object_type}Type)"]
    for flag, fact in ((ab.pickupable, "pickupable"), (ab.movable_receptacle, "isReceptacleObject"),
                       (ab.cleanable, "cleanable"), (ab.heatable, "heatable"), (ab.coolable, "coolable"),
                       (ab.sliceable, "sliceable"), (ab.toggleable, "toggleable"),
                       (ab.toggleable and s.isToggled, "isOn"), (s.isSliced, "isSliced"),
                       (o in state.cleaned, "isClean"), (o in state.heated, "isHot"), (o in state.cooled, "isCool")):
        if flag:
            facts.append(f"({fact} {p})")
    if holder is not None:
        facts += [f"(inReceptacle {p} {ids[holder]})", f"(objectAtLocation {p} {loc[holder]})"]
    if s.parent is not None and s.parent != holder and abilities(state[s.parent].object_type).movable_receptacle:
        facts.append(f"(inReceptacleObject {p} {ids[s.parent]})")
    return facts


def goal(task_type: str, params: Mapping[str, Any]) -> str:
    """The task's goal as ALFWorld's goal library states it, filled with `pddl_params` (a sliced target adds
    `sliceable` and `isSliced`, as the library's `_slice` goals do)."""
    obj, recep = f"{params['object_target']}Type", f"{params['parent_target']}Type"
    sliced = bool(params.get("object_sliced"))

    def target(v: str) -> str:
        return f"(objectType {v} {obj})" + (f" (sliceable {v}) (isSliced {v})" if sliced else "")

    if task_type == "pick_and_place_simple":
        body = f"(exists (?r - receptacle ?o - object) (and {target('?o')} (receptacleType ?r {recep}) " \
               "(inReceptacle ?o ?r)))"
    elif task_type in ("pick_clean_then_place_in_recep", "pick_heat_then_place_in_recep",
                       "pick_cool_then_place_in_recep"):
        able, done = {"pick_clean_then_place_in_recep": ("cleanable", "isClean"),
                      "pick_heat_then_place_in_recep": ("heatable", "isHot"),
                      "pick_cool_then_place_in_recep": ("coolable", "isCool")}[task_type]
        body = f"(exists (?r - receptacle ?o - object) (and ({able} ?o) {target('?o')} " \
               f"(receptacleType ?r {recep}) ({done} ?o) (inReceptacle ?o ?r)))"
    elif task_type == "pick_two_obj_and_place":
        body = f"(exists (?r - receptacle ?o1 - object ?o2 - object) (and (not (= ?o1 ?o2)) {target('?o1')} " \
               f"{target('?o2')} (receptacleType ?r {recep}) (inReceptacle ?o1 ?r) (inReceptacle ?o2 ?r)))"
    elif task_type == "look_at_obj_in_light":
        toggle = f"{params['toggle_target']}Type"
        body = f"(and (exists (?ot - object ?r - receptacle ?a - agent ?l - location) (and (objectType ?ot {toggle}) " \
               "(toggleable ?ot) (isToggled ?ot) (receptacleAtLocation ?r ?l) (atLocation ?a ?l) " \
               f"(inReceptacle ?ot ?r))) (exists (?o - object ?a - agent) (and {target('?o')} (holds ?a ?o))))"
    else:
        mrecep = f"{params['mrecep_target']}Type"
        body = f"(exists (?r - receptacle ?o - object ?mo - object) (and (receptacleType ?r {recep}) " \
               f"{target('?o')} (objectType ?mo {mrecep}) (isReceptacleObject ?mo) (inReceptacleObject ?o ?mo) " \
               "(inReceptacle ?mo ?r)))"
    return f"(and {body})"
