"""The furniture layer: sample each piece's position from its score field and its heading from its
heaviest relation, on the free-floor grid, footprint collision-free and clear of doors."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.grid import HEADINGS, FloorGrid
from luminous_sim.cssg.requests import Request
from luminous_sim.cssg.scores import TEMPERATURE, Placed2D, directional_wall_distance, relation_field

WRONG_HEADING_PENALTY = 0.5
"""metres of cost for standing at a heading other than the preferred one."""


@dataclass
class FloorContext:
    """Everything the furniture layer reads and updates while placing one scene."""

    draft: SceneDraft
    grid: FloorGrid
    wall_dirs: np.ndarray
    centroid: tuple[float, float]
    placed: dict[str, Placed2D]

    @classmethod
    def create(cls, draft: SceneDraft) -> FloorContext:
        poly = draft.shell.polygon()
        grid = FloorGrid.from_polygon(poly)
        for zone in draft.shell.door_clearance_zones():
            grid.block(zone)
        for p in draft.placed:
            if p.obj.parent is None:
                grid.block(p.footprint)
        c = poly.centroid
        return cls(draft, grid, directional_wall_distance(grid), (c.x, c.y), {})

    def anchor(self, name: str | None) -> Placed2D | None:
        return self.placed.get(name) if name else None


def score(ctx: FloorContext, req: Request, entry) -> tuple[np.ndarray, np.ndarray | None]:
    """Weighted total cost per cell and the heading field of the heaviest relation that has one."""
    total = np.zeros(ctx.grid.shape)
    heading, best_w = None, -1.0
    for rel in req.rels:
        anchor = ctx.anchor(rel.anchor)
        if rel.anchor and anchor is None and rel.anchor not in ("wall", "window", "door"):
            continue  # the anchor could not be placed; the report records the relation as unmet
        cost, head = relation_field(rel.relation, ctx.grid, entry, anchor, ctx.wall_dirs, ctx.centroid)
        total += rel.weight * cost
        if head is not None and rel.weight > best_w:
            heading, best_w = head, rel.weight
    return total, heading


def place_piece(ctx: FloorContext, req: Request, tries: int = 4) -> Placed2D | None:
    """Place one furniture request; None if no variant fits anywhere."""
    draft = ctx.draft
    rng = draft.rng
    variants = draft.catalog.of_type(req.type)
    if req.asset:
        variants = [e for e in variants if e.id == req.asset]
    if not variants:
        return None
    for _ in range(tries):
        entry = variants[int(rng.integers(len(variants)))]
        cost, heading = score(ctx, req, entry)
        feas = np.stack([ctx.grid.feasible(entry, h) for h in HEADINGS])
        if not feas.any():
            continue
        if heading is None:
            heading = np.full(ctx.grid.shape, int(rng.integers(4)))
        # each cell's cost at each heading: the preferred heading is free, the others cost extra
        per_heading = np.stack([cost + WRONG_HEADING_PENALTY * (heading != k) for k in range(4)])
        per_heading[~feas] = np.inf
        flat = per_heading.ravel()
        finite = np.isfinite(flat)
        logits = -(flat[finite] - flat[finite].min()) / TEMPERATURE
        prob = np.exp(logits)
        prob /= prob.sum()
        pick = np.flatnonzero(finite)[int(rng.choice(len(prob), p=prob))]
        k, r, c = np.unravel_index(pick, per_heading.shape)
        x, y, yaw = float(ctx.grid.xs[c]), float(ctx.grid.ys[r]), HEADINGS[int(k)]
        obj = draft.add(entry, x, y, -entry.bbox_min[2], yaw, "furniture", fixed=True, name=req.name,
                        states=req.states)
        ctx.grid.block(draft.placed[-1].footprint)
        placed = Placed2D(req.type, x, y, yaw, entry)
        ctx.placed[req.name] = placed
        ctx.placed[obj.id] = placed
        return placed
    return None


def heading_of(yaw: float) -> int:
    return int(round(yaw / (math.pi / 2))) % 4
