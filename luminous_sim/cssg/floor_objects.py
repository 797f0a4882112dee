"""Small objects that lie or stand on the floor, as ALFRED's scenes put them: sports gear in a corner or
against a wall (a bat lies along the wall), a plunger and a scrub brush by the bathroom wall, a watering can
in a living room's corner. Which types may, and where, is data (`placement.json`'s `on_floor`); how often,
ALFRED's share of such placements (`object_hosts.json`'s `floor`)."""

from __future__ import annotations

import numpy as np

from luminous_sim.cssg.furniture import FloorContext, place_piece
from luminous_sim.cssg.requests import Rel, Request
from luminous_sim.cssg.tables import floor_relations, floor_share

FLOOR_WEIGHT = 2.0
"""Weight of the floor relation (a room-structure relation, as the paper weighs them)."""
FLOOR_TRIES = 4


def wants_floor(req: Request, rng: np.random.Generator) -> bool:
    """Whether a default object of a floor type (no on/in relation from the CDF) goes on the floor first:
    drawn with ALFRED's share of its placements on the floor. Draws nothing for other objects."""
    if req.explicit or not floor_relations(req.type) or any(r.relation in ("on", "in") for r in req.rels):
        return False
    return bool(rng.random() < floor_share(req.type))


def may_lie_on_floor(req: Request) -> bool:
    """Whether an object that found no host may go on the floor instead (a default object of a floor type)."""
    return not req.explicit and bool(floor_relations(req.type)) and not any(
        r.relation in ("on", "in") for r in req.rels)


def place_on_floor(ctx: FloorContext, req: Request, by_name: dict[str, str]) -> bool:
    """Lay a small object on the floor by one of its floor relations (in a corner, against a wall), drawn from
    that relation's score field like a piece of furniture, where it keeps every floor piece reachable and is
    within the agent's reach itself; the other relations are tried if the first finds no place."""
    relations = list(floor_relations(req.type))
    for k in ctx.draft.rng.permutation(len(relations)):
        rel = Rel(relations[int(k)], None, FLOOR_WEIGHT, False, False, f"floor:{req.type} {relations[int(k)]}")
        probe = Request(req.name, req.type, req.layer, False, req.asset, dict(req.states), [rel],
                        dict(req.attributes))
        if place_piece(ctx, probe, tries=FLOOR_TRIES, layer="object") is not None:
            by_name[req.name] = ctx.draft.placed[-1].obj.id
            return True
    return False
