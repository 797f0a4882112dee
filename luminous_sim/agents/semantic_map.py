"""The agent's top-down semantic map, built from its own depth, segmentation and pose only (FILM's and HLSM's
map, without learning): floor and obstacle evidence on a fine grid, the instances seen (their type and the
points they were seen at), and the positions ALFRED's moves reach (a 0.25 m grid of nodes)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from luminous_sim.agents.camera import Intrinsics, unproject
from luminous_sim.agents.own_pose import STEP, OwnPose
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT

RESOLUTION = 0.05
"""Metres a map cell."""
EXTENT = 16.0
"""Metres the map reaches from the start each way (a generated house is under 15 m across)."""
FLOOR_BELOW = 0.06
"""Points below this height (metres) are floor."""
OBSTACLE_BELOW = 1.7
"""Points between the floor and this height block the agent's body (a cylinder up to its camera)."""
SEEN_WITHIN = 5.0
"""Depth (metres) beyond which the map does not trust a point."""
BODY_RADIUS = 0.15
"""Obstacle evidence this close to a node's centre blocks it (the body's 0.2 m, and the env's margin)."""
POINTS_KEPT = 600
"""Most points kept per instance (the latest frames' first)."""
STRIDE = 2
"""Every STRIDE-th pixel each way is mapped."""
SITE = 1.0
"""Metres a side of the floor squares an instance is seen in (its sites: a long counter is searched site by
site)."""


@dataclass
class Instance:
    """An object instance the agent has seen: its segmentation id, type, and the points it was seen at."""

    body: int
    type_index: int
    points: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    last_seen: int = 0
    sites: dict[tuple[int, int], tuple[np.ndarray, int]] = field(default_factory=dict)
    """Per `SITE` square it was seen in: the sum of its points seen there, and their number (every frame's,
    where `points` keeps only the latest)."""

    def site_point(self, site: tuple[int, int]) -> np.ndarray:
        """The mean of the points seen in one site."""
        total, count = self.sites[site]
        return total / count

    @property
    def centre(self) -> np.ndarray:
        return self.points.mean(axis=0)


Node = tuple[int, int]


