"""One CSSG sample under construction: placing requests in it, and going back to a checkpoint."""

from __future__ import annotations

from dataclasses import dataclass, field

from shapely.geometry import Polygon

from luminous_sim.cssg.draft import Placed, SceneDraft
from luminous_sim.cssg.floor_objects import may_lie_on_floor, place_on_floor, wants_floor
from luminous_sim.cssg.furniture import FloorContext, hard_relations_met, place_piece, register
from luminous_sim.cssg.objects import place_object
from luminous_sim.cssg.requests import Request
from luminous_sim.cssg.walls import place_wall_piece

ATTACHED = frozenset({"SinkBasin", "Faucet", "BathtubBasin", "StoveBurner", "StoveKnob"})
"""Fixture types that only exist as parts of another fixture: never placed on the floor by themselves."""

Occupied = dict[tuple[str, str], list[Polygon]]
"""Per (host id, region), the footprints already standing there."""


@dataclass(frozen=True)
class Checkpoint:
    """Everything a sample changes, saved before the request at `index` is placed."""

    index: int
    placed: list[Placed]
    floor: tuple
    bound: set[str]
    by_name: dict[str, str]
    occupied: Occupied
    unplaced: list[str]


@dataclass
class Sample:
    """A scene being sampled: the draft, the furniture layer's floor, and what binds CDF names to objects.

    Attributes:
        draft: The objects placed so far.
        ctx: The furniture layer's floor (grid, agent lattice, placed pieces).
        by_name: CDF object name -> id of the object placed (or bound) for it.
        occupied: Footprints already standing in each receptacle region.
        unplaced: Names of requests that could not be placed.
        bound: Names bound to the room's own fixtures (not drawn, so never gone back to).
    """

    draft: SceneDraft
    ctx: FloorContext
    by_name: dict[str, str] = field(default_factory=dict)
    occupied: Occupied = field(default_factory=dict)
    unplaced: list[str] = field(default_factory=list)
    bound: set[str] = field(default_factory=set)

    @classmethod
    def start(cls, draft: SceneDraft) -> Sample:
        """A sample over `draft` (its room's fixtures already placed), nothing else placed yet."""
        return cls(draft, FloorContext.create(draft))

    def checkpoint(self, index: int) -> Checkpoint:
        """Save this sample's state before request `index` is placed."""
        return Checkpoint(index, list(self.draft.placed), self.ctx.snapshot(), set(self.bound), dict(self.by_name),
                          {k: list(v) for k, v in self.occupied.items()}, list(self.unplaced))

    def restore(self, cp: Checkpoint) -> None:
        """Go back to checkpoint `cp` (the draft's random stream goes on; it is not rewound)."""
        self.draft.placed[:] = cp.placed
        self.draft.taken_ids = {p.obj.id for p in self.draft.placed}
        self.ctx.restore(cp.floor)
        self.bound.clear()
        self.bound.update(cp.bound)
        self.by_name.clear()
        self.by_name.update(cp.by_name)
        self.occupied.clear()
        self.occupied.update({k: list(v) for k, v in cp.occupied.items()})
        self.unplaced[:] = cp.unplaced

    def place(self, req: Request) -> bool:
        """Place one request; True when it is placed with its hard relations met.

        A name bound to one of the room's own fixtures is added to `bound`.
        """
        draft, ctx, by_name = self.draft, self.ctx, self.by_name
        if req.layer == "fixture":
            met = self._bind_fixture(req)
            if met is not None:
                self.bound.add(req.name)
                return met
            if req.type in ATTACHED:
                return False
        if req.layer in ("furniture", "fixture"):
            with ctx.seat_zone_open(req):  # a stool at the counter stands where one works at it
                if place_piece(ctx, req) is None:
                    return False
            by_name[req.name] = draft.placed[-1].obj.id
            last = draft.placed[-1].obj
            return hard_relations_met(ctx, req, draft.placed[-1].entry, last.position[0], last.position[1], last.yaw)
        if req.layer == "object":  # sports gear first on the floor as often as ALFRED puts it there
            if wants_floor(req, draft.rng) and place_on_floor(ctx, req, by_name):
                return True
            return place_object(draft, req, by_name, self.occupied) or (
                may_lie_on_floor(req) and place_on_floor(ctx, req, by_name))
        ok = place_wall_piece(draft, req, by_name,
                              accept=lambda e, x, y, yaw: hard_relations_met(ctx, req, e, x, y, yaw))
        if ok:
            by_name[req.name] = draft.placed[-1].obj.id
        return ok

    def _bind_fixture(self, req: Request) -> bool | None:
        """A CDF object of a fixture type names a fixture the room already has (the kitchen's fridge); whether
        its hard relations hold there, or None when there is none to name.

        If that fixture breaks one of the object's hard relations, it (and what it brings along) is taken
        out so that the furniture layer places the object by its relations instead (None), unless it is
        part of another fixture (a sink's basin): that one stays, with its relations unmet.
        """
        draft, ctx, by_name = self.draft, self.ctx, self.by_name
        taken = set(by_name.values())
        hit = next((p for p in draft.placed if p.obj.type == req.type and p.obj.id not in taken), None)
        if hit is None:
            return None
        register(ctx, req.name, hit.obj, hit.entry)
        met = hard_relations_met(ctx, req, hit.entry, hit.obj.position[0], hit.obj.position[1], hit.obj.yaw)
        if not met and req.type not in ATTACHED:
            del ctx.placed[req.name]
            ctx.alternates.pop(req.name, None)
            gone = {hit.obj.id} | {p.obj.id for p in draft.placed if p.obj.parent == hit.obj.id}
            draft.placed[:] = [p for p in draft.placed if p.obj.id not in gone]
            ctx.remove(gone, hit.footprint)
            return None
        by_name[req.name] = hit.obj.id
        if req.states or req.name:
            i = draft.placed.index(hit)
            obj = hit.obj.model_copy(update={"name": req.name, "states": {**hit.obj.states, **req.states}})
            draft.placed[i] = type(hit)(obj, hit.entry, hit.footprint)
        return met
