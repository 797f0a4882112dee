"""CSSG for a house: a floor plan (`rooms.house.plan_house`), each room furnished by CSSG with its room
type's rules inside its own shell, and one scene for the whole house.

Every room is generated as a room of its own (its shell holds its doors, whose clearance zones CSSG keeps
free), then the rooms' objects are put together in one scene whose shell is the house. A room whose
reachable floor is not all reachable from the house's connected floor (furniture walling off a doorway)
is drawn again with its next seed; a plan with a room CSSG cannot furnish is drawn again. Same CDF and seed:
the same house, byte for byte.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cdf.house import room_cdf
from luminous_sim.cdf.predicates import And, Atom, Exists, Expr, Param, atoms, is_variable
from luminous_sim.cdf.schema import ChallengeDefinition, Task
from luminous_sim.cssg.baseline import empty_cdf
from luminous_sim.cssg.pipeline import Generated, generate
from luminous_sim.cssg.requests import PUT_PREDICATES
from luminous_sim.cssg.validate import LayoutReport
from luminous_sim.errors import CDFError, InfeasibleSceneError, RoomError
from luminous_sim.rooms.house import FloorPlan, RoomRequest, plan_house
from luminous_sim.scene import Scene, scene_reachable_grid

__all__ = ["ROOM_REDRAWS", "HouseGenerated", "HouseReport", "generate_house"]

ROOM_REDRAWS = 6
"""Times a room is furnished again (its next seed) when some of its floor cannot be reached from the house's."""
PLAN_STREAM = 1 << 20
"""The floor plan's seed stream, apart from the rooms' (which are numbered 0, 1, ...)."""
PLAN_REDRAWS = 4
"""Floor plans drawn at most: a plan is drawn again when one of its rooms cannot be furnished (CSSG finds no
valid layout, or furniture keeps walling off its doorway)."""


@dataclass(frozen=True)
class HouseReport:
    """What was checked: each room's CSSG report, the house's reachable floor, which rooms it reaches."""

    rooms: dict[str, LayoutReport]
    reachable_points: int
    rooms_reached: dict[str, bool]
    room_seeds: dict[str, int] = field(default_factory=dict)
    plan_redraws: int = 0
    """Floor plans drawn before this one (each had a room CSSG could not furnish)."""

    @property
    def ok(self) -> bool:
        return all(r.ok for r in self.rooms.values()) and all(self.rooms_reached.values()) and \
            self.reachable_points > 0

    def to_dict(self) -> dict[str, Any]:
        return {"ok": self.ok, "reachable_points": self.reachable_points, "rooms_reached": dict(self.rooms_reached),
                "room_seeds": dict(self.room_seeds), "plan_redraws": self.plan_redraws,
                "rooms": {k: v.to_dict() for k, v in self.rooms.items()}}


@dataclass(frozen=True)
class HouseGenerated:
    """A generated house: the scene (its shell is the house), the floor plan, and the report."""

    scene: Scene
    plan: FloorPlan
    report: HouseReport


def _room_seed(seed: int, index: int, redraw: int, plan_redraw: int = 0) -> int:
    entropy = [seed, index, redraw] + ([PLAN_STREAM, plan_redraw] if plan_redraw else [])
    return int(np.random.SeedSequence(entropy).generate_state(1)[0])


def generate_house(cdf: ChallengeDefinition, seed: int = 0, catalog: Catalog | None = None) -> HouseGenerated:
    """The house a CDF's `scene.house` describes, for a seed.

    Raises:
        CDFError: the CDF has no house.
        InfeasibleSceneError: no floor plan fits, or a room cannot be furnished with its floor reachable.
    """
    house = cdf.scene.house
    if house is None:
        raise CDFError(f"CDF {cdf.name or ''}: scene.house is not set; expected a house (rooms, adjacency)")
    catalog = catalog or default_catalog()
    requests = [RoomRequest(r.name, r.type, r.min_area, r.max_area, r.shape or "rect") for r in house.rooms]
    size = (house.size.width, house.size.depth) if house.size is not None else None
    why = ""
    for redraw in range(PLAN_REDRAWS):
        stream = [seed, PLAN_STREAM] + ([redraw] if redraw else [])
        try:
            plan = plan_house(requests, np.random.default_rng(np.random.SeedSequence(stream)), size=size,
                              adjacency=house.adjacency, name=cdf.name or "house", front_door=house.front_door)
        except RoomError as exc:
            raise InfeasibleSceneError(f"CDF {cdf.name or ''}: scene.house: {exc}") from None
        furnished = _furnish(cdf, seed, plan, requests, catalog, redraw)
        if isinstance(furnished, HouseGenerated):
            return furnished
        why = furnished
    raise InfeasibleSceneError(f"CDF {cdf.name or ''}: scene.house: no floor plan of {PLAN_REDRAWS} could be "
                               f"furnished (last: {why})")


