"""Top-down picture of a RoomShell (matplotlib, headless): walls, openings, fixtures, zones."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from luminous_sim.rooms.shell import RoomShell

SLOT_COLOURS = {
    "Sink": "#4f9bd9",
    "StoveBurner": "#d9534f",
    "Fridge": "#7f8c8d",
    "Toilet": "#f0f0f0",
    "Bathtub": "#9fd6f5",
    "Shower": "#c7e9f7",
}
ZONE_COLOURS = ("#f6e3b4", "#d4ecd0", "#e4d7f0", "#f7d4d4")


def _box_corners(
    center: tuple[float, float, float], size: tuple[float, float, float], yaw: float
) -> np.ndarray:
    c, s = math.cos(yaw), math.sin(yaw)
    hx, hy = size[0] / 2, size[1] / 2
    local = np.array([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]])
    return local @ np.array([[c, s], [-s, c]]) + np.array(center[:2])


def plot_shell(
    shell: RoomShell, out: str | Path, reachable: np.ndarray | None = None, dpi: int = 110
) -> Path:
    """Draw `shell` from above and save it as an image file (format from the suffix).

    Args:
        shell: the room.
        out: output path, e.g. `room.png`.
        reachable: optional (N, 2) points to overlay (e.g. ALFRED's reachable positions).
        dpi: resolution.

    Returns:
        The path written.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Arc
    from matplotlib.patches import Polygon as MplPolygon

    x0, y0, x1, y1 = shell.bounds
    fig, ax = plt.subplots(figsize=(7, 7 * max(0.5, (y1 - y0 + 1) / (x1 - x0 + 1))))
    ax.add_patch(
        MplPolygon(np.array(shell.outline), closed=True, fc="#fbfaf5", ec="none", zorder=0)
    )
    for i, z in enumerate(shell.zones):
        poly = np.array(z.polygon)
        ax.add_patch(
            MplPolygon(
                poly,
                closed=True,
                fc=ZONE_COLOURS[i % 4],
                ec="#8a7f62",
                ls="--",
                alpha=0.5,
                zorder=1,
            )
        )
        cx, cy = z.shape().representative_point().coords[0]
        ax.text(
            cx,
            cy,
            z.name,
            ha="center",
            va="center",
            fontsize=10,
            color="#6b5e3c",
            style="italic",
            zorder=6,
        )
    for zone in shell.door_clearance_zones():
        ax.add_patch(
            MplPolygon(
                np.array(zone.exterior.coords),
                closed=True,
                fc="none",
                ec="#2e8b57",
                hatch="//",
                lw=0.5,
                zorder=2,
            )
        )
    for c in shell.fixtures.counters:
        ax.add_patch(
            MplPolygon(
                np.array(shell.footprint(c).exterior.coords),
                closed=True,
                fc="#d2b48c",
                ec="#7a5c32",
                zorder=3,
            )
        )
    for s in shell.fixtures.slots:
        poly = np.array(shell.footprint(s).exterior.coords)
        ax.add_patch(
            MplPolygon(poly, closed=True, fc=SLOT_COLOURS.get(s.type, "#ccc"), ec="#333", zorder=4)
        )
        cx, cy = poly[:-1].mean(axis=0)
        ax.text(
            cx,
            cy,
            s.type.replace("StoveBurner", "Stove"),
            ha="center",
            va="center",
            fontsize=7,
            zorder=6,
        )
    for b in shell.wall_boxes():
        colour = {"solid": "#333333", "lintel": "#999999", "sill": "#6fa8dc", "head": "#6fa8dc"}[
            b.kind
        ]
        ax.add_patch(
            MplPolygon(
                _box_corners(b.center, b.size, b.yaw), closed=True, fc=colour, ec="none", zorder=5
            )
        )
    for d in shell.doors:
        w = shell.wall(d.wall)
        hinge_u = d.offset if d.hinge == "start" else d.offset + d.width
        free_u = d.offset + d.width if d.hinge == "start" else d.offset
        hx, hy = w.point(hinge_u)
        theta0 = math.degrees(math.atan2(*(np.subtract(w.point(free_u), (hx, hy))[::-1])))
        theta1 = math.degrees(math.atan2(w.normal[1], w.normal[0]))
        lo, hi = sorted([theta0, theta1])
        if hi - lo > 180:
            lo, hi = hi, lo + 360
        ax.add_patch(
            Arc(
                (hx, hy),
                2 * d.width,
                2 * d.width,
                theta1=lo,
                theta2=hi,
                color="#2e8b57",
                lw=1,
                zorder=6,
            )
        )
        ex, ey = w.point(hinge_u, d.width)
        ax.plot([hx, ex], [hy, ey], color="#2e8b57", lw=2, zorder=6)
    pts = shell.grid_points()
    if len(pts):
        ax.scatter(
            pts[:, 0], pts[:, 1], s=4, c="#1f77b4", zorder=7, label=f"grid points ({len(pts)})"
        )
    if reachable is not None and len(reachable):
        ax.scatter(
            reachable[:, 0],
            reachable[:, 1],
            s=12,
            facecolors="none",
            edgecolors="#ff7f0e",
            lw=0.7,
            zorder=8,
            label=f"reachable ({len(reachable)})",
        )
    pad = 0.3 + shell.wall_thickness
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    layout = f", {shell.fixtures.layout} layout" if shell.fixtures.layout != "none" else ""
    ax.set_title(
        f"{shell.name}: {shell.room_type}, {shell.shape}, {shell.area:.1f} m²{layout}", fontsize=10
    )
    ax.legend(loc="upper right", fontsize=7, framealpha=0.8)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(out, dpi=dpi, bbox_inches="tight")
    plt.close(fig)
    return out
