"""The uniform-random baseline: the same objects as CSSG (the CDF's plus room defaults), fixtures as
planned, but no relations: furniture at uniformly random free positions and headings, objects on
uniformly chosen compatible receptacles, wall pieces on random stretches of wall."""

from __future__ import annotations

import math

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cdf.schema import ChallengeDefinition
from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.furniture import FloorContext, register
from luminous_sim.cssg.objects import place_object
from luminous_sim.cssg.requests import Request, requests_from_cdf
from luminous_sim.cssg.structure import place_fixtures
from luminous_sim.cssg.validate import LayoutReport, check_layout
from luminous_sim.cssg.walls import place_wall_piece
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.scene import Scene, footprint, reach_of

FURNITURE_TRIES = 200


def empty_cdf(room_type: str) -> ChallengeDefinition:
    """A CDF that asks for nothing but a room of `room_type` (defaults fill it)."""
    from luminous_sim.cdf import loads

    return loads(f"cdf_version: 2\nscene: {{room_type: {room_type}}}\n", source=f"<empty {room_type}>")


def place_uniform(ctx: FloorContext, req: Request) -> bool:
    """A uniformly random free position and heading for one furniture request."""
    draft = ctx.draft
    floor = draft.shell.polygon()
    keep_clear = draft.shell.door_clearance_zones()
    minx, miny, maxx, maxy = floor.bounds
    variants = req.variants(draft.catalog)
    for _ in range(FURNITURE_TRIES):
        if not variants:
            return False
        entry = variants[int(draft.rng.integers(len(variants)))]
        x, y = draft.rng.uniform(minx, maxx), draft.rng.uniform(miny, maxy)
        yaw = float(draft.rng.uniform(0, 2 * math.pi))
        fp = footprint(entry, x, y, yaw)
        if not floor.contains(fp) or any(fp.intersects(z) for z in keep_clear):
            continue
        if fp.intersects(draft.floor_obstacles()):
            continue
        obj = draft.add(entry, x, y, -entry.bbox_min[2], yaw, "furniture", fixed=True, name=req.name,
                        color=req.colour())
        register(ctx, req.name, obj, entry)
        ctx.commit(obj.id, fp, reach_of(entry, obj.position[2]))
        return True
    return False


def sample_uniform(cdf: ChallengeDefinition, shell: RoomShell, rng: np.random.Generator, catalog: Catalog,
                   attempt: int = 0) -> tuple[SceneDraft, LayoutReport]:
    """One baseline sample; its report scores the CDF's relations that it met by chance."""
    draft = SceneDraft(shell, catalog, rng)
    place_fixtures(draft)
    requests = requests_from_cdf(cdf, shell.room_type, rng, area=shell.area,
                                 fixtures=frozenset(p.obj.type for p in draft.placed if p.obj.layer == "fixture"))
    ctx = FloorContext.create(draft)
    by_name: dict[str, str] = {}
    occupied: dict = {}
    unplaced = []
    for req in requests:
        free = Request(req.name, req.type, req.layer, req.explicit, req.asset, req.states,
                       attributes=req.attributes, tag=req.tag)  # no relations, the same variants (bar stools)
        if req.layer in ("furniture", "fixture"):
            ok = place_uniform(ctx, free)
            if ok:
                by_name[req.name] = draft.placed[-1].obj.id
        elif req.layer == "object":
            ok = place_object(draft, free, by_name, occupied, natural=False)
        else:
            ok = place_wall_piece(draft, free, by_name, relations=False)
            if ok:
                by_name[req.name] = draft.placed[-1].obj.id
        if not ok:
            unplaced.append(req.name)
    return draft, check_layout(draft, requests, ctx, unplaced, attempt)


def generate_uniform(shell: RoomShell, seed: int, catalog: Catalog | None = None,
                     cdf: ChallengeDefinition | None = None) -> Scene:
    """One baseline scene (never resampled: the baseline has no notion of a valid layout)."""
    rng = np.random.default_rng(np.random.SeedSequence(seed))
    draft, report = sample_uniform(cdf or empty_cdf(shell.room_type), shell, rng, catalog or default_catalog())
    return draft.to_scene("uniform", seed, notes={"unplaced": report.unplaced})
