"""The scene validation report that needs no physics: relations met, footprint overlaps, the agent's
reachable grid, and which objects an agent can reach (within 1.5 m of a reachable grid point)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import networkx as nx
import numpy as np
from shapely import distance as shp_distance
from shapely.geometry import Point
from shapely.strtree import STRtree

from luminous_sim.cssg.draft import SceneDraft
from luminous_sim.cssg.scores import TOLERANCE, point_cost

AGENT_RADIUS = 0.2
STEP = 0.25
REACH = 1.5
"""ALFRED's visibility distance: the agent interacts with things within 1.5 m."""
AGENT_HEIGHT = 1.8


@dataclass
class RelationCheck:
    subject: str
    relation: str
    anchor: str | None
    source: str
    hard: bool
    explicit: bool
    met: bool
    cost: float


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

    @property
    def ok(self) -> bool:
        hard_failed = [r for r in self.relations if r.explicit and r.hard and not r.met]
        missing = [n for n in self.unplaced if n in self.required]
        return not hard_failed and not missing and not self.overlaps and not self.unreachable and \
            self.reachable_points > 0

    def failed_relations(self) -> list[str]:
        return [f"{r.subject} {r.relation} {r.anchor or ''}".strip() + f" ({r.source})"
                for r in self.relations if r.explicit and r.hard and not r.met]

    def to_dict(self) -> dict:
        d = asdict(self)
        d["ok"] = self.ok
        return d


def floor_obstacles(draft: SceneDraft) -> list[tuple[str, object]]:
    """Footprints of everything an agent bumps into: floor-standing things lower than its height."""
    out = []
    for p in draft.placed:
        if p.obj.parent is not None or p.obj.layer == "object":
            continue
        if p.obj.position[2] + p.entry.bbox_min[2] < AGENT_HEIGHT:
            out.append((p.obj.id, p.footprint))
    return out


def reachable_grid(draft: SceneDraft) -> np.ndarray:
    """Agent positions on the 0.25 m grid, free of obstacles, in the largest connected component."""
    pts = draft.shell.grid_points(STEP, clearance=AGENT_RADIUS, avoid_fixtures=False)
    obstacles = [fp for _, fp in floor_obstacles(draft)]
    if len(pts) == 0:
        return pts
    if obstacles:
        tree = STRtree(obstacles)
        blocked = np.zeros(len(pts), dtype=bool)
        pidx, _ = tree.query([Point(p) for p in pts], predicate="dwithin", distance=AGENT_RADIUS)
        blocked[np.unique(pidx)] = True
        pts = pts[~blocked]
    g = nx.Graph()
    keys = {(round(x / STEP), round(y / STEP)): i for i, (x, y) in enumerate(pts)}
    g.add_nodes_from(range(len(pts)))
    for (i, j), n in keys.items():
        for di, dj in ((1, 0), (0, 1)):
            m = keys.get((i + di, j + dj))
            if m is not None:
                g.add_edge(n, m)
    if len(pts) == 0:
        return pts
    biggest = max(nx.connected_components(g), key=len)
    return pts[sorted(biggest)]


def check_layout(draft: SceneDraft, requests, ctx, unplaced: list[str], attempt: int) -> LayoutReport:
    """Relations, overlaps and reachability of a finished draft."""
    report = LayoutReport(attempt, unplaced=list(unplaced), required=[r.name for r in requests if r.explicit])
    by_name = {p.obj.name: p for p in draft.placed if p.obj.name}
    for req in requests:
        placed = by_name.get(req.name)
        for rel in req.rels:
            if placed is None:
                met, cost = False, float("inf")
            elif rel.relation in ("on", "in"):
                anchor = by_name.get(rel.anchor or "")
                met, cost = anchor is not None and placed.obj.parent == anchor.obj.id, 0.0
            elif rel.relation in ("above", "under"):
                anchor = by_name.get(rel.anchor or "")
                met = anchor is not None and abs(_lateral(placed, anchor)) < 0.3
                cost = 0.0
            else:
                anchor2d = ctx.anchor(rel.anchor)
                if rel.anchor and anchor2d is None and rel.anchor not in ("wall", "window", "door"):
                    met, cost = False, float("inf")
                else:
                    cost = point_cost(rel.relation, ctx.grid, placed.entry, anchor2d, ctx.wall_dirs, ctx.centroid,
                                      placed.obj.position[0], placed.obj.position[1])
                    met = cost <= TOLERANCE.get(rel.relation, 0.3) + 1e-6
            report.relations.append(RelationCheck(req.name, rel.relation, rel.anchor, rel.source, rel.hard,
                                                  rel.explicit, bool(met), round(float(cost), 4)))
    obstacles = floor_obstacles(draft)
    for i, (a, fa) in enumerate(obstacles):
        for b, fb in obstacles[i + 1:]:
            if fa.intersection(fb).area > 1e-4 and not _host_pair(draft, a, b):
                report.overlaps.append((a, b))
    grid = reachable_grid(draft)
    report.reachable_points = int(len(grid))
    if len(grid):
        pts = [Point(p) for p in grid]
        for p in draft.placed:
            if p.obj.layer == "decoration":
                continue
            if min(shp_distance(p.footprint, pt) for pt in _near(pts, p.footprint)) > REACH - 1e-6:
                report.unreachable.append(p.obj.id)
    return report


def _near(points: list[Point], fp) -> list[Point]:
    c = fp.centroid
    near = [pt for pt in points if abs(pt.x - c.x) < 4 and abs(pt.y - c.y) < 4]
    return near or points


def _host_pair(draft: SceneDraft, a: str, b: str) -> bool:
    """A fixture and the anchored part it brings (Sink and its SinkBasin) may overlap by design."""
    objs = {p.obj.id: p.obj for p in draft.placed}
    return objs[a].parent == b or objs[b].parent == a


def _lateral(placed, anchor) -> float:
    """Offset of `placed` from `anchor` along the anchor's own width axis (a painting centred over a sofa: 0)."""
    yaw = anchor.obj.yaw
    axis = np.array([np.cos(yaw), np.sin(yaw)])
    return float((np.array(placed.footprint.centroid.coords[0]) - np.array(anchor.footprint.centroid.coords[0])) @ axis)