class SemanticMap:
    """Floor and obstacle evidence, instances and node bookkeeping in the agent's own frame."""

    def __init__(self, intrinsics: Intrinsics):
        self.intrinsics = intrinsics
        self.size = int(2 * EXTENT / RESOLUTION)
        self.floor = np.zeros((self.size, self.size), np.int32)
        self.obstacle = np.zeros((self.size, self.size), np.int32)
        self.instances: dict[int, Instance] = {}
        self.visited: set[Node] = set()
        self.blocked_moves: set[tuple[Node, int]] = set()
        self.frame = 0
        self._grids: tuple[int, np.ndarray, np.ndarray] | None = None
        rows, cols = np.mgrid[0:intrinsics.height:STRIDE, 0:intrinsics.width:STRIDE]
        self._rows, self._cols = rows.ravel(), cols.ravel()

    def cell(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        half = self.size // 2
        return (np.floor(x / RESOLUTION).astype(np.int64) + half, np.floor(y / RESOLUTION).astype(np.int64) + half)

    def update(self, depth: np.ndarray, segmentation: np.ndarray, types: np.ndarray, pose: OwnPose,
               held: int | None = None) -> None:
        """Add one frame seen from `pose` (depth (H, W) metres, instance ids and type indices (H, W)); the pixels
        of `held`, the instance in the agent's hand, are left out (it moves with the agent)."""
        self.frame += 1
        self.visited.add(pose.node)
        rows, cols = self._rows, self._cols
        d = depth[rows, cols]
        keep = d < SEEN_WITHIN
        if held is not None:
            keep &= segmentation[rows, cols] != held
        rows, cols, d = rows[keep], cols[keep], d[keep]
        pts = unproject(d, rows, cols, self.intrinsics, pose.x, pose.y, pose.yaw, pose.horizon)
        cx, cy = self.cell(pts[:, 0], pts[:, 1])
        inside = (cx >= 0) & (cx < self.size) & (cy >= 0) & (cy < self.size)
        z = pts[:, 2]
        floor = inside & (z < FLOOR_BELOW)
        obstacle = inside & (z >= FLOOR_BELOW) & (z < OBSTACLE_BELOW)
        np.add.at(self.floor, (cx[floor], cy[floor]), 1)
        np.add.at(self.obstacle, (cx[obstacle], cy[obstacle]), 1)
        ids, kinds = segmentation[rows, cols], types[rows, cols]
        for body in np.unique(ids[kinds > 0]):
            mine = ids == body
            found = self.instances.get(int(body))
            if found is None:
                found = self.instances[int(body)] = Instance(int(body), int(kinds[mine][0]))
            found.points = np.concatenate([pts[mine], found.points])[:POINTS_KEPT]
            found.last_seen = self.frame
            _add_sites(found, pts[mine])

    def forget_instance(self, body: int) -> None:
        """An instance that moved (it is in the agent's hand, or was sliced): where it was is no longer known."""
        self.instances.pop(body, None)

    def of_type(self, type_index: int) -> list[Instance]:
        return [i for i in self.instances.values() if i.type_index == type_index]

    def _node_grids(self) -> tuple[np.ndarray, np.ndarray]:
        """Per node: obstacle evidence within the body's radius, and any evidence within half a step (box sums
        over the cells, made once per frame)."""
        if self._grids is None or self._grids[0] != self.frame:
            per = round(STEP / RESOLUTION)
            centres = np.arange(0, self.size, per)
            self._grids = (self.frame, _box_sums(self.obstacle, centres, round(BODY_RADIUS / RESOLUTION)),
                           _box_sums(self.obstacle + self.floor, centres, per // 2))
        return self._grids[1], self._grids[2]

    def _node_index(self, node: Node) -> tuple[int, int] | None:
        half = self.size // (2 * round(STEP / RESOLUTION))
        i, j = node[0] + half, node[1] + half
        n = self.size // round(STEP / RESOLUTION)
        return (i, j) if 0 <= i < n and 0 <= j < n else None

    def blocked(self, node: Node) -> bool:
        """Obstacle evidence within the body's radius of the node (a node stood on is never blocked; one off the
        map always is)."""
        if node in self.visited:
            return False
        at = self._node_index(node)
        return at is None or bool(self._node_grids()[0][at] >= 3)

    def known(self, node: Node) -> bool:
        """Floor or obstacle seen within half a step of the node, or the agent stood on it."""
        if node in self.visited:
            return True
        at = self._node_index(node)
        return at is not None and bool(self._node_grids()[1][at] > 0)

    def known_nodes(self) -> list[Node]:
        """Every node with evidence near it."""
        half = self.size // (2 * round(STEP / RESOLUTION))
        xs, ys = np.nonzero(self._node_grids()[1] > 0)
        return sorted({(int(x) - half, int(y) - half) for x, y in zip(xs, ys)} | self.visited)

    def passable(self, node: Node, heading: int) -> bool:
        """Whether a move from `node` along `heading` (quarter turns) may succeed."""
        return (node, heading) not in self.blocked_moves

    def eye_distance(self, node: Node, points: np.ndarray) -> float:
        """The least distance from the eye standing at `node` to `points`."""
        eye = np.array([node[0] * STEP, node[1] * STEP, CAMERA_HEIGHT])
        return float(np.min(np.linalg.norm(points - eye, axis=1))) if len(points) else float("inf")


def _add_sites(instance: Instance, points: np.ndarray) -> None:
    squares, which = np.unique(np.floor(points[:, :2] / SITE).astype(np.int64), axis=0, return_inverse=True)
    sums = np.zeros((len(squares), 3))
    np.add.at(sums, which.ravel(), points)
    counts = np.bincount(which.ravel(), minlength=len(squares))
    for (i, j), total, n in zip(squares.tolist(), sums, counts.tolist(), strict=True):
        old = instance.sites.get((i, j))
        instance.sites[(i, j)] = (total, n) if old is None else (old[0] + total, old[1] + n)


def _box_sums(grid: np.ndarray, centres: np.ndarray, radius: int) -> np.ndarray:
    """The sum of `grid` over the square of cells within `radius` of each (centre, centre) pair."""
    total = np.zeros((grid.shape[0] + 1, grid.shape[1] + 1), np.int64)
    total[1:, 1:] = grid.cumsum(0).cumsum(1)
    lo = np.clip(centres - radius, 0, grid.shape[0])
    hi = np.clip(centres + radius + 1, 0, grid.shape[0])
    return total[hi][:, hi] - total[lo][:, hi] - total[hi][:, lo] + total[lo][:, lo]