def _furnish(cdf: ChallengeDefinition, seed: int, plan: FloorPlan, requests: list[RoomRequest], catalog: Catalog,
             plan_redraw: int) -> HouseGenerated | str:
    """Every room furnished by CSSG, a room whose floor is cut off from the house's drawn again; a string says
    why the plan could not be furnished."""
    redraws = dict.fromkeys((r.name for r in requests), 0)
    rooms: dict[str, Generated] = {}
    while True:
        for i, (req, shell) in enumerate(zip(requests, plan.rooms, strict=True)):
            if req.name in rooms:
                continue
            sub = _room_seed(seed, i, redraws[req.name], plan_redraw)
            try:
                rooms[req.name] = generate(room_request(cdf, i), seed=sub, room=shell, catalog=catalog)
            except InfeasibleSceneError as exc:
                return f"house room {req.name!r} ({req.room_type}): {exc}"
        scene = _assemble(cdf, seed, plan, rooms, redraws, plan_redraw)
        grid = scene_reachable_grid(scene, catalog)
        keys = {(round(x * 4), round(y * 4)) for x, y in grid}
        reached = {name: _all_in(scene_reachable_grid(g.scene, catalog), keys) for name, g in rooms.items()}
        cut_off = [n for n, ok in reached.items() if not ok]
        if not cut_off:
            break
        for name in cut_off:
            if redraws[name] + 1 >= ROOM_REDRAWS:
                return (f"house room {name!r}: its floor is cut off from the house's in {ROOM_REDRAWS} draws "
                        "(furniture walls off its doorway)")
            redraws[name] += 1
            del rooms[name]
    seeds = {r.name: _room_seed(seed, i, redraws[r.name], plan_redraw) for i, r in enumerate(requests)}
    report = HouseReport({n: g.report for n, g in rooms.items()}, len(grid), reached, seeds, plan_redraw)
    return HouseGenerated(scene, plan, report)


def room_request(cdf: ChallengeDefinition, index: int) -> ChallengeDefinition:
    """What CSSG is asked for in the house's room `index`: its own objects and relations (a room CDF), and
    the puts of the house's goal into its receptacles (so that they keep room for them); with neither, the
    room type's defaults alone (`empty_cdf`)."""
    house = cdf.scene.house
    assert house is not None
    room = house.rooms[index]
    goal = _room_puts(cdf, {o.name for o in room.objects})
    if not room.objects and not room.relations and goal is None:
        return empty_cdf(room.type)
    doc = room_cdf(room)
    if goal is None:
        return doc
    return doc.model_copy(update={"task": Task.model_construct(type=None, agent=None, initial=None, goal=goal)})


def _room_puts(cdf: ChallengeDefinition, mine: set[str]) -> Expr | None:
    """The house goal's puts into receptacles named in this room, other rooms' objects standing as typed
    variables (`requests.goal_holds` reads them); None when the goal puts nothing here."""
    if cdf.task is None:
        return None
    parts: list[Expr] = []
    for atom, scope in atoms(cdf.task.goal):
        if atom.pred not in PUT_PREDICATES or len(atom.args) != 2 or atom.args[1] not in mine:
            continue
        what = atom.args[0]
        if what in mine:
            parts.append(atom)
            continue
        spec = cdf.object_named(what)
        kind = scope.get(what) if is_variable(what) else spec.type if spec is not None else None
        if kind:
            var = what if is_variable(what) else "?held"
            parts.append(Exists((Param(var, kind),), Atom(atom.pred, (var, atom.args[1]))))
    return And(tuple(parts)) if parts else None


def _all_in(points: np.ndarray, keys: set[tuple[int, int]]) -> bool:
    return all((round(x * 4), round(y * 4)) in keys for x, y in points)


def _assemble(cdf: ChallengeDefinition, seed: int, plan: FloorPlan, rooms: dict[str, Generated],
              redraws: dict[str, int], plan_redraw: int) -> Scene:
    """One scene: the house shell and every room's objects (ids are positions, so rooms never clash)."""
    objects = []
    seen: set[str] = set()
    for shell in plan.rooms:
        for o in rooms[shell.name].scene.objects:
            if o.id in seen:
                raise InfeasibleSceneError(f"house room {shell.name!r}: object id {o.id} clashes with another room's")
            seen.add(o.id)
            objects.append(o)
    notes = {"rooms": {s.name: {"room_type": s.room_type, "attempt": rooms[s.name].scene.notes.get("attempt"),
                                "redraws": redraws[s.name]} for s in plan.rooms}, "plan_redraws": plan_redraw}
    return Scene(room=plan.shell, seed=seed, generator="cssg-house", objects=tuple(objects), source=cdf.name or "",
                 notes=notes)
