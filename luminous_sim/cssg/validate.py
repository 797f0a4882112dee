"""The scene validation report that needs no physics: relations met, footprint overlaps, the agent's
reachable grid, and which objects an agent can reach (within 1.5 m of a reachable grid point)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np
import shapely
from shapely.strtree import STRtree

from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.scene import horizontal_reach
from luminous_sim.vocab.agent_body import VISIBILITY_DISTANCE as REACH


@dataclass
class RelationCheck:
    """Whether one relation of one CDF (or default) object holds in a sample.

    Attributes:
        subject: The object's name.
        relation: Canonical relation name.
        anchor: The target's name (an object or a room element), None for a unary relation.
        source: Where the relation comes from (the CDF, an implicit rule).
        hard: Whether the sample is rejected when it is not met (with `explicit`).
        explicit: Whether the CDF states it.
        met: Whether it holds (`scores.holds`).
        cost: Its score-field cost (m) where the subject stands; inf when either object is missing.
        gap: For a relation about distance (beside, near, far, away_from) to an object, the least
            distance (m) between the two footprints; None otherwise. `beside` is not met from WALKWAY up.
    """

    subject: str
    relation: str
    anchor: str | None
    source: str
    hard: bool
    explicit: bool
    met: bool
    cost: float
    gap: float | None = None


@dataclass
class LayoutReport:
    """What CSSG checked on one sample; `ok` says whether it is accepted."""

    attempt: int
    relations: list[RelationCheck] = field(default_factory=list)
    unplaced: list[str] = field(default_factory=list)
    overlaps: list[tuple[str, str]] = field(default_factory=list)
    reachable_points: int = 0
    unreachable: list[str] = field(default_factory=list)
    required: list[str] = field(default_factory=list)
    stopped_after: str | None = None
    """The request after which a sample that could no longer pass was stopped (None: it ran to the end)."""
    ignored_attributes: dict[str, list[str]] = field(default_factory=dict)
    """CDF object -> the attributes (size, colour, material) not applied because the object is one of the
    room's own fixtures (the kitchen's fridge), which keeps its asset."""

    @property
    def ok(self) -> bool:
        hard_failed = [r for r in self.relations if r.explicit and r.hard and not r.met]
        missing = [n for n in self.unplaced if n in self.required]
        return not hard_failed and not missing and not self.overlaps and not self.unreachable and \
            self.reachable_points > 0 and self.stopped_after is None

    def failed_relations(self) -> list[str]:
        return [f"{r.subject} {r.relation} {r.anchor or ''}".strip() + f" ({r.source})"
                for r in self.relations if r.explicit and r.hard and not r.met]

    def to_dict(self) -> dict:
        d = asdict(self)
        d["ok"] = self.ok
        return d


def _z_range(p) -> tuple[float, float]:
    return p.obj.position[2] + p.entry.bbox_min[2], p.obj.position[2] + p.entry.bbox_max[2]


def solid_overlaps(draft: SceneDraft, tol: float = 1e-4) -> list[tuple[str, str]]:
    """Pairs of fixed, free-standing or wall-hung things whose boxes intersect in 3D."""
    solid = [p for p in draft.placed if p.obj.parent is None and p.obj.layer != "object"]
    out = []
    for i, a in enumerate(solid):
        za = _z_range(a)
        for b in solid[i + 1:]:
            zb = _z_range(b)
            if za[0] < zb[1] - 0.005 and zb[0] < za[1] - 0.005 and a.footprint.intersection(b.footprint).area > tol:
                out.append((a.obj.id, b.obj.id))
    return out


def check_layout(draft: SceneDraft, requests, ctx, unplaced: list[str], attempt: int,
                 stopped_after: str | None = None) -> LayoutReport:
    """Relations, overlaps and reachability of a finished draft; of a sample stopped early (`stopped_after`
    its last request), the relations of `requests` placed so far only: it is rejected whatever the rest says."""
    report = LayoutReport(attempt, unplaced=list(unplaced), required=[r.name for r in requests if r.explicit],
                          stopped_after=stopped_after)
    by_name = named(draft)
    for req in requests:
        report.relations.extend(relation_checks(req, by_name, draft, ctx))
    if stopped_after is not None:
        return report
    report.overlaps = solid_overlaps(draft)
    grid = draft.reachable_grid()
    report.reachable_points = len(grid)
    if len(grid):
        report.unreachable = _out_of_reach([p for p in draft.placed if p.obj.layer != "decoration"], grid)
    return report


def named(draft: SceneDraft) -> dict:
    """The draft's placed things by their CDF or default name."""
    return {p.obj.name: p for p in draft.placed if p.obj.name}


def relation_checks(req, by_name: dict, draft: SceneDraft, ctx) -> list[RelationCheck]:
    """Whether each relation of one request holds in the draft (none for a default piece left out: it has
    no relations to meet; a CDF object left out fails all of its own)."""
    placed = by_name.get(req.name)
    if placed is None and not req.explicit:
        return []
    out = []
    for rel in req.rels:
        gap = None
        if placed is None:
            met, cost = False, float("inf")
        elif rel.relation in ("on", "in"):
            anchor = by_name.get(rel.anchor or "")
            met = anchor is not None and placed.obj.parent in {p.obj.id for p in draft.referents(anchor.obj.id)}
            cost = 0.0
        elif rel.relation in ("above", "under"):
            anchor = by_name.get(rel.anchor or "")
            met = anchor is not None and abs(_lateral(placed, anchor)) < 0.3
            cost = 0.0
        elif rel.anchor and ctx.anchor(rel.anchor) is None and rel.anchor not in ("wall", "window", "door"):
            met, cost = False, float("inf")
        else:
            met, cost, gap = ctx.check(rel.relation, placed.entry, rel.anchor, placed.obj.position[0],
                                       placed.obj.position[1], placed.obj.yaw)
        out.append(RelationCheck(req.name, rel.relation, rel.anchor, rel.source, rel.hard, rel.explicit,
                                 bool(met), round(float(cost), 4), None if gap is None else round(gap, 4)))
    return out


def _out_of_reach(placed: list, grid: np.ndarray) -> list[str]:
    """Ids of the placed things out of the agent's reach: farther than REACH from the eye over every
    reachable grid point (on the floor, `horizontal_reach` of the thing's heights)."""
    tree = STRtree(shapely.points(grid))
    out = []
    for p in placed:
        lo, hi = _z_range(p)
        if not len(tree.query(p.footprint, predicate="dwithin", distance=horizontal_reach(lo, hi, REACH) - 1e-6)):
            out.append(p.obj.id)
    return out


def _lateral(placed, anchor) -> float:
    """Offset of `placed` from `anchor` along the anchor's own width axis (a painting centred over a sofa: 0)."""
    yaw = anchor.obj.yaw
    axis = np.array([np.cos(yaw), np.sin(yaw)])
    return float((np.array(placed.footprint.centroid.coords[0]) - np.array(anchor.footprint.centroid.coords[0])) @ axis)
