"""Whether the agent could see a spot in a receptacle region from where it can stand, in closed form on
the region boxes of the host's asset, so that small objects are kept where they can be seen before any
scene is built.

A sight line from the camera (at the agent's eye height, on the reachable grid, within the visibility
distance) to the spot must pass under the region above it (a low shelf under a table top, seen through
its front, since shelf units have side panels) and over the rim around it (the inside of a garbage
can; for a surface, its own edge, which hides the back of a shelf above the eye). Since a sight line
only rises towards the eye, checking it where it leaves the covering or surrounding box is enough.
The built scene's ray test (world/sightlines.py) remains the judge; this is its cheap forecast, a
little stricter.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.scene.pose import rotate
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT, VISIBILITY_DISTANCE

BOARD = 0.03
"""Metres of board assumed under the region above (its floor is the board's top)."""
MARGIN = 0.02
"""Metres a sight line keeps clear of a board edge or a rim."""
REACH_MARGIN = 0.05
"""Metres kept inside the visibility distance (the spot, not the object's nearest point, is measured)."""
MIN_OVERLAP = 0.5
"""Share of a region's area a region above must cover to count as its roof."""


@dataclass(frozen=True)
class Box2:
    """An axis-aligned rectangle in the host's frame: centre and half sizes (x, y)."""

    cx: float
    cy: float
    hx: float
    hy: float

    def contains(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        return (np.abs(x - self.cx) <= self.hx) & (np.abs(y - self.cy) <= self.hy)

    def exit(self, tx, ty, ux: np.ndarray, uy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """From (tx, ty) along unit directions (ux, uy): distance to the boundary and whether the line
        leaves through the front edge (+y)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            sx = np.where(ux > 0, (self.cx + self.hx - tx) / ux, np.where(ux < 0, (self.cx - self.hx - tx) / ux,
                                                                          np.inf))
            sy = np.where(uy > 0, (self.cy + self.hy - ty) / uy, np.where(uy < 0, (self.cy - self.hy - ty) / uy,
                                                                          np.inf))
        return np.maximum(np.minimum(sx, sy), 0.0), (sy <= sx) & (uy > 0)


@dataclass(frozen=True)
class Shade:
    """What stands between the eye and a region, in the host's frame: the region above (its box and the
    height a sight line must stay under) and the rim around it (its box and the height to stay over)."""

    roof: tuple[Box2, float] | None = None
    rim: tuple[Box2, float] | None = None


def _box(entry: AssetEntry, r: dict) -> tuple[Box2, float]:
    """A region's rectangle and floor height in the host's frame."""
    c = np.array(r["center"]) + np.array(entry.link_origins[r["link"]])
    sx, sy, sz = r["size"]
    floor = c[2] if r["kind"] == "surface" else c[2] - sz / 2
    return Box2(float(c[0]), float(c[1]), sx / 2, sy / 2), float(floor)


def _overlap(a: Box2, b: Box2) -> float:
    w = min(a.cx + a.hx, b.cx + b.hx) - max(a.cx - a.hx, b.cx - b.hx)
    h = min(a.cy + a.hy, b.cy + b.hy) - max(a.cy - a.hy, b.cy - b.hy)
    return max(w, 0.0) * max(h, 0.0)


def shades(entry: AssetEntry) -> dict[str, Shade]:
    """Per region of an asset: its roof (the lowest other region over most of it) and its rim (a volume's
    top, a surface's own edge). Regions behind doors have neither: they are seen through the open door."""
    boxes = {r["name"]: _box(entry, r) for r in entry.regions}
    out = {}
    for r in entry.regions:
        if r.get("requires_open"):
            out[r["name"]] = Shade()
            continue
        box, floor = boxes[r["name"]]
        above = [f for name, (b, f) in boxes.items() if name != r["name"] and f > floor + 0.05
                 and _overlap(b, box) >= MIN_OVERLAP * 4 * box.hx * box.hy]
        roof = (box, min(above) - BOARD - MARGIN) if above else None
        # a rim must be cleared by MARGIN; a surface's edge need only be, since what stands on it is above it
        out[r["name"]] = Shade(roof, (box, floor + r["size"][2] + MARGIN if r["kind"] == "volume" else floor))
    return out


class View:
    """The eyes that might see into one region of a placed host, kept in the host's frame, to test many
    spots in that region."""

    def __init__(self, shade: Shade, host_xy: tuple[float, float], host_yaw: float, eyes: np.ndarray,
                 around: tuple[tuple[float, float], float] | None = None, reach: float | None = None):
        """`around` (a world centre and a radius) bounds the spots to be tested: eyes out of reach of every
        point within it are dropped. `reach` bounds the sight lines (default: the visibility distance less
        `REACH_MARGIN`; `math.inf` for sight alone, where the eyes were chosen for reach already)."""
        self.reach = VISIBILITY_DISTANCE - REACH_MARGIN if reach is None else reach
        self.shade, self.origin, self.yaw = shade, np.asarray(host_xy, dtype=float), host_yaw
        eyes = np.asarray(eyes, dtype=float).reshape(-1, 2)
        if around is not None and len(eyes):
            (cx, cy), radius = around
            eyes = eyes[np.hypot(eyes[:, 0] - cx, eyes[:, 1] - cy) <= VISIBILITY_DISTANCE + radius]
        self.eyes = rotate(eyes - self.origin, -host_yaw) if len(eyes) else np.zeros((0, 2))

    def sees(self, spot: tuple[float, float], heights: tuple[float, ...]) -> bool:
        """Whether a point above world `spot` at one of `heights` is seen from one of the eyes, within reach."""
        return bool(self.sees_each(np.asarray(spot, dtype=float)[None], heights)[0])

    def sees_each(self, spots: np.ndarray, heights: tuple[float, ...]) -> np.ndarray:
        """`sees` for each of (K, 2) world points at once."""
        t = rotate(spots - self.origin, -self.yaw)  # (K, 2)
        delta = self.eyes[None] - t[:, None]  # (K, E, 2)
        d = np.maximum(np.hypot(delta[..., 0], delta[..., 1]), 1e-9)  # (K, E)
        z = np.asarray(heights, dtype=float)[:, None, None]  # (H, 1, 1)
        ok = np.hypot(d[None], CAMERA_HEIGHT - z) <= self.reach  # (H, K, E)
        if not ok.any():
            return np.zeros(len(spots), dtype=bool)
        ux, uy = delta[..., 0] / d, delta[..., 1] / d
        rise = (CAMERA_HEIGHT - z) / d[None]  # height gained per metre towards each eye
        tx, ty = t[:, 0:1], t[:, 1:2]
        if self.shade.roof is not None:
            box, under = self.shade.roof
            s, front = box.exit(tx, ty, ux, uy)
            covered = box.contains(tx, ty)  # (K, 1): a spot out from under the roof is not shaded by it
            ok &= ~covered[None] | (front[None] & (z + rise * s[None] <= under))
        if self.shade.rim is not None:
            box, top = self.shade.rim
            s, _ = box.exit(tx, ty, ux, uy)
            ok &= z + rise * s[None] >= top
        return ok.any(axis=(0, 2))


def in_sight(shade: Shade, host_xy: tuple[float, float], host_yaw: float, spot: tuple[float, float],
             heights: tuple[float, ...], eyes: np.ndarray) -> bool:
    """Whether a point above world `spot` at one of `heights` is seen from an eye over one of `eyes`
    ((N, 2) world points on the reachable grid) within reach."""
    return View(shade, host_xy, host_yaw, eyes).sees(spot, heights)
