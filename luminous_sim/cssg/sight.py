"""Whether the agent could see a spot in a receptacle region from where it can stand, in closed form on
the region boxes of the host's asset, so that small objects are kept where they can be seen before any
scene is built.

A sight line from the camera (at the agent's eye height, on the reachable grid, within the visibility
distance) to the spot must pass under the region above it (a low shelf under a table top, seen through
its front, since shelf units have side panels) and over the rim around it (the inside of a garbage
can; for a surface, its own edge, which hides the back of a shelf above the eye). Since a sight line only rises towards the eye, checking it where it leaves the covering or
surrounding box is enough. The built scene's ray test (world/sightlines.py) remains the judge; this is
its cheap forecast, a little stricter.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.cssg.pose import rotate
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

    def exit(self, tx: float, ty: float, ux: np.ndarray, uy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
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


def in_sight(shade: Shade, host_xy: tuple[float, float], host_yaw: float, spot: tuple[float, float],
             heights: tuple[float, ...], eyes: np.ndarray) -> bool:
    """Whether a point above world `spot` at one of `heights` is seen from an eye over one of `eyes`
    ((N, 2) world points on the reachable grid) within reach."""
    if len(eyes) == 0:
        return False
    origin = np.array(host_xy)
    t = rotate((np.array(spot) - origin)[None], -host_yaw)[0]
    g = rotate(eyes - origin, -host_yaw)
    d = np.hypot(g[:, 0] - t[0], g[:, 1] - t[1])
    ux, uy = (g[:, 0] - t[0]) / np.maximum(d, 1e-9), (g[:, 1] - t[1]) / np.maximum(d, 1e-9)
    for z in heights:
        ok = np.hypot(d, CAMERA_HEIGHT - z) <= VISIBILITY_DISTANCE - REACH_MARGIN
        if shade.roof is not None:
            box, under = shade.roof
            if box.contains(np.array(t[0]), np.array(t[1])):
                s, front = box.exit(float(t[0]), float(t[1]), ux, uy)
                ok &= front & (z + (CAMERA_HEIGHT - z) * s / np.maximum(d, 1e-9) <= under)
        if shade.rim is not None:
            box, top = shade.rim
            s, _ = box.exit(float(t[0]), float(t[1]), ux, uy)
            ok &= z + (CAMERA_HEIGHT - z) * s / np.maximum(d, 1e-9) >= top
        if ok.any():
            return True
    return False
