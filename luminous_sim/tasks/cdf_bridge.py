"""Tasks and CDFs, both ways: a CDF's task section as a `TaskInstance`, and a CDF that asks CSSG for
a scene in which a given ALFRED task is feasible.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import replace
from typing import Any

import numpy as np
import yaml

from luminous_sim.cdf import loads
from luminous_sim.cdf.affordances import STANDS_ON, can_support
from luminous_sim.cdf.predicates import (
    And,
    Atom,
    Exists,
    Expr,
    ForAll,
    Not,
    Or,
    atoms,
    is_variable,
    to_sexpr,
)
from luminous_sim.cdf.schema import ChallengeDefinition
from luminous_sim.scene.model import Scene
from luminous_sim.tasks.constraints import DEVICES, params_problems
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.model import PddlParams, TaskInstance
from luminous_sim.tasks.templates import task_description
from luminous_sim.tasks.types import goal_for, task_info
from luminous_sim.vocab import LAMPS, SLICED_TYPES, SLICING_TOOLS, abilities, parent_type

SURFACES: dict[str, tuple[str, ...]] = {
    "Kitchen": ("CounterTop", "DiningTable", "SideTable", "Shelf"),
    "LivingRoom": ("CoffeeTable", "SideTable", "DiningTable", "Dresser", "Shelf", "Sofa", "ArmChair"),
    "Bedroom": ("Dresser", "Desk", "SideTable", "Shelf", "Bed"),
    "Bathroom": ("CounterTop", "Shelf", "SideTable", "Dresser", "Cart"),
}
"""Per room type, the surfaces a task's small objects are put on, in order of preference; the first that
takes the object and is big enough for it (a baseball bat is longer than a side table is wide)."""
LAMP_TABLES: tuple[str, ...] = ("SideTable", "Desk", "Dresser")


def names_from_scene(scene: Scene) -> dict[str, str]:
    """CDF object name -> object id, for the objects of a generated scene that carry a name."""
    return {o.name: o.id for o in scene.objects if o.name}


def _type_of(arg: str, scope: Mapping[str, str | None], cdf: ChallengeDefinition) -> str | None:
    if is_variable(arg):
        return scope.get(arg)
    spec = cdf.object_named(arg)
    return spec.type if spec else None


def _all_known(types: list[str | None]) -> list[str] | None:
    """`types` when every one is known (not None or empty), else None."""
    known = [t for t in types if t]
    return known if len(known) == len(types) else None


def params_from_goal(cdf: ChallengeDefinition, goal: Expr) -> PddlParams:
    """ALFRED parameters read off a CDF goal, as far as its atoms tell (unknown slots stay "").

    `inReceptacleObject(o, m)` gives the object and movable receptacle, `inReceptacle(x, r)` the
    receptacle (of the movable receptacle when there is one), `holds`/`isHot`/... the object,
    `isToggled` of a lamp the toggle target; a sliced type or `isSliced` marks a sliced task.
    """
    slots: dict[str, str] = {}
    sliced = False
    found = list(atoms(goal))
    for atom, scope in found:
        types = [_type_of(a, scope, cdf) for a in atom.args]
        if any(t in SLICED_TYPES for t in types if t) or atom.pred == "isSliced":
            sliced = True
        known = _all_known(types)
        if atom.pred == "inReceptacleObject" and known is not None:
            slots.setdefault("object_target", parent_type(known[0]))
            slots.setdefault("mrecep_target", known[1])
    for atom, scope in found:
        known = _all_known([_type_of(a, scope, cdf) for a in atom.args])
        if known is None:
            continue
        if atom.pred == "inReceptacle":
            what = parent_type(known[0])
            # the movable receptacle's place, or (without one) the object's place
            mrecep = slots.get("mrecep_target")
            if known[0] == mrecep or (
                not mrecep and slots.setdefault("object_target", what) == what
            ):
                slots.setdefault("parent_target", known[1])
        elif atom.pred in ("holds", "isHot", "isCool", "isClean", "isSliced"):
            slots.setdefault("object_target", parent_type(known[0]))
        elif atom.pred in ("isToggled", "isOn") and known[0] in LAMPS:
            slots.setdefault("toggle_target", known[0])
    return PddlParams(
        object_sliced=sliced and slots.get("object_target", "") in SLICED_TYPES.values(),
        **{
            k: slots.get(k, "")
            for k in ("object_target", "parent_target", "toggle_target", "mrecep_target")
        },
    )


def task_from_cdf(
    cdf: ChallengeDefinition,
    names: Mapping[str, str],
    scene_seed: int = 0,
    instruction: str | None = None,
) -> TaskInstance:
    """The task a CDF states, for a scene generated from it.

    Args:
        cdf: the document; its `task.goal` becomes the goal as written (`custom=True`).
        names: CDF object name -> object id in the scene (see `names_from_scene`).
        scene_seed: the scene's seed.
        instruction: the instruction; by default ALFRED's template for a typed task, else a
            plain reading of the goal.

    Raises:
        TaskError: the CDF has no task, or its goal names an object `names` does not map.
    """
    if cdf.task is None:
        raise TaskError(f"CDF {cdf.name or '<unnamed>'}: has no task section; expected task.goal")
    goal = cdf.task.goal
    used = sorted({a for atom, _ in atoms(goal) for a in atom.args if not is_variable(a)})
    missing = [n for n in used if n not in names]
    if missing:
        raise TaskError(
            f"CDF {cdf.name or '<unnamed>'}: task.goal names {', '.join(missing)}, which the "
            f"scene does not map to objects (mapped: {', '.join(sorted(names)) or 'none'})"
        )
    params = params_from_goal(cdf, goal) if cdf.task.type else PddlParams(object_target="")
    task = TaskInstance(
        cdf.task.type or "custom", params, goal, scene_seed, custom=True, names=names
    )
    if instruction is None:
        instruction = task_description(task, np.random.default_rng(scene_seed))
    return replace(task, instruction=instruction)


def required_objects(task_type: str, params: PddlParams) -> list[tuple[str, int]]:
    """The object types (and counts) a scene must hold for the task to be feasible.

    Raises:
        TaskError: parameters ALFRED would not draw for the task type (the message says why).
    """
    problems = params_problems(task_type, params)
    if problems:
        raise TaskError(f"{task_type} with {params.to_json()}: {'; '.join(problems)}")
    two = task_type == "pick_two_obj_and_place" and not params.object_sliced
    wanted = [(params.object_target, 2 if two else 1)]
    if params.object_sliced:
        wanted.append((SLICING_TOOLS[0], 1))
    wanted += [
        (t, 1) for t in (params.mrecep_target, params.parent_target, params.toggle_target) if t
    ]
    wanted += [(t, 1) for t in DEVICES.get(task_type, ())]
    out: dict[str, int] = {}
    for t, n in wanted:
        out[t] = out.get(t, 0) + n
    return list(out.items())


def _snake(object_type: str) -> str:
    return "".join(
        "_" + c.lower() if c.isupper() and i else c.lower() for i, c in enumerate(object_type)
    )


class _Doc:
    """A CDF document being written: objects with names, and `on` relations to surfaces."""

    def __init__(self) -> None:
        self.objects: list[dict[str, Any]] = []
        self.relations: list[dict[str, Any]] = []
        self.by_type: dict[str, str] = {}

    def add(
        self, name: str, object_type: str, count: int = 1, state: dict[str, bool] | None = None
    ) -> str:
        entry: dict[str, Any] = {"name": name, "type": object_type}
        if count > 1:
            entry["count"] = count
        if state:
            entry["state"] = state
        self.objects.append(entry)
        self.by_type.setdefault(object_type, name)
        return name

    def put_on(
        self, name: str, object_type: str, surfaces: tuple[str, ...], avoid: str = "", count: int = 1
    ) -> None:
        """Rest the object on the first surface that takes it and `count` of it fit on (declared once,
        reused after)."""
        for s in surfaces:
            if s != avoid and can_support(s, object_type) and fits_on(s, object_type, count):
                target = self.by_type.get(s) or self.add(_snake(s), s)
                self.relations.append({"subject": name, "relation": "on", "target": target})
                return


def fits_on(surface: str, object_type: str, count: int = 1) -> bool:
    """Whether `count` of some asset of `object_type` fit side by side in one region of some asset of
    `surface` (`scene.can_hold`: in a row, upright; True where the catalog has neither: generation will
    say). Two boxes do not fit on a side table."""
    from luminous_sim.assets.catalog import default_catalog
    from luminous_sim.scene import can_hold

    catalog = default_catalog()
    things, hosts = catalog.of_type(object_type), catalog.of_type(surface)
    if not things or not hosts:
        return True
    return any(can_hold(host, thing, count) for host in hosts for thing in things)


def _cdf_goal(goal: Expr) -> Expr:
    """The goal without `isSliced` on variables of a sliced type: implied, and the CDF checker
    accepts `isSliced` only on sliceable (whole) types."""
    if isinstance(goal, (Exists, ForAll)):
        sliced = {p.var for p in goal.params if p.type in SLICED_TYPES}
        body = _strip(goal.body, sliced)
        return type(goal)(goal.params, body)
    if isinstance(goal, (And, Or)):
        return type(goal)(tuple(_cdf_goal(e) for e in goal.args))
    return goal


def _strip(expr: Expr, sliced: set[str]) -> Expr:
    if isinstance(expr, And):
        kept = [
            e
            for e in expr.args
            if not (isinstance(e, Atom) and e.pred == "isSliced" and e.args[0] in sliced)
        ]
        return And(tuple(_cdf_goal(e) for e in kept))
    return _cdf_goal(expr) if not isinstance(expr, Not) else expr


def cdf_for_task(task_type: str, params: PddlParams, room_type: str,
                 avoid: Collection[str] = ()) -> ChallengeDefinition:
    """A CDF that asks CSSG for a room of `room_type` in which the task is feasible.

    It declares `required_objects` under role names (`target`, `receptacle`, `mrecep`, `lamp`,
    `knife`, and the device: `microwave`, `fridge`, `basin` + `faucet`), puts the small ones on a
    surface of the room that is not the final receptacle (so that the goal does not already hold)
    nor one of the `avoid` types (a dining table that a small kitchen has no room for), the lamp on
    a side table, switched off, and, for a cleaning task, makes the object dirty where it can be.
    The task section carries the type and ALFRED's goal.

    Raises:
        TaskError: bad parameters, or a room type ALFRED does not generate the task in.
    """
    info = task_info(task_type)
    if room_type not in info.rooms:
        raise TaskError(
            f"{task_type} is generated only in {', '.join(sorted(info.rooms))}; got {room_type!r}"
        )
    required = dict(required_objects(task_type, params))
    p = params
    roles = {
        p.object_target: "target",
        p.mrecep_target: "mrecep",
        p.parent_target: "receptacle",
        p.toggle_target: "lamp",
        SLICING_TOOLS[0]: "knife",
        "Microwave": "microwave",
        "Fridge": "fridge",
        "SinkBasin": "basin",
        "Faucet": "faucet",
    }
    first = [t for t in (p.parent_target, *DEVICES.get(task_type, ())) if t]
    doc = _Doc()
    for t in first + [t for t in required if t not in first]:
        state: dict[str, bool] = {}
        if t in LAMPS:
            state["isToggled"] = False
        if (
            t == p.object_target
            and task_type == "pick_clean_then_place_in_recep"
            and abilities(t).dirtyable
        ):
            state["isDirty"] = True
        name = doc.add(roles.get(t, _snake(t)), t, required[t], state)
        if t == "DeskLamp":
            doc.put_on(name, t, tuple(s for s in LAMP_TABLES if s not in avoid))
        elif abilities(t).pickupable or t in STANDS_ON:
            # the object and its movable receptacle must not start in the final receptacle
            final = p.parent_target if t in (p.object_target, p.mrecep_target) else ""
            doc.put_on(name, t, tuple(s for s in SURFACES[room_type] if s not in avoid), final, required[t])
    goal = _cdf_goal(goal_for(params, task_type))
    obj_type = params.object_type
    data = {
        "cdf_version": 2,
        "name": f"{task_type}-{obj_type}-{params.mrecep_target or 'None'}-"
        f"{params.parent_target or params.toggle_target}",
        "scene": {"room_type": room_type, "objects": doc.objects, "relations": doc.relations},
        "task": {"type": task_type, "goal": to_sexpr(goal)},
    }
    return loads(yaml.safe_dump(data, sort_keys=False), source=f"<task {data['name']}>")
