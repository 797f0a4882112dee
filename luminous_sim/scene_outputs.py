"""Write what `luminous generate` produces for one scene: scene JSON, validation report (layout and
physics), a labelled top-down picture with the reachable grid, and an egocentric snapshot."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from luminous_sim.assets.objio import png_bytes, write_atomic
from luminous_sim.cssg import Generated, HouseGenerated


def write_scene_outputs(generated: Generated | HouseGenerated, out_dir: Path, physics: bool = True) -> dict:
    """Write the files for one generated scene (a room or a house) into `out_dir`; returns the combined report
    (a house's `layout` holds each room's CSSG report and which rooms its connected floor reaches)."""
    from luminous_sim.world import build_scene, check_physics, egocentric, top_down

    out_dir = Path(out_dir)
    scene = generated.scene
    report = {"layout": generated.report.to_dict()}
    if physics:
        report["physics"] = check_physics(scene).to_dict()
    built = build_scene(scene)
    try:
        grid = _reachable(scene)
        write_atomic(out_dir / "top_down.png", png_bytes(top_down(built, grid=grid)))
        if len(grid):
            x, y, yaw = _view_from(scene, grid)
            frame = egocentric(built, x, y, yaw, horizon_deg=15.0, width=400, height=300, fov=75)
            write_atomic(out_dir / "egocentric.png", png_bytes(frame.rgb))
    finally:
        built.close()
    scene.save(out_dir / "scene.json")
    write_atomic(out_dir / "report.json", json.dumps(report, indent=1, sort_keys=True) + "\n")
    return report


def _reachable(scene) -> np.ndarray:
    from luminous_sim.scene import scene_reachable_grid

    return scene_reachable_grid(scene)


def _view_from(scene, grid: np.ndarray) -> tuple[float, float, float]:
    """A standing point near the room's middle (a house's largest room's), facing the direction with the most
    room (in a house, up to its interior walls)."""
    from shapely.geometry import Point

    poly = scene.room.polygon()
    c = np.array(poly.centroid.coords[0])
    if scene.room.house is not None:
        biggest = max(scene.room.house.rooms, key=lambda r: (r.polygon().area, r.name))
        c = np.array(biggest.polygon().centroid.coords[0])
        poly = scene.room.free_floor()
    x, y = grid[int(np.argmin(np.linalg.norm(grid - c, axis=1)))]

    def depth(a: float) -> float:
        d = 0.0
        while d < 20 and poly.contains(Point(x + np.sin(np.radians(a)) * d, y + np.cos(np.radians(a)) * d)):
            d += 0.25
        return d

    return float(x), float(y), float(max(range(0, 360, 90), key=depth))
